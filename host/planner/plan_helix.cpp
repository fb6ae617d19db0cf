// SPDX-License-Identifier: Apache-2.0
// The third axis along a path of the plane (a helix): Bresenham's rule over the path's
// iterations, counted by the golden datapath, on the core's linear integrator.
#include <string>

#include "host/planner/plan_detail.hpp"

namespace dda {

using namespace detail;

namespace {

// The iterations a piece takes from its loaded command to its end: the golden datapath,
// the iterations without a step skipped in closed form.
std::uint64_t piece_iterations(const Piece& pc) {
  Datapath dp(pc.cmd, pc.from);
  while (!dp.done()) {
    if (dp.stalled() || dp.iterations() >= pc.iteration_bound) {
      throw GuardError("helix: a piece from " + pt(pc.from) + " to " + pt(pc.to) + " does not end");
    }
    dp.skip_quiet(pc.iteration_bound - dp.iterations());
    if (!dp.done()) dp.step();
  }
  return dp.iterations();
}

}  // namespace

void lift(Plan& plan, std::int64_t z0, std::int64_t z1, Preload preload) {
  if (z0 == z1) {  // the path at its height: no iterations to count, no command changes
    for (const Piece& pc : plan.pieces) {
      if (pc.cmd.cnt_z != 0) throw InputError("lift: a piece of the path already moves the third axis");
    }
    for (Piece& pc : plan.pieces) pc.from.z = pc.to.z = z0;
    plan.from.z = plan.to.z = z0;
    return;
  }
  std::uint64_t total = 0;
  std::vector<std::uint64_t> its;
  its.reserve(plan.pieces.size());
  for (const Piece& pc : plan.pieces) {
    if (pc.cmd.cnt_z != 0) throw InputError("lift: a piece of the path already moves the third axis");
    its.push_back(piece_iterations(pc));
    total += its.back();
  }
  const std::int64_t rise = z1 - z0, steps = rise < 0 ? -rise : rise, sign = rise < 0 ? -1 : 1;
  plan.from.z = z0;
  plan.to.z = z1;
  if (steps != 0 && std::uint64_t(steps) > total) {
    throw InputError("the helix rises " + std::to_string(steps) + " steps along a path of " + std::to_string(total) +
                     " iterations: the third axis steps at most once per iteration (a rise steeper than the "
                     "path in the plane; cut it into several blocks)");
  }
  if (steps != 0 && total >= (std::uint64_t{1} << (hw::kAccWidth - 1))) {
    throw InputError("the helix's path takes " + std::to_string(total) +
                     " iterations: the third axis' capacity holds fewer (hw_params.hpp)");
  }
  // After I iterations of the path the axis has made floor((h + steps I) / total) steps,
  // h the preload: within half a step of the ideal rise steps I / total (half preload).
  const i128 h = steps == 0 ? 0 : preload == Preload::Half ? i128(total / 2) : 0;
  const auto made = [&](std::uint64_t i) { return steps == 0 ? 0 : std::int64_t((h + i128(steps) * i) / i128(total)); };
  std::uint64_t at = 0;
  for (std::size_t k = 0; k < plan.pieces.size(); ++k) {
    Piece& pc = plan.pieces[k];
    const std::uint64_t end = at + its[k];
    const std::int64_t m0 = made(at), m1 = made(end);
    pc.from.z = z0 + sign * m0;
    pc.to.z = z0 + sign * m1;
    if (m1 > m0) {
      if (m1 - m0 > std::int64_t(hw::kCntMax)) {
        throw InputError("a piece of the helix rises " + std::to_string(m1 - m0) + " steps: the counters hold " +
                         std::to_string(hw::kCntMax) + " (cut the helix into several blocks)");
      }
      Command& c = pc.cmd;
      c.cap_z = std::int64_t(total);
      c.jv_z = steps;
      c.jr_z = std::int64_t((h + i128(steps) * at) % i128(total));
      c.cnt_z = m1 - m0;
      c.dir_z_neg = rise < 0;
    }
    at = end;
  }
}

void turn_axes(Plan& plan, int rot) {
  if (rot == 0) return;
  for (Piece& pc : plan.pieces) {
    pc.from = to_run_axes(pc.from, rot);
    pc.to = to_run_axes(pc.to, rot);
    pc.rot = (pc.rot + rot) % 3;
  }
  plan.from = to_run_axes(plan.from, rot);
  plan.to = to_run_axes(plan.to, rot);
}

}  // namespace dda
