// SPDX-License-Identifier: Apache-2.0
// The turns of a rotated ellipse for the anchored planner (plan_anchored.cpp): where the
// ideal curve's tangent is parallel to an axis.
#include <vector>

#include "host/planner/plan_detail.hpp"

namespace dda::detail {

std::pair<i128, i128> ideal_tangent(const ArcSpec& spec, std::int64_t theta) {
  const SinCos t = sincos_udeg(theta), f = sincos_udeg(spec.angle);
  const i128 du = -i128(spec.a) * t.s, dv = i128(spec.b) * t.c;
  return {du * f.c - dv * f.s, du * f.s + dv * f.c};
}

namespace {

// The four turns of a rotated ellipse, found on the deterministic fixed-point sines (the
// same on every machine): the sign changes among 1440 samples, each bisected to the
// micro-degree; a turn's angle is the first micro-degree with the new sign.
std::vector<Turn> find_turns(const ArcSpec& spec) {
  constexpr int kSamples = 1440;
  constexpr std::int64_t kStep = kFullTurn / kSamples;
  std::vector<Turn> v;
  for (const char axis : {'X', 'Y'}) {
    const auto pos = [&](std::int64_t t) {
      const auto [tx, ty] = ideal_tangent(spec, normalize_udeg(t));
      return (axis == 'X' ? tx : ty) > 0;
    };
    for (int k = 0; k < kSamples; ++k) {
      std::int64_t lo = k * kStep, hi = lo + kStep;
      const bool s = pos(lo);
      if (pos(hi) == s) continue;
      while (hi - lo > 1) {
        const std::int64_t m = lo + (hi - lo) / 2;
        (pos(m) == s ? lo : hi) = m;
      }
      v.push_back(Turn{normalize_udeg(hi), axis});
    }
  }
  return v;
}

}  // namespace

// The turns depend only on the semi-axes and the angle (a circle's only on the angle:
// its tangent is a's multiple of the unit circle's, and only signs are compared), and a
// program repeats them: the last few are kept.
std::vector<Turn> turns_of(const ArcSpec& spec) {
  struct Key {
    std::int64_t a, b, angle;
    bool operator==(const Key& o) const { return a == o.a && b == o.b && angle == o.angle; }
  };
  struct Kept {
    Key key;
    std::vector<Turn> turns;
  };
  constexpr std::size_t kKept = 16;
  thread_local std::vector<Kept> kept;
  thread_local std::size_t next = 0;
  const Key key = spec.a == spec.b ? Key{1, 1, spec.angle} : Key{spec.a, spec.b, spec.angle};
  for (const Kept& k : kept) {
    if (k.key == key) return k.turns;
  }
  ArcSpec unit = spec;
  unit.a = key.a;
  unit.b = key.b;
  std::vector<Turn> v = find_turns(unit);
  if (kept.size() < kKept) {
    kept.push_back(Kept{key, v});
  } else {
    kept[next] = Kept{key, v};
    next = (next + 1) % kKept;
  }
  return v;
}

}  // namespace dda::detail
