// Golden reference model of the ellipse DDA: the single definition of behaviour.
//
// Exact integer arithmetic only (no floating point in the datapath). Independent of
// SystemC and Verilator. See docs/design.md for the architecture it defines.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/fixed_trig.hpp"

namespace dda {

// Bad input: a parameter breaks a documented rule. The CLI exits with status 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
// A run-time guard tripped (iteration bound, stall, mismatch). The CLI exits with 1.
class GuardError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Point {
  std::int64_t x = 0;
  std::int64_t y = 0;
  friend bool operator==(const Point& p, const Point& q) { return p.x == q.x && p.y == q.y; }
  friend bool operator!=(const Point& p, const Point& q) { return !(p == q); }
  friend Point operator+(const Point& p, const Point& q) { return Point{p.x + q.x, p.y + q.y}; }
};

// One hardware command: everything the datapath needs to run one arc.
// All values are the exact (scaled) integers the registers hold.
struct Command {
  std::int64_t jv_x = 0, jv_y = 0;  // initial integrands
  std::int64_t jr_x = 0, jr_y = 0;  // accumulator preloads, 0 <= jr < cap
  std::int64_t cap = 1;             // capacity' (2^n * a * b)
  std::int64_t cnt_x = 0, cnt_y = 0;
  bool dir_x_neg = false, dir_y_neg = false;
  // Integrand corrections after a step: jv_<i> += inc_<i>_on_<axis>.
  std::int64_t inc_x_on_x = 0, inc_x_on_y = 0, inc_y_on_x = 0, inc_y_on_y = 0;
};

// The architectural registers between iterations (what the hardware holds).
struct RegState {
  std::int64_t jv_x = 0, jv_y = 0;
  std::int64_t jr_x = 0, jr_y = 0;
  std::int64_t cnt_x = 0, cnt_y = 0;
  friend bool operator==(const RegState& p, const RegState& q) {
    return p.jv_x == q.jv_x && p.jv_y == q.jv_y && p.jr_x == q.jr_x && p.jr_y == q.jr_y &&
           p.cnt_x == q.cnt_x && p.cnt_y == q.cnt_y;
  }
};

// The registers right after a command is loaded.
RegState initial_regs(const Command& c);

// One iteration: the datapath's inputs, intermediate sums and the registers after it.
struct Iteration {
  std::uint64_t iter = 0;           // 1-based, counted across the pieces of an arc
  std::uint32_t seg = 0;            // index of the piece (command) it belongs to
  bool dir_x_neg = false, dir_y_neg = false;  // step directions of that piece
  bool active_x = false, active_y = false;  // counter was non-zero: the axis added
  std::int64_t jv_x = 0, jv_y = 0;  // integrands used in this iteration
  std::int64_t sum_x = 0, sum_y = 0;  // accumulator sums before overflow removal
  bool step_x = false, step_y = false;  // overflow pulses
  RegState after;                   // registers after the iteration (jv corrected); after a
                                    // piece's last one, the next piece's loaded command
  Point pos;                        // position after the iteration
};

// The datapath: one call of iterate() is one iteration (one clock with ce high).
class Datapath {
 public:
  Datapath(const Command& cmd, Point start);
  const RegState& regs() const { return regs_; }
  const Command& command() const { return cmd_; }
  Point pos() const { return pos_; }
  std::uint64_t iterations() const { return iter_; }
  bool done() const { return regs_.cnt_x == 0 && regs_.cnt_y == 0; }
  // An active axis whose integrand is 0 and can no longer change: the arc never ends.
  bool stalled() const;
  Iteration iterate();
  // The same iteration without building its record (the fast path for validation,
  // cross-checks and benchmarks).
  void step();

 private:
  Command cmd_;
  RegState regs_;
  Point pos_;
  std::uint64_t iter_ = 0;
};

enum class Preload { Zero, Half };
const char* to_string(Preload p);

enum class Direction { Ccw, Cw };
const char* to_string(Direction d);

// An arc of the ellipse with semi-axes a, b, turned counter-clockwise by `angle` about
// its centre (so the semi-axis a points in direction angle). Angles that are multiples
// of 90 degrees use the exact integer datapath (integrands a^2 |v|, b^2 |u|); any other
// angle uses fixed-point coefficients (docs/golden-model.md, "Rotated ellipses") and
// needs a radius of curvature at the tips, min(a,b)^2 / max(a,b), above 1/4 step.
struct ArcSpec {
  std::int64_t a = 0, b = 0;
  std::int64_t angle = 0;         // micro-degrees (fixed_trig.hpp), reduced modulo a turn
  int bits = 0;                   // n: capacity 2^n in the paper's units; 0 = default_bits()
  Preload preload = Preload::Zero;
  Point center;                   // lattice point
  Direction dir = Direction::Ccw;
  // Start and end: absolute lattice points, or parametric angles in micro-degrees
  // (exclusive with the point). Defaults: the quarter arc from the end of the a
  // semi-axis to the end of the b semi-axis (parametric angles 0 and 90).
  std::optional<Point> from, to;
  std::optional<std::int64_t> from_theta, to_theta;
};

// The angle as a number of quarter turns 0..3, or -1 if it is not a multiple of 90.
int quarter_turns(const ArcSpec& spec);

// One monotone piece of an arc (each axis moves one way): one hardware command.
// Pieces of an axis-aligned ellipse meet at its vertices (lattice points), or where the
// path stalled short of one; those of a rotated ellipse where an axis turns.
struct Segment {
  Point from, to;
  int quadrant = 1;                   // 1..4: the quadrant (about the centre) it runs in
  Command cmd;
  std::uint64_t iteration_bound = 0;  // a run of this piece that passes it is stopped
};

// Fixed-point coefficients of a rotated ellipse (docs/golden-model.md, "Rotated
// ellipses"): with (x, y) the lattice position relative to the centre, the tangent of
// the counter-clockwise turn is (p x - qx y, qy x - p y), scaled so that the capacity
// is 2^kRotCapBits. For angles that are multiples of 90 degrees: p = 0, qx = ax^2,
// qy = by^2 exactly and the capacity is 2^n a b.
struct Coefficients {
  std::int64_t p = 0, qx = 0, qy = 0;
};
// Capacity of rotated ellipses: 2^kRotCapBits, the largest power of two the hardware's
// AccWidth-bit registers hold.
inline constexpr int kRotCapBits = 49;
// Fraction bits of the ideal start point (a parametric angle's point on the curve).
inline constexpr int kPosFrac = 32;

// A validated arc: resolved points and bits, its pieces, and the guard bound.
struct Plan {
  ArcSpec spec;                    // with bits resolved
  Point from, to;                  // lattice start and end
  // The start the DDA represents: from + (frac_x, frac_y) / 2^kPosFrac. With half
  // preload and a parametric start it is the ideal curve point (the first piece's
  // accumulator preloads carry the fraction); otherwise 0.
  std::int64_t frac_x = 0, frac_y = 0;
  bool full = false;               // one full turn: equal lattice ends or equal angles
  bool rotated = false;            // angle not a multiple of 90 degrees
  std::int64_t ax = 0, by = 0;     // quarter turns: semi-axes along X and Y (a, b swapped by
                                   // odd turns); rotated: a and b
  std::int64_t scale = 1;          // a*b: divide register values by it for paper units
  Coefficients coef;
  std::vector<Segment> segs;
  std::uint64_t iteration_bound = 0;  // sum of the pieces' bounds
  const Command& cmd() const { return segs.front().cmd; }
};

// Smallest valid n for the semi-axes: smallest n >= 1 with 2^n >= max(a, b).
int smallest_valid_bits(std::int64_t a, std::int64_t b);
// Widths above smallest_valid_bits + kMaxExtraBits are refused: past +4 more bits
// change nothing (spec, accuracy table) and each bit doubles the run's length.
inline constexpr int kMaxExtraBits = 16;
// The width used when none is given: four bits above the smallest valid width, where
// half preload does its best (spec: more bits change nothing), fewer if the capacity
// 2^n a b would reach 2^61.
int default_bits(std::int64_t a, std::int64_t b);

// Validate and plan. Throws InputError naming the value and the rule it breaks.
Plan plan_arc(const ArcSpec& spec);

// The curve point of parametric angle theta (micro-degrees) relative to the centre, in
// Q(kPosFrac): (a cos theta, b sin theta) turned by the spec's angle, computed with the
// deterministic fixed-point sines and cosines (the same bits on every machine).
struct FixedPoint {
  std::int64_t x = 0, y = 0;  // Q(kPosFrac)
};
FixedPoint theta_ideal(const ArcSpec& spec, std::int64_t theta);

// Lattice point of parametric angle theta (absolute), by the documented rule
// (docs/golden-model.md, "Parametric angles"): with half preload the nearest lattice
// point to the ideal point (each coordinate rounded half away from zero; the first
// piece's preloads carry the rest, so the DDA starts on the curve); with zero preload,
// of the four lattice points around it (floor and ceiling of each coordinate), the one
// with the least r >= 1, r^2 = Q(p) / Q(curve) for the ellipse's quadratic form Q (on
// or just outside the curve: the DDA follows the ellipse through it, r times the
// nominal one, and cannot stall at a vertex). Ties go to the first in the order
// (floor, floor), (floor, ceil), (ceil, floor), (ceil, ceil).
Point theta_point(const ArcSpec& spec, std::int64_t theta);

// Largest distance (in steps) a start or end point may lie from the ellipse.
inline constexpr double kPointTolerance = 1.0;

// Run a plan to the end, piece after piece. Calls on_iter for each iteration if given.
// Throws GuardError if a piece passes its iteration bound, stalls, or ends anywhere but
// its end point.
struct RunSummary {
  std::uint64_t iterations = 0;
  Point end;
  RegState final_regs;
};
RunSummary run(const Plan& plan, const std::function<void(const Iteration&)>& on_iter = {});
std::vector<Iteration> run_records(const Plan& plan);

// Documented bound on the distance of any path point from the ellipse, in steps
// (docs/golden-model.md, "Deviation bound"): |r - 1| * max(a, b) + E + F, where r^2 =
// u0^2/a^2 + v0^2/b^2 at the represented start in the ellipse's frame (the DDA follows
// the ellipse through its start point, scaled by r), E is the DDA's own drift: 2 +
// cbrt(max(a, b)) / 2 steps with zero preload (the paper's drift grows with size), 1.5
// steps with half preload, and F the fixed-point coefficients' drift bound of a rotated
// ellipse (coefficient_drift_bound; 0 for quarter turns). E is empirical:
// build/tb/deviation_survey prints the measured worst drift by size. A rotated ellipse
// has the bound (E = 1.5) only with half preload, at least the default width and aspect
// ratio <= 4; elsewhere it is infinite (not documented; docs/results.md has measurements).
double deviation_bound(const Plan& plan);
// Its first term, |r - 1| * max(a, b): how far the ellipse through the start point lies
// from the nominal one.
double start_offset(const Plan& plan);
// Analytic bound (steps) on how far the rounding of a rotated ellipse's fixed-point
// coefficients moves the traced curve: max(a,b)^2 2^n / (2^kRotCapBits min(a,b))
// (docs/golden-model.md, "Rotated ellipses"). 0 for quarter turns (exact coefficients).
double coefficient_drift_bound(const Plan& plan);
// Rotated plans are refused when coefficient_drift_bound exceeds this (steps).
inline constexpr double kMaxCoefficientDrift = 0.125;

// Distance (steps) of absolute point (x, y) from the plan's ideal ellipse (turned and
// moved). Measurement only (floating point): not used by the datapath.
double plan_distance(const Plan& plan, double x, double y);

// Shortest distance from (px, py) to the ellipse x^2/a^2 + y^2/b^2 = 1 (a, b > 0).
// Absolute error below 1e-9 * max(a, b). Eberly's bisection method, no sampling.
double ellipse_distance(double a, double b, double px, double py);

}  // namespace dda
