// SPDX-License-Identifier: Apache-2.0
#include "host/driver/feed.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "model/datapath/errors.hpp"
#include "model/motion/motion_map.hpp"

namespace dda::feed {

double dda_speed(const Command& c, const RegState& r) {
  const double vx = r.cnt_x != 0 && r.jv_x > 0 ? double(r.jv_x) : 0.0;
  const double vy = r.cnt_y != 0 && r.jv_y > 0 ? double(r.jv_y) : 0.0;
  const double vz = r.cnt_z != 0 ? double(c.jv_z) / double(c.cap_z) : 0.0;
  return std::hypot(std::hypot(vx, vy) / double(c.cap), vz);
}

PieceMotion piece_motion(const Command& c) {
  Datapath d(c, Point{});
  PieceMotion m;
  m.speed_min = std::numeric_limits<double>::infinity();
  double sum = 0;
  const std::uint64_t bound = std::uint64_t{1} << 40;  // far beyond any planned piece
  while (!d.done()) {
    if (d.stalled() || d.iterations() > bound) throw GuardError("feed: a piece that does not end");
    const double v = dda_speed(c, d.regs());
    m.speed_min = std::min(m.speed_min, v);
    m.speed_max = std::max(m.speed_max, v);
    sum += v;
    const Iteration it = d.iterate();
    m.steps_x += it.step_x;
    m.steps_y += it.step_y;
    m.steps_z += it.step_z;
  }
  m.path = sum;
  m.iterations = d.iterations();
  if (m.iterations == 0) m.speed_min = 0;
  m.speed_mean = m.iterations ? sum / double(m.iterations) : 0;
  return m;
}

std::uint32_t feed_increment(const PieceMotion& m, double feed_steps_per_s, double clock_hz) {
  if (!(feed_steps_per_s > 0) || !(clock_hz > 0)) throw InputError("feed: the feed and the clock must be positive");
  if (m.path <= 0) return 0;  // a piece that does not move: any pace
  const double one = double(std::uint64_t{1} << motion::kFeedWidth);
  const double inc = std::round(one * double(m.iterations) * feed_steps_per_s / (m.path * clock_hz));
  if (inc == one) return 0;  // one iteration per clock: the full rate
  if (inc > one) {
    throw InputError(
        fmt::format("feed: {} steps/s needs {:.3f} iterations per clock on this piece; the core does at "
                    "most 1 (at {} Hz: at most {:.0f} steps/s here)",
                    feed_steps_per_s, inc / one, clock_hz, m.path * clock_hz / double(m.iterations)));
  }
  if (inc < 1) {
    throw InputError(fmt::format("feed: {} steps/s is below the slowest pace, one iteration per {} clocks",
                                 feed_steps_per_s, std::uint64_t{1} << motion::kFeedWidth));
  }
  return std::uint32_t(inc);
}

}  // namespace dda::feed
