// SPDX-License-Identifier: Apache-2.0
// Deterministic double-precision functions for the macro language (docs/programs.md): sine,
// cosine, tangent and arc tangent in radians computed with IEEE 754 additions,
// multiplications and divisions only (no libm, no fused multiply-add: the library is
// built with -ffp-contract=off), so that a macro program computes the same bits, and a
// loop runs the same number of times, on every machine. Accuracy: within 5 units in the
// last place for |x| up to 1e5 (tests/test_program.cpp compares with long double).
#pragma once

namespace dda::det {

double sin(double x);
double cos(double x);
double tan(double x);   // sin / cos
double atan(double x);  // in (-pi/2, pi/2)
// The angle of (x, y) from +x, in [-pi, pi] (0 for (0, 0)), from atan and the quadrant.
double atan2(double y, double x);

inline constexpr double kPi = 3.141592653589793115997963468544185161590576171875;  // the double nearest pi

}  // namespace dda::det
