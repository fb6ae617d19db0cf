// SPDX-License-Identifier: Apache-2.0
// The planner for rotated ellipses anchored on the ideal curve at every turn (half
// preload, and zero preload where the DDA's own turns fail): sections between the
// curve's turns, and lines across tips sharper than the lattice.
#include <algorithm>
#include <cstdlib>
#include <optional>
#include <utility>
#include <vector>

#include "host/planner/plan_detail.hpp"

namespace dda::detail {

namespace {

// Tips sharper than the lattice (docs/golden-model.md, "Tips sharper than the lattice").
// Near the tip of the major axis the curve's motion along that axis is proportional to
// its distance from the axis, which a lattice point beside it gets wrong by up to half a
// step: where the tip's radius of curvature min(a,b)^2 / max(a,b) is below kTipRadius
// steps, the path crosses the zone where the curve lies within kZoneOffset16 / 16 step of
// the major axis in lines, and re-anchors on the curve where it is kReanchorOffsets16 / 16
// steps from the axis on the way in and out. (Tuned on scripts/program-sweep.sh's draws:
// docs/results.md gives the figures.)
constexpr std::int64_t kTipRadius = 4;
constexpr int kZoneOffset16 = 16;
constexpr int kReanchorOffsets16[] = {24, 36, 54, 81};
constexpr std::int64_t kZoneChord = 8;  // steps between the way points of the lines across a zone

bool sharp_tips(const ArcSpec& spec) {
  const std::int64_t mn = std::min(spec.a, spec.b), mx = std::max(spec.a, spec.b);  // sub-step units
  return i128(mn) * mn < (i128(kTipRadius) * mx << spec.sub);
}

// The parametric angle from a tip of the major axis to where the curve is w16 / 16 step
// from that axis (minor * sin(angle) = w16 / 16), to the micro-degree on the fixed-point
// sines; 90 degrees if the minor semi-axis is no longer than that.
std::int64_t offset_angle(const ArcSpec& spec, int w16) {
  const i128 mn = std::min(spec.a, spec.b);  // sub-step units
  const i128 width = (i128(w16) << (kTrigFrac + spec.sub)) / 16;
  if (mn << kTrigFrac <= width) return kQuarterTurn;
  std::int64_t lo = 0, hi = kQuarterTurn;  // minor * sin(hi) >= width > minor * sin(lo)
  while (hi - lo > 1) {
    const std::int64_t m = lo + (hi - lo) / 2;
    (mn * sincos_udeg(m).s >= width ? hi : lo) = m;
  }
  return hi;
}

// The end of a section: where the path passes the section's last curve point e along
// the travel direction t there (the curve's tangent, times the direction of travel), or
// comes within half a step of it: the first position q with (q - e) . t >= -(|tx| +
// |ty|) / 2. Both axes move one way in a section, the ways of t's components (or t's
// component is 0), so (q - e) . t only grows: the first such position is where it stays.
struct PassEnd {
  FixedPoint e;  // relative, Q(kPosFrac)
  i128 tx = 0, ty = 0;
  PassEnd(const ArcSpec& spec, std::int64_t theta) : e(theta_ideal(spec, theta)) {
    const int D = spec.dir == Direction::Ccw ? 1 : -1;
    auto [x, y] = ideal_tangent(spec, theta);
    const auto mag = [](i128 v) { return v < 0 ? -v : v; };
    while (mag(x) >= (i128(1) << 60) || mag(y) >= (i128(1) << 60)) x /= 2, y /= 2;
    tx = D * x;
    ty = D * y;
  }
  bool reached(Point q) const {
    const i128 dx = (i128(q.x) << kPosFrac) - e.x, dy = (i128(q.y) << kPosFrac) - e.y;
    const auto mag = [](i128 v) { return v < 0 ? -v : v; };
    return dx * tx + dy * ty >= -((mag(tx) + mag(ty)) << (kPosFrac - 1));
  }
};

// The signed parametric angle from b to a, in (-180, 180] degrees.
std::int64_t angle_diff(std::int64_t a, std::int64_t b) {
  const std::int64_t d = normalize_udeg(a - b);
  return d > kFullTurn / 2 ? d - kFullTurn : d;
}

// A chain's cost: the largest distance of its points from the curve, then its steps
// (compared in that order).
using Cost = std::pair<double, std::int64_t>;

// The anchored plan of one arc (see plan_anchored_pieces()): the cuts of its parametric
// span, and where the path is as it goes through them.
struct AnchoredArc {
  Plan& p;
  const ArcSpec& spec;
  const Scaled& sc;
  const Coefficients k;
  const int D;
  const Point c;
  const std::int64_t theta_from;
  std::int64_t span = 0;   // travel in parametric angle (a full turn for equal angles)
  std::int64_t delta = 0;  // the parametric half width of a tip zone; 0 without sharp tips
  std::int64_t tip0 = 0;   // the parametric angle of a tip of the major axis
  // The cuts: (distance travelled, 'X'/'Y': that axis turns; see add_cut()).
  std::vector<std::pair<std::int64_t, char>> cuts;
  std::uint64_t guard = 0;
  // Where the plan stands: the kind of the last cut passed, the curve point the next
  // section starts on, the path's position and the distance travelled.
  char prev_axis = 0;
  EndPoint anchor;
  Point pos;
  std::int64_t done = 0;

  AnchoredArc(Plan& plan, const Scaled& scaled, const EndPoint& from, std::int64_t th_from, std::int64_t th_to)
      : p(plan),
        spec(plan.arc().spec),
        sc(scaled),
        k(scaled.k),
        D(spec.dir == Direction::Ccw ? 1 : -1),
        c(spec.center),
        theta_from(th_from),
        anchor(from),
        pos(from.lattice) {
    span = normalize_udeg(D * (th_to - theta_from));
    if (span == 0) span = kFullTurn;
    delta = sharp_tips(spec) ? offset_angle(spec, kZoneOffset16) : 0;
    tip0 = spec.a >= spec.b ? 0 : kQuarterTurn;
    collect_cuts();
    guard = rotated_piece_guard(spec);
  }

  Point rel(Point q) const { return Point{q.x - c.x, q.y - c.y}; }
  // The parametric angle after travelling dist from theta_from.
  std::int64_t at(std::int64_t dist) const { return normalize_udeg(theta_from + D * dist); }
  // Does parametric angle theta lie in a tip zone?
  bool in_zone(std::int64_t theta) const {
    if (delta == 0) return false;
    const std::int64_t d = angle_diff(theta, tip0);
    return std::llabs(d) < delta || kFullTurn / 2 - std::llabs(d) < delta;
  }

  // Cuts the span at parametric angle theta (if it lies inside): `what` is the turning
  // axis, or 'E' a tip zone's end, 'T' a tip, 'R' a re-anchoring point.
  void add_cut(std::int64_t theta, char what) {
    const std::int64_t d = normalize_udeg(D * (theta - theta_from));
    if (d > 0 && d < span) cuts.emplace_back(d, what);
  }

  // The cuts inside the span, in the order travelled and closed by the span's end: the
  // turns outside the tip zones, and around each tip the zone's ends, the tip and the
  // re-anchoring points on the way in and out.
  void collect_cuts() {
    for (const Turn& t : turns_of(spec)) {
      if (!in_zone(t.theta)) add_cut(t.theta, t.axis);
    }
    if (delta != 0) {
      for (const std::int64_t tip : {tip0, tip0 + kFullTurn / 2}) {
        add_cut(normalize_udeg(tip - delta), 'E');
        add_cut(normalize_udeg(tip), 'T');
        add_cut(normalize_udeg(tip + delta), 'E');
        for (const int w : kReanchorOffsets16) {
          const std::int64_t d = offset_angle(spec, w);
          if (d >= kQuarterTurn) break;
          add_cut(normalize_udeg(tip - d), 'R');
          add_cut(normalize_udeg(tip + d), 'R');
        }
      }
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.emplace_back(span, 0);
  }

  // Adds the lines from lattice point a to b (none if they are the same).
  void line_to(Point a, Point b) {
    if (a != b) {
      for (const Piece& l : line_pieces(a, b, spec.preload)) p.pieces.push_back(l);
    }
  }

  // The largest distance from the curve of the points of the lines through the lattice
  // points `way` (as line_pieces() draws them), and their steps.
  Cost chain_cost(std::initializer_list<Point> way) const {
    double worst = 0;
    std::int64_t steps = 0;
    const Point* prev = nullptr;
    for (const Point& q : way) {
      if (prev && *prev != q) {
        for (const Piece& l : line_pieces(*prev, q, spec.preload)) {
          Datapath dp(l.cmd, l.from);
          while (!dp.done()) {
            dp.step();
            worst = std::max(worst, plan_distance(p, double(dp.pos().x), double(dp.pos().y)));
          }
        }
        steps += std::max(std::llabs(q.x - prev->x), std::llabs(q.y - prev->y));
      } else if (!prev) {
        worst = plan_distance(p, double(q.x), double(q.y));
      }
      prev = &q;
    }
    return Cost{worst, steps};
  }

  // The lattice point nearest to the curve point at parametric angle theta.
  Point nearest_lattice(std::int64_t theta) const {
    const FixedPoint f = theta_ideal(spec, theta);
    return Point{c.x + std::int64_t(round_shift(f.x, kPosFrac)), c.y + std::int64_t(round_shift(f.y, kPosFrac))};
  }

  // Lattice points around the curve point at theta, after those of v: the nearest and its
  // 8 neighbours.
  std::vector<Point> around(std::int64_t theta, std::vector<Point> v) const {
    const Point r0 = nearest_lattice(theta);
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) v.push_back(Point{r0.x + dx, r0.y + dy});
    }
    return v;
  }

  // The command of a section starting on the curve point `a` with step directions (sx, sy),
  // counts 0 (set from its walk).
  Command section_command(const EndPoint& a, int sx, int sy) const {
    Command cm;
    cm.cap = sc.cap;
    cm.dir_x_neg = sx < 0;
    cm.dir_y_neg = sy < 0;
    const auto [tx, ty] = fixed_tangent(spec, k, D, a.lattice);
    const i128 jvx = sx * tx, jvy = sy * ty;
    if (jvx < -cm.cap || jvy < -cm.cap || jvx > cm.cap || jvy > cm.cap) {
      throw InputError("bits = " + std::to_string(spec.bits) + " is too small for this arc: an integrand at " +
                       pt(a.lattice) + " exceeds the capacity (use more bits)");
    }
    cm.jv_x = std::int64_t(jvx);
    cm.jv_y = std::int64_t(jvy);
    cm.jr_x = spec.preload == Preload::Half ? fraction_preload(cm.cap, cm.dir_x_neg, a.fx) : 0;
    cm.jr_y = spec.preload == Preload::Half ? fraction_preload(cm.cap, cm.dir_y_neg, a.fy) : 0;
    cm.inc_x_on_x = D * k.p;
    cm.inc_x_on_y = -D * sx * sy * k.qx;
    cm.inc_y_on_x = D * sx * sy * k.qy;
    cm.inc_y_on_y = -D * k.p;
    return cm;
  }

  // The extent of the tip zone whose first section ends at cuts[i]: the index of the cut
  // it ends at, and in `marks` (which holds where it starts) the tip's distance and that
  // of its end.
  std::size_t zone_end(std::size_t i, std::vector<std::int64_t>& marks) const {
    std::size_t j = i;
    while (j + 1 < cuts.size() && in_zone(at(cuts[j].first + (cuts[j + 1].first - cuts[j].first) / 2))) {
      if (cuts[j].second == 'T') marks.push_back(cuts[j].first);
      ++j;
    }
    marks.push_back(cuts[j].first);
    return j;
  }

  // The way points across a zone (distances travelled): the marks, each stretch between
  // them halved until its ends' lattice points are at most kZoneChord apart.
  std::vector<std::int64_t> zone_way(const std::vector<std::int64_t>& marks) const {
    std::vector<std::int64_t> way{marks.front()};
    for (std::size_t m = 1; m < marks.size(); ++m) {
      std::vector<std::int64_t> stack{marks[m]};
      while (!stack.empty()) {
        const std::int64_t d0 = way.back(), d1 = stack.back();
        const Point q0 = nearest_lattice(at(d0)), q1 = nearest_lattice(at(d1));
        if (d1 - d0 > 1 && std::max(std::llabs(q1.x - q0.x), std::llabs(q1.y - q0.y)) > kZoneChord) {
          stack.push_back(d0 + (d1 - d0) / 2);
        } else {
          way.push_back(d1);
          stack.pop_back();
        }
      }
    }
    return way;
  }

  // Candidates per way point; the first is where the path is (and, after an arc, the
  // points near the entry), the last goes on to `out` (or is it, at the arc's end).
  std::vector<std::vector<Point>> zone_candidates(const std::vector<std::int64_t>& way, bool exit, Point out) const {
    std::vector<std::vector<Point>> cand(way.size());
    for (std::size_t w = 0; w < way.size(); ++w) {
      if (w == 0 && prev_axis != 'E') {
        cand[w] = {pos};
      } else if (w + 1 == way.size() && !exit) {
        cand[w] = {out};
      } else {
        cand[w] = around(at(way[w]), w == 0 ? std::vector<Point>{pos} : std::vector<Point>{});
      }
    }
    return cand;
  }

  // The candidates, one per way point, whose lines from where the path is (and, leaving
  // the zone by its exit, on to `out`) keep closest to the curve, then take the fewest
  // steps: a bottleneck shortest path over the way points (dynamic programming).
  std::vector<Point> best_chain(const std::vector<std::vector<Point>>& cand, bool exit, Point out) const {
    const auto plus = [](Cost u, Cost v) { return Cost{std::max(u.first, v.first), u.second + v.second}; };
    const std::size_t n = cand.size();
    std::vector<std::vector<Cost>> best(n);
    std::vector<std::vector<std::size_t>> from_idx(n);
    for (std::size_t q = 0; q < cand[0].size(); ++q) {
      best[0].push_back(cand[0][q] == pos ? Cost{0.0, 0} : chain_cost({pos, cand[0][q]}));
      from_idx[0].push_back(0);
    }
    for (std::size_t w = 1; w < n; ++w) {
      for (const Point& q : cand[w]) {
        std::optional<Cost> b;
        std::size_t bi = 0;
        for (std::size_t r = 0; r < cand[w - 1].size(); ++r) {
          Cost cst = plus(best[w - 1][r], chain_cost({cand[w - 1][r], q}));
          if (w + 1 == n && exit) cst = plus(cst, chain_cost({q, out}));
          if (!b || cst < *b) b = cst, bi = r;
        }
        best[w].push_back(*b);
        from_idx[w].push_back(bi);
      }
    }
    std::size_t idx = std::size_t(std::min_element(best.back().begin(), best.back().end()) - best.back().begin());
    std::vector<Point> pts(n);
    for (std::size_t w = n; w-- > 0;) {
      pts[w] = cand[w][idx];
      idx = from_idx[w][idx];
    }
    return pts;
  }

  // Across the tip zone whose first section ends at cuts[i]: lines through lattice
  // points near curve points no more than kZoneChord steps apart (the zone's entry, the
  // tip, its exit and points between), each chosen among the nearest lattice point and
  // its 8 neighbours so that the lines' points keep closest to the curve (then the
  // fewest steps), from where the path is to the next section's start. Returns the
  // index of the cut the zone ends at.
  std::size_t cross_zone(std::size_t i) {
    std::vector<std::int64_t> marks{done};  // distances travelled: entry, tip, exit
    const std::size_t j = zone_end(i, marks);
    const bool exit = cuts[j].second == 'E';
    const EndPoint out = resolve_point(spec, std::nullopt, at(cuts[j].first), 0, std::nullopt);
    const std::vector<std::int64_t> way = zone_way(marks);
    const std::vector<Point> pts = best_chain(zone_candidates(way, exit, out.lattice), exit, out.lattice);
    Point at_pt = pos;
    for (const Point& q : pts) line_to(at_pt, q), at_pt = q;
    line_to(at_pt, out.lattice);
    pos = out.lattice;
    prev_axis = cuts[j].second;
    anchor = out;
    done = cuts[j].first;
    return j;
  }

  // Runs a section's probe command from `start` until the path passes the section's end
  // (or stalls, or passes the guard); refuses an integrand beyond the capacity on an
  // axis still owed steps.
  Datapath walk_section(const Command& probe, Point start, const PassEnd& end) const {
    Datapath dp(probe, start);
    while (!dp.stalled() && dp.iterations() < guard) {
      const RegState& r = dp.regs();
      if ((r.cnt_x != 0 && std::llabs(r.jv_x) > probe.cap) || (r.cnt_y != 0 && std::llabs(r.jv_y) > probe.cap)) {
        throw InputError("bits = " + std::to_string(spec.bits) + " is too small for this arc: an integrand at " +
                         pt(dp.pos()) + " exceeds the capacity (use more bits)");
      }
      // The position and the registers read above hold until the next step: the
      // iterations before it run in closed form (at most to the guard). (The walk
      // starts short of the end, run_section() checks, and ends at the step that
      // passes it.)
      const std::uint64_t room = guard - dp.iterations();
      if (dp.skip_quiet(room) == room) break;
      dp.step();
      if (end.reached(rel(dp.pos()))) break;
    }
    return dp;
  }

  // The section from the anchor to the curve point at th_b (`next`), where turn_axis
  // turns; mid is its middle's parametric angle. After a line from where the path is to
  // the anchor, it runs the datapath until the path passes the section's end, the
  // turning axis at most to the end's lattice coordinate, and adds the piece if it moved.
  // A section whose ends share their lattice point, or whose start has already passed its
  // end, adds nothing.
  void run_section(char turn_axis, std::int64_t th_b, std::int64_t mid, const EndPoint& next) {
    if (next.lattice == anchor.lattice) return;  // nothing to run: the next section starts here
    line_to(pos, anchor.lattice);
    const Point start = pos = anchor.lattice;
    // Step directions: the curve's, in the middle of the section.
    const auto [mtx, mty] = ideal_tangent(spec, mid);
    const int sx = D * mtx >= 0 ? 1 : -1, sy = D * mty >= 0 ? 1 : -1;
    Command cm = section_command(anchor, sx, sy);
    // Run to the ray; the turning axis at most to the end's lattice coordinate.
    Command probe = cm;
    constexpr std::int64_t kOpen = std::int64_t{1} << 40;
    probe.cnt_x = turn_axis == 'X' ? std::max<std::int64_t>(0, sx * (next.lattice.x - start.x)) : kOpen;
    probe.cnt_y = turn_axis == 'Y' ? std::max<std::int64_t>(0, sy * (next.lattice.y - start.y)) : kOpen;
    const PassEnd end(spec, th_b);
    if (end.reached(rel(start))) return;  // already there: the next section starts from here
    const Datapath dp = walk_section(probe, start, end);
    pos = dp.pos();
    cm.cnt_x = std::llabs(pos.x - start.x);
    cm.cnt_y = std::llabs(pos.y - start.y);
    if (pos != start) {
      Piece pc;
      pc.quadrant = quadrant_of_steps(sx, sy, spec.dir);
      pc.from = start;
      pc.to = pos;
      pc.cmd = cm;
      pc.iteration_bound = dp.iterations();  // exact: the run above is the piece's run
      p.pieces.push_back(pc);
    }
  }

  // An arc shorter than a step (its ends' curve points round to one lattice point): one
  // command without a step at `from`, as the other planners' last piece.
  void add_stepless_piece(const EndPoint& from) {
    const auto [t0x, t0y] = ideal_tangent(spec, theta_from);
    const int sx = D * t0x >= 0 ? 1 : -1, sy = D * t0y >= 0 ? 1 : -1;
    Piece pc;
    pc.quadrant = quadrant_of_steps(sx, sy, spec.dir);
    pc.from = pc.to = from.lattice;
    pc.cmd = section_command(from, sx, sy);
    pc.iteration_bound = 1;
    p.pieces.push_back(pc);
  }

  // The sections and tip zones in the order travelled.
  void plan(const EndPoint& from) {
    for (std::size_t i = 0; i < cuts.size(); ++i) {
      const auto [dist, turn_axis] = cuts[i];
      const std::int64_t th_b = at(dist), mid = at(done + (dist - done) / 2);
      const EndPoint next = resolve_point(spec, std::nullopt, th_b, 0, std::nullopt);
      if (in_zone(mid)) {
        i = cross_zone(i);
        continue;
      }
      prev_axis = turn_axis;
      run_section(turn_axis, th_b, mid, next);
      anchor = next;
      done = dist;
    }
    if (p.pieces.empty()) add_stepless_piece(from);
  }
};

}  // namespace

// docs/golden-model.md, "Rotated ellipses". The arc is cut at the turns of the ideal
// curve (where its tangent is parallel to an axis) into sections in which both axes move
// one way. Each section starts on the ideal curve at its first angle: from the lattice
// point nearest to that curve point (zero preload: theta_point()'s), with half preload
// the rest of it in the preloads, and runs until the path passes the section's last
// curve point (PassEnd); the axis that turns there takes at most the steps to that
// point's lattice point. The next section starts on the ideal curve again, after a short
// line from where the path stopped if that is another lattice point. So the DDA never
// runs past a turn on its own (where the lattice position's tangent points the other way
// than the curve's): every turn is re-anchored on the curve. A section whose start and
// end have the same lattice point is skipped; one that cannot move ends where it stands,
// and the line goes on to the next anchor.
// Around a tip sharper than the lattice (sharp_tips()) the path re-anchors more often on
// the way in and out, and crosses the zone where the curve lies within a step of the
// major axis in lines: through a lattice point near the zone's entry, one near the tip
// and one near its exit, chosen among the nearest and its neighbours so that the lines'
// points keep closest to the curve.
void plan_anchored_pieces(Plan& p, const Scaled& sc, const EndPoint& from, std::int64_t theta_from,
                          std::int64_t theta_to) {
  AnchoredArc(p, sc, from, theta_from, theta_to).plan(from);
}

}  // namespace dda::detail
