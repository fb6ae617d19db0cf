// SPDX-License-Identifier: Apache-2.0
// How far a plan's path may lie from its ideal ellipse (docs/golden-model.md,
// "Deviation bound"): the documented bounds the property tests hold the runner to.
#pragma once

#include "host/planner/plan.hpp"

namespace dda {

// Documented bound on the distance of any path point from the ellipse, in steps:
// |r - 1| * max(a, b) + E + F, where r^2 = u0^2/a^2 + v0^2/b^2 at the represented start
// in the ellipse's frame (the DDA follows the ellipse through its start point, scaled by
// r), E is the DDA's own drift: 2 + cbrt(max(a, b)) / 2 steps with zero preload (the
// paper's drift grows with size), 1.5 steps with half preload, and F the fixed-point
// coefficients' drift bound of a rotated ellipse (coefficient_drift_bound; 0 for quarter
// turns). E is empirical: deviation_survey prints the measured worst drift by size. A
// rotated ellipse has the bound (E = 1.5) only with half preload, at least the default
// width and aspect ratio <= 4; elsewhere it is infinite (not documented;
// docs/results.md has measurements).
double deviation_bound(const Plan& plan);
// Its first term, |r - 1| * max(a, b): how far the ellipse through the start point lies
// from the nominal one.
double start_offset(const Plan& plan);

// The accuracy targets (docs/results.md; half preload, default width), in steps: a
// line's points from the line between its ends; an axis-aligned ellipse's (a circle's)
// up to aspect ratio kTargetAspect; any other ellipse's.
inline constexpr double kTargetLine = 0.5;
inline constexpr double kTargetAligned = 0.8;
inline constexpr double kTargetOther = 1.0;
inline constexpr double kTargetAspect = 4.0;

}  // namespace dda
