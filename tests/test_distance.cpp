// SPDX-License-Identifier: Apache-2.0
// ellipse_distance against an independent long-double computation.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "host/accuracy/golden.hpp"

namespace {

// Independent method: the closest point is (a cos t, b sin t) for some t in [0, pi/2]
// (after folding the point into quadrant I). Dense sampling of the squared distance,
// then golden-section search around the best samples, all in long double.
long double reference_distance(long double a, long double b, long double u, long double v) {
  u = std::fabs(u);
  v = std::fabs(v);
  const auto f = [&](long double t) {
    const long double dx = a * std::cos(t) - u, dy = b * std::sin(t) - v;
    return dx * dx + dy * dy;
  };
  const int n = 4096;
  const long double h = (M_PIl / 2) / n;
  long double best = f(0);
  for (int i = 0; i <= n; ++i) best = std::min(best, f(h * i));
  // Refine around every local minimum of the samples (there are at most two).
  for (int i = 0; i <= n; ++i) {
    const long double fi = f(h * i);
    const bool left = i == 0 || fi <= f(h * (i - 1));
    const bool right = i == n || fi <= f(h * (i + 1));
    if (!left || !right) continue;
    long double lo = std::max<long double>(0, h * (i - 1)), hi = std::min(M_PIl / 2, h * (i + 1));
    const long double g = (std::sqrt(5.0L) - 1) / 2;
    for (int k = 0; k < 200; ++k) {
      const long double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
      if (f(m1) < f(m2))
        hi = m2;
      else
        lo = m1;
    }
    best = std::min(best, f((lo + hi) / 2));
  }
  return std::sqrt(best);
}

void check_point(double a, double b, double x, double y) {
  const double d = dda::ellipse_distance(a, b, x, y);
  const long double r = reference_distance(a, b, x, y);
  const double tol = 1e-9 * std::max(a, b);
  INFO("a=" << a << " b=" << b << " point (" << x << ',' << y << ") got " << d << " ref " << static_cast<double>(r));
  CHECK(std::fabs(d - static_cast<double>(r)) <= tol);
}

}  // namespace

TEST_CASE("distance: exact values on and off the axes", "[distance]") {
  CHECK(dda::ellipse_distance(10, 6, 10, 0) == 0.0);
  CHECK(dda::ellipse_distance(10, 6, 0, 6) == 0.0);
  CHECK(dda::ellipse_distance(10, 6, 11, 0) == 1.0);
  CHECK(dda::ellipse_distance(10, 6, 0, 7) == 1.0);
  CHECK(dda::ellipse_distance(10, 6, 0, 0) == 6.0);
  CHECK(dda::ellipse_distance(6, 10, 0, 0) == 6.0);
  CHECK(dda::ellipse_distance(5, 5, 3, 4) == Approx(0.0).margin(1e-12));
  CHECK(dda::ellipse_distance(5, 5, 6, 8) == Approx(5.0).epsilon(1e-15));
  CHECK(dda::ellipse_distance(5, 5, -6, -8) == Approx(5.0).epsilon(1e-15));
}

TEST_CASE("distance: agrees with a long-double reference on random points", "[distance]") {
  const unsigned seed = 20261122;
  std::mt19937_64 rng(seed);
  INFO("seed " << seed);
  std::uniform_real_distribution<double> lg(0.0, std::log(4096.0));
  for (int i = 0; i < 3000; ++i) {
    const double a = std::round(std::exp(lg(rng))), b = std::round(std::exp(lg(rng)));
    std::uniform_int_distribution<int> kind(0, 4);
    const double m = std::max(a, b) * 1.3;
    std::uniform_real_distribution<double> ux(-m, m);
    double x = std::round(ux(rng)), y = std::round(ux(rng));
    switch (kind(rng)) {
      case 0:
        x = 0;
        break;  // on the Y axis
      case 1:
        y = 0;
        break;   // on the X axis
      case 2: {  // near the curve: a lattice point beside it
        std::uniform_real_distribution<double> t(0, 2 * M_PI);
        const double th = t(rng);
        x = std::round(a * std::cos(th));
        y = std::round(b * std::sin(th));
        break;
      }
      default:
        break;
    }
    check_point(a, b, x, y);
  }
}

TEST_CASE("distance: thin ellipses and points near the major axis", "[distance]") {
  for (double a : {4096.0, 1000.0, 37.0}) {
    for (double b : {1.0, 2.0}) {
      for (double x : {0.0, 1.0, a / 2, a - 1, a, a + 1, a - 0.001}) {
        for (double y : {0.0, 1e-6, 0.5, 1.0, 2.0}) {
          check_point(a, b, x, y);
          check_point(b, a, y, x);
        }
      }
    }
  }
}
