// SPDX-License-Identifier: Apache-2.0
// Exact integer rounding in 128 bits, the one definition the planner, the reader and the
// program planner share: halves away from zero, as docs/golden-model.md states.
#pragma once

namespace dda {

using i128 = __int128;

// v / 2^sh rounded to nearest, halves away from zero (sh >= 1).
inline i128 round_shift(i128 v, int sh) {
  const i128 half = i128(1) << (sh - 1);
  return v < 0 ? -((-v + half) >> sh) : (v + half) >> sh;
}

// num / den rounded to nearest, halves away from zero (den > 0).
inline i128 round_div(i128 num, i128 den) { return num < 0 ? -((-num + den / 2) / den) : (num + den / 2) / den; }

}  // namespace dda
