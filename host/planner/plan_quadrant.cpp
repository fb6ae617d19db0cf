// SPDX-License-Identifier: Apache-2.0
// The planner for quarter turns: monotone pieces that meet at the ellipse's vertices.
#include <cstdlib>

#include "host/planner/plan_detail.hpp"

namespace dda::detail {

namespace {

// The quadrant a piece starting at relative point (u, v) runs in.
int start_quadrant(std::int64_t u, std::int64_t v, Direction dir) {
  const bool ccw = dir == Direction::Ccw;
  if (v == 0) return u > 0 ? (ccw ? 1 : 4) : (ccw ? 3 : 2);  // on the u axis
  if (u == 0) return v > 0 ? (ccw ? 2 : 1) : (ccw ? 4 : 3);  // on the v axis
  if (u > 0) return v > 0 ? 1 : 4;
  return v > 0 ? 2 : 3;
}

// The vertex a piece in quadrant q ends at, relative to the centre: moving u towards 0
// ends on the v axis at (0, sv*b); otherwise on the u axis at (su*a, 0).
Point end_vertex(int q, Direction dir, std::int64_t a, std::int64_t b) {
  if (step_sx(q, dir) == -kSu[q]) return Point{0, kSv[q] * b};
  return Point{kSu[q] * a, 0};
}

int next_quadrant(int q, Direction dir) { return dir == Direction::Ccw ? q % 4 + 1 : (q + 2) % 4 + 1; }

// Is relative point e reached from relative point s by a monotone move in quadrant q?
bool in_piece(int q, Direction dir, Point s, Point e) {
  if (e.x * kSu[q] < 0 || e.y * kSv[q] < 0) return false;  // outside the closed quadrant
  return (e.x - s.x) * step_sx(q, dir) >= 0 && (e.y - s.y) * step_sy(q, dir) >= 0;
}

// The command of the piece in quadrant q from relative point cur to relative point end,
// preloaded again (the first piece: with the start's fraction, half preload).
Command quadrant_command(const Plan& p, std::int64_t cap, const EndPoint& from, int q, Point cur, Point end) {
  const ArcGeometry& g = p.arc();
  const ArcSpec& spec = g.spec;
  const std::int64_t ax2 = g.ax * g.ax, by2 = g.by * g.by;
  const int sx = step_sx(q, spec.dir), sy = step_sy(q, spec.dir);
  Command cm;
  cm.cap = cap;
  // Integrands are magnitudes: |dx| ~ ax^2 |v| and |dy| ~ by^2 |u| (scaled by a*b).
  cm.jv_x = ax2 * std::llabs(cur.y);
  cm.jv_y = by2 * std::llabs(cur.x);
  cm.jr_x = cm.jr_y = spec.preload == Preload::Half ? cap / 2 : 0;
  if (p.pieces.empty() && spec.preload == Preload::Half) {  // the start's fraction
    cm.jr_x = fraction_preload(cap, sx < 0, from.fx);
    cm.jr_y = fraction_preload(cap, sy < 0, from.fy);
  }
  cm.cnt_x = std::llabs(end.x - cur.x);
  cm.cnt_y = std::llabs(end.y - cur.y);
  cm.dir_x_neg = sx < 0;
  cm.dir_y_neg = sy < 0;
  cm.inc_x_on_y = ax2 * sy * kSv[q];  // a Y step changes |v| by sy * sv
  cm.inc_y_on_x = by2 * sx * kSu[q];  // an X step changes |u| by sx * su
  cm.inc_x_on_x = cm.inc_y_on_y = 0;
  return cm;
}

// Refuses a piece (from relative point cur to end) whose integrands exceed the capacity.
// The integrands are largest where |v| and |u| are: at one end of the piece. Each must
// not exceed cap, or an accumulator could carry twice in one iteration.
std::optional<Refusal> check_quadrant_capacity(const ArcGeometry& g, const Piece& pc, Point cur, Point end) {
  const std::int64_t ax2 = g.ax * g.ax, by2 = g.by * g.by;
  const Command& cm = pc.cmd;
  const std::int64_t jvx_max = ax2 * std::max(std::llabs(cur.y), std::llabs(end.y));
  const std::int64_t jvy_max = by2 * std::max(std::llabs(cur.x), std::llabs(end.x));
  if (jvx_max > cm.cap || jvy_max > cm.cap) {
    const bool xside = jvx_max > cm.cap;
    std::ostringstream m;
    m << "bits = " << g.spec.bits << " is too small for this arc: the "
      << (xside ? "X integrand (ax/by)*|y-yc|" : "Y integrand (by/ax)*|x-xc|") << " exceeds 2^n between " << pt(pc.from)
      << " and " << pt(pc.to) << " (use more bits)";
    return Refusal{m.str()};
  }
  return std::nullopt;
}

// The iteration bound of a piece starting at relative point cur (docs/golden-model.md):
// an active axis whose integrand is not 0 carries at least every K iterations; an axis
// starting with a zero integrand waits at most one K of the other axis. nullopt: the
// bound would not fit 64 bits.
std::optional<std::uint64_t> quadrant_iteration_bound(const ArcGeometry& g, const Command& cm, Point cur) {
  const std::int64_t ax2 = g.ax * g.ax, by2 = g.by * g.by;
  const std::int64_t kx = ceil_div(cm.cap, ax2), ky = ceil_div(cm.cap, by2);
  const auto tx = checked_mul(cm.cnt_x, kx);
  const auto ty = checked_mul(cm.cnt_y, ky);
  if (!tx || !ty || *tx > (std::int64_t{1} << 60) || *ty > (std::int64_t{1} << 60)) {
    return std::nullopt;
  }
  const std::int64_t tx_total = *tx + ((cur.y == 0 && cm.cnt_x > 0) ? ky : 0);
  const std::int64_t ty_total = *ty + ((cur.x == 0 && cm.cnt_y > 0) ? kx : 0);
  return static_cast<std::uint64_t>(std::max(tx_total, ty_total));
}

// Walks a piece from relative point cur to its vertex `end` (relative to the centre c)
// and cuts it where the walk ends early: a parametric end where the path crosses the ray
// (then the arc ends there: returns true); a tip sharper than the lattice (the path
// reaches the vertex's axis, where one integrand is 0, with steps still owed on that
// axis) where it stalls, and the next piece goes on from there.
bool walk_to_vertex(Piece& pc, Point c, Point cur, Point& end, std::optional<RayEnd>& ray) {
  Command& cm = pc.cmd;
  Datapath dp(cm, pc.from);
  const auto cut_here = [&] {
    end = Point{dp.pos().x - c.x, dp.pos().y - c.y};
    pc.to = dp.pos();
    cm.cnt_x = std::llabs(end.x - cur.x);
    cm.cnt_y = std::llabs(end.y - cur.y);
  };
  while (!dp.done() && dp.iterations() < pc.iteration_bound) {
    if (dp.stalled()) {
      // With a lattice end the skipped stretch could hold it: refuse, as rule 6 says.
      if (!ray) return false;  // the validation run names the stall
      cut_here();
      return false;
    }
    dp.step();
    if (ray && ray->crossed(Point{dp.pos().x - c.x, dp.pos().y - c.y})) {
      cut_here();
      return true;
    }
  }
  return false;
}

}  // namespace

// Quarter turns: cut the arc into monotone pieces at the vertices (lattice points on
// the curve; docs/golden-model.md, "Pieces"), each preloaded again.
std::optional<Refusal> plan_quadrant_pieces(Plan& p, std::int64_t cap, const EndPoint& from,
                                            std::optional<RayEnd> ray) {
  const ArcGeometry& g = p.arc();
  const ArcSpec& spec = g.spec;
  const Point c = spec.center;
  const auto rel = [&](Point q) { return Point{q.x - c.x, q.y - c.y}; };
  const Point rt = rel(p.to);
  Point cur = rel(p.from);
  if (cur == Point{0, 0}) {
    return Refusal{"from point " + pt(p.from) + " is the centre of the ellipse: the tangent is 0 there"};
  }
  int q = start_quadrant(cur.x, cur.y, spec.dir);
  int empty_pieces = 0;
  for (int guard = 0;; ++guard) {
    if (guard > 5) {
      return Refusal{"the DDA cannot reach the end from " + pt(p.from) +
                     ": its path passed six pieces without crossing the end (the start lies far inside the curve?)"};
    }
    bool last = !ray && !(g.full && guard == 0) && in_piece(q, spec.dir, cur, rt);
    Point end = last ? rt : end_vertex(q, spec.dir, g.ax, g.by);
    if (!last && !in_piece(q, spec.dir, cur, end)) {
      return Refusal{"from point " + pt(p.from) + " lies beyond the vertex " + pt(Point{c.x + end.x, c.y + end.y}) +
                     " it runs to (" + to_string(spec.dir) + "): a point next to a vertex must lie before it"};
    }
    Piece pc;
    pc.quadrant = q;
    pc.from = Point{c.x + cur.x, c.y + cur.y};
    pc.to = Point{c.x + end.x, c.y + end.y};
    pc.cmd = quadrant_command(p, cap, from, q, cur, end);
    if (auto too_wide = check_quadrant_capacity(g, pc, cur, end)) return too_wide;
    const std::optional<std::uint64_t> bound = quadrant_iteration_bound(g, pc.cmd, cur);
    if (!bound) return Refusal{"iteration bound overflows 64 bits for this arc: reduce bits"};
    pc.iteration_bound = *bound;
    if (!last) last = walk_to_vertex(pc, c, cur, end, ray);
    if (!last && pc.cmd.cnt_x == 0 && pc.cmd.cnt_y == 0) {  // stalled on its first iteration: no piece
      q = next_quadrant(q, spec.dir);
      if (++empty_pieces > 4) {
        return Refusal{"the DDA cannot leave " + pt(Point{c.x + cur.x, c.y + cur.y}) +
                       ": it stalls in every direction"};
      }
      continue;
    }
    p.iteration_bound += pc.iteration_bound;
    p.pieces.push_back(pc);
    if (last) return std::nullopt;
    cur = end;
    q = next_quadrant(q, spec.dir);
  }
}

}  // namespace dda::detail
