// SPDX-License-Identifier: Apache-2.0
#include "tb/cosim/paced_program.hpp"

#include <algorithm>

#include "host/driver/motion_driver.hpp"
#include "host/speed/segments.hpp"
#include "tb/monitors/bus_monitors.hpp"

namespace dda::motion {

MotionLimits pin_limits(const speed::PlannedProgram& pp, const speed::PlannerLimits& pl,
                        const speed::MachineLimits& lim, double step_mm, double clock_hz) {
  double top = 0;
  for (const auto& s : pp.segments) top = std::max(top, s.peak);
  MotionLimits ml;
  ml.clock_hz = clock_hz;
  ml.max_speed = top / step_mm;
  ml.max_accel = pl.accel / step_mm;
  // The block's axes are the run's plane's (u, v, normal): G18 (Z, X, Y), G19 (Y, Z, X).
  const std::array<std::size_t, 3> machine = speed::machine_axes(pp.totals.plane);
  for (std::size_t a = 0; a < 3; ++a) {
    ml.axis_speed[a] = lim.axes[machine[a]].vmax / 60 / step_mm;
    ml.axis_accel[a] = lim.axes[machine[a]].accel / step_mm;
  }
  return ml;
}

PacedRun run_paced_program(BusTarget& t, const speed::PlannedProgram& pp, const speed::ProgramPacing& pace,
                           const MotionLimits& pins, const PacedRunOptions& opt) {
  SpeedWatch watch(t, pins);
  WishboneMaster m(watch, opt.seed, opt.pipelined, 10);
  std::uint64_t cycles = 0;
  m.each_cycle = [&] { ++cycles; };
  MotionDriver d(m, opt.seed + 1);
  watch.set_reset(false);
  m.idle(2);
  watch.set_reset(true);
  for (const char axis : {'x', 'y', 'z'}) d.set_timings(axis, opt.timing);
  d.set_pacing(std::uint32_t(pace.setup.accel), pace.setup.vmin);
  d.preset(pp.plan.from);
  for (std::size_t i = 0; i < pp.plan.pieces.size(); ++i) {
    const Piece& pc = pp.plan.pieces[i];
    d.queue(pc.cmd, 0, pc.rot, pace.entries[i]);
  }
  d.drain(100000000);
  const Point end = d.position();
  return PacedRun{cycles, end, watch.monitor()};
}

}  // namespace dda::motion
