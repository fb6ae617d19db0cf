// SPDX-License-Identifier: Apache-2.0
// Deterministic angles and trigonometry for the planner: the same bits on every machine.
//
// Angles are exact integers in micro-degrees (1e-6 degree), parsed from decimal text
// without floating point. Sines and cosines are computed by integer Taylor series in
// Q60 (__int128) and rounded once to Q(kTrigFrac): no libm, no floating point, so the
// fixed-point coefficients and start points of a rotated ellipse never depend on how a
// machine's libm rounds. docs/golden-model.md, "Rotated ellipses", has the error analysis.
#pragma once

#include <cstdint>
#include <string>

namespace dda {

inline constexpr std::int64_t kMicroDeg = 1'000'000;        // micro-degrees per degree
inline constexpr std::int64_t kFullTurn = 360 * kMicroDeg;  // one turn
inline constexpr std::int64_t kQuarterTurn = 90 * kMicroDeg;

// Fraction bits of the sines and cosines (|error| <= 2^-(kTrigFrac+1) + 2^-58).
inline constexpr int kTrigFrac = 40;

struct SinCos {
  std::int64_t c = 0, s = 0;  // cos and sin in Q(kTrigFrac)
};

// cos and sin of an angle given in micro-degrees (any integer; reduced modulo a turn).
// Multiples of 90 degrees give exact 0 and +-1.
SinCos sincos_udeg(std::int64_t udeg);

// Angle text in degrees ("330", "-30", "12.5", "0.000001") to micro-degrees, exactly.
// At most 6 decimals and |value| < 10^9 degrees; anything else throws InputError naming
// `name` and the rule.
std::int64_t parse_degrees(const std::string& name, const std::string& text);
// Micro-degrees back to the shortest decimal text parse_degrees reads to the same value.
std::string format_degrees(std::int64_t udeg);
// udeg reduced to [0, kFullTurn).
std::int64_t normalize_udeg(std::int64_t udeg);

}  // namespace dda
