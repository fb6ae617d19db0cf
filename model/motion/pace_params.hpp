// SPDX-License-Identifier: Apache-2.0
// The pacer's units and widths (docs/design.md, "Pacer"): the one definition the
// reference model (model/motion/pacer.hpp) and the SystemC model (model/systemc/dda_pace.hpp) read;
// rtl/dda_pace.v takes them as parameters whose defaults tests/test_pace.cpp checks by
// running it beside the reference.
#pragma once

#include <cstdint>

namespace dda::motion {

// Units. Entry speeds: path steps per clock x 2^kSpeedFrac (32 bits: at most 1 step per
// clock, a resolution of 0.0093 steps/s at 40 MHz). The commanded speed, the phase and
// the acceleration (steps per clock per clock): x 2^kRampFrac. Distances kept inside:
// x 2^kDistFrac steps; entry lengths: x 2^kLenFrac steps. The override: x 1/kOverrideOne.
inline constexpr int kSpeedFrac = 32;
inline constexpr int kRampFrac = 48;
inline constexpr int kDistFrac = 32;
inline constexpr int kLenFrac = 8;
inline constexpr int kNormFrac = 20;
inline constexpr std::uint32_t kOverrideOne = 256;  // 100%; OVERRIDE runs 0 .. 2 * kOverrideOne (200%)
inline constexpr int kOverrideBits = 10;            // the override's width
// The cruise speed times the override is formed by shift and add, a bit of the override
// per clock: ready kOverrideBits clocks after a take or an override change.
inline constexpr int kOverrideClocks = kOverrideBits;
// Clocks from a step to the fresh d: one divider and one squarer serve the three axes,
// two bits per clock (rtl/dda_norm.v): three divisions, the last square, the sum, the
// root, each of kNormClocks clocks.
inline constexpr int kNormClocks = (kNormFrac + 2) / 2;  // ceil((kNormFrac + 1) / 2)
inline constexpr int kNormLatency = 5 * kNormClocks + 1;
// The norm unit reads z's operands kNormOperandEdges edges after its start, x's and
// y's before: they must hold until then.
inline constexpr int kNormOperandEdges = 2 * kNormClocks + 1;
inline constexpr int kMarginShift = 3;  // ramp down 2^-kMarginShift step before the end
// The phase saturates below 2^kPhaseBits (256 steps of path): a speed the core cannot
// follow (above one iteration per clock, or one step per kNormLatency + 1 clocks) leaves
// a backlog the phase cannot grow without bound.
inline constexpr int kPhaseBits = kRampFrac + 8;
// The phase is signed: a correction of provisional iterations (docs/design.md, "Pacer")
// takes it below 0 by less than 2^kPhaseBits.
inline constexpr int kPhaseWidth = kPhaseBits + 1;
// The iterations the pacer paces with the run before's d, at most: the norm unit's
// clocks after it has read its operands.
inline constexpr int kProvisionalMax = kNormLatency - kNormOperandEdges + 1;
// The bits of a count from 0 to n (the RTL's $clog2(n + 1)): the pacer's counters'
// widths, derived from their ranges as rtl/dda_pace.v derives them.
constexpr int count_bits(int n) {
  int b = 0;
  while ((1 << b) <= n) ++b;
  return b;
}
inline constexpr int kProvisionalWidth = count_bits(kProvisionalMax);
// The correction is applied a bit of the provisional count per clock after the pacer
// takes the run's d: the difference of two d's (below 2^(kNormFrac + 2) either way)
// shifted up by up to kProvisionalWidth - 1 bits, signed.
inline constexpr int kCorrectionWidth = kNormFrac + 2 + kProvisionalWidth;
// The widths of the block's pacing registers: ACCEL (x 2^kRampFrac), VMIN (x 2^kSpeedFrac).
inline constexpr int kAccelWidth = 32;
// The widths of rtl/dda_pace.v's registers the block harnesses compare: s and the distance
// to go (below 2^(kDistFrac + 25)), the norm unit's clock count (up to kNormLatency), the
// product's clock count (up to kOverrideClocks).
inline constexpr int kDistWidth = kDistFrac + 26;
inline constexpr int kNormBusyWidth = count_bits(kNormLatency);
inline constexpr int kOverrideCountWidth = 4;
static_assert(kOverrideClocks < (1 << kOverrideCountWidth), "the product's clock count fits its register");
// A correction: at most kProvisionalMax times a d (below 2^(kNormFrac + 2)), at the
// phase's scale, within the phase's range below 0.
static_assert(std::int64_t(kProvisionalMax) << (kNormFrac + 2 + kRampFrac - kNormFrac) < std::int64_t(1) << kPhaseBits,
              "a correction fits the phase");

}  // namespace dda::motion
