// SPDX-License-Identifier: Apache-2.0
// The planner for rotated ellipses by the DDA's own turns (zero preload): pieces found by running the datapath
// to each turn.
#include <algorithm>
#include <cstdlib>
#include <utility>
#include <vector>

#include "host/planner/plan_detail.hpp"

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

// The walk of a rotated ellipse's pieces: each piece runs the datapath from where the
// last one turned, and hands its step directions, preloads and turn to the next.
struct RotatedWalk {
  Plan& p;
  const bool full;  // one full turn
  const ArcSpec& spec;
  const Scaled& sc;
  std::optional<RayEnd>& ray;
  const Coefficients k;
  const int D;
  const Point c;
  const Point rt;  // the lattice end, relative to the centre
  const std::uint64_t guard;
  Point cur;                        // the piece's start, relative to the centre
  int sx = 0, sy = 0;               // its step directions
  std::int64_t jr_x = 0, jr_y = 0;  // its preloads
  bool first = true;                // no piece added yet
  char last_turn = 0;               // turns alternate between the axes around a convex curve

  RotatedWalk(Plan& plan, const Scaled& scaled, const EndPoint& from, std::optional<RayEnd>& ray_end)
      : p(plan),
        full(plan.arc().full),
        spec(plan.arc().spec),
        sc(scaled),
        ray(ray_end),
        k(scaled.k),
        D(spec.dir == Direction::Ccw ? 1 : -1),
        c(spec.center),
        rt{plan.to.x - c.x, plan.to.y - c.y},
        guard(rotated_piece_guard(spec)),
        cur{plan.from.x - c.x, plan.from.y - c.y} {
    sx = sign(tx(cur)), sy = sign(ty(cur));
    if (sx == 0 && sy == 0) {  // only at the centre, which plan_rotated_pieces() refuses
      throw GuardError("planner fault: the tangent is 0 at " + pt(p.from) + ", not the centre");
    }
    // On a turning line the axis takes the direction its integrand will grow in.
    if (sx == 0) sx = -D * sy;
    if (sy == 0) sy = D * sx;
    // The first piece's preloads: the start's fraction with half preload.
    if (spec.preload == Preload::Half) {
      jr_x = fraction_preload(sc.cap, sx < 0, from.fx);
      jr_y = fraction_preload(sc.cap, sy < 0, from.fy);
    }
  }

  // The tangent of the direction of travel at relative lattice point r.
  i128 tx(Point r) const { return D * (i128(k.p) * r.x - i128(k.qx) * r.y); }
  i128 ty(Point r) const { return D * (i128(k.qy) * r.x - i128(k.p) * r.y); }
  Point abs_pt(Point r) const { return Point{c.x + r.x, c.y + r.y}; }

  // Does an axis turn at registers r: its integrand negative while the other axis' steps
  // drive it further down (the path has crossed the line where the tangent of that axis
  // is 0)? A negative integrand the other axis drives back up is only a step's overshoot:
  // its axis holds until it is positive again.
  bool turn_x(const Command& cm, const RegState& r) const {
    return last_turn != 'X' && r.jv_x < 0 && cm.inc_x_on_y < 0;
  }
  bool turn_y(const Command& cm, const RegState& r) const {
    return last_turn != 'Y' && r.jv_y < 0 && cm.inc_y_on_x < 0;
  }

  // Refuses the arc once its path has turned kMaxRotatedTurns times. A convex curve turns
  // four times a turn; far more means the path lost the curve (a lattice end point was
  // missed) or hops between the turns at a tip sharper than the lattice (radius of
  // curvature min(a,b)^2 / max(a,b) steps).
  Refusal lost(int piece) const {
    const std::int64_t mn = std::min(spec.a, spec.b), mx = std::max(spec.a, spec.b);
    std::ostringstream m;
    m.precision(3);
    m << "the DDA cannot follow this rotated ellipse to " << pt(p.to) << ": its path from " << pt(p.from) << " turned "
      << piece << " times without reaching it (tip radius of curvature " << double(mn) * double(mn) / double(mx)
      << " steps: too thin for the lattice at this angle)";
    return Refusal{m.str()};
  }

  // The command of the piece starting at cur (cm), counts 0 (set once its run has found
  // its end); refuses an integrand beyond the capacity.
  std::optional<Refusal> piece_command(Command& cm) const {
    cm = Command{};
    cm.cap = sc.cap;
    cm.dir_x_neg = sx < 0;
    cm.dir_y_neg = sy < 0;
    const i128 jvx = sx * tx(cur), jvy = sy * ty(cur);
    if (jvx < -cm.cap || jvy < -cm.cap || jvx > cm.cap || jvy > cm.cap) {
      return Refusal{"bits = " + std::to_string(spec.bits) + " is too small for this arc: an integrand at " +
                     pt(abs_pt(cur)) + " exceeds the capacity (use more bits)"};
    }
    cm.jv_x = std::int64_t(jvx);
    cm.jv_y = std::int64_t(jvy);
    cm.jr_x = jr_x;
    cm.jr_y = jr_y;
    cm.inc_x_on_x = D * k.p;
    cm.inc_x_on_y = -D * sx * sy * k.qx;
    cm.inc_y_on_x = D * sx * sy * k.qy;
    cm.inc_y_on_y = -D * k.p;
    return std::nullopt;
  }

  // Refuses a run that cannot go on: an integrand beyond the capacity, a stall, or more
  // than `guard` iterations without turning (it circles: refused like a thin tip).
  std::optional<Refusal> check_running(const Command& cm, const Datapath& dp) const {
    const RegState& r = dp.regs();
    if (std::max(std::llabs(r.jv_x), std::llabs(r.jv_y)) > cm.cap) {
      return Refusal{"bits = " + std::to_string(spec.bits) + " is too small for this arc: an integrand at " +
                     pt(dp.pos()) + " exceeds the capacity (use more bits)"};
    }
    if (dp.stalled()) {
      return Refusal{"the DDA cannot follow this rotated ellipse from " + pt(p.from) + ": it stalls at " +
                     pt(dp.pos()) + " (both integrands <= 0: the lattice is too coarse for so thin an ellipse)"};
    }
    if (dp.iterations() >= guard) {
      return Refusal{"the DDA cannot follow this rotated ellipse: a piece from " + pt(abs_pt(cur)) + " passed " +
                     std::to_string(guard) + " iterations (a " + std::to_string(spec.a) + ", b " +
                     std::to_string(spec.b) + ", angle " + format_degrees(spec.angle) + ", bits " +
                     std::to_string(spec.bits) + ") without turning"};
    }
    return std::nullopt;
  }

  // The datapath that runs the piece of command cm from cur with unbounded counts.
  Datapath probe(const Command& cm) const {
    Command unbounded = cm;
    unbounded.cnt_x = unbounded.cnt_y = std::int64_t{1} << 40;
    return Datapath(unbounded, abs_pt(cur));
  }

  // Runs dp (probe(cm)) to the piece's turn, or (a parametric end) until the path
  // crosses the ray: then ray_end is set.
  std::optional<Refusal> run_to_turn(const Command& cm, Datapath& dp, bool& ray_end) const {
    while (!turn_x(cm, dp.regs()) && !turn_y(cm, dp.regs())) {
      if (auto stuck = check_running(cm, dp)) return stuck;
      dp.step();
      if (ray && ray->crossed(Point{dp.pos().x - c.x, dp.pos().y - c.y})) {
        ray_end = true;
        break;
      }
    }
    return std::nullopt;
  }

  // Adds the piece of command cm from cur to where its run stopped, `cut` (relative),
  // and says whether it is the arc's last: its run crossed the ray of a parametric end,
  // or its walk spans the lattice end (which it then gets the exact counts to). A turn
  // without a step adds no piece.
  bool add_piece(Command& cm, Point cut, bool ray_end) {
    const auto between = [](std::int64_t lo, std::int64_t v, std::int64_t hi, int s) {
      return (v - lo) * s >= 0 && (hi - v) * s >= 0;
    };
    const bool last =
        ray ? ray_end : !(full && first) && between(cur.x, rt.x, cut.x, sx) && between(cur.y, rt.y, cut.y, sy);
    const Point end = last && !ray ? rt : cut;
    cm.cnt_x = std::llabs(end.x - cur.x);
    cm.cnt_y = std::llabs(end.y - cur.y);
    if (last || cm.cnt_x != 0 || cm.cnt_y != 0) {
      Piece pc;
      pc.quadrant = quadrant_of_steps(sx, sy, spec.dir);
      pc.from = abs_pt(cur);
      pc.to = abs_pt(end);
      pc.cmd = cm;
      pc.iteration_bound = guard;
      p.iteration_bound += guard;
      p.pieces.push_back(pc);
      first = false;
    }
    return last;
  }

  // Sets up the next piece at `cut`, where the run of command cm turned with registers
  // r: the axes that turned reverse, and the accumulators carry their remainders with
  // half preload (mirrored for a reversed axis).
  void turn(const Command& cm, const RegState& r, Point cut) {
    const bool flip_x = turn_x(cm, r), flip_y = turn_y(cm, r);
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
};

}  // namespace

std::optional<Refusal> plan_rotated_pieces(Plan& p, const Scaled& sc, const EndPoint& from, std::optional<RayEnd> ray) {
  const ArcSpec& spec = p.arc().spec;
  if (spec.sub != 0) throw GuardError("planner fault: sub-step geometry goes to the anchored planner");
  // The tangent (a non-singular linear map of the position) is 0 only at the centre.
  if (p.from == spec.center) {
    return Refusal{"from point " + pt(p.from) + " is the centre of the ellipse: the tangent is 0 there"};
  }
  RotatedWalk w(p, sc, from, ray);
  for (int piece = 0;; ++piece) {
    if (piece >= kMaxRotatedTurns) return w.lost(piece);
    Command cm;
    if (auto too_wide = w.piece_command(cm)) return too_wide;
    bool ray_end = false;
    Datapath dp = w.probe(cm);
    if (auto stuck = w.run_to_turn(cm, dp, ray_end)) return stuck;
    const Point cut{dp.pos().x - w.c.x, dp.pos().y - w.c.y};
    if (w.add_piece(cm, cut, ray_end)) return std::nullopt;
    w.turn(cm, dp.regs(), cut);
  }
}

}  // namespace dda::detail
