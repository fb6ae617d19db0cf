// Golden reference model: datapath iteration, arc planning and validation.
#include "dda/golden.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

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
  it.sum_x = it.active_x ? regs_.jr_x + regs_.jv_x : regs_.jr_x;
  it.sum_y = it.active_y ? regs_.jr_y + regs_.jv_y : regs_.jr_y;
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
  const std::int64_t sx = ax ? regs_.jr_x + regs_.jv_x : regs_.jr_x;
  const std::int64_t sy = ay ? regs_.jr_y + regs_.jv_y : regs_.jr_y;
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

}  // namespace

Point theta_point(const ArcSpec& spec, double theta_deg) {
  const std::int64_t lim = std::int64_t{1} << 30, coord_lim = std::int64_t{1} << 40;
  if (spec.a < 1 || spec.b < 1 || spec.a > lim || spec.b > lim) {
    throw InputError("a = " + std::to_string(spec.a) + ", b = " + std::to_string(spec.b) +
                     " is invalid: semi-axes must be positive integers up to 2^30");
  }
  if (std::llabs(spec.center.x) > coord_lim || std::llabs(spec.center.y) > coord_lim) {
    throw InputError("center " + pt(spec.center) + " is out of range: coordinates must be within 2^40");
  }
  if (!std::isfinite(theta_deg)) throw InputError("theta is invalid: a finite angle in degrees");
  const double m = std::fmod(theta_deg, 360.0);
  const double t = m < 0 ? m + 360.0 : m;
  double c = 0, s = 0;
  if (t == 0.0) {
    c = 1;
  } else if (t == 90.0) {
    s = 1;
  } else if (t == 180.0) {
    c = -1;
  } else if (t == 270.0) {
    s = -1;
  } else {
    const double rad = t * (std::acos(-1.0) / 180.0);
    c = std::cos(rad);
    s = std::sin(rad);
  }
  // Of the four lattice points around the curve point (in the ellipse's own frame), the
  // one on or outside the curve whose ellipse through it, r times the nominal one, is the
  // smallest (least r >= 1): a start inside the curve makes the DDA follow a smaller
  // ellipse, which can stall at a vertex, and the DDA's offset from the nominal curve
  // grows with r - 1. r^2 a^2 b^2 = u^2 b^2 + v^2 a^2 is compared exactly. Turning comes
  // after: a quarter turn maps the lattice onto itself.
  const double fu = double(spec.a) * c, fv = double(spec.b) * s;
  const __int128 a2 = __int128(spec.a) * spec.a, b2 = __int128(spec.b) * spec.b;
  Point r{std::llround(fu), std::llround(fv)};
  __int128 best = -1;
  for (const double cu : {std::floor(fu), std::ceil(fu)}) {
    for (const double cv : {std::floor(fv), std::ceil(fv)}) {
      const std::int64_t u = std::int64_t(cu), v = std::int64_t(cv);
      const __int128 r2 = __int128(u) * u * b2 + __int128(v) * v * a2;  // r^2 a^2 b^2
      if (r2 < a2 * b2) continue;  // inside the ellipse
      if (best < 0 || r2 < best) {
        best = r2;
        r = Point{u, v};
      }
    }
  }
  for (int k = 0; k < ((spec.quarter_turns % 4) + 4) % 4; ++k) r = Point{-r.y, r.x};
  return Point{spec.center.x + r.x, spec.center.y + r.y};
}

Plan plan_arc(const ArcSpec& spec_in) {
  Plan p;
  p.spec = spec_in;
  ArcSpec& spec = p.spec;
  const std::int64_t a = spec.a, b = spec.b;
  if (a < 1) throw InputError("a = " + std::to_string(a) + " is invalid: a semi-axis must be a positive integer");
  if (b < 1) throw InputError("b = " + std::to_string(b) + " is invalid: a semi-axis must be a positive integer");
  const std::int64_t lim = std::int64_t{1} << 30;
  if (a > lim || b > lim) {
    throw InputError((a > lim ? "a = " + std::to_string(a) : "b = " + std::to_string(b)) +
                     " is out of range: semi-axes must be at most 2^30");
  }
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
  const auto cap = checked_mul(ab, std::int64_t{1} << spec.bits);
  if (!cap || *cap >= kCapLimit) {
    throw InputError("capacity 2^" + std::to_string(spec.bits) + " * a * b = 2^" +
                     std::to_string(spec.bits) + " * " + std::to_string(a) + " * " +
                     std::to_string(b) + " is out of range: it must be below 2^61");
  }
  const std::int64_t coord_lim = std::int64_t{1} << 40;
  if (std::llabs(spec.center.x) > coord_lim || std::llabs(spec.center.y) > coord_lim) {
    throw InputError("center " + pt(spec.center) + " is out of range: coordinates must be within 2^40");
  }
  p.scale = ab;
  if (spec.quarter_turns < 0 || spec.quarter_turns > 3) {
    throw InputError("quarter_turns = " + std::to_string(spec.quarter_turns) + " is invalid: use 0 to 3");
  }
  // A quarter turn swaps the semi-axes along X and Y: from here on the ellipse is the
  // axis-aligned one with semi-axes ax (along X) and by (along Y).
  p.ax = spec.quarter_turns % 2 ? b : a;
  p.by = spec.quarter_turns % 2 ? a : b;
  const std::int64_t ax = p.ax, by = p.by, ax2 = ax * ax, by2 = by * by;
  const Point c = spec.center;
  p.from = spec.from.value_or(Point{c.x + ax, c.y});
  p.to = spec.to.value_or(Point{c.x, c.y + by});
  const auto rel = [&](Point q) { return Point{q.x - c.x, q.y - c.y}; };

  const double tol = kPointTolerance + 1e-9 * static_cast<double>(std::max(a, b));
  for (const auto& [name, q] : {std::pair{"from", p.from}, std::pair{"to", p.to}}) {
    const Point r = rel(q);
    if (std::llabs(r.x) > 2 * ax + 2 || std::llabs(r.y) > 2 * by + 2) {
      throw InputError(std::string(name) + " point " + pt(q) +
                       " is far from the ellipse: start and end must lie within 1 step of it");
    }
    const double d = ellipse_distance(double(ax), double(by), double(r.x), double(r.y));
    if (d > tol) {
      std::ostringstream m;
      m.precision(4);
      m << std::fixed << name << " point " << pt(q) << " is " << d
        << " steps from the ellipse: start and end must lie within " << kPointTolerance
        << " step of it";
      throw InputError(m.str());
    }
  }
  p.full = p.from == p.to;

  // Cut the arc into monotone pieces at the vertices (docs/golden-model.md, "Pieces").
  const Point rt = rel(p.to);
  Point cur = rel(p.from);
  int q = start_quadrant(cur.x, cur.y, spec.dir);
  for (int guard = 0;; ++guard) {
    if (guard > 5) throw GuardError("planner guard: more than 6 pieces");
    const bool last = !(p.full && guard == 0) && in_piece(q, spec.dir, cur, rt);
    const Point end = last ? rt : end_vertex(q, spec.dir, ax, by);
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
    cm.cap = *cap;
    // Integrands are magnitudes: |dx| ~ ax^2 |v| and |dy| ~ by^2 |u| (scaled by a*b).
    cm.jv_x = ax2 * std::llabs(cur.y);
    cm.jv_y = by2 * std::llabs(cur.x);
    cm.jr_x = cm.jr_y = spec.preload == Preload::Half ? *cap / 2 : 0;
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
    p.iteration_bound += sg.iteration_bound;
    p.segs.push_back(sg);
    if (last) break;
    cur = end;
    q = next_quadrant(q, spec.dir);
  }

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

double start_offset(const Plan& plan) {
  const double a = double(plan.ax), b = double(plan.by);
  const double u0 = double(plan.from.x - plan.spec.center.x) / a;
  const double v0 = double(plan.from.y - plan.spec.center.y) / b;
  return std::fabs(std::sqrt(u0 * u0 + v0 * v0) - 1.0) * std::max(a, b);
}

double deviation_bound(const Plan& plan) {
  const double m = double(std::max(plan.ax, plan.by));
  const double drift = plan.spec.preload == Preload::Zero ? 2.0 + std::cbrt(m) / 2.0 : 1.5;
  return start_offset(plan) + drift;
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
