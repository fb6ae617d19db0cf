// SPDX-License-Identifier: Apache-2.0
// The lathe paper's macro program (304 G01 chords of the oblique ellipse) against the same
// contour as one native ellipse block (docs/results.md, "The lathe paper's macro
// program"). Both programs are read, planned and run on the golden model (the SystemC
// model and the RTL run them identically: tests/check-examples.sh); over the contour's
// blocks (G01 chords, or the G6.3 block) it measures blocks, core commands, steps,
// iterations, the lattice path's largest and mean distance from the ideal ellipse, the
// programmed chords' own largest distance, and the direction reversals; it prints a
// markdown table and draws both paths in one picture and a close-up. At feeds (--feeds),
// with the lathe's default limits but the acceleration and the junction deviation
// given, it plans both programs' speeds (docs/programs.md, "Feeds and speeds"), runs
// the plans on the pacer's reference model at 40 MHz and prints a second table: the
// contour's planned time, the slowest junction inside it, the whole program's planned
// and paced time, and how much sooner the native block ends; --speed-svg PREFIX draws
// each program's speed at one of the feeds (PREFIX-macro.svg, PREFIX-native.svg).
//   usage: paper_compare --macro FILE --native FILE [--svg FILE --closeup FILE]
//          [--feeds F,F,.. --accel A --junction-deviation D --speed-svg PREFIX --speed-feed F]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "host/geometry/fixed_trig.hpp"
#include "host/geometry/geometry.hpp"
#include "host/program_plan/program_plan.hpp"
#include "host/report/report.hpp"
#include "host/runner/runner.hpp"
#include "host/speed/pace_plan.hpp"
#include "tb/measure/pace_report.hpp"

using namespace dda;
using namespace dda::program;

namespace {

// The paper's ellipse (../shared/spec/ellipse-dda.md): A 25 mm along 330 degrees, B 15 mm,
// centre Z -30 mm, X 5 mm as a radius; in steps of 0.001 mm.
constexpr double kA = 25000, kB = 15000, kCu = -30000, kCv = 5000;
constexpr std::int64_t kAngle = 330000000;  // micro-degrees

double ellipse_dist(double x, double y) {
  const auto [u, v] = to_frame(kAngle, x - kCu, y - kCv);
  return ellipse_distance(kA, kB, u, v);
}

struct Measure {
  std::string name;
  std::size_t blocks = 0, commands = 0;
  std::uint64_t steps = 0, iterations = 0, reversals = 0;
  double max_dev = 0, sum_dev = 0, chord_dev = 0;
  std::vector<Point> path;  // the contour's lattice points
  Point first, last;
};

bool contour_block(const Move& m) {
  return m.kind == MoveKind::Line || m.kind == MoveKind::EllipseCw || m.kind == MoveKind::EllipseCcw;
}

ReadOptions lathe_at_start() {
  ReadOptions ro;
  ro.machine = Machine::Lathe;
  ro.start = start_point(Machine::Lathe, 60 * kNmPerMm, 5 * kNmPerMm);  // X60 Z5, as the examples' Run line
  return ro;
}

Measure measure(const std::string& file, const std::string& name) {
  std::ifstream in(file);
  if (!in) throw InputError("cannot read " + file);
  std::stringstream text;
  text << in.rdbuf();
  const ProgramPlan pp = plan_program(read(text.str(), file, lathe_at_start()), LatticeOptions{}, file);
  Measure m;
  m.name = name;
  for (const BlockPlan& b : pp.blocks) {
    if (!contour_block(b.move)) continue;
    ++m.blocks;
    m.commands += b.plan.pieces.size();
    if (b.move.kind == MoveKind::Line) {  // the chord's own distance: its middle is the farthest
      const double s = double(pp.lattice.step);
      const double mx = double(b.move.from.u + b.move.to.u) / 2 / s, my = double(b.move.from.v + b.move.to.v) / 2 / s;
      m.chord_dev = std::max(m.chord_dev, ellipse_dist(mx, my));
    }
  }
  int dir_x = 0, dir_y = 0;
  bool started = false;
  run(pp.plan, [&](const Iteration& it) {
    if (!contour_block(pp.blocks[block_of_piece(pp, it.piece)].move)) return;
    if (!started) {
      started = true;
      m.first = Point{it.pos.x - (it.step_x ? (it.dir_x_neg ? -1 : 1) : 0),
                      it.pos.y - (it.step_y ? (it.dir_y_neg ? -1 : 1) : 0)};
      m.path.push_back(m.first);
    }
    ++m.iterations;
    if (!it.step_x && !it.step_y) return;
    ++m.steps;
    const int dx = it.step_x ? (it.dir_x_neg ? -1 : 1) : 0, dy = it.step_y ? (it.dir_y_neg ? -1 : 1) : 0;
    if (dx != 0) m.reversals += dir_x != 0 && dx != dir_x, dir_x = dx;
    if (dy != 0) m.reversals += dir_y != 0 && dy != dir_y, dir_y = dy;
    const double d = ellipse_dist(double(it.pos.x), double(it.pos.y));
    m.max_dev = std::max(m.max_dev, d);
    m.sum_dev += d;
    m.path.push_back(it.pos);
    m.last = it.pos;
  });
  return m;
}

// The paper's ellipse from parametric angle t0 to t1 (degrees).
std::vector<std::pair<double, double>> ideal_arc(double t0, double t1) {
  return ellipse_points(EllipseDrawing{kCu, kCv, kA, kB, kAngle}, t0 * M_PI / 180, (t1 - t0) * M_PI / 180, 2000);
}

void picture(const std::string& path, const Measure& native, const Measure& chords, const std::vector<double>& view,
             const std::string& title) {
  SvgPicture pic;
  pic.pts = native.path;
  for (const Point& p : pic.pts) pic.dist.push_back(ellipse_dist(double(p.x), double(p.y)));
  pic.ideal.push_back(ideal_arc(50, 146));
  pic.title = title;
  pic.curve = "the ellipse";
  pic.other = chords.path;
  pic.other_label = "chords";
  pic.view = view;
  pic.max_markers = 1500;
  std::ofstream out(path);
  write_svg(out, pic);
  if (!out) throw GuardError("cannot write " + path);
}

// One program at one feed: its plan and the plan's run on the pacer.
struct Timed {
  double contour_time = 0, slowest = 0, planned = 0, paced = 0;
  std::size_t pieces = 0;
};

Timed timed(const std::string& file, const speed::MachineLimits& lim, const std::string& svg) {
  std::ifstream in(file);
  if (!in) throw InputError("cannot read " + file);
  const speed::PlannedProgram pp = speed::plan_program_pieces(in, file, lathe_at_start(), LatticeOptions{}, lim);
  const speed::PlannerLimits pl = speed::planner_limits(lim, Machine::Lathe);
  const speed::PaceSetup setup = speed::pace_setup(pl, lim, LatticeOptions{}.step, 40e6);
  Timed t;
  t.slowest = speed::kInfinity;
  // The junctions inside the contour: the speed each allows (Grbl's, at most the feed),
  // at every piece of a contour block but the contour's first.
  bool inside = false;
  std::size_t seg = 0;
  for (const speed::BlockSpeeds& b : pp.blocks) {
    const std::size_t first = seg;
    seg += b.pieces;
    if (!contour_block(b.move)) continue;
    t.contour_time += b.time;
    t.pieces += b.pieces;
    for (std::size_t k = first; k < seg; ++k) {
      if (inside) t.slowest = std::min(t.slowest, pp.segments[k].junction);
      inside = true;
    }
  }
  t.planned = pp.totals.time;
  if (svg.empty()) {
    t.paced = pace_program(pp, setup, pl, lim).seconds();
  } else {
    std::ofstream os(svg);
    t.paced = write_program_speed_svg(os, pp, setup, pl, lim,
                                      std::filesystem::path(file).filename().string() +
                                          fmt::format(": the plan at {:g} mm/min on the pacer", lim.default_feed))
                  .seconds();
    if (!os) throw GuardError("cannot write " + svg);
  }
  return t;
}

void feed_table(const std::string& macro, const std::string& native, const std::vector<double>& feeds, double accel,
                double deviation, const std::string& svg, double svg_feed) {
  fmt::print(
      "\n| feed (mm/min) | program | contour pieces | contour: planned time (s) | slowest junction inside it "
      "(mm/min) | program: planned time (s) | program on the pacer (s) | the native block ends sooner by |\n"
      "|---|---|---|---|---|---|---|---|\n");
  for (std::size_t k = 0; k < feeds.size(); ++k) {
    speed::MachineLimits lim = speed::default_limits(Machine::Lathe);
    for (speed::AxisLimits& a : lim.axes) a.accel = accel;
    lim.junction_deviation = deviation;
    lim.default_feed = feeds[k];
    const bool draw = feeds[k] == svg_feed && !svg.empty();
    const Timed c = timed(macro, lim, draw ? svg + "-macro.svg" : "");
    const Timed n = timed(native, lim, draw ? svg + "-native.svg" : "");
    const auto row = [&](const char* name, const Timed& t, const std::string& gain) {
      fmt::print("| {:g} | {} | {} | {:.4f} | {} | {:.4f} | {:.4f} | {} |\n", feeds[k], name, t.pieces, t.contour_time,
                 std::isfinite(t.slowest) ? fmt::format("{:.1f}", t.slowest * 60) : std::string("straight on"),
                 t.planned, t.paced, gain);
    };
    row("macro (G01 chords)", c, "");
    row("native (G6.3)", n,
        fmt::format("{:.4f} s ({:.1f}% of the contour's time)", c.contour_time - n.contour_time,
                    100 * (c.contour_time - n.contour_time) / c.contour_time));
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"the lathe paper's macro program against one native ellipse block"};
  std::string macro, native, svg, closeup;
  app.add_option("--macro", macro, "the macro program (examples/lathe-paper-macro.ngc)")->required();
  app.add_option("--native", native, "the native program (examples/lathe-paper-native.ngc)")->required();
  app.add_option("--svg", svg, "both paths in one picture");
  app.add_option("--closeup", closeup, "a close-up where the chords show");
  std::vector<double> feeds;
  double accel = 500, deviation = 0.01;
  std::string speed_svg;
  app.add_option("--feeds", feeds, "feeds (mm/min) to plan both programs at")->delimiter(',');
  app.add_option("--accel", accel, "every axis' acceleration, mm/s^2 (default 500)");
  app.add_option("--junction-deviation", deviation, "mm (default 0.01)");
  double speed_feed = 0;
  app.add_option("--speed-svg", speed_svg, "PREFIX: both programs' speed at --speed-feed (default: the first feed)");
  app.add_option("--speed-feed", speed_feed, "the feed of the --speed-svg pictures (one of --feeds)");
  CLI11_PARSE(app, argc, argv);
  try {
    const Measure c = measure(macro, "the paper's macro program (G01 chords)");
    const Measure n = measure(native, "one native ellipse block (G6.3)");
    fmt::print(
        "| program | contour blocks | core commands | steps | iterations | path: largest distance (steps) "
        "| path: mean distance (steps) | programmed chords: largest distance (steps) | direction reversals "
        "| contour's lattice start / end |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Measure* m : {&c, &n}) {
      fmt::print("| {} | {} | {} | {} | {} | {:.3f} | {:.3f} | {} | {} | ({},{}) / ({},{}) |\n", m->name, m->blocks,
                 m->commands, m->steps, m->iterations, m->max_dev,
                 m->sum_dev / double(std::max<std::uint64_t>(1, m->steps)),
                 m->blocks > 1 ? fmt::format("{:.3f}", m->chord_dev) : std::string("-"), m->reversals, m->first.x,
                 m->first.y, m->last.x, m->last.y);
    }
    if (!svg.empty())
      picture(svg, n, c, {}, "the paper's oblique ellipse: native block (dots) and 304 chords (orange)");
    if (!closeup.empty()) {
      // Around the chord vertex nearest to the ellipse's 100-degree point.
      const auto [x, y] = ideal_arc(100, 100).front();
      picture(closeup, n, c, {x - 12, y - 12, x + 12, y + 12}, "close-up at the 100-degree point (24 x 24 steps)");
    }
    if (!feeds.empty())
      feed_table(macro, native, feeds, accel, deviation, speed_svg, speed_feed > 0 ? speed_feed : feeds[0]);
  } catch (const std::exception& e) {
    std::cerr << "paper_compare: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
