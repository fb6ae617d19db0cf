// SPDX-License-Identifier: Apache-2.0
// Seeded random arc configurations shared by the property tests, the lockstep tests
// and the regression scripts: a, b log-uniform in [1, max_axis], n uniform from the
// smallest valid width to +8, both preloads; start and end points drawn on the quarter
// (ArcKind::Quarter) or anywhere on a whole, moved, possibly turned ellipse (ArcKind::Whole).
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>

#include "dda/golden.hpp"
#include "dda/report.hpp"

namespace dda {

// The seed for a test: DDA_SEED from the environment if set, else the default.
std::uint64_t test_seed(std::uint64_t default_seed);

enum class ArcKind {
  Quarter,  // quadrant I, counter-clockwise, sub-arcs of the quarter (the paper's case)
  Whole,    // any arc: random centre, start and end anywhere on the ellipse, both
            // directions, full turns, circles, quarter turns of the axes
};

class RandomArcs {
 public:
  RandomArcs(std::uint64_t seed, std::int64_t max_axis, int extra_bits_max = 8, ArcKind kind = ArcKind::Quarter);
  // The next configuration, or nullopt when the drawn one was rejected by plan_arc
  // (an unreachable end point, for example); rejected() counts those.
  std::optional<Plan> next();
  std::uint64_t rejected() const { return rejected_; }

 private:
  std::mt19937_64 rng_;
  std::int64_t max_axis_;
  int extra_bits_max_;
  ArcKind kind_;
  std::uint64_t rejected_ = 0;
};

}  // namespace dda
