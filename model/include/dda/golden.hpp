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

// One iteration: the datapath's inputs, intermediate sums and the registers after it.
struct Iteration {
  std::uint64_t iter = 0;           // 1-based
  bool active_x = false, active_y = false;  // counter was non-zero: the axis added
  std::int64_t jv_x = 0, jv_y = 0;  // integrands used in this iteration
  std::int64_t sum_x = 0, sum_y = 0;  // accumulator sums before overflow removal
  bool step_x = false, step_y = false;  // overflow pulses
  RegState after;                   // registers after the iteration (jv corrected)
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

 private:
  Command cmd_;
  RegState regs_;
  Point pos_;
  std::uint64_t iter_ = 0;
};

enum class Preload { Zero, Half };
const char* to_string(Preload p);

// User-level description of a quadrant-I counter-clockwise arc (the paper's case).
struct ArcSpec {
  std::int64_t a = 0, b = 0;
  int bits = 0;                   // n: capacity 2^n in the paper's units
  Preload preload = Preload::Zero;
  std::optional<Point> from, to;  // defaults (a,0) and (0,b)
};

// A validated arc: the resolved points, the hardware command and the guard bound.
struct Plan {
  ArcSpec spec;
  Point from, to;
  std::int64_t scale = 1;          // a*b: divide register values by it for paper units
  Command cmd;
  std::uint64_t iteration_bound = 0;  // a run that passes it is stopped (GuardError)
};

// Smallest valid n for the semi-axes: smallest n >= 1 with 2^n >= max(a, b).
int smallest_valid_bits(std::int64_t a, std::int64_t b);

// Validate and plan. Throws InputError naming the value and the rule it breaks.
Plan plan_arc(const ArcSpec& spec);

// Largest distance (in steps) a start or end point may lie from the ellipse.
inline constexpr double kPointTolerance = 1.0;

// Run a plan to the end. Calls on_iter for each iteration if given.
// Throws GuardError if the iteration bound is passed or the datapath stalls.
struct RunSummary {
  std::uint64_t iterations = 0;
  Point end;
  RegState final_regs;
};
RunSummary run(const Plan& plan, const std::function<void(const Iteration&)>& on_iter = {});
std::vector<Iteration> run_records(const Plan& plan);

// Documented bound on the distance of any path point from the ellipse, in steps
// (docs/design.md, "Deviation bound"): |r - 1| * max(a, b) + E, where r^2 =
// x0^2/a^2 + y0^2/b^2 at the start (the DDA follows the ellipse through its start
// point, scaled by r) and E is the DDA's own drift: 2 + cbrt(max(a, b)) / 2 steps with
// zero preload (the paper's drift grows with size), 1.5 steps with half preload.
// E is empirical: scripts/deviation-survey prints the measured worst excess by size.
double deviation_bound(const Plan& plan);

// Shortest distance from (px, py) to the ellipse x^2/a^2 + y^2/b^2 = 1 (a, b > 0).
// Absolute error below 1e-9 * max(a, b). Eberly's bisection method, no sampling.
double ellipse_distance(double a, double b, double px, double py);

}  // namespace dda
