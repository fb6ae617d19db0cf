// SPDX-License-Identifier: Apache-2.0
// Engine-independent views of a run: trace rows, path, statistics.
//
// Every engine (golden, SystemC, RTL) turns its run into a vector of Iteration records;
// these functions print them, so the same command with another engine prints the same
// rows and `diff` is a valid cross-check.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "dda/golden.hpp"

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

// Lattice points of the path: the start, then the position after every move.
std::vector<Point> path_points(const Plan& plan, const std::vector<Iteration>& iters);

enum class PathFormat { Csv, Json };
void write_path(std::ostream& os, const std::vector<Point>& points, PathFormat fmt);

struct Stats {
  std::uint64_t iterations = 0, moves = 0, pulses_x = 0, pulses_y = 0, points = 0;
  double max_dev = 0.0;  // largest distance of a path point from the ellipse, in steps
  Point max_dev_at;
  double mean_dev = 0.0;
};
Stats compute_stats(const Plan& plan, const std::vector<Iteration>& iters);

enum class StatsFormat { Text, Json };
void write_stats(std::ostream& os, const Plan& plan, const Stats& s, StatsFormat fmt);

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
  std::size_t max_markers = 4000;  // point markers drawn at most (every k-th beyond)
};
void write_svg(std::ostream& os, const SvgPicture& pic);

}  // namespace dda
