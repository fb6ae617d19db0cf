// SPDX-License-Identifier: Apache-2.0
// Points of the ideal curve on the fixed-point sines (the same on every machine): the
// curve point of a parametric angle, and the angle of the curve point nearest to a
// lattice point.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include "host/planner/plan_detail.hpp"

namespace dda {

namespace detail {

void check_axes_and_center(const ArcSpec& spec) {
  if (spec.sub < 0 || spec.sub > kMaxSubBits) {
    throw InputError("sub = " + std::to_string(spec.sub) + " is invalid: sub-step units are 2^-sub step, sub in [0, " +
                     std::to_string(kMaxSubBits) + "]");
  }
  const std::int64_t one = std::int64_t{1} << spec.sub;
  const auto frac_ok = [&](std::int64_t f) { return f >= 0 && f < one; };
  if (!frac_ok(spec.center_frac.x) || !frac_ok(spec.center_frac.y)) {
    throw InputError("center fraction " + pt(spec.center_frac) + " is invalid: each part must be in [0, 2^sub)");
  }
  const std::int64_t a = steps_ceil(spec, spec.a), b = steps_ceil(spec, spec.b);
  if (spec.a < 1) {
    throw InputError("a = " + std::to_string(spec.a) + " is invalid: a semi-axis must be a positive integer");
  }
  if (spec.b < 1) {
    throw InputError("b = " + std::to_string(spec.b) + " is invalid: a semi-axis must be a positive integer");
  }
  const bool rotated = quarter_turns(spec) < 0;
  const std::int64_t lim = std::int64_t{1} << (rotated ? 20 : 30);
  if (a > lim || b > lim) {
    throw InputError((a > lim ? "a = " + std::to_string(a) : "b = " + std::to_string(b)) +
                     " is out of range: semi-axes must be at most 2^" + (rotated ? "20 for a rotated ellipse" : "30"));
  }
  const std::int64_t coord_lim = std::int64_t{1} << 40;
  const auto out = [&](std::int64_t v) { return v < -coord_lim || v > coord_lim; };  // no llabs(INT64_MIN)
  if (out(spec.center.x) || out(spec.center.y)) {
    throw InputError("center " + pt(spec.center) + " is out of range: coordinates must be within 2^40");
  }
}

namespace {

// theta_ideal()'s arithmetic for one ellipse, checked and set up once: the curve point of
// the parametric angle whose fixed-point sines are t.
class CurveFrame {
 public:
  explicit CurveFrame(const ArcSpec& spec) : spec_(spec), qt_(quarter_turns(spec)) {
    check_axes_and_center(spec);
    if (qt_ < 0) f_ = sincos_udeg(spec.angle), off_ = center_offset(spec);
  }
  FixedPoint at(const SinCos& t) const {
    // Frame point (a cos, b sin) in Q(kTrigFrac) (sub-step geometry: Q(kTrigFrac + sub)).
    const i128 u = i128(spec_.a) * t.c, v = i128(spec_.b) * t.s;
    if (qt_ >= 0) {  // exact quarter turns
      i128 x = u, y = v;
      for (int k = 0; k < qt_; ++k) std::tie(x, y) = std::pair<i128, i128>{-y, x};
      return FixedPoint{std::int64_t(round_shift(x, kTrigFrac - kPosFrac)),
                        std::int64_t(round_shift(y, kTrigFrac - kPosFrac))};
    }
    const i128 x = u * f_.c - v * f_.s, y = u * f_.s + v * f_.c;  // Q(2 kTrigFrac + sub)
    // Relative to the lattice centre: the centre's fraction added.
    return FixedPoint{std::int64_t(round_shift(x, 2 * kTrigFrac + spec_.sub - kPosFrac)) + off_.x,
                      std::int64_t(round_shift(y, 2 * kTrigFrac + spec_.sub - kPosFrac)) + off_.y};
  }

 private:
  const ArcSpec& spec_;
  int qt_;
  SinCos f_{};
  FixedPoint off_{};
};

}  // namespace

namespace {

constexpr int kNearestSamples = 1440;

// The sines of the samples, computed once (sincos_udeg is deterministic).
const std::array<SinCos, kNearestSamples>& nearest_samples() {
  static const std::array<SinCos, kNearestSamples> table = [] {
    std::array<SinCos, kNearestSamples> t{};
    for (int k = 0; k < kNearestSamples; ++k) t[std::size_t(k)] = sincos_udeg(k * (kFullTurn / kNearestSamples));
    return t;
  }();
  return table;
}

// The first of the samples whose exact squared distance d2_of() is the least, without
// computing every one: the samples come in blocks of kBlock, and a block's samples are
// computed only if the block can hold the least. Along the curve a sample is at most
// L = R * 2 pi / kNearestSamples from the next (R the larger semi-axis in Q(kPosFrac)
// units, plus the fixed-point curve's rounding), so a block's distances lie within
// (kBlock - 1) L of its first sample's; a block whose first sample is farther than that
// beyond the nearest first sample holds none as near as that one, and is skipped. (The
// square roots in double are off by far less than the margins.)
template <typename D2>
int nearest_sample(const ArcSpec& spec, const D2& d2_of) {
  constexpr int kBlock = 8, kBlocks = kNearestSamples / kBlock;
  static_assert(kNearestSamples % kBlock == 0, "whole blocks");
  const auto& samples = nearest_samples();
  const double r = std::ldexp(double(std::max(spec.a, spec.b)), kPosFrac - spec.sub);
  const double reach = (kBlock - 1) * (r * 2 * M_PI / kNearestSamples * (1 + 1e-6) + r * 1e-8 + 4);
  const auto dist = [](i128 d2) { return std::sqrt(double(d2)); };
  std::array<i128, kBlocks> first{};
  double nearest_first = std::numeric_limits<double>::infinity();
  for (int b = 0; b < kBlocks; ++b) {
    first[std::size_t(b)] = d2_of(samples[std::size_t(b * kBlock)]);
    nearest_first = std::min(nearest_first, dist(first[std::size_t(b)]));
  }
  const double margin = nearest_first * 1e-12 + 1;
  int best = 0;
  i128 best_d = first[0];
  for (int b = 0; b < kBlocks; ++b) {
    const double d = dist(first[std::size_t(b)]);
    if (d - d * 1e-12 - reach - 1 > nearest_first + margin) continue;
    for (int k = b * kBlock; k < (b + 1) * kBlock; ++k) {
      const i128 dk = k == b * kBlock ? first[std::size_t(b)] : d2_of(samples[std::size_t(k)]);
      if (dk < best_d) best_d = dk, best = k;
    }
  }
  return best;
}

}  // namespace

// The parametric angle (micro-degrees) of the curve point nearest to lattice point q,
// found with the deterministic fixed-point curve points (the same on every machine): the
// best of 1440 samples, then a ternary search of the bracket around it to the micro-degree.
std::int64_t nearest_theta(const ArcSpec& spec, Point q) {
  const CurveFrame curve(spec);
  const i128 qx = i128(q.x - spec.center.x) << kPosFrac, qy = i128(q.y - spec.center.y) << kPosFrac;
  const auto d2_of = [&](const SinCos& t) {
    const FixedPoint f = curve.at(t);
    const i128 dx = f.x - qx, dy = f.y - qy;
    return dx * dx + dy * dy;
  };
  const auto d2 = [&](std::int64_t t) { return d2_of(sincos_udeg(t)); };
  constexpr std::int64_t kStep = kFullTurn / kNearestSamples;
  const std::int64_t best = kStep * nearest_sample(spec, d2_of);
  std::int64_t lo = best - kStep, hi = best + kStep;
  while (hi - lo > 2) {
    const std::int64_t m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (d2(m1) <= d2(m2)) {
      hi = m2;
    } else {
      lo = m1;
    }
  }
  std::int64_t t = lo;
  for (std::int64_t k = lo + 1; k <= hi; ++k) {
    if (d2(k) < d2(t)) t = k;
  }
  return normalize_udeg(t);
}

}  // namespace detail

FixedPoint theta_ideal(const ArcSpec& spec, std::int64_t theta) {
  return detail::CurveFrame(spec).at(sincos_udeg(theta));
}

}  // namespace dda
