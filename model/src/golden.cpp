// Golden reference model: datapath iteration, arc planning and validation.
#include "dda/golden.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>
#include <utility>

namespace dda {

namespace {

std::string pt(Point p) {
  std::ostringstream s;
  s << '(' << p.x << ',' << p.y << ')';
  return s.str();
}

// Ceil(num / den) for positive operands.
std::int64_t ceil_div(std::int64_t num, std::int64_t den) { return (num + den - 1) / den; }

// a * b, or nullopt if it does not fit in int64.
std::optional<std::int64_t> checked_mul(std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  if (__builtin_mul_overflow(a, b, &r)) return std::nullopt;
  return r;
}

// Headroom: every sum the datapath forms is below 2 * cap, and integrand corrections
// stay within [-(cap), 2 * cap]; keeping cap below 2^61 keeps all of them in int64.
constexpr std::int64_t kCapLimit = std::int64_t{1} << 61;

}  // namespace

const char* to_string(Preload p) { return p == Preload::Zero ? "zero" : "half"; }

Datapath::Datapath(const Command& cmd, Point start)
    : cmd_(cmd), regs_(initial_regs(cmd)), pos_(start) {}

bool Datapath::stalled() const {
  if (done()) return false;
  const bool x_can = regs_.cnt_x != 0 && regs_.jv_x > 0;
  const bool y_can = regs_.cnt_y != 0 && regs_.jv_y > 0;
  return !x_can && !y_can;
}

Iteration Datapath::iterate() {
  Iteration it;
  it.iter = ++iter_;
  it.active_x = regs_.cnt_x != 0;
  it.active_y = regs_.cnt_y != 0;
  it.jv_x = regs_.jv_x;
  it.jv_y = regs_.jv_y;
  // Both accumulators add the integrands of this iteration; a carry (sum >= cap)
  // is a step and the accumulator keeps sum - cap.
  // An axis adds while active with a positive integrand; a negative one holds.
  it.sum_x = it.active_x && regs_.jv_x > 0 ? regs_.jr_x + regs_.jv_x : regs_.jr_x;
  it.sum_y = it.active_y && regs_.jv_y > 0 ? regs_.jr_y + regs_.jv_y : regs_.jr_y;
  it.step_x = it.active_x && it.sum_x >= cmd_.cap;
  it.step_y = it.active_y && it.sum_y >= cmd_.cap;
  RegState& r = regs_;
  r.jr_x = it.step_x ? it.sum_x - cmd_.cap : it.sum_x;
  r.jr_y = it.step_y ? it.sum_y - cmd_.cap : it.sum_y;
  r.cnt_x -= it.step_x ? 1 : 0;
  r.cnt_y -= it.step_y ? 1 : 0;
  // Corrections apply after the iteration, from the steps of this iteration.
  r.jv_x += (it.step_x ? cmd_.inc_x_on_x : 0) + (it.step_y ? cmd_.inc_x_on_y : 0);
  r.jv_y += (it.step_x ? cmd_.inc_y_on_x : 0) + (it.step_y ? cmd_.inc_y_on_y : 0);
  if (it.step_x) pos_.x += cmd_.dir_x_neg ? -1 : 1;
  if (it.step_y) pos_.y += cmd_.dir_y_neg ? -1 : 1;
  it.after = r;
  it.pos = pos_;
  return it;
}

RegState initial_regs(const Command& c) {
  RegState r;
  r.jv_x = c.jv_x;
  r.jv_y = c.jv_y;
  r.jr_x = c.jr_x;
  r.jr_y = c.jr_y;
  r.cnt_x = c.cnt_x;
  r.cnt_y = c.cnt_y;
  return r;
}

void Datapath::step() {
  const bool ax = regs_.cnt_x != 0, ay = regs_.cnt_y != 0;
  const std::int64_t sx = ax && regs_.jv_x > 0 ? regs_.jr_x + regs_.jv_x : regs_.jr_x;
  const std::int64_t sy = ay && regs_.jv_y > 0 ? regs_.jr_y + regs_.jv_y : regs_.jr_y;
  const bool cx = ax && sx >= cmd_.cap, cy = ay && sy >= cmd_.cap;
  regs_.jr_x = cx ? sx - cmd_.cap : sx;
  regs_.jr_y = cy ? sy - cmd_.cap : sy;
  regs_.cnt_x -= cx;
  regs_.cnt_y -= cy;
  regs_.jv_x += (cx ? cmd_.inc_x_on_x : 0) + (cy ? cmd_.inc_x_on_y : 0);
  regs_.jv_y += (cx ? cmd_.inc_y_on_x : 0) + (cy ? cmd_.inc_y_on_y : 0);
  if (cx) pos_.x += cmd_.dir_x_neg ? -1 : 1;
  if (cy) pos_.y += cmd_.dir_y_neg ? -1 : 1;
  ++iter_;
}

int smallest_valid_bits(std::int64_t a, std::int64_t b) {
  const std::int64_t m = std::max(a, b);
  int n = 1;
  while (n < 62 && (std::int64_t{1} << n) < m) ++n;
  return n;
}

int default_bits(std::int64_t a, std::int64_t b) {
  // Four bits above the smallest valid width, fewer if the capacity would leave range.
  int n = smallest_valid_bits(a, b) + 4;
  while (n > smallest_valid_bits(a, b) && (__int128(a) * b << n) >= (__int128(1) << 61)) --n;
  return n;
}

const char* to_string(Direction d) { return d == Direction::Ccw ? "ccw" : "cw"; }

namespace {

// Runs piece k; iteration numbers continue from first_iter.
RunSummary run_segment(const Plan& plan, std::size_t k, std::uint64_t first_iter,
                       const std::function<void(const Iteration&)>* on_iter, bool for_validation) {
  const Segment& sg = plan.segs[k];
  Datapath dp(sg.cmd, sg.from);
  while (!dp.done()) {
    // An active axis' integrand must stay within [-cap, cap]: above cap an accumulator
    // could carry twice in one iteration. The planner refuses such an arc.
    const auto& rg = dp.regs();
    for (const auto& [axis, active, jv] : {std::tuple{'X', rg.cnt_x != 0, rg.jv_x}, std::tuple{'Y', rg.cnt_y != 0, rg.jv_y}}) {
      if (active && (jv < -sg.cmd.cap || jv > sg.cmd.cap)) {
        std::ostringstream m;
        m << "end point " << pt(plan.to) << " is unreachable from " << pt(plan.from) << ": at " << pt(dp.pos())
          << " the " << axis << " integrand's magnitude exceeds the capacity with "
          << (axis == 'X' ? rg.cnt_x : rg.cnt_y) << ' ' << axis << " step(s) still owed";
        if (for_validation) throw InputError(m.str());
        throw GuardError("integrand guard: " + m.str());
      }
    }
    if (dp.stalled()) {
      const auto& r = dp.regs();
      const char axis = (r.cnt_y != 0 && r.jv_y == 0) ? 'Y' : 'X';
      const std::int64_t owed = axis == 'Y' ? r.cnt_y : r.cnt_x;
      std::ostringstream m;
      m << "end point " << pt(plan.to) << " is unreachable from " << pt(plan.from) << ": at "
        << pt(dp.pos()) << " the " << axis << " integrand is 0 with " << owed << ' ' << axis
        << " step(s) still owed (the DDA would never finish)";
      if (for_validation) throw InputError(m.str());
      throw GuardError("stall guard: " + m.str());
    }
    if (dp.iterations() >= sg.iteration_bound) {
      std::ostringstream m;
      m << "iteration guard: the piece to " << pt(sg.to) << " reached its bound of "
        << sg.iteration_bound << " iterations";
      throw GuardError(m.str());
    }
    if (!on_iter || !*on_iter) {
      dp.step();
      continue;
    }
    Iteration it = dp.iterate();
    // Back to back, the edge of a piece's last iteration also loads the next piece's
    // command: the registers after it are that command's.
    if (dp.done() && k + 1 < plan.segs.size()) it.after = initial_regs(plan.segs[k + 1].cmd);
    it.iter += first_iter;
    it.seg = static_cast<std::uint32_t>(k);
    it.dir_x_neg = sg.cmd.dir_x_neg;
    it.dir_y_neg = sg.cmd.dir_y_neg;
    (*on_iter)(it);
  }
  if (dp.pos() != sg.to) {
    throw GuardError("end-point guard: the counters reached 0 at " + pt(dp.pos()) +
                     " instead of " + pt(sg.to));
  }
  return RunSummary{dp.iterations(), dp.pos(), dp.regs()};
}

RunSummary run_impl(const Plan& plan, const std::function<void(const Iteration&)>* on_iter,
                    bool for_validation) {
  RunSummary total;
  for (std::size_t k = 0; k < plan.segs.size(); ++k) {
    const RunSummary r = run_segment(plan, k, total.iterations, on_iter, for_validation);
    total.iterations += r.iterations;
    total.end = r.end;
    total.final_regs = r.final_regs;
  }
  return total;
}

// Quadrant signs (su, sv) of the four quadrants about the centre.
constexpr int kSu[5] = {0, +1, -1, -1, +1};
constexpr int kSv[5] = {0, +1, +1, -1, -1};

// The quadrant a piece starting at relative point (u, v) runs in.
int start_quadrant(std::int64_t u, std::int64_t v, Direction dir) {
  const bool ccw = dir == Direction::Ccw;
  if (v == 0) return u > 0 ? (ccw ? 1 : 4) : (ccw ? 3 : 2);  // on the u axis
  if (u == 0) return v > 0 ? (ccw ? 2 : 1) : (ccw ? 4 : 3);  // on the v axis
  if (u > 0) return v > 0 ? 1 : 4;
  return v > 0 ? 2 : 3;
}

// Step directions in quadrant q: counter-clockwise, du has the sign of -v and dv of u.
int step_sx(int q, Direction dir) { return dir == Direction::Ccw ? -kSv[q] : kSv[q]; }
int step_sy(int q, Direction dir) { return dir == Direction::Ccw ? kSu[q] : -kSu[q]; }

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

// A resolved start or end point: lattice point and the fraction of the ideal point.
struct EndPoint {
  Point lattice;
  std::int64_t fx = 0, fy = 0;  // Q(kPosFrac); non-zero only for half preload and theta
};

// Preload of an axis so that the represented position, lattice + s (jr / cap - 1/2),
// is lattice + frac / 2^kPosFrac (half preload; |frac| <= 1/2).
std::int64_t fraction_preload(std::int64_t cap, bool dir_neg, std::int64_t frac) {
  const __int128 s_frac = dir_neg ? -__int128(frac) : __int128(frac);
  const __int128 jr = (__int128(cap) * ((__int128(1) << (kPosFrac - 1)) + s_frac)) >> kPosFrac;
  return std::int64_t(std::clamp<__int128>(jr, 0, cap - 1));
}

// An end given as a parametric angle: the arc ends where the path first crosses the
// ray from the centre through that angle's ideal point `e` (relative, Q(kPosFrac)),
// moving in direction D; a full turn must pass the far side (the half-plane behind the
// centre) first. Whether the ray is still ahead at the start is decided from the
// represented start (the ideal point of a parametric start, which the lattice point can
// lie on the other side of). crossed() is called with every position after the start.
struct RayEnd {
  FixedPoint e;
  int D = 1;
  bool far_seen = true;
  bool armed = false;
  Point last;  // the position last looked at (relative); starts at the lattice start
  RayEnd(FixedPoint end, Direction dir, bool full, FixedPoint start, Point lattice_start)
      : e(end), D(dir == Direction::Ccw ? 1 : -1), last(lattice_start) {
    // side < 0: the end lies less than half a turn ahead, so the path may end as soon as
    // it crosses the ray; otherwise (and for a full turn) it must pass the far side first.
    armed = far_seen = !full && side(start.x, start.y) < 0;
  }
  __int128 side(__int128 x, __int128 y) const { return D * (e.x * y - e.y * x); }
  bool ahead(Point q) const { return __int128(e.x) * q.x + __int128(e.y) * q.y > 0; }
  // Only a step can cross the ray: an iteration without one leaves the verdict as it was.
  bool crossed(Point q) {
    if (q == last) return false;
    last = q;
    if (armed && side(q.x, q.y) >= 0 && ahead(q)) return true;
    far_seen = far_seen || !ahead(q);
    armed = far_seen && side(q.x, q.y) < 0;
    return false;
  }
};

// Quarter turns: cut the arc into monotone pieces at the vertices (lattice points on
// the curve; docs/golden-model.md, "Pieces"), each preloaded again.
void plan_quadrant_pieces(Plan& p, std::int64_t cap, const EndPoint& from, std::optional<RayEnd> ray) {
  const ArcSpec& spec = p.spec;
  const std::int64_t ax = p.ax, by = p.by, ax2 = ax * ax, by2 = by * by;
  const Point c = spec.center;
  const auto rel = [&](Point q) { return Point{q.x - c.x, q.y - c.y}; };
  const Point rt = rel(p.to);
  Point cur = rel(p.from);
  if (cur == Point{0, 0}) {
    throw InputError("from point " + pt(p.from) + " is the centre of the ellipse: the tangent is 0 there");
  }
  int q = start_quadrant(cur.x, cur.y, spec.dir);
  int empty_pieces = 0;
  for (int guard = 0;; ++guard) {
    if (guard > 5) {
      throw InputError("the DDA cannot reach the end from " + pt(p.from) +
                       ": its path passed six pieces without crossing the end (the start lies far inside the curve?)");
    }
    bool last = !ray && !(p.full && guard == 0) && in_piece(q, spec.dir, cur, rt);
    Point end = last ? rt : end_vertex(q, spec.dir, ax, by);
    if (!last && !in_piece(q, spec.dir, cur, end)) {
      throw InputError("from point " + pt(p.from) + " lies beyond the vertex " +
                       pt(Point{c.x + end.x, c.y + end.y}) + " it runs to (" + to_string(spec.dir) +
                       "): a point next to a vertex must lie before it");
    }
    Segment sg;
    sg.quadrant = q;
    sg.from = Point{c.x + cur.x, c.y + cur.y};
    sg.to = Point{c.x + end.x, c.y + end.y};
    const int sx = step_sx(q, spec.dir), sy = step_sy(q, spec.dir);
    Command& cm = sg.cmd;
    cm.cap = cap;
    // Integrands are magnitudes: |dx| ~ ax^2 |v| and |dy| ~ by^2 |u| (scaled by a*b).
    cm.jv_x = ax2 * std::llabs(cur.y);
    cm.jv_y = by2 * std::llabs(cur.x);
    cm.jr_x = cm.jr_y = spec.preload == Preload::Half ? cap / 2 : 0;
    if (p.segs.empty() && spec.preload == Preload::Half) {  // the start's fraction
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
    // The integrands are largest where |v| and |u| are: at one end of the piece. Each
    // must not exceed cap, or an accumulator could carry twice in one iteration.
    const std::int64_t jvx_max = ax2 * std::max(std::llabs(cur.y), std::llabs(end.y));
    const std::int64_t jvy_max = by2 * std::max(std::llabs(cur.x), std::llabs(end.x));
    if (jvx_max > cm.cap || jvy_max > cm.cap) {
      const bool xside = jvx_max > cm.cap;
      std::ostringstream m;
      m << "bits = " << spec.bits << " is too small for this arc: the "
        << (xside ? "X integrand (ax/by)*|y-yc|" : "Y integrand (by/ax)*|x-xc|") << " exceeds 2^n between "
        << pt(sg.from) << " and " << pt(sg.to) << " (use more bits)";
      throw InputError(m.str());
    }
    // Iteration bound (docs/golden-model.md): an active axis whose integrand is not 0
    // carries at least every K iterations; an axis starting with a zero integrand waits
    // at most one K of the other axis.
    const std::int64_t kx = ceil_div(cm.cap, ax2), ky = ceil_div(cm.cap, by2);
    const auto tx = checked_mul(cm.cnt_x, kx);
    const auto ty = checked_mul(cm.cnt_y, ky);
    if (!tx || !ty || *tx > (std::int64_t{1} << 60) || *ty > (std::int64_t{1} << 60)) {
      throw InputError("iteration bound overflows 64 bits for this arc: reduce bits");
    }
    const std::int64_t tx_total = *tx + ((cur.y == 0 && cm.cnt_x > 0) ? ky : 0);
    const std::int64_t ty_total = *ty + ((cur.x == 0 && cm.cnt_y > 0) ? kx : 0);
    sg.iteration_bound = static_cast<std::uint64_t>(std::max(tx_total, ty_total));
    if (!last) {
      // Walk the piece to its vertex: a parametric end cuts it where the path crosses
      // the ray; a tip sharper than the lattice (the path reaches the vertex's axis,
      // where one integrand is 0, with steps still owed on that axis) ends it where it
      // stalls, and the next piece goes on from there.
      Datapath dp(cm, sg.from);
      const auto cut_here = [&] {
        end = Point{dp.pos().x - c.x, dp.pos().y - c.y};
        sg.to = dp.pos();
        cm.cnt_x = std::llabs(end.x - cur.x);
        cm.cnt_y = std::llabs(end.y - cur.y);
      };
      while (!dp.done() && dp.iterations() < sg.iteration_bound) {
        if (dp.stalled()) {
          // With a lattice end the skipped stretch could hold it: refuse, as rule 6 says.
          if (!ray) break;  // the validation run names the stall
          cut_here();
          break;
        }
        dp.step();
        if (ray && ray->crossed(Point{dp.pos().x - c.x, dp.pos().y - c.y})) {
          last = true;
          cut_here();
          break;
        }
      }
    }
    if (!last && cm.cnt_x == 0 && cm.cnt_y == 0) {  // stalled on its first iteration: no piece
      q = next_quadrant(q, spec.dir);
      if (++empty_pieces > 4) throw InputError("the DDA cannot leave " + pt(Point{c.x + cur.x, c.y + cur.y}) + ": it stalls in every direction");
      continue;
    }
    p.iteration_bound += sg.iteration_bound;
    p.segs.push_back(sg);
    if (last) break;
    cur = end;
    q = next_quadrant(q, spec.dir);
  }
}

}  // namespace

int quarter_turns(const ArcSpec& spec) {
  const std::int64_t t = normalize_udeg(spec.angle);
  return t % kQuarterTurn == 0 ? static_cast<int>(t / kQuarterTurn) : -1;
}

namespace {

using i128 = __int128;

// v / 2^sh rounded to nearest, halves away from zero.
i128 round_shift(i128 v, int sh) {
  const i128 half = i128(1) << (sh - 1);
  return v < 0 ? -((-v + half) >> sh) : (v + half) >> sh;
}
// num / den rounded to nearest, halves away from zero (den > 0).
i128 round_div(i128 num, i128 den) {
  return num < 0 ? -((-num + den / 2) / den) : (num + den / 2) / den;
}

void check_axes_and_center(const ArcSpec& spec) {
  const std::int64_t a = spec.a, b = spec.b;
  if (a < 1) throw InputError("a = " + std::to_string(a) + " is invalid: a semi-axis must be a positive integer");
  if (b < 1) throw InputError("b = " + std::to_string(b) + " is invalid: a semi-axis must be a positive integer");
  const bool rotated = quarter_turns(spec) < 0;
  const std::int64_t lim = std::int64_t{1} << (rotated ? 20 : 30);
  if (a > lim || b > lim) {
    throw InputError((a > lim ? "a = " + std::to_string(a) : "b = " + std::to_string(b)) +
                     " is out of range: semi-axes must be at most 2^" + (rotated ? "20 for a rotated ellipse" : "30"));
  }
  const std::int64_t coord_lim = std::int64_t{1} << 40;
  if (std::llabs(spec.center.x) > coord_lim || std::llabs(spec.center.y) > coord_lim) {
    throw InputError("center " + pt(spec.center) + " is out of range: coordinates must be within 2^40");
  }
}

// The ellipse's quadratic form on lattice points relative to the centre, and its value
// on the nominal curve: Q(x, y) = qy x^2 - 2 p x y + qx y^2, Q = level on the curve.
i128 quad_form(const Coefficients& k, std::int64_t x, std::int64_t y) {
  return i128(k.qy) * x * x - 2 * i128(k.p) * x * y + i128(k.qx) * y * y;
}

}  // namespace

FixedPoint theta_ideal(const ArcSpec& spec, std::int64_t theta) {
  check_axes_and_center(spec);
  const SinCos t = sincos_udeg(theta);
  // Frame point (a cos, b sin) in Q(kTrigFrac).
  const i128 u = i128(spec.a) * t.c, v = i128(spec.b) * t.s;
  const int qt = quarter_turns(spec);
  if (qt >= 0) {  // exact quarter turns
    i128 x = u, y = v;
    for (int k = 0; k < qt; ++k) std::tie(x, y) = std::pair<i128, i128>{-y, x};
    return FixedPoint{std::int64_t(round_shift(x, kTrigFrac - kPosFrac)),
                      std::int64_t(round_shift(y, kTrigFrac - kPosFrac))};
  }
  const SinCos f = sincos_udeg(spec.angle);
  const i128 x = u * f.c - v * f.s, y = u * f.s + v * f.c;  // Q(2 kTrigFrac)
  return FixedPoint{std::int64_t(round_shift(x, 2 * kTrigFrac - kPosFrac)),
                    std::int64_t(round_shift(y, 2 * kTrigFrac - kPosFrac))};
}

namespace {

// The coefficients of a turned ellipse for width n (see Coefficients), exact for
// quarter turns; the capacity goes with them.
struct Scaled {
  Coefficients k;
  std::int64_t cap = 0;
  i128 level = 0;  // quad_form on the nominal curve: a^2 b^2 (exact) or a b 2^(K-n)
};

Scaled scaled_coefficients(const ArcSpec& spec, int n) {
  Scaled r;
  const std::int64_t a = spec.a, b = spec.b;
  const int qt = quarter_turns(spec);
  if (qt >= 0) {
    const std::int64_t ax = qt % 2 ? b : a, by = qt % 2 ? a : b;
    r.k = Coefficients{0, ax * ax, by * by};
    const __int128 cap = __int128(a) * b << n;  // plan_arc refuses capacities from 2^61 up
    r.cap = cap < (__int128(1) << 62) ? std::int64_t(cap) : 0;
    r.level = i128(a) * a * b * b;
    return r;
  }
  // Tangent of the counter-clockwise turn times a b: (P x - Qx y, Qy x - P y) with
  // P = cs (a^2 - b^2), Qx = a^2 c^2 + b^2 s^2, Qy = a^2 s^2 + b^2 c^2; scaled by
  // 2^K / (a b 2^n) so that the capacity is 2^K, K = kRotCapBits, and rounded to
  // nearest. c, s are Q(kTrigFrac), so the products are Q(2 kTrigFrac).
  const SinCos f = sincos_udeg(spec.angle);
  const i128 a2 = i128(a) * a, b2 = i128(b) * b, cc = i128(f.c) * f.c, ss = i128(f.s) * f.s,
             cs = i128(f.c) * f.s;
  const int sh = 2 * kTrigFrac - (kRotCapBits - n);  // n >= 1 keeps it >= 32
  const i128 den = (i128(a) * b) << sh;
  r.k.p = std::int64_t(round_div(cs * (a2 - b2), den));
  r.k.qx = std::int64_t(round_div(a2 * cc + b2 * ss, den));
  r.k.qy = std::int64_t(round_div(a2 * ss + b2 * cc, den));
  r.cap = std::int64_t{1} << kRotCapBits;
  r.level = (i128(a) * b) << (kRotCapBits - n);
  return r;
}

}  // namespace

Point theta_point(const ArcSpec& spec, std::int64_t theta) {
  const FixedPoint f = theta_ideal(spec, theta);
  const Point c = spec.center;
  if (spec.preload == Preload::Half) {
    const auto nearest = [](std::int64_t v) { return std::int64_t(round_shift(v, kPosFrac)); };
    return Point{c.x + nearest(f.x), c.y + nearest(f.y)};
  }
  const int n = spec.bits != 0 ? spec.bits : default_bits(spec.a, spec.b);
  const Scaled sc = scaled_coefficients(spec, std::clamp(n, 1, kRotCapBits));
  const std::int64_t fx = f.x >> kPosFrac, fy = f.y >> kPosFrac;  // floors
  const std::int64_t mask = (std::int64_t{1} << kPosFrac) - 1;
  const std::int64_t cx = fx + ((f.x & mask) != 0), cy = fy + ((f.y & mask) != 0);
  Point best{fx, fy}, outermost{fx, fy};
  i128 best_q = -1, out_q = -1;
  for (const std::int64_t x : {fx, cx}) {
    for (const std::int64_t y : {fy, cy}) {
      const i128 q = quad_form(sc.k, x, y);
      if (q > out_q) {
        out_q = q;
        outermost = Point{x, y};
      }
      if (q < sc.level) continue;  // inside the ellipse
      if (best_q < 0 || q < best_q) {
        best_q = q;
        best = Point{x, y};
      }
    }
  }
  // (Rounded coefficients of a rotated ellipse can leave all four just inside: then the
  // outermost of them.)
  if (best_q < 0) best = outermost;
  return Point{c.x + best.x, c.y + best.y};
}

namespace {

// Turns the relative point by -angle into the ellipse's frame (measurement only).
std::pair<double, double> to_frame(const ArcSpec& spec, double x, double y) {
  const SinCos f = sincos_udeg(spec.angle);
  const double c = std::ldexp(double(f.c), -kTrigFrac), s = std::ldexp(double(f.s), -kTrigFrac);
  return {x * c + y * s, -x * s + y * c};
}


EndPoint resolve_point(const ArcSpec& spec, const std::optional<Point>& pnt,
                       const std::optional<std::int64_t>& theta, std::int64_t default_theta,
                       const std::optional<Point>& default_pnt) {
  if (pnt) return EndPoint{*pnt};
  if (!theta && default_pnt) return EndPoint{*default_pnt};
  const std::int64_t t = theta.value_or(default_theta);
  EndPoint e{theta_point(spec, t)};
  if (spec.preload == Preload::Half) {
    const FixedPoint f = theta_ideal(spec, t);
    e.fx = f.x - ((e.lattice.x - spec.center.x) << kPosFrac);
    e.fy = f.y - ((e.lattice.y - spec.center.y) << kPosFrac);
  }
  return e;
}


// The quadrant (about the centre) whose steps, for direction dir, have signs (sx, sy).
int quadrant_of_steps(int sx, int sy, Direction dir) {
  for (int q = 1; q <= 4; ++q) {
    if (step_sx(q, dir) == sx && step_sy(q, dir) == sy) return q;
  }
  return 1;
}

int sign(i128 v) { return (v > 0) - (v < 0); }

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
void plan_rotated_pieces(Plan& p, const Scaled& sc, const EndPoint& from, std::optional<RayEnd> ray) {
  const ArcSpec& spec = p.spec;
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
  // Guard: a piece has at most 4 max(a, b) + 8 steps, and between two steps at most
  // 2^(n+2) / min(a, b) + 4 iterations (the larger integrand is at least about half the
  // tangent's length, which is at least a b min(a, b) times the scale).
  const std::uint64_t guard = std::uint64_t(4 * mx + 8) * (std::uint64_t(ceil_div(std::int64_t{1} << (spec.bits + 2), mn)) + 4);
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
        throw InputError("the DDA cannot follow this rotated ellipse: a piece from " + pt(Point{c.x + cur.x, c.y + cur.y}) + " passed " +
                         std::to_string(guard) + " iterations (a " + std::to_string(spec.a) + ", b " +
                         std::to_string(spec.b) + ", angle " + format_degrees(spec.angle) + ", bits " +
                         std::to_string(spec.bits) + ") without turning");
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
    const bool last = ray ? ray_end
                          : !(p.full && first) && between(cur.x, rt.x, cut.x, sx) && between(cur.y, rt.y, cut.y, sy);
    const Point end = last && !ray ? rt : cut;
    cm.cnt_x = std::llabs(end.x - cur.x);
    cm.cnt_y = std::llabs(end.y - cur.y);
    if (last || cm.cnt_x != 0 || cm.cnt_y != 0) {  // a turn without a step adds no piece
      Segment sg;
      sg.quadrant = quadrant_of_steps(sx, sy, spec.dir);
      sg.from = Point{c.x + cur.x, c.y + cur.y};
      sg.to = Point{c.x + end.x, c.y + end.y};
      sg.cmd = cm;
      sg.iteration_bound = guard;
      p.iteration_bound += guard;
      p.segs.push_back(sg);
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

}  // namespace

Plan plan_arc(const ArcSpec& spec_in) {
  Plan p;
  p.spec = spec_in;
  ArcSpec& spec = p.spec;
  spec.angle = normalize_udeg(spec.angle);
  check_axes_and_center(spec);
  const std::int64_t a = spec.a, b = spec.b;
  const int qt = quarter_turns(spec);
  p.rotated = qt < 0;
  const int nmin = smallest_valid_bits(a, b);
  if (spec.bits == 0) spec.bits = default_bits(a, b);
  if (spec.bits < 1 || spec.bits > 61 || (std::int64_t{1} << spec.bits) < std::max(a, b)) {
    throw InputError("bits = " + std::to_string(spec.bits) +
                     " is invalid: n must satisfy 2^n >= max(a, b) (smallest valid n here is " +
                     std::to_string(nmin) + ")");
  }
  if (spec.bits > nmin + kMaxExtraBits) {
    throw InputError("bits = " + std::to_string(spec.bits) + " is invalid: at most " +
                     std::to_string(kMaxExtraBits) + " bits above the smallest valid width (" +
                     std::to_string(nmin) + ") are accepted; each bit doubles the run");
  }
  const std::int64_t ab = a * b;
  if (!p.rotated) {
    const auto cap = checked_mul(ab, std::int64_t{1} << spec.bits);
    if (!cap || *cap >= kCapLimit) {
      throw InputError("capacity 2^" + std::to_string(spec.bits) + " * a * b = 2^" +
                       std::to_string(spec.bits) + " * " + std::to_string(a) + " * " +
                       std::to_string(b) + " is out of range: it must be below 2^61");
    }
  } else if (4 * __int128(std::min(a, b)) * std::min(a, b) <= std::max(a, b)) {
    std::ostringstream m;
    m.precision(3);
    m << "a = " << a << ", b = " << b << " is too thin to turn by " << format_degrees(spec.angle)
      << " degrees: the radius of curvature at the tips, min(a,b)^2 / max(a,b) = "
      << double(std::min(a, b)) * double(std::min(a, b)) / double(std::max(a, b))
      << " steps, must exceed 1/4 step for a rotated ellipse (the lattice path cannot follow a sharper tip)";
    throw InputError(m.str());
  } else if (coefficient_drift_bound(p) > kMaxCoefficientDrift || spec.bits > kRotCapBits) {
    std::ostringstream m;
    m << "bits = " << spec.bits << " is too large for this rotated ellipse: its fixed-point coefficients "
      << "could move the curve by " << coefficient_drift_bound(p) << " steps (at most " << kMaxCoefficientDrift
      << " allowed: max(a,b)^2 2^n / (2^" << kRotCapBits << " min(a,b)); use fewer bits)";
    throw InputError(m.str());
  }
  p.scale = ab;
  const Scaled sc = scaled_coefficients(spec, spec.bits);
  p.coef = sc.k;
  p.ax = qt >= 0 && qt % 2 ? b : a;
  p.by = qt >= 0 && qt % 2 ? a : b;
  if (spec.from && spec.from_theta) throw InputError("from and from-theta are both given: choose one");
  if (spec.to && spec.to_theta) throw InputError("to and to-theta are both given: choose one");
  const Point c = spec.center;
  // Defaults: the quadrant-I quarter arc (quarter turns), parametric 0 to 90 (rotated).
  const auto dflt = [&](Point q) { return p.rotated ? std::optional<Point>{} : std::optional<Point>{q}; };
  const EndPoint from = resolve_point(spec, spec.from, spec.from_theta, 0, dflt(Point{c.x + p.ax, c.y}));
  const EndPoint to = resolve_point(spec, spec.to, spec.to_theta, kQuarterTurn, dflt(Point{c.x, c.y + p.by}));
  p.from = from.lattice;
  p.to = to.lattice;
  p.frac_x = from.fx;
  p.frac_y = from.fy;

  const double tol = kPointTolerance + 1e-9 * static_cast<double>(std::max(a, b));
  for (const auto& [name, q] : {std::pair{"from", p.from}, std::pair{"to", p.to}}) {
    if (spec.to_theta && std::string(name) == "to") continue;  // found by the walk
    const Point r{q.x - c.x, q.y - c.y};
    const std::int64_t reach = 2 * std::max(a, b) + 2;
    if (std::llabs(r.x) > reach || std::llabs(r.y) > reach) {
      throw InputError(std::string(name) + " point " + pt(q) +
                       " is far from the ellipse: start and end must lie within 1 step of it");
    }
    const double d = plan_distance(p, double(q.x), double(q.y));
    if (d > tol) {
      std::ostringstream m;
      m.precision(4);
      m << std::fixed << name << " point " << pt(q) << " is " << d
        << " steps from the ellipse: start and end must lie within " << kPointTolerance
        << " step of it";
      throw InputError(m.str());
    }
  }
  // A full turn: equal lattice ends, or equal parametric angles (a parametric end is
  // found by the walk, so its lattice point is not known yet).
  p.full = spec.to_theta ? spec.from_theta && normalize_udeg(*spec.from_theta) == normalize_udeg(*spec.to_theta)
                         : p.from == p.to;
  std::optional<RayEnd> ray;
  if (spec.to_theta) {
    const FixedPoint start{((p.from.x - c.x) << kPosFrac) + from.fx, ((p.from.y - c.y) << kPosFrac) + from.fy};
    ray.emplace(theta_ideal(spec, *spec.to_theta), spec.dir, p.full,
                spec.from_theta ? theta_ideal(spec, *spec.from_theta) : start, Point{p.from.x - c.x, p.from.y - c.y});
  }
  if (p.rotated) {
    plan_rotated_pieces(p, sc, from, ray);
  } else {
    plan_quadrant_pieces(p, sc.cap, from, ray);
  }

  if (ray) p.to = p.segs.back().to;
  // Reachability: the exact model decides whether every piece ends (no stall).
  run_impl(p, nullptr, /*for_validation=*/true);
  return p;
}

RunSummary run(const Plan& plan, const std::function<void(const Iteration&)>& on_iter) {
  return run_impl(plan, &on_iter, false);
}

std::vector<Iteration> run_records(const Plan& plan) {
  std::vector<Iteration> v;
  run(plan, [&](const Iteration& it) { v.push_back(it); });
  return v;
}

double plan_distance(const Plan& plan, double x, double y) {
  const double rx = x - double(plan.spec.center.x), ry = y - double(plan.spec.center.y);
  if (!plan.rotated) return ellipse_distance(double(plan.ax), double(plan.by), rx, ry);
  const auto [u, v] = to_frame(plan.spec, rx, ry);
  return ellipse_distance(double(plan.spec.a), double(plan.spec.b), u, v);
}

double start_offset(const Plan& plan) {
  const double fx = std::ldexp(double(plan.frac_x), -kPosFrac), fy = std::ldexp(double(plan.frac_y), -kPosFrac);
  double u = double(plan.from.x - plan.spec.center.x) + fx, v = double(plan.from.y - plan.spec.center.y) + fy;
  double a = double(plan.ax), b = double(plan.by);
  if (plan.rotated) {
    std::tie(u, v) = to_frame(plan.spec, u, v);
    a = double(plan.spec.a);
    b = double(plan.spec.b);
  }
  return std::fabs(std::hypot(u / a, v / b) - 1.0) * std::max(a, b);
}

double coefficient_drift_bound(const Plan& plan) {
  if (quarter_turns(plan.spec) >= 0) return 0.0;
  const double mx = double(std::max(plan.spec.a, plan.spec.b)), mn = double(std::min(plan.spec.a, plan.spec.b));
  return std::ldexp(mx * mx / mn, plan.spec.bits - kRotCapBits);
}

double deviation_bound(const Plan& plan) {
  const double m = double(std::max(plan.spec.a, plan.spec.b));
  if (plan.rotated) {
    // Measured (build/tb/deviation_survey): half preload at the default width or more
    // and aspect ratio <= 4 stays within 1 step; elsewhere no bound is documented.
    const bool covered = plan.spec.preload == Preload::Half &&
                         plan.spec.bits >= smallest_valid_bits(plan.spec.a, plan.spec.b) + 4 &&
                         m <= 4.0 * double(std::min(plan.spec.a, plan.spec.b));
    if (!covered) return std::numeric_limits<double>::infinity();
  }
  const double drift = plan.spec.preload == Preload::Zero ? 2.0 + std::cbrt(m) / 2.0 : 1.5;
  return start_offset(plan) + drift + coefficient_drift_bound(plan);
}

// ---------------------------------------------------------------------------------
// Distance from a point to an ellipse: D. Eberly, "Distance from a Point to an Ellipse,
// an Ellipsoid, or a Hyperellipsoid" (Geometric Tools, 2013). The closest point's
// Lagrange parameter s is the unique root of F(s) = (r0 z0/(s+r0))^2 + (z1/(s+1))^2 - 1
// in a bracket where F is monotone; bisection runs until the bracket cannot shrink.
namespace {

double robust_length(double v0, double v1) { return std::hypot(v0, v1); }

double get_root(double r0, double z0, double z1, double g) {
  const double n0 = r0 * z0;
  double s0 = z1 - 1.0;
  double s1 = g < 0 ? 0.0 : robust_length(n0, z1) - 1.0;
  double s = 0;
  for (int i = 0; i < 2200; ++i) {
    s = 0.5 * (s0 + s1);
    if (s == s0 || s == s1) break;
    const double ratio0 = n0 / (s + r0), ratio1 = z1 / (s + 1.0);
    const double gs = ratio0 * ratio0 + ratio1 * ratio1 - 1.0;
    if (gs > 0) {
      s0 = s;
    } else if (gs < 0) {
      s1 = s;
    } else {
      break;
    }
  }
  return s;
}

// e0 >= e1 > 0, y0, y1 >= 0.
double distance_sorted(double e0, double e1, double y0, double y1) {
  if (y1 > 0) {
    if (y0 > 0) {
      const double z0 = y0 / e0, z1 = y1 / e1;
      const double g = z0 * z0 + z1 * z1 - 1.0;
      if (g == 0) return 0.0;
      const double r0 = (e0 / e1) * (e0 / e1);
      const double sbar = get_root(r0, z0, z1, g);
      const double x0 = r0 * y0 / (sbar + r0), x1 = y1 / (sbar + 1.0);
      return std::hypot(x0 - y0, x1 - y1);
    }
    return std::fabs(y1 - e1);
  }
  const double numer0 = e0 * y0, denom0 = e0 * e0 - e1 * e1;
  if (numer0 < denom0) {
    const double xde0 = numer0 / denom0;
    const double x0 = e0 * xde0, x1 = e1 * std::sqrt(1.0 - xde0 * xde0);
    return std::hypot(x0 - y0, x1);
  }
  return std::fabs(y0 - e0);
}

}  // namespace

double ellipse_distance(double a, double b, double px, double py) {
  px = std::fabs(px);
  py = std::fabs(py);
  return a >= b ? distance_sorted(a, b, px, py) : distance_sorted(b, a, py, px);
}

}  // namespace dda
