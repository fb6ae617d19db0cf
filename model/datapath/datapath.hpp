// SPDX-License-Identifier: Apache-2.0
// The hardware reference: one DDA command and the datapath's next-state function.
//
// Exact integer arithmetic only (no floating point). Independent of SystemC, Verilator
// and the planner; docs/design.md is the architecture it defines. next_state() is the
// single definition of one iteration: Datapath::iterate(), Datapath::step() and the
// cycle-level model (core_model.hpp) all call it.
#pragma once

#include <cstdint>

#include "model/datapath/errors.hpp"

namespace dda {

// A lattice point: the plane's axes x, y and the third (linear) axis z, which stays 0
// in a run that never moves it.
struct Point {
  std::int64_t x = 0;
  std::int64_t y = 0;
  std::int64_t z = 0;
  friend bool operator==(const Point& p, const Point& q) { return p.x == q.x && p.y == q.y && p.z == q.z; }
  friend bool operator!=(const Point& p, const Point& q) { return !(p == q); }
  friend Point operator+(const Point& p, const Point& q) { return Point{p.x + q.x, p.y + q.y, p.z + q.z}; }
};

// A piece in another plane than the run's: the core's axes (x, y: the piece's plane, z:
// its normal) drive the run's axes turned by `rot` (0, 1 or 2): core axis i moves run
// axis (i + rot) mod 3. The planes G17 (X, Y, Z), G18 (Z, X, Y) and G19 (Y, Z, X) are
// cyclic turns of one another, so a turn maps any of them onto the run's plane.
inline Point to_run_axes(Point p, int rot) {
  return rot == 0 ? p : rot == 1 ? Point{p.z, p.x, p.y} : Point{p.y, p.z, p.x};
}
inline Point to_plane_axes(Point p, int rot) {
  return rot == 0 ? p : rot == 1 ? Point{p.y, p.z, p.x} : Point{p.z, p.x, p.y};
}

// One hardware command: everything the datapath needs to run one piece.
// All values are the exact (scaled) integers the registers hold.
struct Command {
  std::int64_t jv_x = 0, jv_y = 0;  // initial integrands
  std::int64_t jr_x = 0, jr_y = 0;  // accumulator preloads, 0 <= jr < cap
  std::int64_t cap = 1;             // capacity' (2^n * a * b)
  std::int64_t cnt_x = 0, cnt_y = 0;
  bool dir_x_neg = false, dir_y_neg = false;
  // Integrand corrections after a step: jv_<i> += inc_<i>_on_<axis>.
  std::int64_t inc_x_on_x = 0, inc_x_on_y = 0, inc_y_on_x = 0, inc_y_on_y = 0;
  // The third (linear) axis: a constant integrand 0 <= jv_z <= cap_z of its own
  // capacity, preload 0 <= jr_z < cap_z, cnt_z steps (Bresenham's rule).
  std::int64_t jv_z = 0, jr_z = 0, cap_z = 1, cnt_z = 0;
  bool dir_z_neg = false;
};

// The datapath registers between iterations (what the hardware holds).
// (The third axis' integrand and capacity are constant: they stay in the Command.)
struct RegState {
  std::int64_t jv_x = 0, jv_y = 0;
  std::int64_t jr_x = 0, jr_y = 0;
  std::int64_t cnt_x = 0, cnt_y = 0;
  std::int64_t jr_z = 0, cnt_z = 0;
  friend bool operator==(const RegState& p, const RegState& q) {
    return p.jv_x == q.jv_x && p.jv_y == q.jv_y && p.jr_x == q.jr_x && p.jr_y == q.jr_y && p.cnt_x == q.cnt_x &&
           p.cnt_y == q.cnt_y && p.jr_z == q.jr_z && p.cnt_z == q.cnt_z;
  }
};

// The registers right after a command is loaded.
inline RegState initial_regs(const Command& c) {
  RegState r;
  r.jv_x = c.jv_x;
  r.jv_y = c.jv_y;
  r.jr_x = c.jr_x;
  r.jr_y = c.jr_y;
  r.cnt_x = c.cnt_x;
  r.cnt_y = c.cnt_y;
  r.jr_z = c.jr_z;
  r.cnt_z = c.cnt_z;
  return r;
}

// What one iteration computes besides the next registers.
struct StepOut {
  bool active_x = false, active_y = false, active_z = false;  // counter was non-zero: the axis may add
  std::int64_t sum_x = 0, sum_y = 0, sum_z = 0;               // accumulator sums before overflow removal
  bool step_x = false, step_y = false, step_z = false;        // carries: one step each
};

// One iteration of the datapath (one clock with ce high): the single definition.
// Both accumulators add their integrands; an axis adds while active with a positive
// integrand (a negative one holds); a carry (sum >= cap) is a step and the accumulator
// keeps sum - cap. Corrections apply after the iteration, from its steps. The third
// axis adds its constant integrand to its own accumulator while active and carries
// against its own capacity; its steps change no integrand.
inline StepOut next_state(const Command& cmd, RegState& r) {
  StepOut o;
  o.active_x = r.cnt_x != 0;
  o.active_y = r.cnt_y != 0;
  o.sum_x = o.active_x && r.jv_x > 0 ? r.jr_x + r.jv_x : r.jr_x;
  o.sum_y = o.active_y && r.jv_y > 0 ? r.jr_y + r.jv_y : r.jr_y;
  // (A negative integrand neither adds nor carries, as in the RTL, even for a command
  // whose preload breaks jr < cap.)
  o.step_x = o.active_x && r.jv_x >= 0 && o.sum_x >= cmd.cap;
  o.step_y = o.active_y && r.jv_y >= 0 && o.sum_y >= cmd.cap;
  r.jr_x = o.step_x ? o.sum_x - cmd.cap : o.sum_x;
  r.jr_y = o.step_y ? o.sum_y - cmd.cap : o.sum_y;
  r.cnt_x -= o.step_x ? 1 : 0;
  r.cnt_y -= o.step_y ? 1 : 0;
  r.jv_x += (o.step_x ? cmd.inc_x_on_x : 0) + (o.step_y ? cmd.inc_x_on_y : 0);
  r.jv_y += (o.step_x ? cmd.inc_y_on_x : 0) + (o.step_y ? cmd.inc_y_on_y : 0);
  o.sum_z = r.jr_z;
  if (r.cnt_z != 0) {  // (a plane's command skips the third axis in one predictable branch)
    o.active_z = true;
    o.sum_z += cmd.jv_z;
    o.step_z = o.sum_z >= cmd.cap_z;
    r.jr_z = o.step_z ? o.sum_z - cmd.cap_z : o.sum_z;
    r.cnt_z -= o.step_z ? 1 : 0;
  }
  return o;
}

// An active axis whose integrand is 0 or negative cannot carry; when no active axis
// can, the command never ends (the hardware raises err_o).
inline bool finished(const RegState& r) { return r.cnt_x == 0 && r.cnt_y == 0 && r.cnt_z == 0; }
inline bool stalled(const Command& cmd, const RegState& r) {
  if (finished(r)) return false;
  const bool x_can = r.cnt_x != 0 && r.jv_x > 0;
  const bool y_can = r.cnt_y != 0 && r.jv_y > 0;
  const bool z_can = r.cnt_z != 0 && cmd.jv_z > 0;
  return !x_can && !y_can && !z_can;
}

// The iterations before the next one with a step, in closed form. Between steps the
// integrands and counters hold, so an axis that adds (active, integrand > 0) only grows
// its accumulator by its integrand, and its first carry comes after
// ceil((cap - jr) / jv) iterations. kNever: no axis can step (the stall guard's case).
// quiet_iterations(c, r) calls of next_state() from r step on neither axis, and leave
// r as skip_quiet(c, r, n) does; a test runs both side by side.
constexpr std::uint64_t kNever = ~std::uint64_t{0};
inline std::uint64_t quiet_iterations(const Command& cmd, const RegState& r) {
  const auto until_carry = [&](bool active, std::int64_t jv, std::int64_t jr, std::int64_t cap) -> std::uint64_t {
    if (!active || jv < 0) return kNever;
    if (jr + jv >= cap) return 0;  // this iteration carries (jv = 0: a preload at or above cap)
    if (jv == 0) return kNever;
    return std::uint64_t((cap - jr + jv - 1) / jv) - 1;
  };
  // (An axis that carries on the next iteration decides without a division.)
  const std::uint64_t x = until_carry(r.cnt_x != 0, r.jv_x, r.jr_x, cmd.cap);
  if (x == 0) return 0;
  const std::uint64_t y = until_carry(r.cnt_y != 0, r.jv_y, r.jr_y, cmd.cap);
  if (y == 0) return 0;
  const std::uint64_t z = until_carry(r.cnt_z != 0, cmd.jv_z, r.jr_z, cmd.cap_z), xy = x < y ? x : y;
  return xy < z ? xy : z;
}
// n iterations without a step (n <= quiet_iterations(cmd, r)).
inline void skip_quiet(const Command& cmd, RegState& r, std::uint64_t n) {
  if (r.cnt_x != 0 && r.jv_x > 0) r.jr_x += std::int64_t(n) * r.jv_x;
  if (r.cnt_y != 0 && r.jv_y > 0) r.jr_y += std::int64_t(n) * r.jv_y;
  if (r.cnt_z != 0) r.jr_z += std::int64_t(n) * cmd.jv_z;
}

// One iteration: the datapath's inputs, intermediate sums and the registers after it.
struct Iteration {
  std::uint64_t iter = 0;                                        // 1-based, counted across the pieces of an arc
  std::uint32_t piece = 0;                                       // index of the piece (command) it belongs to
  bool piece_end = false;                                        // the piece's last iteration (set by the runner)
  bool dir_x_neg = false, dir_y_neg = false, dir_z_neg = false;  // step directions of that piece
  bool active_x = false, active_y = false, active_z = false;     // counter was non-zero: the axis added
  std::int64_t jv_x = 0, jv_y = 0, jv_z = 0;                     // integrands used in this iteration
  std::int64_t sum_x = 0, sum_y = 0, sum_z = 0;                  // accumulator sums before overflow removal
  bool step_x = false, step_y = false, step_z = false;           // overflow pulses
  RegState after;  // registers after the iteration (jv corrected); after a
                   // piece's last one, the next piece's loaded command
  Point pos;       // position after the iteration
};

// The datapath running one command: one call of iterate() is one iteration.
class Datapath {
 public:
  // `rot`: the turn from the core's axes to the position's (to_run_axes).
  Datapath(const Command& cmd, Point start, int rot = 0)
      : cmd_(cmd), regs_(initial_regs(cmd)), pos_(start), rot_(rot) {}
  const RegState& regs() const { return regs_; }
  const Command& command() const { return cmd_; }
  Point pos() const { return pos_; }
  std::uint64_t iterations() const { return iter_; }
  bool done() const { return finished(regs_); }
  // An active axis whose integrand is 0 and can no longer change: the piece never ends.
  bool stalled() const { return dda::stalled(cmd_, regs_); }
  Iteration iterate() {
    Iteration it;
    it.jv_x = regs_.jv_x;
    it.jv_y = regs_.jv_y;
    it.jv_z = cmd_.jv_z;
    // (On copies held in registers: the record's copies then read no value just stored.)
    RegState r = regs_;
    const StepOut o = next_state(cmd_, r);
    const Point p = moved(o);
    regs_ = r;
    pos_ = p;
    ++iter_;
    it.iter = iter_;
    it.active_x = o.active_x;
    it.active_y = o.active_y;
    it.active_z = o.active_z;
    it.sum_x = o.sum_x;
    it.sum_y = o.sum_y;
    it.sum_z = o.sum_z;
    it.step_x = o.step_x;
    it.step_y = o.step_y;
    it.step_z = o.step_z;
    it.after = r;
    it.pos = p;
    return it;
  }
  // The same iteration without building its record (the fast path for validation,
  // cross-checks and benchmarks).
  void step() {
    const StepOut o = next_state(cmd_, regs_);
    move(o);
  }
  // The iterations before the next step, at most `limit` of them, in closed form
  // (quiet_iterations()): how many ran. The report of a run that looks only at the
  // iterations with a step, and the planner's reachability check, skip them so.
  std::uint64_t skip_quiet(std::uint64_t limit) {
    const std::uint64_t q = quiet_iterations(cmd_, regs_), n = q < limit ? q : limit;
    dda::skip_quiet(cmd_, regs_, n);
    iter_ += n;
    return n;
  }

 private:
  Point moved(const StepOut& o) const {
    Point d;
    if (o.step_x) d.x = cmd_.dir_x_neg ? -1 : 1;
    if (o.step_y) d.y = cmd_.dir_y_neg ? -1 : 1;
    if (o.step_z) d.z = cmd_.dir_z_neg ? -1 : 1;
    return pos_ + (rot_ == 0 ? d : to_run_axes(d, rot_));
  }
  void move(const StepOut& o) {
    pos_ = moved(o);
    ++iter_;
  }
  Command cmd_;
  RegState regs_;
  Point pos_;
  int rot_ = 0;
  std::uint64_t iter_ = 0;
};

}  // namespace dda
