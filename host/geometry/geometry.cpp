// SPDX-License-Identifier: Apache-2.0
// Geometry for measurement: distance to an ellipse, turning into its frame.
#include "host/geometry/geometry.hpp"

#include <algorithm>
#include <cmath>

#include "host/geometry/fixed_trig.hpp"

namespace dda {

std::vector<std::pair<double, double>> ellipse_points(const EllipseDrawing& e, double t0, double span, int n) {
  const SinCos f = sincos_udeg(e.angle_udeg);
  const double c = std::ldexp(double(f.c), -kTrigFrac), s = std::ldexp(double(f.s), -kTrigFrac);
  std::vector<std::pair<double, double>> pts;
  pts.reserve(std::size_t(n) + 1);
  for (int k = 0; k <= n; ++k) {
    const double t = t0 + span * k / n, u = e.a * std::cos(t), v = e.b * std::sin(t);
    pts.emplace_back((e.cx + u * c - v * s) / e.scale, (e.cy + u * s + v * c) / e.scale);
  }
  return pts;
}

std::pair<double, double> to_frame(std::int64_t angle_udeg, double x, double y) {
  const SinCos f = sincos_udeg(angle_udeg);
  const double c = std::ldexp(double(f.c), -kTrigFrac), s = std::ldexp(double(f.s), -kTrigFrac);
  return {x * c + y * s, -x * s + y * c};
}

// ---------------------------------------------------------------------------------
// Distance from a point to an ellipse: D. Eberly, "Distance from a Point to an Ellipse,
// an Ellipsoid, or a Hyperellipsoid" (Geometric Tools, 2013). The closest point's
// Lagrange parameter s is the unique root of F(s) = (r0 z0/(s+r0))^2 + (z1/(s+1))^2 - 1
// in the bracket [z1 - 1, s1], where F is convex and decreasing: Newton's method from the
// bracket's left end (F >= 0 there) climbs to the root without passing it, until a step
// is within 2^-64 of max(1, |s|) (about 1e-16 of a step in the distance); if it has not
// converged in 64 steps, bisection of what is left of the bracket finishes.
namespace {

double robust_length(double v0, double v1) { return std::sqrt(v0 * v0 + v1 * v1); }

double bisect_root(double r0, double n0, double z1, double s0, double s1) {
  double s = s0;
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

double get_root(double r0, double z0, double z1, double g) {
  const double n0 = r0 * z0;
  const double s1 = g < 0 ? 0.0 : robust_length(n0, z1) - 1.0;
  double s = z1 - 1.0;
  for (int i = 0; i < 64; ++i) {
    const double ratio0 = n0 / (s + r0), ratio1 = z1 / (s + 1.0);
    const double f = ratio0 * ratio0 + ratio1 * ratio1 - 1.0;
    if (f <= 0) return s;  // the root (or past it by a rounding)
    const double df = -2.0 * (ratio0 * ratio0 / (s + r0) + ratio1 * ratio1 / (s + 1.0));
    const double next = std::min(s - f / df, s1);
    if (next - s <= 0x1p-64 * std::max(1.0, std::fabs(s))) return next;
    s = next;
  }
  return bisect_root(r0, n0, z1, s, s1);
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
      return robust_length(x0 - y0, x1 - y1);
    }
    return std::fabs(y1 - e1);
  }
  const double numer0 = e0 * y0, denom0 = e0 * e0 - e1 * e1;
  if (numer0 < denom0) {
    const double xde0 = numer0 / denom0;
    const double x0 = e0 * xde0, x1 = e1 * std::sqrt(1.0 - xde0 * xde0);
    return robust_length(x0 - y0, x1);
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
