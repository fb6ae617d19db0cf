// SPDX-License-Identifier: Apache-2.0
// The planner (driver software): validates an arc and cuts it into pieces, one
// hardware command each (docs/golden-model.md). Uses the runner to check reachability.
#pragma once

#include <cstdint>
#include <vector>

#include "host/geometry/fixed_trig.hpp"
#include "host/planner/plan.hpp"

namespace dda {

// The angle as a number of quarter turns 0..3, or -1 if it is not a multiple of 90.
int quarter_turns(const ArcSpec& spec);

// Smallest valid n for the semi-axes: smallest n >= 1 with 2^n >= max(a, b).
int smallest_valid_bits(std::int64_t a, std::int64_t b);
// Widths above smallest_valid_bits + kMaxExtraBits are refused: past +4 more bits
// change nothing (spec, accuracy table) and each bit doubles the run's length.
inline constexpr int kMaxExtraBits = 16;
// The width used when none is given: four bits above the smallest valid width, where
// half preload does its best (spec: more bits change nothing), fewer if the capacity
// 2^n a b would not fit the hardware's AccWidth-bit capacity field.
int default_bits(std::int64_t a, std::int64_t b);

// Sub-step geometry (ArcSpec::sub): at most kMaxSubBits fraction bits; part programs use
// kSubBits (1/1024 step).
inline constexpr int kMaxSubBits = 16;
inline constexpr int kSubBits = 10;

// Largest distance (in steps) a start or end point may lie from the ellipse.
inline constexpr double kPointTolerance = 1.0;

// Validate and plan. Throws InputError naming the value and the rule it breaks.
Plan plan_arc(const ArcSpec& spec);

// A straight line from `from` to `to` (different lattice points) through the same core:
// constant integrands |dx|, |dy|, no corrections, capacity max(|dx|, |dy|); with half
// preload the path is Bresenham's line (every point within half a step of the line between its ends),
// with zero preload it lags by up to a step. A line longer than the hardware's counters
// is cut into pieces whose preloads carry the line's running remainder, so the path is
// the same as one piece's. Throws InputError for a line of length 0, a point beyond
// 2^40 or a line longer than kMaxLineSteps on its longer axis.
inline constexpr std::int64_t kMaxLineSteps = std::int64_t{1} << 30;
Plan plan_line(Point from, Point to, Preload preload);
// The pieces of such a line (also used inside arcs, near their ends).
std::vector<Piece> line_pieces(Point from, Point to, Preload preload);

// The third axis along a path of the plane (a helix, or a path at constant height): sets
// every piece's third-axis fields and coordinates so that the axis goes from z0 to z1
// over the path's iterations by Bresenham's rule (with half preload within half a step
// of the ideal rise at every iteration), its phase carried from piece to piece. The
// iterations are counted by running each piece on the golden datapath. Throws
// InputError when the rise exceeds the path's iterations (at most one step per
// iteration) or a piece's counter.
void lift(Plan& plan, std::int64_t z0, std::int64_t z1, Preload preload);
// Turns a plan planned in another plane's axes onto the run's (a G18 arc in a G17
// program): each piece's core axes drive the run's axes turned by rot more
// (Piece::rot, to_run_axes), its ends and the plan's turned alike. The commands and the
// geometry stay in the plane they were planned in.
void turn_axes(Plan& plan, int rot);

// The curve point of parametric angle theta (micro-degrees) relative to the centre, in
// Q(kPosFrac): (a cos theta, b sin theta) turned by the spec's angle, computed with the
// deterministic fixed-point sines and cosines (the same bits on every machine).
struct FixedPoint {
  std::int64_t x = 0, y = 0;  // Q(kPosFrac)
};
FixedPoint theta_ideal(const ArcSpec& spec, std::int64_t theta);

// Lattice point of parametric angle theta (absolute), by the documented rule
// (docs/golden-model.md, "Parametric angles"): with half preload the nearest lattice
// point to the ideal point (each coordinate rounded half away from zero; the first
// piece's preloads carry the rest, so the DDA starts on the curve); with zero preload,
// of the four lattice points around it (floor and ceiling of each coordinate), the one
// with the least r >= 1, r^2 = Q(p) / Q(curve) for the ellipse's quadratic form Q (on
// or just outside the curve: the DDA follows the ellipse through it, r times the
// nominal one, and cannot stall at a vertex). Ties go to the first in the order
// (floor, floor), (floor, ceil), (ceil, floor), (ceil, ceil).
Point theta_point(const ArcSpec& spec, std::int64_t theta);

// Analytic bound (steps) on how far the rounding of a rotated ellipse's fixed-point
// coefficients moves the traced curve: max(a,b)^2 2^n / (2^kRotCapBits min(a,b))
// (docs/golden-model.md, "Rotated ellipses"). 0 for quarter turns (exact coefficients).
double coefficient_drift_bound(const Plan& plan);
// Rotated plans are refused when coefficient_drift_bound exceeds this (steps).
inline constexpr double kMaxCoefficientDrift = 0.125;

// Distance (steps) of absolute point (x, y) from the plan's ideal ellipse (turned and
// moved), or from a line between its ends. Measurement only (floating point): not used by the
// datapath.
double plan_distance(const Plan& plan, double x, double y);

}  // namespace dda
