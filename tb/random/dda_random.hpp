// SPDX-License-Identifier: Apache-2.0
// Seeded random arc configurations shared by the property tests, the lockstep tests
// and the regression scripts: a, b log-uniform in [1, max_axis] (max_axis no larger than
// the widths allow, hw::max_semi_axis), n uniform from the
// smallest valid width to +8, both preloads; start and end points drawn on the quarter
// (ArcKind::Quarter) or anywhere on a whole, moved, possibly turned ellipse (ArcKind::Whole).
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>

#include "host/accuracy/golden.hpp"
#include "host/report/report.hpp"

namespace dda {

// The seed for a test: DDA_SEED from the environment if set, else the default.
std::uint64_t test_seed(std::uint64_t default_seed);

// The paper's worked example (Table 1): a = 10, b = 6, capacity 2^4, zero preload.
ArcSpec paper_example();

enum class ArcKind {
  Quarter,  // quadrant I, counter-clockwise, sub-arcs of the quarter (the paper's case)
  Whole,    // any arc: random centre, start and end anywhere on the ellipse, both
            // directions, full turns, circles, quarter turns of the axes
  Program,  // as part programs give them: lattice start and end points
            // rounded from random points of the curve, full turns by point and by angle,
            // aspect ratios up to 1000, half of the ellipses rotated, and lines
  Spatial,  // the third axis: 3-D lines (each axis in turn the longest), moves of the
            // third axis alone (plunges), and helices (Program's arcs with a random rise
            // of either sign, up to one step per iteration)
};

// The seed of case `index` of a run seeded `seed`: every case draws from its own stream,
// so a run cut into shards draws the same cases as one unsharded run.
std::uint64_t case_seed(std::uint64_t seed, std::uint64_t index);

// A shard "I/N" (0 <= I < N) of a run's cases: those whose index is I modulo N.
struct Shard {
  std::uint64_t index = 0, count = 1;
  bool has(std::uint64_t case_index) const { return case_index % count == index; }
};
// Parses "I/N"; throws std::invalid_argument naming the rule.
Shard parse_shard(const std::string& text);

class RandomArcs {
 public:
  RandomArcs(std::uint64_t seed, std::int64_t max_axis, int extra_bits_max = 8, ArcKind kind = ArcKind::Quarter);
  // The next configuration, or nullopt when the drawn one was rejected by plan_arc
  // (an unreachable end point, for example); rejected() counts those.
  std::optional<Plan> next();
  std::uint64_t rejected() const { return rejected_; }
  // The planner's message for the last rejected draw.
  const std::string& last_refusal() const { return last_refusal_; }
  // Program arcs: the kind of the last draw, for the sweep's classes.
  enum class Drawn { Line, AxisAligned, Rotated };
  Drawn drawn() const { return drawn_; }
  bool drawn_thin() const { return drawn_thin_; }  // aspect ratio above 4
  // The options of the last draw (for a report when planning it failed).
  const std::string& drawn_options() const { return drawn_options_; }

 private:
  std::mt19937_64 rng_;
  std::int64_t max_axis_;
  int extra_bits_max_;
  ArcKind kind_;
  std::uint64_t rejected_ = 0;
  std::string last_refusal_;
  Drawn drawn_ = Drawn::AxisAligned;
  bool drawn_thin_ = false;
  std::string drawn_options_;
  std::optional<Plan> next_program();
  std::optional<Plan> next_spatial();
};

}  // namespace dda
