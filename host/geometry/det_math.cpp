// SPDX-License-Identifier: Apache-2.0
// Deterministic sine, cosine, tangent and arc tangent (det_math.hpp): IEEE 754 + - * /
// and sqrt only, each correctly rounded by the standard, evaluated in a fixed order
// (the library is built with -ffp-contract=off, so no fused multiply-add changes a bit).
#include "host/geometry/det_math.hpp"

#include <cmath>

namespace dda::det {

namespace {

// pi/2 in three parts (Cody and Waite): the first two have 33 significant bits, so
// k * part is exact for |k| < 2^20 and the reduction keeps about 100 bits of pi/2.
constexpr double kPio2Hi = 1.57079632673412561417e+00;
constexpr double kPio2Mid = 6.07710050630396597660e-11;
constexpr double kPio2Lo = 2.02226624879595063154e-21;
constexpr double kTwoOverPi = 6.36619772367581382433e-01;

// x = k pi/2 + r with |r| <= pi/4 (about); k modulo 4 is the quadrant.
double reduce(double x, long long& k) {
  const double kd = std::floor(x * kTwoOverPi + 0.5);
  k = static_cast<long long>(kd);
  return ((x - kd * kPio2Hi) - kd * kPio2Mid) - kd * kPio2Lo;
}

// Taylor series on |r| <= pi/4 + a little, in Horner's form from the smallest term:
// sin r = r (1 - z/(2.3) (1 - z/(4.5) (1 - ...))), z = r^2, to r^19/19!; cos r = 1 -
// z/(1.2) (1 - z/(3.4) (...)) to r^20/20!. The first term left out is below 1e-19.
double sin_kernel(double r) {
  const double z = r * r;
  double s = 1.0;
  for (int n = 19; n >= 3; n -= 2) s = 1.0 - z / double((n - 1) * n) * s;
  return r * s;
}
double cos_kernel(double r) {
  const double z = r * r;
  double s = 1.0;
  for (int n = 20; n >= 2; n -= 2) s = 1.0 - z / double((n - 1) * n) * s;
  return s;
}

// sin(k pi/2 + r): the kernel of r in quadrant k (cos(x) = sin(x + pi/2): quadrant k + 1).
double in_quadrant(double r, long long k) {
  switch (k & 3) {
    case 0:
      return sin_kernel(r);
    case 1:
      return cos_kernel(r);
    case 2:
      return -sin_kernel(r);
    default:
      return -cos_kernel(r);
  }
}

}  // namespace

double sin(double x) {
  if (!std::isfinite(x)) return x - x;  // NaN
  long long k = 0;
  const double r = reduce(x, k);
  return in_quadrant(r, k);
}

double cos(double x) {
  if (!std::isfinite(x)) return x - x;
  long long k = 0;
  const double r = reduce(x, k);
  return in_quadrant(r, k + 1);
}

double tan(double x) { return sin(x) / cos(x); }

double atan(double x) {
  if (x != x) return x;
  const bool neg = x < 0;
  double a = neg ? -x : x;
  // atan(a) = pi/2 - atan(1/a) for a > 1; then two halvings of the angle,
  // atan(a) = 2 atan(a / (1 + sqrt(1 + a^2))), bring a below tan(pi/16) < 0.2.
  const bool inverted = a > 1.0;
  if (inverted) a = 1.0 / a;
  for (int i = 0; i < 2; ++i) a = a / (1.0 + std::sqrt(1.0 + a * a));
  // Taylor series a - a^3/3 + ... to a^29: the first term left out is below 1e-22.
  const double z = a * a;
  double s = 0.0;
  for (int n = 29; n >= 3; n -= 2) s = z * (1.0 / double(n) - s);
  double t = 4.0 * (a - a * s);
  if (inverted) t = (kPi / 2 - t) + 6.123233995736766e-17;  // pi/2 = kPi/2 + 6.12e-17
  return neg ? -t : t;
}

double atan2(double y, double x) {
  if (x == 0 && y == 0) return 0;
  if (std::fabs(x) >= std::fabs(y)) {
    const double a = atan(y / x);
    if (x > 0) return a;
    return y < 0 ? a - kPi : a + kPi;
  }
  const double a = atan(x / y);  // |x / y| < 1
  return y > 0 ? kPi / 2 - a : -kPi / 2 - a;
}

}  // namespace dda::det
