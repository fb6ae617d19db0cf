// SPDX-License-Identifier: Apache-2.0
// Documented deviation bounds of a plan (docs/golden-model.md, "Deviation bound").
#include "accuracy/accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "geometry/geometry.hpp"
#include "planner/planner.hpp"

namespace dda {

double start_offset(const Plan& plan) {
  const double fx = std::ldexp(double(plan.frac_x), -kPosFrac), fy = std::ldexp(double(plan.frac_y), -kPosFrac);
  double u = double(plan.arc_from.x) - center_x(plan.spec) + fx, v = double(plan.arc_from.y) - center_y(plan.spec) + fy;
  double a = double(plan.ax), b = double(plan.by);
  if (plan.rotated) {
    std::tie(u, v) = to_frame(plan.spec.angle, u, v);
    a = a_steps(plan.spec);
    b = b_steps(plan.spec);
  }
  return std::fabs(std::hypot(u / a, v / b) - 1.0) * std::max(a, b);
}

double deviation_bound(const Plan& plan) {
  const double m = std::max(a_steps(plan.spec), b_steps(plan.spec));
  if (plan.rotated) {
    // Measured (build/bin/deviation_survey): half preload at the default width or more
    // and aspect ratio <= 4 stays within 1 step; elsewhere no bound is documented.
    const bool covered =
        plan.spec.preload == Preload::Half &&
        plan.spec.bits >=
            smallest_valid_bits(steps_ceil(plan.spec, plan.spec.a), steps_ceil(plan.spec, plan.spec.b)) + 4 &&
        m <= 4.0 * std::min(a_steps(plan.spec), b_steps(plan.spec));
    if (!covered) return std::numeric_limits<double>::infinity();
  }
  const double drift = plan.spec.preload == Preload::Zero ? 2.0 + std::cbrt(m) / 2.0 : 1.5;
  return start_offset(plan) + drift + coefficient_drift_bound(plan);
}

}  // namespace dda
