// SPDX-License-Identifier: Apache-2.0
// The reports of a part program's run, as streams (pipeline.hpp): one row per motion
// block as soon as its records have passed (source line, block number, kind,
// programmed end in mm, its lattice point and rounding, commands, steps, iterations,
// largest and mean distance from the programmed geometry, its target) with running
// totals, and the picture of the whole path over the programmed geometry.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "host/pipeline/pipeline.hpp"
#include "host/program_plan/program_plan.hpp"
#include "host/report/report.hpp"

namespace dda::program {

// A length in exact decimal millimetres, trailing zeros dropped ("-2.5", "10").
std::string mm(Length v);

enum class BlockStatsFormat { Text, Csv, Json };

// What the report of a block has gathered from its records.
struct BlockStats {
  std::uint64_t iterations = 0, steps = 0, points = 0;
  double max_dev = 0, sum_dev = 0;
  Point max_at, end;
};

// The blocks announced and not yet passed by the records: the block of a record.
class BlockWindow {
 public:
  struct Entry {
    BlockPlan block;
    BlockDistance distance;
    BlockStats stats;
    std::uint64_t pieces_end;  // the index of the first piece after the block's
  };
  explicit BlockWindow(Length step) : step_(step) {}
  void push(const BlockPlan& b);
  // The block of piece `piece`; the blocks before it are handed to `done` first.
  template <typename Done>
  Entry& of_piece(std::uint32_t piece, Done done) {
    while (!held_.empty() && held_.front().pieces_end <= piece) {
      done(held_.front());
      held_.pop_front();
    }
    return front();
  }
  template <typename Done>
  void drain(Done done) {
    for (; !held_.empty(); held_.pop_front()) done(held_.front());
  }

 private:
  Entry& front();
  Length step_;
  std::deque<Entry> held_;
};

class BlockStatsSink : public RunSink {
 public:
  // third_axis: the program may move the axis normal to its plane; each block's end
  // then has its third coordinate (mm and steps; in CSV two more columns at the end).
  BlockStatsSink(std::ostream& os, const LatticeOptions& lattice, Point2 start, BlockStatsFormat fmt,
                 bool third_axis = false);
  void block(const BlockPlan& b) override;
  void record(const Iteration& it) override;
  void finish() override;
  bool steps_only() const override { return true; }

 private:
  void header();
  void measure(BlockWindow::Entry& e);
  void row(BlockWindow::Entry& e);
  std::string end_text(const BlockPlan& b, bool in_mm) const;
  std::ostream& os_;
  LatticeOptions lattice_;
  Point start_;
  BlockStatsFormat fmt_;
  bool z_ = false;
  // The points of the front block whose distance is not measured yet: measured
  // kMeasureBatch at a time, in their order (the same sums and maxima as one by one).
  static constexpr std::size_t kMeasureBatch = 256;
  std::array<Point, kMeasureBatch> pending_;
  std::size_t pending_n_ = 0;
  bool started_ = false;
  BlockWindow window_;
  bool targeted_;
  double prev_rounding_ = 0;
  std::uint64_t last_iter_ = 0;  // the previous record's `iter`
  // Totals.
  std::uint64_t blocks_ = 0, commands_ = 0, it_sum_ = 0, steps_ = 0, points_ = 0, over_ = 0;
  double worst_ = 0, round_worst_ = 0, dev_sum_ = 0;
  std::size_t worst_line_ = 0;
  bool all_ok_ = true;
};

// The whole path over the programmed geometry (dda plot --program), bounded: the path
// through PathSample, the geometry's vertices likewise.
class ProgramSvgSink : public RunSink {
 public:
  // view: the projection (the third axis against x or y: --view xz|yz); the markers are
  // coloured by their distance in the plane from the programmed geometry in every view.
  ProgramSvgSink(std::ostream& os, const LatticeOptions& lattice, Point2 start, std::string title,
                 View view = View::XY);
  void block(const BlockPlan& b) override;
  void record(const Iteration& it) override;
  void finish() override;
  bool steps_only() const override { return true; }

 private:
  void geometry(const BlockPlan& b);
  void thin_ideal();
  std::ostream& os_;
  LatticeOptions lattice_;
  std::string title_;
  View view_;
  BlockWindow window_;
  PathSample sample_;
  bool first_ = true;
  Point start_;
  std::vector<std::vector<std::pair<double, double>>> ideal_;
  std::size_t ideal_vertices_ = 0, ideal_budget_ = 200000;
  std::uint64_t ideal_seq_ = 0, ideal_stride_ = 1;
  bool provisional_ = false;
};

}  // namespace dda::program
