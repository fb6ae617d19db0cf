// SPDX-License-Identifier: Apache-2.0
// The planner: validation, end points, parametric angles, and the cut into pieces
// (plan_quadrant.cpp, plan_rotated.cpp).
#include "host/planner/planner.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <tuple>
#include <utility>

#include "host/geometry/geometry.hpp"
#include "host/planner/plan_detail.hpp"
#include "host/runner/runner.hpp"
#include "model/datapath/hw_params.hpp"

namespace dda {

using namespace detail;

// The capacity for rotated ellipses must be a value the hardware's capacity register
// holds below 2^(AccWidth-1) (every integrand up to it positive).
static_assert(kRotCapBits < hw::kAccWidth - 1, "kRotCapBits (plan.hpp) no longer fits AccWidth (hw_params.hpp)");

namespace {

// Headroom: every sum the datapath forms is below 2 * cap, and integrand corrections
// stay within [-(cap), 2 * cap]; keeping cap below 2^61 keeps all of them in int64.
constexpr std::int64_t kCapLimit = std::int64_t{1} << 61;

}  // namespace

const char* to_string(Preload p) { return p == Preload::Zero ? "zero" : "half"; }

double a_steps(const ArcSpec& s) { return std::ldexp(double(s.a), -s.sub); }
double b_steps(const ArcSpec& s) { return std::ldexp(double(s.b), -s.sub); }
double center_x(const ArcSpec& s) { return double(s.center.x) + std::ldexp(double(s.center_frac.x), -s.sub); }
double center_y(const ArcSpec& s) { return double(s.center.y) + std::ldexp(double(s.center_frac.y), -s.sub); }
std::int64_t steps_ceil(const ArcSpec& s, std::int64_t v) {
  return s.sub == 0 ? v : (v + (std::int64_t{1} << s.sub) - 1) >> s.sub;
}
const char* to_string(Direction d) { return d == Direction::Ccw ? "ccw" : "cw"; }

Preload Plan::preload() const {
  if (const auto* a = std::get_if<ArcGeometry>(&geometry)) return a->spec.preload;
  if (const auto* l = std::get_if<LineGeometry>(&geometry)) return l->preload;
  return std::get<ProgramGeometry>(geometry).preload;
}

int smallest_valid_bits(std::int64_t a, std::int64_t b) {
  const std::int64_t m = std::max(a, b);
  int n = 1;
  while (n < 62 && (std::int64_t{1} << n) < m) ++n;
  return n;
}

int default_bits(std::int64_t a, std::int64_t b) {
  // Four bits above the smallest valid width, fewer if the capacity 2^n a b would not fit
  // the hardware's capacity field (below 2^(AccWidth-1)), so the default runs on every
  // engine whenever some width does.
  const int nmin = smallest_valid_bits(a, b);
  int n = nmin + 4;
  while (n > nmin && (__int128(a) * b << n) >= (__int128(1) << (hw::kAccWidth - 1))) --n;
  return n;
}

int quarter_turns(const ArcSpec& spec) {
  if (spec.sub != 0) return -1;  // sub-step geometry: the fixed-point datapath
  const std::int64_t t = normalize_udeg(spec.angle);
  return t % kQuarterTurn == 0 ? static_cast<int>(t / kQuarterTurn) : -1;
}

namespace {

// The ellipse's quadratic form on lattice points relative to the centre, and its value
// on the nominal curve: Q(x, y) = qy x^2 - 2 p x y + qx y^2, Q = level on the curve.
i128 quad_form(const Coefficients& k, i128 x, i128 y) { return k.qy * x * x - 2 * k.p * x * y + k.qx * y * y; }

Scaled scaled_coefficients(const ArcSpec& spec, int n) {
  Scaled r;
  const std::int64_t a = spec.a, b = spec.b;
  const int qt = quarter_turns(spec);
  if (spec.sub != 0) {
    // Sub-step geometry: the same coefficients from a and b in sub-step units (only their
    // ratio enters), with the squares of the sines and cosines rounded to Q(kTrigFrac)
    // so that the products stay within 128 bits; the level is in sub-step units squared.
    const SinCos f = sincos_udeg(spec.angle);
    const i128 a2 = i128(a) * a, b2 = i128(b) * b;
    const i128 cc = round_shift(i128(f.c) * f.c, kTrigFrac), ss = round_shift(i128(f.s) * f.s, kTrigFrac),
               cs = round_shift(i128(f.c) * f.s, kTrigFrac);
    const int sh = kTrigFrac - (kRotCapBits - n);  // n >= 1: sh >= kTrigFrac - kRotCapBits + 1
    const i128 num_scale = sh < 0 ? i128(1) << -sh : 1;
    const i128 den = sh < 0 ? i128(a) * b : (i128(a) * b) << sh;
    r.k.p = std::int64_t(round_div(cs * (a2 - b2) * num_scale, den));
    r.k.qx = std::int64_t(round_div((a2 * cc + b2 * ss) * num_scale, den));
    r.k.qy = std::int64_t(round_div((a2 * ss + b2 * cc) * num_scale, den));
    r.cap = std::int64_t{1} << kRotCapBits;
    r.level = (i128(a) * b) << (kRotCapBits - n);
    return r;
  }
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
  const i128 a2 = i128(a) * a, b2 = i128(b) * b, cc = i128(f.c) * f.c, ss = i128(f.s) * f.s, cs = i128(f.c) * f.s;
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
  const int n = spec.bits != 0 ? spec.bits : default_bits(steps_ceil(spec, spec.a), steps_ceil(spec, spec.b));
  const Scaled sc = scaled_coefficients(spec, std::clamp(n, 1, kRotCapBits));
  const std::int64_t fx = f.x >> kPosFrac, fy = f.y >> kPosFrac;  // floors
  const std::int64_t mask = (std::int64_t{1} << kPosFrac) - 1;
  const std::int64_t cx = fx + ((f.x & mask) != 0), cy = fy + ((f.y & mask) != 0);
  Point best{fx, fy}, outermost{fx, fy};
  i128 best_q = -1, out_q = -1;
  for (const std::int64_t x : {fx, cx}) {
    for (const std::int64_t y : {fy, cy}) {
      const auto [rx, ry] = sub_rel(spec, Point{c.x + x, c.y + y});
      const i128 q = quad_form(sc.k, rx, ry);
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
  // Beside a thin ellipse the lattice point just outside can be more than a step from the
  // curve (a start the planner would refuse): then the lattice point nearest to the
  // ideal point (within half a step per axis of it).
  const auto [u, v] =
      to_frame(spec.angle, double(c.x + best.x) - center_x(spec), double(c.y + best.y) - center_y(spec));
  if (ellipse_distance(a_steps(spec), b_steps(spec), u, v) > kPointTolerance) {
    best = Point{std::int64_t(round_shift(f.x, kPosFrac)), std::int64_t(round_shift(f.y, kPosFrac))};
  }
  return Point{c.x + best.x, c.y + best.y};
}

namespace detail {

EndPoint resolve_point(const ArcSpec& spec, const std::optional<Point>& pnt, const std::optional<std::int64_t>& theta,
                       std::int64_t default_theta, const std::optional<Point>& default_pnt) {
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

}  // namespace detail

namespace {

// Settles the width n (the default if none is given) and refuses one below the smallest
// valid width, 2^n >= max(a, b) (whole steps), or more than kMaxExtraBits above it.
void resolve_bits(ArcSpec& spec, std::int64_t a, std::int64_t b) {
  const int nmin = smallest_valid_bits(a, b);
  if (spec.bits == 0) spec.bits = default_bits(a, b);
  if (spec.bits < 1 || spec.bits > 61 || (std::int64_t{1} << spec.bits) < std::max(a, b)) {
    throw InputError("bits = " + std::to_string(spec.bits) +
                     " is invalid: n must satisfy 2^n >= max(a, b) (smallest valid n here is " + std::to_string(nmin) +
                     ")");
  }
  if (spec.bits > nmin + kMaxExtraBits) {
    throw InputError("bits = " + std::to_string(spec.bits) + " is invalid: at most " + std::to_string(kMaxExtraBits) +
                     " bits above the smallest valid width (" + std::to_string(nmin) +
                     ") are accepted; each bit doubles the run");
  }
}

// Refuses a width the datapath cannot run: quarter turns, a capacity 2^n a b from 2^61
// up (kCapLimit); a rotated ellipse, a width whose fixed-point coefficients could move
// the curve by more than kMaxCoefficientDrift steps, or above kRotCapBits.
void check_capacity(const Plan& p, std::int64_t a, std::int64_t b) {
  const ArcSpec& spec = p.arc().spec;
  const std::int64_t ab = spec.a * spec.b;
  if (!p.arc().rotated) {
    const auto cap = checked_mul(ab, std::int64_t{1} << spec.bits);
    if (!cap || *cap >= kCapLimit) {
      throw InputError("capacity 2^" + std::to_string(spec.bits) + " * a * b = 2^" + std::to_string(spec.bits) + " * " +
                       std::to_string(a) + " * " + std::to_string(b) + " is out of range: it must be below 2^61");
    }
  } else if (coefficient_drift_bound(p) > kMaxCoefficientDrift || spec.bits > kRotCapBits) {
    std::ostringstream m;
    m << "bits = " << spec.bits << " is too large for this rotated ellipse: its fixed-point coefficients "
      << "could move the curve by " << coefficient_drift_bound(p) << " steps (at most " << kMaxCoefficientDrift
      << " allowed: max(a,b)^2 2^n / (2^" << kRotCapBits << " min(a,b)); use fewer bits)";
    throw InputError(m.str());
  }
}

// Refuses a lattice start or end (p.from, p.to) that lies more than the tolerance from
// the ellipse; a parametric end is found by the walk, so it is not checked here.
void check_end_points(const Plan& p, std::int64_t a, std::int64_t b) {
  const ArcSpec& spec = p.arc().spec;
  const Point c = spec.center;
  const double tol =
      (spec.tolerance > 0 ? spec.tolerance : kPointTolerance) + 1e-9 * static_cast<double>(std::max(a, b));
  for (const auto& [name, q] : {std::pair{"from", p.from}, std::pair{"to", p.to}}) {
    if (spec.to_theta && std::string(name) == "to") continue;  // found by the walk
    const std::int64_t reach = 2 * std::max(a, b) + 2 + std::int64_t(spec.tolerance);
    const std::int64_t far = std::int64_t{1} << 42;  // beyond any centre plus reach: no overflow below
    if (q.x < -far || q.x > far || q.y < -far || q.y > far) {
      throw InputError(std::string(name) + " point " + pt(q) +
                       " is far from the ellipse: start and end must lie within 1 step of it");
    }
    const Point r{q.x - c.x, q.y - c.y};
    if (std::llabs(r.x) > reach || std::llabs(r.y) > reach) {
      throw InputError(std::string(name) + " point " + pt(q) +
                       " is far from the ellipse: start and end must lie within 1 step of it");
    }
    const double d = plan_distance(p, double(q.x), double(q.y));
    if (d > tol) {
      std::ostringstream m;
      m.precision(4);
      m << std::fixed << name << " point " << pt(q) << " is " << d
        << " steps from the ellipse: start and end must lie within "
        << (spec.tolerance > 0 ? spec.tolerance : kPointTolerance) << " step of it";
      throw InputError(m.str());
    }
  }
}

// The cut of a validated arc into pieces, from its start p.from to its end p.to.
// docs/golden-model.md, "Start and end points". With half preload a lattice start maps
// to the nearest point of the curve: the arc starts from the lattice point nearest to
// that point, the rest of it in the preloads (so the DDA follows the ideal curve, not
// the level set through the lattice start), after a lead-in line from the start if
// that lattice point is another one. A lattice end (half preload, or zero preload when
// the path cannot reach it by counting its steps) ends the arc where the path crosses
// the ray through the end's nearest curve point, and a lead-out line goes on to the
// end. A full turn closes with a line to its start.
struct ArcPieces {
  Plan& p;
  ArcGeometry& g;
  const ArcSpec& spec;
  const Scaled& sc;
  const Point c;
  const Point start, target;  // the path's own ends (target: lattice ends)
  const bool half;
  EndPoint arc_from;  // the arc's own start
  // The pieces are known to reach their ends: each anchored section's command ran to its
  // end while it was planned (with the same registers and activity up to its last step,
  // and its exact iteration count as its bound), and line pieces end on their points by
  // construction, so no second run checks them.
  bool run_while_planned = false;
  // Its parametric angle, when a lattice start was mapped to the curve (half preload).
  std::optional<std::int64_t> theta_start;

  ArcPieces(Plan& plan, const Scaled& scaled, const EndPoint& from)
      : p(plan),
        g(plan.arc()),
        spec(g.spec),
        sc(scaled),
        c(g.spec.center),
        start(plan.from),
        target(plan.to),
        half(g.spec.preload == Preload::Half),
        arc_from(from) {
    if (half && !spec.from_theta) {
      theta_start = nearest_theta(spec, start);
      arc_from = resolve_point(spec, std::nullopt, *theta_start, 0, std::nullopt);
    }
  }

  // The end where the path crosses the ray through the curve point e, seen from the
  // arc's start.
  RayEnd ray_to(FixedPoint e) const {
    const Point s0 = arc_from.lattice;
    const FixedPoint rep{((s0.x - c.x) << kPosFrac) + arc_from.fx, ((s0.y - c.y) << kPosFrac) + arc_from.fy};
    return RayEnd(e, spec.dir, g.full, spec.from_theta ? theta_ideal(spec, *spec.from_theta) : rep,
                  Point{s0.x - c.x, s0.y - c.y}, center_offset(spec));
  }

  // The ray through the lattice end's nearest curve point (a full turn: the start's).
  RayEnd end_ray() const {
    const std::int64_t te = g.full && theta_start ? *theta_start : nearest_theta(spec, target);
    return ray_to(theta_ideal(spec, te));
  }

  // The pieces by the DDA's own turns (plan_rotated.cpp) or at the vertices
  // (plan_quadrant.cpp), ending at the ray, or with a lattice end at the target; or why
  // the path cannot be cut that way.
  std::optional<Refusal> plan_pieces(std::optional<RayEnd> ray) {
    p.pieces.clear();
    p.iteration_bound = 0;
    p.from = arc_from.lattice;  // the piece planners start at the arc's own start
    p.to = target;
    if (g.rotated) return detail::plan_rotated_pieces(p, sc, arc_from, ray);
    return detail::plan_quadrant_pieces(p, sc.cap, arc_from, ray);
  }

  // Zero preload with a lattice end: the path counts its steps to it, as in the paper,
  // unless it cannot reach it; then it ends at the ray.
  std::optional<Refusal> plan_counted_or_ray() {
    std::optional<Refusal> counted = plan_pieces(std::nullopt);
    if (!counted) {
      p.from = start;
      counted = unreachable(p);
    }
    return counted ? plan_pieces(end_ray()) : std::nullopt;
  }

  // The pieces anchored on the ideal curve at every turn (plan_anchored.cpp).
  void plan_anchored() {
    p.pieces.clear();
    p.from = arc_from.lattice;
    p.to = target;
    const std::int64_t t0 = spec.from_theta ? *spec.from_theta
                            : theta_start   ? *theta_start
                                            : nearest_theta(spec, start);
    const std::int64_t t1 = spec.to_theta ? *spec.to_theta : g.full ? t0 : nearest_theta(spec, target);
    detail::plan_anchored_pieces(p, sc, arc_from, normalize_udeg(t0), normalize_udeg(t1));
    run_while_planned = true;
  }

  // The arc's pieces by the planner that fits the ellipse, its preload and its ends.
  void plan() {
    // Rotated ellipses with half preload, and with zero preload where the DDA's own turns
    // lose the curve (always at tips sharper than a quarter step: radius of curvature
    // min(a,b)^2 / max(a,b)), are anchored on the ideal curve at every turn.
    const bool quarter_step_tips =
        4 * i128(std::min(spec.a, spec.b)) * std::min(spec.a, spec.b) <= i128(std::max(spec.a, spec.b)) << spec.sub;
    if (!spec.to_theta && !g.full &&
        nearest_theta(spec, target) == (theta_start ? *theta_start : nearest_theta(spec, start))) {
      // Both ends map to the same point of the curve: the arc between them is the line.
      p.pieces = line_pieces(start, target, spec.preload);
      run_while_planned = true;
    } else if (g.rotated && (half || quarter_step_tips || spec.sub != 0)) {
      plan_anchored();
    } else if (g.rotated) {
      // Zero preload: the DDA's own turns (plan_rotated.cpp), unless they lose the curve.
      const std::optional<Refusal> own =
          spec.to_theta ? plan_pieces(ray_to(theta_ideal(spec, *spec.to_theta))) : plan_counted_or_ray();
      if (own) plan_anchored();
    } else if (spec.to_theta) {
      refuse(plan_pieces(ray_to(theta_ideal(spec, *spec.to_theta))));
    } else if (half) {
      refuse(plan_pieces(end_ray()));
    } else {
      refuse(plan_counted_or_ray());
    }
  }

  static void refuse(const std::optional<Refusal>& r) {
    if (r) throw InputError(r->why);
  }

  // The lead-in and lead-out lines around the arc's pieces, and the plan's ends, start
  // point fraction and iteration bound; a full turn given by angles closes on its start.
  void add_lead_lines() {
    const Point arc_start = p.pieces.empty() ? arc_from.lattice : p.pieces.front().from;
    const Point arc_end = p.pieces.empty() ? arc_from.lattice : p.pieces.back().to;
    const Point end = spec.to_theta && !g.full ? arc_end : g.full && spec.to_theta ? start : target;
    if (arc_end != end) {
      for (const Piece& l : line_pieces(arc_end, end, spec.preload)) p.pieces.push_back(l);
    }
    if (arc_start != start) {
      std::vector<Piece> v = line_pieces(start, arc_start, spec.preload);
      p.pieces.insert(p.pieces.begin(), v.begin(), v.end());
    }
    if (p.pieces.empty()) throw GuardError("planner fault: the arc from " + pt(start) + " has no piece");
    p.from = start;
    p.to = end;
    g.arc_from = arc_from.lattice;
    g.frac_x = arc_from.fx;
    g.frac_y = arc_from.fy;
    p.iteration_bound = 0;
    for (const Piece& pc : p.pieces) p.iteration_bound += pc.iteration_bound;
  }
};

}  // namespace

Plan plan_arc(const ArcSpec& spec_in) {
  Plan p;
  ArcGeometry& g = p.geometry.emplace<ArcGeometry>();
  g.spec = spec_in;
  ArcSpec& spec = g.spec;
  spec.angle = normalize_udeg(spec.angle);
  check_axes_and_center(spec);
  const std::int64_t a = steps_ceil(spec, spec.a), b = steps_ceil(spec, spec.b);  // whole steps
  const int qt = quarter_turns(spec);
  g.rotated = qt < 0;
  resolve_bits(spec, a, b);
  check_capacity(p, a, b);
  g.scale = spec.a * spec.b;
  const Scaled sc = scaled_coefficients(spec, spec.bits);
  g.coef = sc.k;
  g.ax = qt >= 0 && qt % 2 ? spec.b : spec.a;
  g.by = qt >= 0 && qt % 2 ? spec.a : spec.b;
  if (spec.from && spec.from_theta) throw InputError("from and from-theta are both given: choose one");
  if (spec.to && spec.to_theta) throw InputError("to and to-theta are both given: choose one");
  const Point c = spec.center;
  // Defaults: the quadrant-I quarter arc (quarter turns), parametric 0 to 90 (rotated).
  const auto dflt = [&](Point q) { return g.rotated ? std::optional<Point>{} : std::optional<Point>{q}; };
  const EndPoint from = resolve_point(spec, spec.from, spec.from_theta, 0, dflt(Point{c.x + g.ax, c.y}));
  const EndPoint to = resolve_point(spec, spec.to, spec.to_theta, kQuarterTurn, dflt(Point{c.x, c.y + g.by}));
  p.from = from.lattice;
  p.to = to.lattice;
  g.frac_x = from.fx;
  g.frac_y = from.fy;
  check_end_points(p, a, b);
  // A full turn: equal lattice ends, or equal parametric angles (a parametric end is
  // found by the walk, so its lattice point is not known yet).
  g.full = spec.to_theta ? spec.from_theta && normalize_udeg(*spec.from_theta) == normalize_udeg(*spec.to_theta)
                         : p.from == p.to;
  ArcPieces pieces(p, sc, from);
  pieces.plan();
  pieces.add_lead_lines();
  // Reachability: the exact model decides whether every piece ends (no stall), unless
  // the pieces ran to their ends while they were planned.
  if (!pieces.run_while_planned) check_reachable(p);
  return p;
}

double plan_distance(const Plan& plan, double x, double y) {
  if (plan.is_program()) throw GuardError("plan_distance: a program's distance is its blocks' (BlockDistance)");
  if (plan.is_line()) {
    const double x0 = double(plan.from.x), y0 = double(plan.from.y);
    const double ux = double(plan.to.x) - x0, uy = double(plan.to.y) - y0;
    const double t = std::clamp(((x - x0) * ux + (y - y0) * uy) / (ux * ux + uy * uy), 0.0, 1.0);
    return std::hypot(x - (x0 + t * ux), y - (y0 + t * uy));
  }
  const ArcGeometry& g = plan.arc();
  const double rx = x - center_x(g.spec), ry = y - center_y(g.spec);
  if (!g.rotated) return ellipse_distance(double(g.ax), double(g.by), rx, ry);
  const auto [u, v] = to_frame(g.spec.angle, rx, ry);
  return ellipse_distance(a_steps(g.spec), b_steps(g.spec), u, v);
}

double coefficient_drift_bound(const Plan& plan) {
  const ArcSpec& spec = plan.arc().spec;
  if (quarter_turns(spec) >= 0) return 0.0;
  const double mx = std::max(a_steps(spec), b_steps(spec)), mn = std::min(a_steps(spec), b_steps(spec));
  return std::ldexp(mx * mx / mn, spec.bits - kRotCapBits);
}

}  // namespace dda
