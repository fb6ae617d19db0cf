// SPDX-License-Identifier: Apache-2.0
// Arcs of a radius beyond what the datapath's sub-step geometry holds (kMaxDatapathRadius
// steps), as a chain of lines between lattice points next to the circle
// (docs/programs.md, "From blocks to commands"): each chord's sagitta at most
// kChordSagitta steps, each vertex the lattice point nearest the circle around the
// ideal one along the curve, so that the path stays within the arc's accuracy target.
#include <algorithm>
#include <cmath>

#include "host/planner/planner.hpp"
#include "host/program_plan/program_plan.hpp"

namespace dda::program {

namespace {

constexpr double kTwoPi = 6.283185307179586;

// A lattice point next to the circle (c, r) near its point at angle t: along the axis the
// curve moves faster on there, up to `reach` columns (or rows) either side, the one
// nearest the circle (ties: the one nearest the ideal point).
Point vertex_near(double cx, double cy, double r, double t, std::int64_t reach) {
  const double x = cx + r * std::cos(t), y = cy + r * std::sin(t);
  const bool along_x = std::fabs(std::sin(t)) >= std::fabs(std::cos(t));  // the curve moves mostly in x
  Point best{std::llround(x), std::llround(y)};
  double best_off = std::fabs(std::hypot(double(best.x) - cx, double(best.y) - cy) - r), best_j = 0;
  for (std::int64_t j = -reach; j <= reach; ++j) {
    // The column (row) j away and the curve's crossing of it on this side of the centre.
    const double a = along_x ? double(std::llround(x) + j) : double(std::llround(y) + j);
    const double da = along_x ? a - cx : a - cy;
    if (std::fabs(da) >= r) continue;
    const double db = std::sqrt(r * r - da * da) * ((along_x ? y - cy : x - cx) < 0 ? -1 : 1);
    const double b = (along_x ? cy : cx) + db;
    for (const double bb : {std::floor(b), std::ceil(b)}) {
      const double px = along_x ? a : bb, py = along_x ? bb : a;
      const double off = std::fabs(std::hypot(px - cx, py - cy) - r);
      if (off < best_off - 1e-12 || (off < best_off + 1e-12 && std::abs(double(j)) < best_j)) {
        best = Point{std::int64_t(px), std::int64_t(py)};
        best_off = off;
        best_j = std::abs(double(j));
      }
    }
  }
  return best;
}

}  // namespace

bool beyond_datapath(const Move& mv, Length step) {
  const bool arc = mv.kind == MoveKind::ArcCw || mv.kind == MoveKind::ArcCcw;
  return arc && double(mv.radius) / double(step) > double(kMaxDatapathRadius);
}

Plan plan_chords(const Move& mv, Length step, Preload preload, Point from, Point to) {
  const double s = double(step);
  const double cx = double(mv.center.u) / s, cy = double(mv.center.v) / s, r = double(mv.radius) / s;
  const double t0 = std::atan2(double(from.y) - cy, double(from.x) - cx);
  const double t1 = std::atan2(double(to.y) - cy, double(to.x) - cx);
  const bool cw = mv.kind == MoveKind::ArcCw;
  double sweep = cw ? t0 - t1 : t1 - t0;  // the turn in the arc's direction, in (0, 2 pi]
  while (sweep <= 0) sweep += kTwoPi;
  while (sweep > kTwoPi) sweep -= kTwoPi;
  if (from == to) sweep = kTwoPi;
  const double chord_angle = 2 * std::acos(1 - kChordSagitta / r);
  const auto n = std::int64_t(std::ceil(sweep / chord_angle));
  // (A vertex moves along the curve by at most a quarter of a chord.)
  const auto reach = std::min<std::int64_t>(2048, std::int64_t(r * chord_angle / 3));
  Plan plan;
  plan.geometry = LineGeometry{preload};
  plan.from = from;
  plan.to = to;
  Point at = from;
  for (std::int64_t k = 1; k <= n; ++k) {
    const double t = t0 + (cw ? -1.0 : 1.0) * sweep * double(k) / double(n);
    const Point next = k == n ? to : vertex_near(cx, cy, r, t, reach);
    if (next == at) continue;
    const Plan line = plan_line(at, next, preload);
    plan.pieces.insert(plan.pieces.end(), line.pieces.begin(), line.pieces.end());
    plan.iteration_bound += line.iteration_bound;
    at = next;
  }
  return plan;
}

}  // namespace dda::program
