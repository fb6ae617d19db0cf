// SPDX-License-Identifier: Apache-2.0
// Engine-independent views of a run: trace rows, path, statistics.
//
// Every engine (golden, SystemC, RTL) turns its run into a stream of Iteration records;
// the sinks below print them as they come (pipeline.hpp), so the same command with
// another engine prints the same rows and `diff` is a valid cross-check. Each keeps a
// bounded state: running aggregates, the few pieces in flight, a sampled picture.
#pragma once

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "host/accuracy/golden.hpp"
#include "host/pipeline/pipeline.hpp"

namespace dda {

// v / scale rounded to 4 decimals (half away from zero), exact integer arithmetic.
std::string paper_units(std::int64_t v, std::int64_t scale);

enum class TraceFormat { Csv, Table, Json };
// Row 0 shows `initial` (the registers after the first command's load; by default the
// command's own values). The paper's columns are printed for a one-piece
// counter-clockwise quadrant-I arc about the origin; any other arc adds the piece, the
// step directions and the position after each iteration.
void write_trace(std::ostream& os, const Plan& plan, const RegState& initial, const std::vector<Iteration>& iters,
                 TraceFormat fmt);
void write_trace(std::ostream& os, const Plan& plan, const std::vector<Iteration>& iters, TraceFormat fmt);
bool paper_columns(const Plan& plan);
// Does a plan move the third axis (or run away from its zero)? Its reports then add the
// third axis' columns; a plan of the plane alone reports as the two-axis core did.
bool third_axis(const Plan& plan);

// Lattice points of the path: the start, then the position after every move.
std::vector<Point> path_points(const Plan& plan, const std::vector<Iteration>& iters);

enum class PathFormat { Csv, Json };
void write_path(std::ostream& os, const std::vector<Point>& points, PathFormat fmt);

struct Stats {
  std::uint64_t iterations = 0, moves = 0, pulses_x = 0, pulses_y = 0, pulses_z = 0, points = 0;
  double max_dev = 0.0;  // largest distance of a path point from the ellipse, in steps
  Point max_dev_at;
  double mean_dev = 0.0;
};
Stats compute_stats(const Plan& plan, const std::vector<Iteration>& iters);
enum class StatsFormat { Text, Json };

void write_stats(std::ostream& os, const Plan& plan, const Stats& s, StatsFormat fmt);

// The trace as a stream: the header and row 0 at initial(), a row per record. For a
// program (the second constructor) the header names its start, the closing line its
// commands and end, and in JSON each piece's command stands in its first record.
class TraceSink : public RunSink {
 public:
  TraceSink(std::ostream& os, const Plan& plan, TraceFormat fmt);
  // third_axis: the program may move the third axis (its columns are written).
  TraceSink(std::ostream& os, Preload preload, Point from, TraceFormat fmt, bool third_axis);
  void initial(const RegState& r) override;
  void piece(const Piece& pc) override;
  void record(const Iteration& it) override;
  void finish() override;

 private:
  void header(const RegState& r);
  void json_header(const RegState& init);
  void json_record(const Iteration& it, const Piece& pc);
  std::ostream& os_;
  const Plan* plan_ = nullptr;  // null for a program
  Preload preload_;
  Point from_, at_;
  TraceFormat fmt_;
  bool paper_ = false;
  bool z_ = false;  // the third axis' columns
  PieceWindow window_;
  std::uint64_t pieces_ = 0, records_ = 0;
  std::int64_t last_piece_ = -1;
};

// The path as a stream: the start, then the position after every move.
// (Written from the first piece on: a program the reader refuses prints nothing.)
class PathSink : public RunSink {
 public:
  // third_axis: each point has its third coordinate.
  PathSink(std::ostream& os, Point from, PathFormat fmt, bool third_axis = false);
  void piece(const Piece&) override { start(); }
  void record(const Iteration& it) override;
  void finish() override;
  bool steps_only() const override { return true; }

 private:
  void start();
  void point(Point p);
  std::ostream& os_;
  PathFormat fmt_;
  Point from_;
  bool z_ = false;
  bool started_ = false;
  std::uint64_t n_ = 0;
};

// Running statistics of one arc's or line's run; written to `os` (if given) at finish().
class StatsSink : public RunSink {
 public:
  explicit StatsSink(const Plan& plan, std::ostream* os = nullptr, StatsFormat fmt = StatsFormat::Text);
  void record(const Iteration& it) override;
  void finish() override;
  bool steps_only() const override { return true; }
  const Stats& stats();

 private:
  void point(Point p);
  const Plan& plan_;
  std::ostream* os_;
  StatsFormat fmt_;
  Stats s_;
  double sum_ = 0;
};

// A bounded sample of a path for a picture: every point while there are at most
// `budget`, beyond that every k-th (k doubling as needed), always the farthest from the
// ideal geometry, and points marked `keep` (block ends) while they are at most a
// quarter of the budget.
class PathSample {
 public:
  explicit PathSample(std::size_t budget = 200000) : budget_(std::max<std::size_t>(budget, 8)) {}
  void add(Point p, double dist, bool keep = false);
  std::uint64_t seen() const { return seen_; }
  std::uint64_t stride() const { return stride_; }
  // The kept points in path order, with their distances.
  void take(std::vector<Point>& pts, std::vector<double>& dist);

 private:
  struct Kept {
    std::uint64_t seq;
    Point p;
    double dist;
    bool keep;
  };
  void thin();
  std::size_t budget_;
  std::vector<Kept> kept_;
  std::uint64_t seen_ = 0, stride_ = 1, marked_ = 0;
  bool have_worst_ = false;
  Kept worst_{};
};

// The plot of one arc's or line's run (write_svg at finish()).
// The projection a picture draws (dda plot --view): the plane of the two ellipse axes,
// or the third axis against one of them.
enum class View { XY, XZ, YZ };
// A point in a view: (x, y), (x, z) or (y, z) as the picture's (x, y).
inline Point project(Point p, View v) {
  return v == View::XY ? Point{p.x, p.y} : v == View::XZ ? Point{p.x, p.z} : Point{p.y, p.z};
}
// The view's axis names ("x", "y"; "x", "z"; "y", "z").
inline std::pair<const char*, const char*> view_axes(View v) {
  return v == View::XY ? std::pair{"x", "y"} : v == View::XZ ? std::pair{"x", "z"} : std::pair{"y", "z"};
}

class SvgSink : public RunSink {
 public:
  // The markers are coloured by their distance in the plane (x, y) from the ellipse in
  // every view.
  SvgSink(std::ostream& os, const Plan& plan, std::string title, View view = View::XY);
  void record(const Iteration& it) override;
  void finish() override;
  bool steps_only() const override { return true; }

 private:
  std::ostream& os_;
  const Plan& plan_;
  std::string title_;
  View view_;
  PathSample sample_;
};

// Reproducer for a plan: the `dda` options that rebuild it.
std::string describe(const Plan& plan);

// An SVG picture of the path over its ideal ellipse: point markers coloured by their
// distance from the curve, a colour legend, axes in steps, and the largest deviation
// ringed and labelled "max D @ (x,y)" (dda plot).
void write_svg(std::ostream& os, const Plan& plan, const std::vector<Iteration>& iters, const std::string& title);
// The same picture of any path: its points with their distances (steps) from the ideal
// geometry, drawn as polylines of (x, y) in steps; `curve` names it in the legend.
struct SvgPicture {
  std::vector<Point> pts;
  std::vector<double> dist;
  std::vector<std::vector<std::pair<double, double>>> ideal;
  std::string title, curve;
  // Optionally a second path drawn over it in orange (a comparison), with its legend
  // label, and a view window (x0, y0, x1, y1 in steps) instead of the path's extent.
  std::vector<Point> other;
  std::string other_label;
  std::vector<double> view;
  View projection = View::XY;      // names the axes
  std::size_t max_markers = 4000;  // point markers drawn at most (every k-th beyond)
  // The path's points before sampling (PathSample): 0 when pts holds them all.
  std::uint64_t sampled_from = 0;
  std::uint64_t sample_stride = 1;
};
void write_svg(std::ostream& os, const SvgPicture& pic);

}  // namespace dda
