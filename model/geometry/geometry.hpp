// SPDX-License-Identifier: Apache-2.0
// Geometry for measurement (floating point, never in the datapath).
#pragma once

#include <cstdint>
#include <utility>

namespace dda {

// Shortest distance from (px, py) to the ellipse x^2/a^2 + y^2/b^2 = 1 (a, b > 0).
// Absolute error below 1e-9 * max(a, b). Eberly's bisection method, no sampling.
double ellipse_distance(double a, double b, double px, double py);

// (x, y) turned by -angle (micro-degrees) into an ellipse's own frame, with the
// deterministic sines and cosines of fixed_trig.hpp.
std::pair<double, double> to_frame(std::int64_t angle_udeg, double x, double y);

}  // namespace dda
