// SPDX-License-Identifier: Apache-2.0
// Geometry for measurement (floating point, never in the datapath).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace dda {

// Shortest distance from (px, py) to the ellipse x^2/a^2 + y^2/b^2 = 1 (a, b > 0).
// Absolute error below 1e-9 * max(a, b). Eberly's root of the closest point's Lagrange
// parameter (Newton's method in its bracket), no sampling.
double ellipse_distance(double a, double b, double px, double py);

// (x, y) turned by -angle (micro-degrees) into an ellipse's own frame, with the
// deterministic sines and cosines of fixed_trig.hpp.
std::pair<double, double> to_frame(std::int64_t angle_udeg, double x, double y);

// An ellipse to draw: centre (cx, cy), semi-axes a and b, turned counter-clockwise by
// angle_udeg on the same sines. n + 1 points from parametric angle t0 (radians) over
// `span` (negative: clockwise), each coordinate divided by `scale`.
struct EllipseDrawing {
  double cx = 0, cy = 0, a = 0, b = 0;
  std::int64_t angle_udeg = 0;
  double scale = 1;
};
std::vector<std::pair<double, double>> ellipse_points(const EllipseDrawing& e, double t0, double span, int n);

}  // namespace dda
