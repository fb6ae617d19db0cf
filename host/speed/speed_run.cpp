// SPDX-License-Identifier: Apache-2.0
#include "host/speed/speed_run.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace dda::speed {

SpeedRun::SpeedRun(const MachineLimits& lim, program::Machine m, program::Length step, std::string file,
                   std::function<void(const BlockSpeeds&)> on_block,
                   std::function<void(const PlannedSegment&)> on_segment)
    : plim_(planner_limits(lim, m)),
      build_(lim, plim_, step, std::move(file)),
      on_block_(std::move(on_block)),
      on_segment_(std::move(on_segment)),
      ahead_(plim_, [this](const PlannedSegment& p) { segment(p); }) {}

void SpeedRun::block(program::BlockPlan& b) {
  const std::size_t index = blocks_++;
  std::vector<Segment> segs = build_.block(b, index);
  dwell_ += b.move.dwell;
  if (segs.empty()) return;
  BlockSpeeds s;
  s.move = b.move;
  s.pieces = segs.size();
  s.feed = segs.front().feed;
  s.dwell = dwell_;
  s.stop = segs.front().rest_before;
  dwell_ = 0;
  pending_.emplace_back(index, std::move(s));
  for (const Segment& g : segs) ahead_.push(g);
}

void SpeedRun::segment(const PlannedSegment& p) {
  if (on_segment_) on_segment_(p);
  while (pending_.front().first != p.seg.block) {
    on_block_(pending_.front().second);
    pending_.pop_front();
    started_front_ = false;
    front_min_ = kInfinity;
  }
  BlockSpeeds& s = pending_.front().second;
  if (!started_front_) s.entry = p.entry;
  started_front_ = true;
  s.exit = p.exit;
  s.length += p.seg.length;
  s.time += p.time;
  s.cruise = std::max(s.cruise, p.peak);
  // The block's limit: that of its slowest piece held below the feed.
  const Limit l = p.limit();
  if (l != Limit::None && p.peak < front_min_) {
    s.limit = l;
    front_min_ = p.peak;
  }
}

void SpeedRun::finish() {
  ahead_.finish();
  for (; !pending_.empty(); pending_.pop_front()) on_block_(pending_.front().second);
}

double axes_factor(const Segment& s) {
  double sum = 0;
  int moving = 0;
  for (const double share : s.share) {
    sum += share;
    moving += share > 0 ? 1 : 0;
  }
  return std::min(sum, std::sqrt(double(moving)));
}

SpeedTotals plan_program_speeds(std::istream& in, const std::string& file, const program::ReadOptions& read,
                                const program::LatticeOptions& lattice, std::size_t window, const MachineLimits& lim,
                                const std::function<void(const BlockSpeeds&)>& on_block,
                                const std::function<void(const PlannedSegment&)>& on_segment,
                                const std::function<void(const program::BlockPlan&)>& on_pieces) {
  check(lim, read.machine);
  SpeedTotals t;
  SpeedRun run(
      lim, read.machine, lattice.step, file,
      [&](const BlockSpeeds& b) {
        t.add(b);
        on_block(b);
      },
      on_segment);
  const program::Point2 start = read.start.value_or(program::Point2{});
  program::BlockPlanner planner(lattice, start, file, window, [&](program::BlockPlan&& b) {
    run.block(b);
    if (on_pieces) on_pieces(b);
  });
  const program::ReadSummary sum =
      program::read_stream(in, file, read, [&](const program::Move& mv) { planner.move(mv); });
  planner.finish();
  run.finish();
  t.dwell_at_end(sum.dwell_after + run.dwell_left());
  t.plane = sum.plane;
  return t;
}

}  // namespace dda::speed
