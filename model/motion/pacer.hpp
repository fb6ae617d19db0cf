// SPDX-License-Identifier: Apache-2.0
// The pacer: the reference model of the motion block's speed generator, clock by clock
// and in exact integers (docs/design.md, "Pacer"). It decides on every clock whether the
// core iterates, so that the path speed follows a commanded speed v that ramps at the
// acceleration a: up to the piece's cruise speed (times the override, clamped to its
// limit), down early enough to reach its exit speed at its end (vmin, when no piece
// follows in the queue), down to rest on a hold.
//
// Constant tangential feed. An iteration moves the tool by d = |(jv_x, jv_y) / cap,
// jv_z / cap_z| steps along the path (the integrands are the DDA's velocity; an axis
// whose counter is done, or whose integrand is not positive, adds 0). A phase adds v on
// every clock and the core iterates when it reaches the pacer's d, taking it off: the
// path speed is v whatever d does along an ellipse. d comes from the norm unit, exact
// to kNormFrac bits: q = floor(jv_i * 2^kNormFrac / cap_i) per axis, d =
// floor(sqrt(q_x^2 + q_y^2 + q_z^2)). Only a step changes an integrand or ends an axis,
// so the iterations between two steps (a run) have one d. The norm unit takes
// kNormLatency clocks, longer than the core takes for a run at speed, so the core does
// not wait for it: when a step comes in (on the edge after its iteration: the core's
// registered step pulses), the norm unit starts on the new run's registers and the
// pacer goes on with the run before's d, provisionally, counting those iterations (m).
// Once the unit has the run's own d, the pacer takes it and corrects the phase and the
// distance to go by m times the difference, as if every iteration of the run had been
// paced with its own d from the start. Every iteration therefore counts its own d, as
// pace_length sums it, whenever the clocks fall. The core waits on the clock a step
// comes in, while the norm unit reads its operands (kNormOperandEdges edges after its
// start), on the clock of a correction, when a step comes while the unit is still at
// work (it is due: the correction and the start wait for the unit), and after a take
// until the first run's d is in; else it can iterate on every clock.
//
// The cruise speed the ramp heads for, the entry's times the override clamped to the
// entry's limit, is formed by shift and add over kOverrideClocks clocks after a take or
// an override change; until then the one before holds.
//
// Acceleration. v changes by at most a per clock. The braking distance s, the distance
// a ramp down at a from v to the minimum speed vmin travels, is kept by additions alone:
// a ramp step up from v adds v if v is above vmin, one down to v' takes v' off if v' is
// above vmin (a clamp onto a target, less than a, counts as a whole step: it moves s by
// less than v). The pacer ramps down once s, less the braking distance of the exit speed
// (the entry's brake_exit, which the planner computes with brake_distance()), reaches
// the distance still to go (the entry's length, less d per iteration, less the phase:
// the way gone toward the next iteration) less 2^-kMarginShift step: the piece then
// ends at its exit speed, the last one at vmin (never below while a piece runs and no
// hold is on: a drive can start and stop at vmin, and the last step comes in bounded
// time).
#pragma once

#include <cstdint>
#include <vector>

#include "model/datapath/datapath.hpp"
#include "model/motion/pace_params.hpp"

namespace dda::motion {

// The pacing fields of a queue entry.
struct PaceEntry {
  std::uint32_t cruise = 0;      // the speed to hold (x 2^kSpeedFrac steps/clock)
  std::uint32_t limit = 0;       // the override never takes the speed above this
  std::uint32_t exit = 0;        // the speed to end at when another piece follows
  std::uint32_t length = 0;      // the piece's path length, the sum of d (x 2^kLenFrac steps)
  std::uint32_t brake_exit = 0;  // brake_distance(exit, vmin, accel) (x 2^kLenFrac steps)
};
// The block's settings the pacer reads.
struct PaceSettings {
  std::uint64_t accel = 0;  // x 2^kRampFrac steps/clock^2; 0: no ramp (the speed jumps)
  std::uint32_t vmin = 0;   // x 2^kSpeedFrac steps/clock
  std::uint32_t override_ = kOverrideOne;
  bool hold = false;
};

// The norm unit's operands (rtl/dda_norm.v's v_x_i .. cap_z_i, the core's norm_*_o
// ports) from the core's registers: an axis whose counter is done or whose integrand is
// not positive gives 0.
struct NormOperands {
  std::uint64_t v_x = 0, v_y = 0, v_z = 0, cap = 0, cap_z = 0;
};
NormOperands norm_operands(const Command& c, const RegState& r);
// The DDA's path length per iteration, x 2^kNormFrac steps (the norm unit's d): from the
// norm operands, or from the core's registers.
std::uint64_t iteration_distance(const NormOperands& o);
std::uint64_t iteration_distance(const Command& c, const RegState& r);
// The distance a ramp down from speed v to vmin (x 2^kSpeedFrac) at accel travels, as
// the pacer counts it, x 2^kLenFrac steps, rounded up; 0 for accel 0.
std::uint32_t brake_distance(std::uint32_t v, std::uint32_t vmin, std::uint64_t accel);
// A piece's length as the pacer counts it: the sum of iteration_distance over its
// iterations, x 2^kLenFrac steps, rounded up. Throws GuardError for a piece that does
// not end or is longer than the field holds.
std::uint32_t pace_length(const Command& c);
// The shortest positive iteration_distance over a piece's iterations (x 2^kNormFrac
// steps; 0 when none moves): a piece at v steps/s asks up to v / d iterations per
// second (also provisionally: a run is paced with the d of the run before until its
// own is in).
std::uint64_t min_iteration_distance(const Command& c);
// The highest speed up to cap (x 2^kSpeedFrac) whose brake_distance is within budget
// (x 2^kLenFrac steps): at least min(vmin, cap), which brakes in no distance.
std::uint32_t fastest_within(std::uint32_t cap, std::uint64_t budget, std::uint32_t vmin, std::uint64_t accel);
// Lowers exit speeds, backward from the last entry, to what the pacer can slow down from
// in the piece after: the fastest speed whose brake_distance and the pacer's margin
// (2^-kMarginShift step) fit the next piece's length and the braking from its own exit
// (none after the last piece: it ends at vmin); and sets every entry's brake_exit from
// its exit. Exits and lengths as the pacer reads them, so the pacer never enters a
// piece too fast to leave it at its exit. No exit is lowered for accel 0 (the speed
// jumps). Throws GuardError for an exit whose braking distance the field cannot hold.
void limit_exits(std::vector<PaceEntry>& entries, std::uint32_t vmin, std::uint64_t accel);
// The entries a driver writes for pieces run back to back at one cruise speed (x
// 2^kSpeedFrac, also their limit): their lengths, and exits at the cruise speed (the
// last one's 0: it ends at vmin) lowered by limit_exits.
std::vector<PaceEntry> pace_entries(const std::vector<Command>& pieces, std::uint32_t cruise, std::uint32_t vmin,
                                    std::uint64_t accel);

class Pacer {
 public:
  // The inputs of one clock: advance (ce_i, no stage holds the core), whether a piece
  // runs and the norm operands of the core's registers before the edge (the running or
  // the last piece's), whether the core's last iteration (on the edge before) made a
  // step (its registered step pulses), whether the core takes an entry on this edge
  // and that entry, whether another entry waits in the queue.
  struct In {
    bool advance = false;
    bool running = false;
    NormOperands norm;
    bool stepped = false;
    bool take = false;
    PaceEntry entry;
    bool next_queued = false;
    PaceSettings set;
  };
  // Whether the core iterates on this edge (a wire: from the state before the edge).
  bool iterate(const In& in) const;
  // Clocks from now on which, the inputs held, the edge only adds v to the phase: the
  // core does not iterate, the speed sits at its target, the norm unit is idle and the
  // decision to ramp down does not change (0 when this clock is not one). skip() runs
  // that many such edges at once, exactly as edge() would one by one.
  std::uint64_t idle_clocks(const In& in) const;
  void skip(const In& in, std::uint64_t clocks);
  void edge(const In& in);

  std::uint64_t speed() const { return v_; }  // x 2^kRampFrac steps/clock
  std::uint64_t phase() const;                // the register: kPhaseWidth bits, two's complement
  std::int64_t phase_value() const { return ph_; }
  int norm_busy() const { return busy_; }  // clocks until the norm unit's d is new
  bool pending() const { return pending_; }
  bool first() const { return first_; }   // after a take: the first run's d is not in yet
  bool due() const { return due_; }       // a step's norm waits for the unit
  bool fresh() const { return fresh_; }   // d is the run's own (no correction waits)
  int provisional() const { return m_; }  // the run's iterations paced with the d before
  // The correction of a run's provisional iterations, a bit of their count per clock:
  // the bits still to apply, and the difference of the d's times 2^(bits applied)
  // (the register: kCorrectionWidth bits, two's complement).
  int correction_bits() const { return cm_; }
  std::uint64_t correction_step() const { return cd_; }
  const PaceEntry& entry() const { return e_; }
  // The cruise speed times the override, clamped to the limit (x 2^kRampFrac), the
  // override it is of, and the clocks until a new one is ready (0: ready).
  std::uint64_t cruise_speed() const { return eff_; }
  std::uint32_t override_of() const { return ovr_; }
  int override_busy() const { return mul_; }
  std::uint64_t distance() const { return d_; }        // the d the pacer paces with
  std::uint64_t norm_distance() const { return nd_; }  // the norm unit's last d
  bool ramping_down() const { return down_; }
  std::uint64_t brake() const { return s_; }    // x 2^kDistFrac steps
  std::uint64_t to_go() const { return rem_; }  // x 2^kDistFrac steps
  std::uint64_t target(const In& in) const;     // the speed the ramp heads for

 private:
  bool decelerate(const In& in) const;
  bool blocked(const In& in) const;  // the core waits for d or for the norm unit
  // The norm unit's and the hand-over's part of the edge: the pacer takes the run's own
  // d and starts its correction.
  void norm_edge(const In& in, bool it);
  std::int64_t correction_part() const;                // this clock's part of the correction, x 2^-kNormFrac steps
  void ramp_edge(const In& in, std::uint64_t target);  // v toward the target, with s

  std::uint64_t v_ = 0, d_ = 0, nd_ = 0, s_ = 0, rem_ = 0, eff_ = 0;
  std::int64_t ph_ = 0;  // below 0 after a correction: the core went ahead
  std::uint32_t ovr_ = 0;
  int mul_ = 0;
  PaceEntry e_;
  int busy_ = 0;          // clocks until the norm unit's d is new
  bool pending_ = false;  // an iteration happened on the last edge: did it step?
  bool first_ = false;    // a take: the first run's d is not in yet
  bool due_ = false;      // a step came while the norm unit was at work
  bool fresh_ = false;    // d_ is the run's own
  int m_ = 0;             // the run's iterations paced with the d before (fresh_ false)
  int cm_ = 0;            // the correction's bits of m still to apply, shifting down
  std::uint64_t cd_ = 0;  // the difference of the d's, shifting up (kCorrectionWidth bits)
  bool down_ = false;
  // The norm unit's quotients, each from the operands on the edge it reads them (x's
  // on the edge after its start, y's and z's kNormClocks and 2 kNormClocks later), and
  // its d from them, made public (nd_) when its count runs out: iteration_distance of
  // the operands when they hold.
  std::uint64_t qx_ = 0, qy_ = 0, qz_ = 0;
  std::uint64_t unit_d() const;
};

}  // namespace dda::motion
