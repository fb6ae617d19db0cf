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

// An arc of the ellipse with semi-axes a, b, turned counter-clockwise by quarter_turns
// * 90 degrees about its centre (so the semi-axis a points along X for 0 and 2 turns,
// along Y for 1 and 3).
struct ArcSpec {
  std::int64_t a = 0, b = 0;
  int quarter_turns = 0;          // 0..3
  int bits = 0;                   // n: capacity 2^n in the paper's units; 0 = default_bits()
  Preload preload = Preload::Zero;
  Point center;                   // lattice point
  Direction dir = Direction::Ccw;
  std::optional<Point> from, to;  // absolute lattice points; defaults: the quarter arc
                                  // center + (ax,0) to center + (0,by)
};

// One monotone piece of an arc (each axis moves one way): one hardware command.
// Pieces meet at the ellipse's vertices, which are lattice points.
struct Segment {
  Point from, to;
  int quadrant = 1;                   // 1..4: the quadrant (about the centre) it runs in
  Command cmd;
  std::uint64_t iteration_bound = 0;  // a run of this piece that passes it is stopped
};

// A validated arc: resolved points and bits, its pieces, and the guard bound.
struct Plan {
  ArcSpec spec;                    // with bits resolved
  Point from, to;
  bool full = false;               // from == to: one full turn
  std::int64_t ax = 0, by = 0;     // semi-axes along X and Y (a, b swapped by odd turns)
  std::int64_t scale = 1;          // a*b: divide register values by it for paper units
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

// Lattice point of the parametric angle theta (degrees): of the four lattice points
// around center + (a cos, b sin) (floor and ceiling of each coordinate, in the
// ellipse's own frame before any quarter turn), the one with the least r >= 1, where
// r^2 = u^2/a^2 + v^2/b^2 (tested exactly): on or just outside the curve, so the DDA
// cannot stall at a vertex and follows the ellipse through it, r times the nominal one,
// as closely as the lattice allows. Ties go to the first in the order (floor, floor),
// (floor, ceil), (ceil, floor), (ceil, ceil). Multiples of 90 degrees use exact
// cosines and sines (so they give the vertices).
Point theta_point(const ArcSpec& spec, double theta_deg);

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
// (docs/golden-model.md, "Deviation bound"): |r - 1| * max(a, b) + E, where r^2 =
// u0^2/a^2 + v0^2/b^2 at the start relative to the centre (the DDA follows the ellipse
// through its start point, scaled by r) and E is the DDA's own drift: 2 + cbrt(max(a,
// b)) / 2 steps with zero preload (the paper's drift grows with size), 1.5 steps with
// half preload. E is empirical: build/tb/deviation_survey prints the measured worst
// drift by size.
double deviation_bound(const Plan& plan);
// Its first term, |r - 1| * max(a, b): how far the ellipse through the start point lies
// from the nominal one.
double start_offset(const Plan& plan);

// Shortest distance from (px, py) to the ellipse x^2/a^2 + y^2/b^2 = 1 (a, b > 0).
// Absolute error below 1e-9 * max(a, b). Eberly's bisection method, no sampling.
double ellipse_distance(double a, double b, double px, double py);

}  // namespace dda
