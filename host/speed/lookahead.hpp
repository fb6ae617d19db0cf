// SPDX-License-Identifier: Apache-2.0
// The lookahead speed planner (docs/programs.md, "Feeds and speeds"): the pieces of a
// program in path order, each with its length, its tangents, its curvature and the speed
// the program asks; out, each piece's entry, cruise and exit speeds, planned over a
// window of the pieces that follow so that the machine can always stop at rest at the
// end of what it has seen, with one path acceleration (the block's ACCEL) for every
// ramp. Junction speeds follow Grbl's rule (the speed at which a circle of the junction
// deviation through the corner is taken at the axes' acceleration), the per-axis
// velocity limits are projected on the piece's direction, and a curved piece keeps to
// v <= sqrt(A_n rho) at its smallest radius of curvature rho. Memory: the window.
#pragma once

#include <array>
#include <cstddef>
#include <deque>
#include <functional>
#include <limits>

namespace dda::speed {

using Vec3 = std::array<double, 3>;  // machine axes X, Y, Z
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// One piece as the planner sees it (millimetres, seconds).
struct Segment {
  double length = 0;              // mm along the path
  Vec3 t0{}, t1{};                // unit tangents at its start and its end
  Vec3 share{};                   // the largest |tangent component| of each axis along it
  double min_radius = kInfinity;  // its smallest radius of curvature, mm (a line: infinity)
  double feed = 0;                // the speed the program asks, mm/s
  bool rapid = false;             // G00: feed is the rapid rate
  bool rest_before = false;       // the tool is at rest at its start (a stop, a dwell, G61)
  double deviation = 0;           // the junction deviation at its start, mm
  std::size_t block = 0;          // the caller's index of the block it belongs to
};

// What holds a piece's speed below the program's: nothing, an axis' velocity, the
// curvature, or its length (the ramps from its entry and to its exit meet before the
// speed allowed is reached).
enum class Limit : unsigned char { None, VelocityX, VelocityY, VelocityZ, Curvature, Length };
const char* to_string(Limit l);

struct PlannedSegment {
  Segment seg;
  double cap = 0;               // the cruise speed allowed: min(feed, velocity, curvature limits)
  Limit cap_by = Limit::None;   // what set cap below the feed
  double junction = kInfinity;  // the largest speed at its start (Grbl's rule; 0 at rest)
  double entry = 0, exit = 0;   // mm/s
  double peak = 0;              // the speed it reaches: cap, or less when it is too short
  double time = 0;              // s, ramps and cruise
  Limit limit() const { return peak < cap * (1 - 1e-9) ? Limit::Length : cap_by; }
};

struct PlannerLimits {
  double accel = 0;         // the path acceleration of every ramp, mm/s^2
  double normal_accel = 0;  // the centripetal acceleration curves may use, mm/s^2
  Vec3 vmax{};              // each axis' velocity, mm/s (0: the axis is absent)
  Vec3 axis_accel{};        // each axis' acceleration, mm/s^2 (junctions; 0: absent)
  std::size_t window = 16;  // pieces planned over
};

// Grbl's junction speed between a piece ending in direction `in` and one starting in
// direction `out` (unit vectors), mm/s: 0 for a reversal, infinity straight on, else
// sqrt(a d sin(t/2) / (1 - sin(t/2))) with t the angle between -in and out, d the
// junction deviation and a the axes' acceleration along out - in.
double junction_speed(const Vec3& in, const Vec3& out, double deviation, const Vec3& axis_accel);

// A piece's time at acceleration a from entry v0 to exit v1 with the cruise speed vc
// allowed (a trapezoid, or a triangle whose peak it writes to *peak).
double ramp_time(double length, double v0, double v1, double vc, double a, double* peak);

class Lookahead {
 public:
  Lookahead(const PlannerLimits& lim, std::function<void(const PlannedSegment&)> out);
  // A piece, in path order; the oldest leaves, planned, once `window` pieces follow it.
  void push(const Segment& s);
  // The rest, to rest at the end.
  void finish();
  double cap(const Segment& s, Limit* by) const;

 private:
  struct Item {
    PlannedSegment p;
    double entry_max = 0;  // from the backward pass
  };
  void emit_front();
  PlannerLimits lim_;
  std::function<void(const PlannedSegment&)> out_;
  std::deque<Item> q_;
  double front_entry_ = 0;  // the speed the front piece starts at (fixed)
  bool started_ = false;
  Vec3 last_t1_{};
  double last_cap_ = 0;
};

}  // namespace dda::speed
