// SPDX-License-Identifier: Apache-2.0
// The planner for rotated ellipses by the DDA's own turns (zero preload): pieces found by running the datapath
// to each turn.
#include <algorithm>
#include <cstdlib>
#include <utility>
#include <vector>

#include "plan_detail.hpp"

namespace dda::detail {

namespace {

// Rotated ellipse: the pieces are found by running the datapath (docs/golden-model.md,
// "Rotated ellipses"): a piece ends on the iteration after which one integrand has
// turned negative (its axis must reverse); the next piece starts there with that axis
// reversed and, with half preload, the accumulators carrying their remainders
// (mirrored for a reversed axis). The piece that contains the end point gets the exact
// counts to it.
// At a tip sharper than the lattice the path can hop between the two turns a few times;
// past kMaxRotatedTurns turns the arc is refused.
constexpr int kMaxRotatedTurns = 64;
//
// An end given as a parametric angle is where the path first crosses the ray from the
// centre through that angle's ideal point (with a full turn: after passing the far side),
// so it is always reached; an end given as a lattice point is reached with exact counts
// by the piece whose walk spans it, and refused if the path cannot get there.

}  // namespace

void plan_rotated_pieces(Plan& p, const Scaled& sc, const EndPoint& from, std::optional<RayEnd> ray) {
  const ArcSpec& spec = p.spec;
  if (spec.sub != 0) throw GuardError("planner fault: sub-step geometry goes to the anchored planner");
  const Coefficients k = sc.k;
  const int D = spec.dir == Direction::Ccw ? 1 : -1;
  const Point c = spec.center;
  const auto tx = [&](Point r) { return D * (i128(k.p) * r.x - i128(k.qx) * r.y); };
  const auto ty = [&](Point r) { return D * (i128(k.qy) * r.x - i128(k.p) * r.y); };
  const Point rt{p.to.x - c.x, p.to.y - c.y};
  Point cur{p.from.x - c.x, p.from.y - c.y};
  int sx = sign(tx(cur)), sy = sign(ty(cur));
  if (sx == 0 && sy == 0) {
    throw InputError("from point " + pt(p.from) + " is the centre of the ellipse: the tangent is 0 there");
  }
  // On a turning line the axis takes the direction its integrand will grow in.
  if (sx == 0) sx = -D * sy;
  if (sy == 0) sy = D * sx;
  const std::int64_t mn = std::min(spec.a, spec.b), mx = std::max(spec.a, spec.b);
  const std::uint64_t guard = rotated_piece_guard(spec);
  std::int64_t jr_x = spec.preload == Preload::Half ? sc.cap / 2 : 0, jr_y = jr_x;
  bool first = true;
  char last_turn = 0;  // turns alternate between the axes around a convex curve
  for (int piece = 0;; ++piece) {
    if (piece >= kMaxRotatedTurns) {
      // A convex curve turns four times a turn; far more means the path lost the curve
      // (a lattice end point was missed) or hops between the turns at a tip sharper
      // than the lattice (radius of curvature min(a,b)^2 / max(a,b) steps).
      std::ostringstream m;
      m.precision(3);
      m << "the DDA cannot follow this rotated ellipse to " << pt(p.to) << ": its path from " << pt(p.from)
        << " turned " << piece << " times without reaching it (tip radius of curvature "
        << double(mn) * double(mn) / double(mx) << " steps: too thin for the lattice at this angle)";
      throw InputError(m.str());
    }
    Command cm;
    cm.cap = sc.cap;
    cm.dir_x_neg = sx < 0;
    cm.dir_y_neg = sy < 0;
    const i128 jvx = sx * tx(cur), jvy = sy * ty(cur);
    if (jvx < -cm.cap || jvy < -cm.cap || jvx > cm.cap || jvy > cm.cap) {
      throw InputError("bits = " + std::to_string(spec.bits) + " is too small for this arc: an integrand at " +
                       pt(Point{c.x + cur.x, c.y + cur.y}) + " exceeds the capacity (use more bits)");
    }
    cm.jv_x = std::int64_t(jvx);
    cm.jv_y = std::int64_t(jvy);
    if (piece == 0 && spec.preload == Preload::Half) {
      jr_x = fraction_preload(cm.cap, cm.dir_x_neg, from.fx);
      jr_y = fraction_preload(cm.cap, cm.dir_y_neg, from.fy);
    }
    cm.jr_x = jr_x;
    cm.jr_y = jr_y;
    cm.inc_x_on_x = D * k.p;
    cm.inc_x_on_y = -D * sx * sy * k.qx;
    cm.inc_y_on_x = D * sx * sy * k.qy;
    cm.inc_y_on_y = -D * k.p;
    // Run the piece with unbounded counts to its turn: an integrand negative while the
    // other axis' steps drive it further down (the path has crossed the line where the
    // tangent of that axis is 0). A negative integrand the other axis drives back up is
    // only a step's overshoot: its axis holds until it is positive again.
    Command probe = cm;
    probe.cnt_x = probe.cnt_y = std::int64_t{1} << 40;
    bool ray_end = false;
    Datapath dp(probe, Point{c.x + cur.x, c.y + cur.y});
    const auto turn_x = [&](const RegState& r) { return last_turn != 'X' && r.jv_x < 0 && cm.inc_x_on_y < 0; };
    const auto turn_y = [&](const RegState& r) { return last_turn != 'Y' && r.jv_y < 0 && cm.inc_y_on_x < 0; };
    while (!turn_x(dp.regs()) && !turn_y(dp.regs())) {
      const RegState& r = dp.regs();
      if (std::max(std::llabs(r.jv_x), std::llabs(r.jv_y)) > cm.cap) {
        throw InputError("bits = " + std::to_string(spec.bits) + " is too small for this arc: an integrand at " +
                         pt(dp.pos()) + " exceeds the capacity (use more bits)");
      }
      if (dp.stalled()) {
        throw InputError("the DDA cannot follow this rotated ellipse from " + pt(p.from) + ": it stalls at " +
                         pt(dp.pos()) + " (both integrands <= 0: the lattice is too coarse for so thin an ellipse)");
      }
      if (dp.iterations() >= guard) {  // it circles without turning: refuse, like a thin tip
        throw InputError("the DDA cannot follow this rotated ellipse: a piece from " +
                         pt(Point{c.x + cur.x, c.y + cur.y}) + " passed " + std::to_string(guard) + " iterations (a " +
                         std::to_string(spec.a) + ", b " + std::to_string(spec.b) + ", angle " +
                         format_degrees(spec.angle) + ", bits " + std::to_string(spec.bits) + ") without turning");
      }
      dp.step();
      if (ray && ray->crossed(Point{dp.pos().x - c.x, dp.pos().y - c.y})) {
        ray_end = true;
        break;
      }
    }
    const Point cut{dp.pos().x - c.x, dp.pos().y - c.y};
    const auto between = [](std::int64_t lo, std::int64_t v, std::int64_t hi, int s) {
      return (v - lo) * s >= 0 && (hi - v) * s >= 0;
    };
    const bool last =
        ray ? ray_end : !(p.full && first) && between(cur.x, rt.x, cut.x, sx) && between(cur.y, rt.y, cut.y, sy);
    const Point end = last && !ray ? rt : cut;
    cm.cnt_x = std::llabs(end.x - cur.x);
    cm.cnt_y = std::llabs(end.y - cur.y);
    if (last || cm.cnt_x != 0 || cm.cnt_y != 0) {  // a turn without a step adds no piece
      Piece pc;
      pc.quadrant = quadrant_of_steps(sx, sy, spec.dir);
      pc.from = Point{c.x + cur.x, c.y + cur.y};
      pc.to = Point{c.x + end.x, c.y + end.y};
      pc.cmd = cm;
      pc.iteration_bound = guard;
      p.iteration_bound += guard;
      p.pieces.push_back(pc);
      first = false;
    }
    if (last) break;
    // Next piece: reverse the axes that turned.
    const RegState& r = dp.regs();
    const bool flip_x = turn_x(r), flip_y = turn_y(r);
    const auto carry = [&](std::int64_t jr, bool flip) {
      if (spec.preload == Preload::Zero) return std::int64_t{0};
      return flip ? std::min(cm.cap - jr, cm.cap - 1) : jr;
    };
    jr_x = carry(r.jr_x, flip_x);
    jr_y = carry(r.jr_y, flip_y);
    if (flip_x) sx = -sx;
    if (flip_y) sy = -sy;
    last_turn = flip_y ? 'Y' : 'X';
    cur = cut;
  }
}

}  // namespace dda::detail
