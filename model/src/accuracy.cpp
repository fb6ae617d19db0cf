// SPDX-License-Identifier: Apache-2.0
// Documented deviation bounds of a plan (docs/golden-model.md, "Deviation bound").
#include "dda/accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "dda/geometry.hpp"
#include "dda/planner.hpp"

namespace dda {

double start_offset(const Plan& plan) {
  const double fx = std::ldexp(double(plan.frac_x), -kPosFrac), fy = std::ldexp(double(plan.frac_y), -kPosFrac);
  double u = double(plan.arc_from.x - plan.spec.center.x) + fx, v = double(plan.arc_from.y - plan.spec.center.y) + fy;
  double a = double(plan.ax), b = double(plan.by);
  if (plan.rotated) {
    std::tie(u, v) = to_frame(plan.spec.angle, u, v);
    a = double(plan.spec.a);
    b = double(plan.spec.b);
  }
  return std::fabs(std::hypot(u / a, v / b) - 1.0) * std::max(a, b);
}

double deviation_bound(const Plan& plan) {
  const double m = double(std::max(plan.spec.a, plan.spec.b));
  if (plan.rotated) {
    // Measured (build/bin/deviation_survey): half preload at the default width or more
    // and aspect ratio <= 4 stays within 1 step; elsewhere no bound is documented.
    const bool covered = plan.spec.preload == Preload::Half &&
                         plan.spec.bits >= smallest_valid_bits(plan.spec.a, plan.spec.b) + 4 &&
                         m <= 4.0 * double(std::min(plan.spec.a, plan.spec.b));
    if (!covered) return std::numeric_limits<double>::infinity();
  }
  const double drift = plan.spec.preload == Preload::Zero ? 2.0 + std::cbrt(m) / 2.0 : 1.5;
  return start_offset(plan) + drift + coefficient_drift_bound(plan);
}

}  // namespace dda
