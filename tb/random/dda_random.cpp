// SPDX-License-Identifier: Apache-2.0
#include "dda_random.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace dda {

std::uint64_t test_seed(std::uint64_t default_seed) {
  if (const char* s = std::getenv("DDA_SEED"); s && *s) return std::strtoull(s, nullptr, 0);
  return default_seed;
}

RandomArcs::RandomArcs(std::uint64_t seed, std::int64_t max_axis, int extra_bits_max, ArcKind kind)
    : rng_(seed), max_axis_(max_axis), extra_bits_max_(extra_bits_max), kind_(kind) {}

std::optional<Plan> RandomArcs::next() {
  // Floating point only shapes the draw (axis lengths, angles); what is drawn is an exact
  // integer configuration and describe() prints it, so a failure is reproducible from its
  // printed options even where another libm would round a draw differently.
  const auto uni = [&](std::uint64_t n) { return rng_() % n; };  // n << 2^64: bias negligible
  const auto log_axis = [&]() {
    const double u = double(uni(1u << 30)) / double(1u << 30);
    const double v = std::exp(u * std::log(double(max_axis_)));
    return std::max<std::int64_t>(1, std::min<std::int64_t>(max_axis_, std::int64_t(v + 0.5)));
  };
  ArcSpec s;
  s.a = log_axis();
  s.b = log_axis();
  s.bits = smallest_valid_bits(s.a, s.b) + int(uni(std::uint64_t(extra_bits_max_) + 1));
  s.preload = uni(2) ? Preload::Half : Preload::Zero;
  if (kind_ == ArcKind::Whole) {
    if (uni(16) == 0) s.b = s.a;  // circles
    s.bits = smallest_valid_bits(s.a, s.b) + int(uni(std::uint64_t(extra_bits_max_) + 1));
    s.center = Point{std::int64_t(uni(2001)) - 1000, std::int64_t(uni(2001)) - 1000};
    s.dir = uni(2) ? Direction::Cw : Direction::Ccw;
    // Half the ellipses are turned by a uniform angle (micro-degrees), half by quarter turns.
    s.angle = uni(2) ? std::int64_t(uni(std::uint64_t(kFullTurn))) : kQuarterTurn * std::int64_t(uni(4));
    // Ellipses too thin to turn (tip radius of curvature at most 1/4 step, refused by
    // the planner) take a quarter turn instead.
    if (4 * std::min(s.a, s.b) * std::min(s.a, s.b) <= std::max(s.a, s.b)) {
      s.angle = kQuarterTurn * std::int64_t(s.angle % 4);
    }
    const auto theta = [&]() { return std::int64_t(uni(std::uint64_t(kFullTurn))); };
    s.from_theta = theta();
    // One in eight is a full turn, one in eight starts on a vertex (parametric 0, 90, 180
    // or 270 degrees), one in eight starts at a lattice point (the DDA follows the curve
    // through it).
    const unsigned shape = unsigned(uni(8));
    if (shape == 1) s.from_theta = kQuarterTurn * std::int64_t(uni(4));
    s.to_theta = shape == 0 ? *s.from_theta : theta();
    if (shape == 2) {
      s.from = theta_point(s, *s.from_theta);
      s.from_theta.reset();
    }
  } else if (uni(8) != 0) {  // one in eight keeps the default quarter arc
    const double kQuarter = std::acos(0.0);
    double t0 = kQuarter * double(uni(1u << 20)) / double(1u << 20);
    double t1 = kQuarter * double(uni(1u << 20)) / double(1u << 20);
    if (t0 > t1) std::swap(t0, t1);
    s.from = Point{std::llround(double(s.a) * std::cos(t0)), std::llround(double(s.b) * std::sin(t0))};
    s.to = Point{std::llround(double(s.a) * std::cos(t1)), std::llround(double(s.b) * std::sin(t1))};
  }
  try {
    return plan_arc(s);
  } catch (const InputError&) {
    ++rejected_;
    return std::nullopt;
  }
}

}  // namespace dda
