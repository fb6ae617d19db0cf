// SPDX-License-Identifier: Apache-2.0
#include "tb/random/random_program.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace dda::randgen {

namespace {
constexpr double kPi = 3.14159265358979323846;

double mm6(double v) { return std::round(v * 1e6) / 1e6; }

std::string words(const char* a, double x, const char* b, double y) {
  char buf[96];
  std::snprintf(buf, sizeof buf, " %s%.6f %s%.6f", a, x, b, y);
  return buf;
}
}  // namespace

double Curve::length() const {
  if (line) return std::hypot(x1 - x0, y1 - y0);
  double s = 0;
  const int n = 4000;
  for (int k = 0; k < n; ++k) s += speed(t0 + sweep * (k + 0.5) / n) * std::abs(sweep) / n;
  return s;
}

double Curve::speed(double t) const { return std::hypot(a * std::sin(t), b * std::cos(t)); }

std::array<double, 2> Curve::tangent(double t) const {
  if (line) {
    const double l = length();
    return {(x1 - x0) / l, (y1 - y0) / l};
  }
  const double dx = -a * std::sin(t) * (sweep > 0 ? 1 : -1), dy = b * std::cos(t) * (sweep > 0 ? 1 : -1);
  const double c = std::cos(q), s = std::sin(q), n = std::hypot(dx, dy);
  return {(c * dx - s * dy) / n, (s * dx + c * dy) / n};
}

double Curve::radius(double t) const {
  if (line) return std::numeric_limits<double>::infinity();
  return std::pow(std::pow(a * std::sin(t), 2) + std::pow(b * std::cos(t), 2), 1.5) / (a * b);
}

std::string curve_block(Curve& c, double& x, double& y, bool circle, bool ccw) {
  const double cq = std::cos(c.q), sq = std::sin(c.q);
  const double px = c.a * std::cos(c.t0), py = c.b * std::sin(c.t0);
  const double i = mm6(-(cq * px - sq * py)), j = mm6(-(sq * px + cq * py));
  c.cx = x + i, c.cy = y + j;
  if (circle) c.a = c.b = std::hypot(i, j);
  c.t0 = std::atan2(((-sq) * -i + cq * -j) / c.b, (cq * -i + sq * -j) / c.a);
  const double t1 = c.t0 + c.sweep, ex = c.a * std::cos(t1), ey = c.b * std::sin(t1);
  const double x1 = mm6(c.cx + cq * ex - sq * ey), y1 = mm6(c.cy + sq * ex + cq * ey);
  std::string code = circle ? (ccw ? "G3" : "G2") : (ccw ? "G6.3" : "G6.2");
  code += words("X", x1, "Y", y1) + words("I", i, "J", j);
  if (!circle) {
    char buf[96];
    std::snprintf(buf, sizeof buf, " A%.6f B%.6f Q%d", c.a, c.b, int(std::lround(c.q * 180 / kPi * 1000)));
    code += buf;
  }
  x = x1, y = y1;
  return code;
}

RandomProgram random_program(std::mt19937_64& rng, int blocks, bool ellipses) {
  std::uniform_real_distribution<double> u(0, 1);
  RandomProgram p;
  p.text = "G21 G90 G64\n";
  double x = 0, y = 0, heading = 0;
  const int feeds[] = {300, 1000, 3000, 6000};
  for (int k = 0; k < blocks; ++k) {
    Curve c;
    const double r = u(rng);
    const int feed = feeds[rng() % 4];
    c.feed = feed / 60.0;
    const double dir = u(rng) < 0.5 ? heading : u(rng) * 2 * kPi;  // tangent on, or a corner
    std::string line;
    if (r < 0.4 || (!ellipses && r < 0.6)) {
      const bool rapid = u(rng) < 0.15;
      const double len = 0.5 + 20 * u(rng);
      c.x0 = x, c.y0 = y;
      c.x1 = mm6(x + len * std::cos(dir));
      c.y1 = mm6(y + len * std::sin(dir));
      if (rapid) c.feed = 6000.0 / 60;
      line = std::string(rapid ? "G0" : "G1") + words("X", c.x1, "Y", c.y1);
      x = c.x1, y = c.y1, heading = dir;
    } else {
      c.line = false;
      const bool circle = !ellipses || r < 0.75, ccw = u(rng) < 0.5;
      c.a = circle ? 0.2 + 20 * u(rng) : mm6(1 + 15 * u(rng));
      c.b = circle ? c.a : mm6(c.a * (0.15 + 0.85 * u(rng)));
      c.q = circle ? 0 : std::round(u(rng) * 360000) / 1000 * kPi / 180;
      c.sweep = (ccw ? 1 : -1) * (circle ? 20 + 250 * u(rng) : 20 + 150 * u(rng)) * kPi / 180;
      // A circle starts tangent to `dir`, an ellipse at a random parameter.
      c.t0 = circle ? dir - (ccw ? kPi / 2 : -kPi / 2) : u(rng) * 2 * kPi;
      line = curve_block(c, x, y, circle, ccw);
      const auto t = c.tangent(c.t0 + c.sweep);
      heading = std::atan2(t[1], t[0]);
    }
    if (line[1] != '0') line += " F" + std::to_string(feed);
    p.text += line + "\n";
    p.curves.push_back(c);
  }
  p.text += "M2\n";
  return p;
}

}  // namespace dda::randgen
