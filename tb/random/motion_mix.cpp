// SPDX-License-Identifier: Apache-2.0
#include "tb/random/motion_mix.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "host/driver/motion_driver.hpp"
#include "host/planner/planner.hpp"
#include "model/datapath/errors.hpp"
#include "tb/monitors/bus_monitors.hpp"
#include "tb/monitors/stepdir_monitor.hpp"
#include "tb/random/dda_random.hpp"
#include "tb/random/input_noise.hpp"

namespace dda::motion {

namespace {
constexpr std::uint32_t kTimingMax = (1u << kTimingWidth) - 1;

// One run of the mix: the bench on the target (the timing and piece monitors, the bus
// master, the firmware driver), the arc generators, and the stream every other random
// choice (batch kinds, timings, feeds, ce_i, how a batch ends) is drawn from.
class Mix {
 public:
  Mix(BusTarget& t, std::uint64_t seed, bool pipelined, std::int64_t max_axis)
      : rng_(seed),
        gen_(seed, max_axis, 4, ArcKind::Program),
        short_arcs_(seed + 3, std::min<std::int64_t>(max_axis, 8), 4, ArcKind::Program),
        paced_arcs_(seed + 5, std::min<std::int64_t>(max_axis, 30), 4, ArcKind::Program),
        spatial_(seed + 4, max_axis, 4, ArcKind::Spatial),
        timing_(t),
        speed_(timing_),
        mon_(speed_),
        m_(mon_, seed + 1, pipelined, 20),
        d_(m_, seed + 2),
        noise_(mon_, m_, d_, seed + 6) {
    m_.each_cycle = [this] {
      mon_.set_ce(rng_() % 10 != 0);
      noise_.each_cycle();
    };
  }
  Mix(const Mix&) = delete;
  Mix& operator=(const Mix&) = delete;

  MixStats run(std::uint64_t arcs);

 private:
  void ctrl(std::string_view bit) { m_.write(reg_offset("CTRL"), field_bit("CTRL", bit)); }
  // The pacing of a batch: none (feed increments), or the pacer's settings and the
  // entries' cruise speed.
  struct Pacing {
    bool on = false;
    std::uint32_t cruise = 0, vmin = 0, accel = 0;
    bool threshold = false;  // the comparisons at their thresholds (no piece slowed, no override)
  };
  std::vector<Plan> draw_batch(bool large, bool paced, std::uint64_t arcs);
  Pacing draw_pacing(bool paced);
  void pace_events(bool override);
  void set_outputs(unsigned kind, bool large);
  void partial_commit();
  Point queue_batch(const std::vector<Plan>& batch, const Pacing& pc);
  void slow_some(std::vector<PaceEntry>& pace, const Pacing& pc);
  bool cut_short(const Plan& first);
  void abort_batch();
  void hard_stop_batch();
  void soft_stop_batch(bool watchdog);
  std::uint32_t wait_status(std::string_view field, bool value);
  void reset_batch();
  void overflow(const Plan& first);
  void check_position(Point want);
  void watch_speed(const Pacing& pc);
  void unwatch_speed();

  MixStats st_;
  std::mt19937_64 rng_;
  RandomArcs gen_, short_arcs_, paced_arcs_, spatial_;
  StepDirMonitor timing_;
  SpeedWatch speed_;  // on a paced batch, from rest to its end or its soft stop
  PieceMonitor mon_;
  WishboneMaster m_;
  MotionDriver d_;
  InputNoise noise_;   // glitches on the machine's inputs every batch, real trips in some
  int axes_ = 3;       // the block's (CONFIG.axes): with 2, no arc moves the third axis
  bool pacer_ = true;  // the block's (CONFIG.pacer): without, no batch is paced by the pacer
};

MixStats Mix::run(std::uint64_t arcs) {
  mon_.set_reset(false);
  m_.idle(2);
  mon_.set_reset(true);
  d_.read_build();
  axes_ = d_.axes();
  pacer_ = d_.pacer();
  noise_.configure(true);
  while (st_.arcs < arcs) {
    ++st_.batches;
    // One to four arcs back to back from a preset position; a twentieth of the batches
    // are one short arc with large timings; a fifth are paced by the pacer (shorter
    // arcs: a paced step takes a hundred clocks or more); on a block without the pacer
    // those and a fifth more are fed batches with a feed hold.
    const unsigned kind = unsigned(rng_() % 20);
    const bool large = kind == 0, paced = kind % 5 == 2 && pacer_;
    const bool held = !pacer_ && (kind % 5 == 2 || kind % 5 == 3);
    const std::vector<Plan> batch = draw_batch(large, paced, arcs);
    if (batch.empty()) break;
    d_.drain();
    set_outputs(kind, large);
    const Pacing pc = draw_pacing(paced);
    d_.preset(batch.front().from);
    if (rng_() % 10 == 0) partial_commit();
    watch_speed(pc);
    const Point want = queue_batch(batch, pc);
    st_.arcs += batch.size();
    const bool cut = cut_short(batch.front());
    if (!cut) {
      if (pc.on || held) pace_events(pc.on && !pc.threshold);
      d_.drain();
      check_position(want);
    }
    unwatch_speed();
  }
  st_.piece_checks = mon_.checked();
  st_.pulses = timing_.pulses(0) + timing_.pulses(1) + timing_.pulses(2);
  st_.pulses_z = timing_.pulses(2);
  st_.glitches = noise_.glitches();
  return st_;
}

// The arcs of a batch: one short arc if large, else one to four, no more than the run
// still needs; a third of the others move the third axis (3-D lines, plunges, helices),
// turned onto another plane of the block's axes two times in three (the entry's axes);
// on a block of two axes, those are planar arcs too.
std::vector<Plan> Mix::draw_batch(bool large, bool paced, std::uint64_t arcs) {
  std::vector<Plan> batch;
  const std::uint64_t n = large ? 1 : paced ? 1 + rng_() % 2 : 1 + rng_() % 4;
  while (batch.size() < n && st_.arcs + batch.size() < arcs) {
    const bool spatial = !large && !paced && rng_() % 3 == 0;  // (drawn whatever the axes: the same draws)
    RandomArcs& g = large ? short_arcs_ : paced ? paced_arcs_ : spatial && axes_ == 3 ? spatial_ : gen_;
    if (auto p = g.next()) {
      st_.spatial += &g == &spatial_;
      if (&g == &spatial_) {
        const int rot = int(rng_() % 3);
        turn_axes(*p, rot);
        st_.turned += rot != 0;
      }
      batch.push_back(std::move(*p));
    }
  }
  return batch;
}

// The batch's step/dir timings (all 0 on an even kind) and output polarity.
void Mix::set_outputs(unsigned kind, bool large) {
  for (const char axis : kAxes) {
    const auto draw = [&]() -> std::uint32_t {
      if (large) return rng_() % 8 == 0 ? kTimingMax : std::uint32_t(rng_() % 1024);
      return std::uint32_t(rng_() % 9);
    };
    StageTimings tm;
    if (large || kind % 2 == 1) tm = StageTimings{draw(), draw(), draw(), draw()};
    d_.set_timings(axis, tm);
  }
  st_.timed_batches += large || kind % 2 == 1;
  st_.large_timing_batches += large;
  d_.set_polarity(std::uint32_t(rng_() % 64));
}

// A paced batch's settings: a cruise speed of 0.002 to 0.02 steps per clock (above about
// 0.009 the norm unit's latency is the limit: the phase saturates), a minimum speed of
// 0.0005 to 0.0015, a ramp to the cruise speed over 1000 to 4000 clocks (no ramp an
// eighth of the time). A third of the batches put the pacer's comparisons at their
// thresholds instead: the cruise speed a whole number of ramp steps (0 to 3) above the
// minimum speed, or one unit either side of it (not below the minimum speed).
Mix::Pacing Mix::draw_pacing(bool paced) {
  Pacing pc;
  if (!paced) return pc;
  pc.on = true;
  ++st_.paced_batches;
  if (rng_() % 3 == 0) {
    pc.threshold = true;
    ++st_.threshold_batches;
    pc.accel = 1u << 20;  // x 2^-kRampFrac steps/clock^2: a ramp step of 16 entry speed units
    pc.vmin = 1u << 24;   // 1/256 step per clock
    const std::uint32_t k = std::uint32_t(rng_() % 4), step = pc.accel >> (kRampFrac - kSpeedFrac);
    const int off = k == 0 ? int(rng_() % 2) : int(rng_() % 3) - 1;
    pc.cruise = pc.vmin + k * step + std::uint32_t(off);
  } else {
    std::uniform_real_distribution<double> u(0, 1);
    const double cruise = 0.002 + 0.018 * u(rng_), vmin = 0.0005 + 0.001 * u(rng_);
    const double accel = rng_() % 8 == 0 ? 0 : cruise / (1000 + 3000 * u(rng_));
    pc.cruise = std::uint32_t(std::ldexp(cruise, kSpeedFrac));
    pc.vmin = std::uint32_t(std::ldexp(vmin, kSpeedFrac));
    pc.accel = std::uint32_t(std::min(std::ldexp(accel, kRampFrac), 4294967295.0));
  }
  d_.set_pacing(pc.accel, pc.vmin);
  return pc;
}

// While a paced batch runs: an override change (0 to 235%: above 200% is clamped), a
// feed hold and its end, the override back to 100%; at the thresholds the hold alone (an
// override would move the cruise speed off them; the resume ramps through them again),
// and the hold alone on a fed batch of a block without the pacer.
void Mix::pace_events(bool override) {
  m_.idle(int(rng_() % 3000));
  if (override) d_.set_override(std::uint32_t(20 + rng_() % 580));
  m_.idle(int(rng_() % 3000));
  d_.hold();
  ++st_.holds;
  m_.idle(int(rng_() % 6000));
  if (!get_field("STATUS", "held", m_.read(reg_offset("STATUS"))) &&
      !get_field("STATUS", "holding", m_.read(reg_offset("STATUS")))) {
    throw GuardError("motion mix: a feed hold shows neither holding nor held");
  }
  d_.resume();
  m_.idle(int(rng_() % 3000));
  if (override) d_.set_override(kOverrideOne);
}

// A partial entry committed: refused, with err_partial.
void Mix::partial_commit() {
  m_.write(reg_offset("ENTRY"), std::uint32_t(rng_()));
  ctrl("commit");
  ++st_.partial;
  if (!get_field("STATUS", "err_partial", m_.read(reg_offset("STATUS")))) {
    throw GuardError("motion mix: a partial commit was not reported");
  }
  ctrl("clear");
}

// Queues every piece of the batch (a random feed on half of them), each expected to end
// on its point; returns where the batch ends.
Point Mix::queue_batch(const std::vector<Plan>& batch, const Pacing& pc) {
  Point want = batch.front().from;
  Point at = batch.front().from;
  std::vector<PaceEntry> pace;
  if (pc.on) {
    std::vector<Command> cmds;
    for (const auto& p : batch)
      for (const auto& piece : p.pieces) cmds.push_back(piece.cmd);
    pace = pace_entries(cmds, pc.cruise, pc.vmin, pc.accel);
    if (!pc.threshold) slow_some(pace, pc);
  }
  std::size_t k = 0;
  for (const auto& p : batch) {
    for (const auto& piece : p.pieces) {
      at = at + Point{piece.to.x - piece.from.x, piece.to.y - piece.from.y, piece.to.z - piece.from.z};
      mon_.expect(at);
      const std::uint32_t feed = rng_() % 2 == 0 ? 0 : 0x20000000u + std::uint32_t(rng_() % 0xE0000000u);
      st_.fed_pieces += feed != 0 && !pc.on;
      st_.paced_pieces += pc.on;
      d_.queue(piece.cmd, feed, piece.rot, pc.on ? pace[k++] : PaceEntry{});
    }
    want = want + Point{p.to.x - p.from.x, p.to.y - p.from.y, p.to.z - p.from.z};
    st_.pieces += p.pieces.size();
  }
  return want;
}

// A quarter of a paced batch's pieces slower than the rest: cruise speed and limit 30
// to 90% of the batch's, the exits into and out of them no faster (a take then lowers
// the limit under a running ramp; a piece may enter above its cruise speed and ramp
// down at the acceleration).
void Mix::slow_some(std::vector<PaceEntry>& pace, const Pacing& pc) {
  std::uniform_real_distribution<double> u(0.3, 0.9);
  for (std::size_t k = 0; k < pace.size(); ++k) {
    if (rng_() % 4 != 0) continue;
    const auto c = std::uint32_t(pc.cruise * u(rng_));
    pace[k].cruise = pace[k].limit = c;
    for (const std::size_t j : {k, k - 1}) {
      if (j < pace.size()) pace[j].exit = std::min(pace[j].exit, c);  // (k - 1 wraps for k = 0)
    }
  }
  // The exits before a slowed piece, as low as it needs to be met.
  limit_exits(pace, pc.vmin, pc.accel);
}

// Ends a third of the batches early (an abort, a reset, an overflow, a hard stop,
// a soft stop, the watchdog running out, a machine input); true if this one was.
bool Mix::cut_short(const Plan& first) {
  const unsigned how = unsigned(rng_() % 24);
  if (how < 4 || how == 6 || how == 7) unwatch_speed();  // an infinite deceleration: no limit holds
  switch (how) {
    case 0:
      abort_batch();
      return true;
    case 1:
      reset_batch();
      return true;
    case 2:
      overflow(first);
      return true;
    case 3:
      hard_stop_batch();
      return true;
    case 4:
      soft_stop_batch(false);
      return true;
    case 5:
      soft_stop_batch(true);
      return true;
    case 6:
    case 7:
      noise_.trip();
      mon_.flush();
      ++st_.input_trips;
      return true;
    default:
      return false;
  }
}

// Polls STATUS until `field` reads `value`; returns STATUS then.
std::uint32_t Mix::wait_status(std::string_view field, bool value) {
  for (int i = 0; i < 1000000; ++i) {
    const std::uint32_t s = m_.read(reg_offset("STATUS"));
    if ((get_field("STATUS", field, s) != 0) == value) return s;
    m_.idle(int(rng_() % 16));
  }
  throw GuardError("motion mix: STATUS." + std::string(field) + " did not become " + (value ? "1" : "0"));
}

// A hard stop in the middle: an abort with STATUS.err_hard_stop.
void Mix::hard_stop_batch() {
  m_.idle(int(rng_() % 300));
  ctrl("hard_stop");
  mon_.flush();
  ++st_.hard_stops;
  const std::uint32_t s = m_.read(reg_offset("STATUS"));
  if (!get_field("STATUS", "aborted", s) || !get_field("STATUS", "err_hard_stop", s) ||
      get_field("STATUS", "level", s) != 0) {
    throw GuardError("motion mix: a hard stop left the queue non-empty or was not reported");
  }
  ctrl("clear");
}

// A soft stop in the middle, asked for or by the watchdog (a timeout of 500 to 5500
// clocks not rewritten): a ramp to rest, then the flush (STATUS.aborted; with the
// watchdog STATUS.err_watchdog). The timing monitor checks on every edge that the
// position counters count exactly the pulses that went out.
void Mix::soft_stop_batch(bool watchdog) {
  if (watchdog) {
    m_.write(reg_offset("WATCHDOG"), 500 + std::uint32_t(rng_() % 5000));
    wait_status("err_watchdog", true);
    ++st_.watchdogs;
  } else {
    m_.idle(int(rng_() % 3000));
    ctrl("soft_stop");
    ++st_.soft_stops;
  }
  const std::uint32_t s = wait_status("stopping", false);
  m_.write(reg_offset("WATCHDOG"), 0);
  if (!get_field("STATUS", "aborted", s) || get_field("STATUS", "level", s) != 0) {
    throw GuardError("motion mix: a soft stop did not flush the queue or was not reported");
  }
  mon_.flush();
  ctrl("clear");
}

// An abort in the middle: the queue flushed, STATUS.aborted set.
void Mix::abort_batch() {
  m_.idle(int(rng_() % 300));
  ctrl("abort");
  mon_.flush();
  ++st_.aborts;
  const std::uint32_t s = m_.read(reg_offset("STATUS"));
  if (!get_field("STATUS", "aborted", s) || get_field("STATUS", "level", s) != 0) {
    throw GuardError("motion mix: an abort left the queue non-empty or was not reported");
  }
  ctrl("clear");
}

// A reset in the middle of the queue.
void Mix::reset_batch() {
  m_.idle(int(rng_() % 300));
  mon_.set_reset(false);
  m_.idle(1 + int(rng_() % 3));
  mon_.set_reset(true);
  noise_.configure(false);
  ++st_.resets;
}

// Fills the queue past its depth with ce_i low: err_overflow; then aborts.
void Mix::overflow(const Plan& first) {
  const auto save = m_.each_cycle;
  m_.each_cycle = [this] {
    mon_.set_ce(false);
    noise_.each_cycle();
  };
  const std::uint32_t cfg = m_.read(reg_offset("CONFIG"));
  const std::uint32_t depth = 1u << get_field("CONFIG", "depth_log2", cfg);
  const std::vector<std::uint32_t> w = entry_words(first.pieces.front().cmd);
  for (std::uint32_t k = 0; k <= depth + 1; ++k) {
    for (std::size_t j = 0; j < w.size(); ++j) m_.write(reg_offset("ENTRY") + 4 * std::uint32_t(j), w[j]);
    ctrl("commit");
  }
  ++st_.overflow;
  if (!get_field("STATUS", "err_overflow", m_.read(reg_offset("STATUS")))) {
    throw GuardError("motion mix: a full queue took a commit");
  }
  m_.each_cycle = save;
  ctrl("abort");
  mon_.flush();
  ctrl("clear");
}

// The speed monitor on a paced batch, from rest (the batch before drained): the path
// speed at the pins within the cruise speed (the override is clamped to it, the entries'
// limit) and, with a ramp, the acceleration within the batch's. Clocks as time (a
// clock of 1 Hz: steps per clock); ce_i low only slows the motion.
void Mix::watch_speed(const Pacing& pc) {
  if (!pc.on) return;
  MotionLimits lim;
  lim.clock_hz = 1;
  lim.max_speed = std::ldexp(pc.cruise, -kSpeedFrac);
  lim.max_accel = std::ldexp(pc.accel, -kRampFrac);
  speed_.watch(lim);
  ++st_.speed_watched;
}

// The batch's windows into the statistics; the monitor off.
void Mix::unwatch_speed() {
  if (!speed_.watching()) return;
  st_.speed_windows += speed_.monitor().samples().size();
  st_.peak_speed_share =
      std::max(st_.peak_speed_share, speed_.monitor().peak_speed() / speed_.monitor().limits().max_speed);
  speed_.unwatch();
}

// After a batch that ran to its end: the position counters on the batch's end.
void Mix::check_position(Point want) {
  const Point got = d_.position();
  ++st_.position_checks;
  if (got != want) {
    const auto text = [](Point p) {
      return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
    };
    throw GuardError("motion mix: the position counters read " + text(got) + ", the batch ends at " + text(want) +
                     "; last arcs: " + gen_.drawn_options() + " / " + spatial_.drawn_options());
  }
}

}  // namespace

MixStats run_motion_mix(BusTarget& t, std::uint64_t seed, std::uint64_t arcs, bool pipelined, std::int64_t max_axis) {
  Mix mix(t, seed, pipelined, max_axis);
  return mix.run(arcs);
}

}  // namespace dda::motion
