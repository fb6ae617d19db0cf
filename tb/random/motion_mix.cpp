// SPDX-License-Identifier: Apache-2.0
#include "motion_mix.hpp"

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "dda/errors.hpp"
#include "dda/stepdir_monitor.hpp"
#include "dda_random.hpp"

namespace dda::motion {

namespace {
constexpr std::uint32_t kTimingMax = (1u << kTimingWidth) - 1;
}

MixStats run_motion_mix(BusTarget& t, std::uint64_t seed, std::uint64_t arcs, bool pipelined, std::int64_t max_axis) {
  MixStats st;
  std::mt19937_64 rng(seed);
  RandomArcs gen(seed, max_axis, 4, ArcKind::Program);
  RandomArcs short_arcs(seed + 3, std::min<std::int64_t>(max_axis, 8), 4, ArcKind::Program);
  StepDirMonitor timing(t);
  PieceMonitor mon(timing);
  WishboneMaster m(mon, seed + 1, pipelined, 20);
  m.each_cycle = [&] { mon.set_ce(rng() % 10 != 0); };
  MotionDriver d(m, seed + 2);
  const auto ctrl = [&](std::string_view bit) { m.write(reg_offset("CTRL"), field_bit("CTRL", bit)); };
  mon.set_reset(false);
  m.idle(2);
  mon.set_reset(true);
  while (st.arcs < arcs) {
    ++st.batches;
    // One to four arcs back to back from a preset position; a twentieth of the batches
    // are one short arc with large timings.
    const unsigned kind = unsigned(rng() % 20);
    const bool large = kind == 0;
    std::vector<Plan> batch;
    const std::uint64_t n = large ? 1 : 1 + rng() % 4;
    while (batch.size() < n && st.arcs + batch.size() < arcs) {
      if (auto p = (large ? short_arcs : gen).next()) batch.push_back(std::move(*p));
    }
    if (batch.empty()) break;
    d.drain();
    for (const char axis : {'x', 'y'}) {
      const auto draw = [&]() -> std::uint32_t {
        if (large) return rng() % 8 == 0 ? kTimingMax : std::uint32_t(rng() % 1024);
        return std::uint32_t(rng() % 9);
      };
      StageTimings tm;
      if (large || kind % 2 == 1) tm = StageTimings{draw(), draw(), draw(), draw()};
      d.set_timings(axis, tm);
    }
    st.timed_batches += large || kind % 2 == 1;
    st.large_timing_batches += large;
    d.set_polarity(std::uint32_t(rng() % 16));
    d.preset(batch.front().from);
    Point want = batch.front().from;
    if (rng() % 10 == 0) {  // a partial entry committed: refused
      m.write(reg_offset("ENTRY"), std::uint32_t(rng()));
      ctrl("commit");
      ++st.partial;
      if (!get_field("STATUS", "err_partial", m.read(reg_offset("STATUS")))) {
        throw GuardError("motion mix: a partial commit was not reported");
      }
      ctrl("clear");
    }
    Point at = batch.front().from;
    for (const auto& p : batch) {
      for (const auto& piece : p.pieces) {
        at = Point{at.x + (piece.to.x - piece.from.x), at.y + (piece.to.y - piece.from.y)};
        mon.expect(at);
        const std::uint32_t feed = rng() % 2 == 0 ? 0 : 0x2000 + std::uint32_t(rng() % 0xE000);
        st.fed_pieces += feed != 0;
        d.queue(piece.cmd, feed);
      }
      want = Point{want.x + (p.to.x - p.from.x), want.y + (p.to.y - p.from.y)};
      st.pieces += p.pieces.size();
    }
    st.arcs += batch.size();
    const unsigned end = unsigned(rng() % 16);
    if (end == 0) {  // abort in the middle
      m.idle(int(rng() % 300));
      ctrl("abort");
      mon.flush();
      ++st.aborts;
      const std::uint32_t s = m.read(reg_offset("STATUS"));
      if (!get_field("STATUS", "aborted", s) || get_field("STATUS", "level", s) != 0) {
        throw GuardError("motion mix: an abort left the queue non-empty or was not reported");
      }
      ctrl("clear");
      continue;
    }
    if (end == 1) {  // reset in the middle of the queue
      m.idle(int(rng() % 300));
      mon.set_reset(false);
      m.idle(1 + int(rng() % 3));
      mon.set_reset(true);
      ++st.resets;
      continue;
    }
    if (end == 2) {  // fill past the depth with ce_i low: overflow
      const auto save = m.each_cycle;
      m.each_cycle = [&] { mon.set_ce(false); };
      const std::uint32_t cfg = m.read(reg_offset("CONFIG"));
      const std::uint32_t depth = 1u << get_field("CONFIG", "depth_log2", cfg);
      const std::vector<std::uint32_t> w = entry_words(batch.front().pieces.front().cmd);
      for (std::uint32_t k = 0; k <= depth + 1; ++k) {
        for (std::size_t j = 0; j < w.size(); ++j) m.write(reg_offset("ENTRY") + 4 * std::uint32_t(j), w[j]);
        ctrl("commit");
      }
      ++st.overflow;
      if (!get_field("STATUS", "err_overflow", m.read(reg_offset("STATUS")))) {
        throw GuardError("motion mix: a full queue took a commit");
      }
      m.each_cycle = save;
      ctrl("abort");
      mon.flush();
      ctrl("clear");
      continue;
    }
    d.drain();
    const Point got = d.position();
    ++st.position_checks;
    if (got.x != want.x || got.y != want.y) {
      throw GuardError("motion mix: the position counters read (" + std::to_string(got.x) + ", " +
                       std::to_string(got.y) + "), the batch ends at (" + std::to_string(want.x) + ", " +
                       std::to_string(want.y) + "); last arc: " + gen.drawn_options());
    }
  }
  st.piece_checks = mon.checked();
  st.pulses = timing.pulses(0) + timing.pulses(1);
  return st;
}

}  // namespace dda::motion
