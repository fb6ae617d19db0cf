// SPDX-License-Identifier: Apache-2.0
// Documented deviation bounds of a plan (docs/golden-model.md, "Deviation bound").
#include "host/accuracy/accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "host/geometry/geometry.hpp"
#include "host/planner/planner.hpp"

namespace dda {

double start_offset(const Plan& plan) {
  const ArcGeometry& g = plan.arc();
  const double fx = std::ldexp(double(g.frac_x), -kPosFrac), fy = std::ldexp(double(g.frac_y), -kPosFrac);
  double u = double(g.arc_from.x) - center_x(g.spec) + fx, v = double(g.arc_from.y) - center_y(g.spec) + fy;
  double a = double(g.ax), b = double(g.by);
  if (g.rotated) {
    std::tie(u, v) = to_frame(g.spec.angle, u, v);
    a = a_steps(g.spec);
    b = b_steps(g.spec);
  }
  return std::fabs(std::hypot(u / a, v / b) - 1.0) * std::max(a, b);
}

double deviation_bound(const Plan& plan) {
  const ArcSpec& spec = plan.arc().spec;
  const double m = std::max(a_steps(spec), b_steps(spec));
  if (plan.arc().rotated) {
    // Measured (build/bin/deviation_survey): half preload at the default width or more
    // and aspect ratio <= 4 stays within 1 step; elsewhere no bound is documented.
    const bool covered = spec.preload == Preload::Half &&
                         spec.bits >= smallest_valid_bits(steps_ceil(spec, spec.a), steps_ceil(spec, spec.b)) + 4 &&
                         m <= 4.0 * std::min(a_steps(spec), b_steps(spec));
    if (!covered) return std::numeric_limits<double>::infinity();
  }
  const double drift = spec.preload == Preload::Zero ? 2.0 + std::cbrt(m) / 2.0 : 1.5;
  return start_offset(plan) + drift + coefficient_drift_bound(plan);
}

}  // namespace dda
