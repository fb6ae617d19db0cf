#include "dda_random.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace dda {

std::uint64_t test_seed(std::uint64_t default_seed) {
  if (const char* s = std::getenv("DDA_SEED"); s && *s) return std::strtoull(s, nullptr, 0);
  return default_seed;
}

std::string describe(const Plan& plan) {
  std::ostringstream s;
  s << "--a " << plan.spec.a << " --b " << plan.spec.b << " --bits " << plan.spec.bits
    << " --preload " << to_string(plan.spec.preload) << " --from " << plan.from.x << ','
    << plan.from.y << " --to " << plan.to.x << ',' << plan.to.y;
  return s.str();
}

RandomArcs::RandomArcs(std::uint64_t seed, std::int64_t max_axis, int extra_bits_max)
    : rng_(seed), max_axis_(max_axis), extra_bits_max_(extra_bits_max) {}

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
  // One in eight keeps the default quarter arc; the others draw two parameter angles.
  if (uni(8) != 0) {
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
