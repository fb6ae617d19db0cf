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

Datapath::Datapath(const Command& cmd, Point start) : cmd_(cmd), pos_(start) {
  regs_.jv_x = cmd.jv_x;
  regs_.jv_y = cmd.jv_y;
  regs_.jr_x = cmd.jr_x;
  regs_.jr_y = cmd.jr_y;
  regs_.cnt_x = cmd.cnt_x;
  regs_.cnt_y = cmd.cnt_y;
}

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

int smallest_valid_bits(std::int64_t a, std::int64_t b) {
  const std::int64_t m = std::max(a, b);
  int n = 1;
  while (n < 62 && (std::int64_t{1} << n) < m) ++n;
  return n;
}

namespace {

RunSummary run_impl(const Plan& plan, const std::function<void(const Iteration&)>* on_iter,
                    bool for_validation) {
  Datapath dp(plan.cmd, plan.from);
  while (!dp.done()) {
    if (dp.stalled()) {
      const auto& r = dp.regs();
      const char axis = (r.cnt_y != 0 && r.jv_y == 0) ? 'Y' : 'X';
      const std::int64_t owed = axis == 'Y' ? r.cnt_y : r.cnt_x;
      std::ostringstream m;
      m << "end point " << pt(plan.to) << " is unreachable from " << pt(plan.from)
        << ": at " << pt(dp.pos()) << " the " << axis << " integrand is 0 with " << owed << ' '
        << axis << " step(s) still owed (the DDA would never finish)";
      if (for_validation) throw InputError(m.str());
      throw GuardError("stall guard: " + m.str());
    }
    if (dp.iterations() >= plan.iteration_bound) {
      std::ostringstream m;
      m << "iteration guard: " << dp.iterations() << " iterations reached the bound "
        << plan.iteration_bound << " before the end point " << pt(plan.to);
      throw GuardError(m.str());
    }
    Iteration it = dp.iterate();
    if (on_iter && *on_iter) (*on_iter)(it);
  }
  if (dp.pos() != plan.to) {
    throw GuardError("end-point guard: the counters reached 0 at " + pt(dp.pos()) +
                     " instead of " + pt(plan.to));
  }
  return RunSummary{dp.iterations(), dp.pos(), dp.regs()};
}

}  // namespace

Plan plan_arc(const ArcSpec& spec) {
  Plan p;
  p.spec = spec;
  const std::int64_t a = spec.a, b = spec.b;
  if (a < 1) throw InputError("a = " + std::to_string(a) + " is invalid: a semi-axis must be a positive integer");
  if (b < 1) throw InputError("b = " + std::to_string(b) + " is invalid: a semi-axis must be a positive integer");
  const int nmin = smallest_valid_bits(a, b);
  if (spec.bits < 1 || spec.bits > 61 || (std::int64_t{1} << spec.bits) < std::max(a, b)) {
    throw InputError("bits = " + std::to_string(spec.bits) +
                     " is invalid: n must satisfy 2^n >= max(a, b) (smallest valid n here is " +
                     std::to_string(nmin) + ")");
  }
  const auto ab = checked_mul(a, b);
  const auto a2 = checked_mul(a, a);
  const auto b2 = checked_mul(b, b);
  const auto cap = ab ? checked_mul(*ab, std::int64_t{1} << spec.bits) : std::nullopt;
  if (!ab || !a2 || !b2 || !cap || *cap >= kCapLimit) {
    throw InputError("capacity 2^" + std::to_string(spec.bits) + " * a * b = 2^" +
                     std::to_string(spec.bits) + " * " + std::to_string(a) + " * " +
                     std::to_string(b) + " is out of range: it must be below 2^61");
  }
  p.scale = *ab;
  p.from = spec.from.value_or(Point{a, 0});
  p.to = spec.to.value_or(Point{0, b});

  const double tol = kPointTolerance + 1e-9 * static_cast<double>(std::max(a, b));
  for (const auto& [name, q] : {std::pair{"from", p.from}, std::pair{"to", p.to}}) {
    if (q.x < 0 || q.y < 0) {
      throw InputError(std::string(name) + " point " + pt(q) +
                       " is outside quadrant I: this version interpolates x >= 0, y >= 0 only");
    }
    const double d = ellipse_distance(static_cast<double>(a), static_cast<double>(b),
                                      static_cast<double>(q.x), static_cast<double>(q.y));
    if (d > tol) {
      std::ostringstream m;
      m.precision(4);
      m << std::fixed << name << " point " << pt(q) << " is " << d
        << " steps from the ellipse: start and end must lie within " << kPointTolerance
        << " step of it";
      throw InputError(m.str());
    }
  }
  if (p.from == p.to) {
    throw InputError("from " + pt(p.from) + " equals to " + pt(p.to) +
                     ": a full ellipse (from == to) is not supported yet");
  }
  if (p.to.x > p.from.x || p.to.y < p.from.y) {
    throw InputError("to " + pt(p.to) + " comes before from " + pt(p.from) +
                     " on the counter-clockwise quadrant-I arc: the end needs x <= " +
                     std::to_string(p.from.x) + " and y >= " + std::to_string(p.from.y));
  }
  // Scaled integrands: JVX' = a^2 y, JVY' = b^2 x. x only decreases and y only increases,
  // so their largest values are a^2 * to.y and b^2 * from.x. Each must not exceed cap, or an
  // accumulator could carry twice in one iteration.
  const std::int64_t jvx_max = *a2 * p.to.y, jvy_max = *b2 * p.from.x;
  if (jvx_max > *cap || jvy_max > *cap) {
    const bool xside = jvx_max > *cap;
    std::ostringstream m;
    m << "bits = " << spec.bits << " is too small for this arc: the "
      << (xside ? "X integrand a*y/b" : "Y integrand b*x/a") << " reaches "
      << (xside ? "a*" + std::to_string(p.to.y) + "/b" : "b*" + std::to_string(p.from.x) + "/a")
      << " > 2^n (use more bits)";
    throw InputError(m.str());
  }

  Command& c = p.cmd;
  c.cap = *cap;
  c.jv_x = *a2 * p.from.y;
  c.jv_y = *b2 * p.from.x;
  c.jr_x = c.jr_y = spec.preload == Preload::Half ? *cap / 2 : 0;
  c.cnt_x = p.from.x - p.to.x;
  c.cnt_y = p.to.y - p.from.y;
  c.dir_x_neg = true;   // quadrant I counter-clockwise: -X
  c.dir_y_neg = false;  // and +Y
  c.inc_x_on_y = *a2;   // y + 1  ->  JVX' + a^2
  c.inc_y_on_x = -*b2;  // x - 1  ->  JVY' - b^2
  c.inc_x_on_x = c.inc_y_on_y = 0;

  // Iteration bound (docs/design.md, "Iteration bound"). While an axis is active and
  // its integrand is at least its smallest non-zero value (a^2 for X, b^2 for Y), it
  // steps at least every K = ceil(cap / smallest) iterations. Y is active on a prefix
  // of the run with x >= 1; X is active on a prefix with y >= 1 except, when the arc
  // starts on the X axis, before the first Y step (at most K_y iterations).
  const std::int64_t kx = ceil_div(c.cap, *a2), ky = ceil_div(c.cap, *b2);
  const auto ty = checked_mul(c.cnt_y, ky);
  const auto tx = checked_mul(c.cnt_x, kx);
  if (!ty || !tx || *tx > std::numeric_limits<std::int64_t>::max() - ky) {
    throw InputError("iteration bound overflows 64 bits for this arc: reduce bits");
  }
  const std::int64_t tx_total = *tx + ((p.from.y == 0 && c.cnt_x > 0) ? ky : 0);
  p.iteration_bound = static_cast<std::uint64_t>(std::max(*ty, tx_total));

  // Reachability: the exact model decides whether the arc ends (no stall).
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

double deviation_bound(const Plan& plan) {
  const double a = double(plan.spec.a), b = double(plan.spec.b);
  const double x0 = double(plan.from.x) / a, y0 = double(plan.from.y) / b;
  const double r = std::sqrt(x0 * x0 + y0 * y0);
  const double drift =
      plan.spec.preload == Preload::Zero ? 2.0 + std::cbrt(std::max(a, b)) / 2.0 : 1.5;
  return std::fabs(r - 1.0) * std::max(a, b) + drift;
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
