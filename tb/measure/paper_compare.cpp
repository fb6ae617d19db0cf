// SPDX-License-Identifier: Apache-2.0
// The lathe paper's macro program (304 G01 chords of the oblique ellipse) against the same
// contour as one native ellipse block (docs/results.md, "The lathe paper's macro
// program"). Both programs are read, planned and run on the golden model (the SystemC
// model and the RTL run them identically: tests/check-examples.sh); over the contour's
// blocks (G01 chords, or the G6.3 block) it measures blocks, core commands, steps,
// iterations, the lattice path's largest and mean distance from the ideal ellipse, the
// programmed chords' own largest distance, and the direction reversals; it prints a
// markdown table and draws both paths in one picture and a close-up.
//   usage: paper_compare --macro FILE --native FILE [--svg FILE --closeup FILE]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "geometry/fixed_trig.hpp"
#include "geometry/geometry.hpp"
#include "program_plan/program_plan.hpp"
#include "report/report.hpp"
#include "runner/runner.hpp"

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

Measure measure(const std::string& file, const std::string& name) {
  std::ifstream in(file);
  if (!in) throw InputError("cannot read " + file);
  std::stringstream text;
  text << in.rdbuf();
  ReadOptions ro;
  ro.machine = Machine::Lathe;
  ro.start = start_point(Machine::Lathe, 60 * kNmPerMm, 5 * kNmPerMm);  // X60 Z5, as the examples' Run line
  const ProgramPlan pp = plan_program(read(text.str(), file, ro), LatticeOptions{}, file);
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"the lathe paper's macro program against one native ellipse block"};
  std::string macro, native, svg, closeup;
  app.add_option("--macro", macro, "the macro program (examples/lathe-paper-macro.ngc)")->required();
  app.add_option("--native", native, "the native program (examples/lathe-paper-native.ngc)")->required();
  app.add_option("--svg", svg, "both paths in one picture");
  app.add_option("--closeup", closeup, "a close-up where the chords show");
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
  } catch (const std::exception& e) {
    std::cerr << "paper_compare: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
