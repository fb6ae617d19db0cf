// SPDX-License-Identifier: Apache-2.0
// Part programs onto the lattice (host/program_plan/program_plan.hpp, docs/programs.md):
// geometry between lattice points through the planner, and the programs of examples/
// on the golden model: every block on its rounded end, a continuous path, and each
// block within the accuracy targets of docs/results.md against the programmed geometry.
// (tests/check-examples.sh runs the same programs on the SystemC model and the RTL.)
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "host/pipeline/pipeline.hpp"
#include "host/planner/planner.hpp"
#include "host/program_plan/program_plan.hpp"
#include "host/report/program_report.hpp"
#include "host/runner/runner.hpp"

using namespace dda;
using namespace dda::program;

namespace {

// The reader's tests are written in HNC-21T's dialect, the project's first (a plain
// program would be read as LinuxCNC's on a mill: docs/programs.md, "Dialects").
ReadOptions options_for(Machine m) {
  ReadOptions o;
  o.machine = m;
  o.dialect = Dialect::Hnc;
  return o;
}

struct Measured {
  std::vector<double> max_dev;
  std::vector<Point> end;
};

// Runs the program's plan on the golden model; per block, the largest distance of its
// points from its programmed geometry and where its last piece ended.
Measured measure(const ProgramPlan& pp) {
  Measured r;
  r.max_dev.assign(pp.blocks.size(), 0.0);
  for (const BlockPlan& b : pp.blocks) r.end.push_back(b.from);
  run(pp.plan, [&](const Iteration& it) {
    const std::size_t k = block_of_piece(pp, it.piece);
    r.end[k] = it.pos;
    const Point q = to_plane_axes(it.pos, pp.blocks[k].rot);  // in the block's own plane
    const double d = block_distance(pp.blocks[k], pp.lattice.step, double(q.x), double(q.y));
    r.max_dev[k] = std::max(r.max_dev[k], d);
  });
  return r;
}

ProgramPlan plan_text(const std::string& text, Machine m = Machine::Mill, Length step = 1000) {
  LatticeOptions lo;
  lo.step = step;
  return plan_program(read(text, "p.nc", options_for(m)), lo, "p.nc");
}

std::string error_of(const std::string& text, bool hardware = false) {
  try {
    const ProgramPlan pp = plan_text(text);
    if (hardware) check_hardware(pp, "p.nc");
  } catch (const ProgramError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("program plan: arcs with sub-step centres and semi-axes stay within the targets", "[program]") {
  // Seeded draws: circles and ellipses (aspect up to 4, half of them turned) whose
  // centres and semi-axes fall anywhere between lattice points, half preload.
  std::mt19937_64 rng(20261130);
  const auto uni = [&](std::int64_t lo, std::int64_t hi) {
    return lo + std::int64_t(rng() % std::uint64_t(hi - lo + 1));
  };
  double worst = 0;
  for (int k = 0; k < 60; ++k) {
    ArcSpec s;
    s.sub = kSubBits;
    s.a = uni(3 << kSubBits, 1500 << kSubBits);
    s.b = k % 3 == 0 ? s.a : uni(s.a / 4, s.a);
    s.center = Point{uni(-500, 500), uni(-500, 500)};
    s.center_frac = Point{uni(0, (1 << kSubBits) - 1), uni(0, (1 << kSubBits) - 1)};
    s.angle = k % 2 ? uni(0, 359999999) : 0;
    s.dir = k % 4 < 2 ? Direction::Ccw : Direction::Cw;
    s.preload = Preload::Half;
    s.from_theta = uni(0, 359999999);
    s.to_theta = uni(0, 359999999);
    const Plan p = plan_arc(s);
    // The anchored planner ran each piece while planning it (no second check): the
    // runner's reachability check agrees.
    CHECK(unreachable(p).value_or(Refusal{}).why.empty());
    double dev = 0;
    Point end = p.from;
    run(p, [&](const Iteration& it) {
      dev = std::max(dev, plan_distance(p, double(it.pos.x), double(it.pos.y)));
      end = it.pos;
    });
    INFO("draw " << k << ": a " << s.a << " b " << s.b << " angle " << s.angle << " (1/1024 steps)");
    CHECK(end == p.to);
    CHECK(dev <= (s.angle == 0 ? 0.8 : 1.0));
    worst = std::max(worst, dev);
  }
  CHECK(worst > 0.3);  // the measure sees the path at all
}

TEST_CASE("program plan: a sub-step ellipse whose centre is a lattice point follows the exact one", "[program]") {
  // The same circle given in whole steps (exact datapath) and in sub-step units
  // (fixed-point coefficients): both stay within the target of the same circle.
  ArcSpec whole;
  whole.a = whole.b = 700;
  whole.preload = Preload::Half;
  whole.from = Point{700, 0};
  whole.to = Point{-700, 0};
  ArcSpec sub = whole;
  sub.sub = kSubBits;
  sub.a = sub.b = 700 << kSubBits;
  const Plan pw = plan_arc(whole), ps = plan_arc(sub);
  CHECK(ps.arc().rotated);
  CHECK_FALSE(pw.arc().rotated);
  for (const Plan* p : {&pw, &ps}) {
    double dev = 0;
    const RunSummary r = run(
        *p, [&](const Iteration& it) { dev = std::max(dev, plan_distance(*p, double(it.pos.x), double(it.pos.y))); });
    CHECK(r.end == Point{-700, 0});
    CHECK(dev <= 0.8);
  }
}

TEST_CASE("program plan: the examples run to their rounded ends within the targets", "[program]") {
  std::size_t programs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(DDA_EXAMPLES_DIR)) {
    if (entry.path().extension() != ".ngc") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string src = text.str();
    ReadOptions ro;
    if (src.find("--machine lathe") != std::string::npos) ro.machine = Machine::Lathe;  // (before the start)
    // The machine and start of its "; Run:" line, read as the dda command reads them.
    const std::string run = src.substr(src.find("; Run:"), src.find('\n', src.find("; Run:")) - src.find("; Run:"));
    if (const auto at = run.find("--start "); at != std::string::npos) {
      const std::string xy = run.substr(at + 8, run.find(' ', at + 8) - (at + 8));
      const auto first = parse_mm(xy.substr(0, xy.find(','))), second = parse_mm(xy.substr(xy.find(',') + 1));
      REQUIRE(first);
      REQUIRE(second);
      ro.start = start_point(ro.machine, *first, *second);
    }
    const ProgramPlan pp = plan_program(read(src, entry.path().string(), ro), LatticeOptions{}, "x");
    check_hardware(pp, "x");  // every example fits the hardware's widths
    const Measured m = measure(pp);
    INFO(entry.path().filename().string());
    Point at = pp.start;
    double prev_rounding = 0;
    for (std::size_t k = 0; k < pp.blocks.size(); ++k) {
      const BlockPlan& b = pp.blocks[k];
      INFO("block at line " << b.move.pos.line);
      CHECK(b.from == at);      // continuous: each block starts where the last ended
      CHECK(m.end[k] == b.to);  // and ends on its rounded end
      CHECK(m.max_dev[k] <= block_target(b, prev_rounding, Preload::Half) + 1e-9);
      at = b.to;
      prev_rounding = b.rounding;
    }
    ++programs;
  }
  CHECK(programs >= 7);
}

TEST_CASE("program plan: moves shorter than a step, full turns and the rounding report", "[program]") {
  // An arc whose ends round to one lattice point: nothing to run if it sweeps less than
  // half a turn; a full turn if it sweeps more.
  const ProgramPlan tiny = plan_text("G01 X1 Y0\nG03 X0.9999998 Y0.0004 I-1 J0\nG01 X2 Y0\n");
  REQUIRE(tiny.blocks.size() == 3);
  CHECK(tiny.blocks[1].plan.pieces.empty());
  CHECK(tiny.blocks[1].from == tiny.blocks[1].to);
  const ProgramPlan nearly = plan_text("G01 X1 Y0\nG02 X0.9999998 Y0.0004 I-1 J0\n");
  REQUIRE(nearly.blocks.size() == 2);
  CHECK(nearly.blocks[1].plan.arc().full);
  // Rounding: 0.0005 mm is half a step: away from zero.
  const ProgramPlan r = plan_text("G01 X0.0005 Y-0.0025\n");
  CHECK(r.blocks[0].to == Point{1, -3});
  CHECK(std::fabs(r.blocks[0].rounding - std::sqrt(0.5)) < 1e-9);
  // The lattice unit.
  CHECK(parse_step("0.001") == 1000);
  CHECK(parse_step("1") == kNmPerMm);
  CHECK(parse_step(".0005") == 500);
  CHECK_THROWS_AS(parse_step("0.0000001"), InputError);
  CHECK_THROWS_AS(parse_step("2"), InputError);
  CHECK_THROWS_AS(parse_step("0"), InputError);
  CHECK_THROWS_AS(parse_step("1e-3"), InputError);
  CHECK(parse_mm("-2.5") == -2500000);
  CHECK(parse_mm("+10") == 10 * kNmPerMm);
  CHECK_FALSE(parse_mm("1.2.3"));
  CHECK_FALSE(parse_mm("-"));
  CHECK_FALSE(parse_mm("12345678"));
  CHECK(start_point(Machine::Lathe, 60 * kNmPerMm, 5 * kNmPerMm) == Point2{5 * kNmPerMm, 30 * kNmPerMm});
  CHECK(start_point(Machine::Mill, 60 * kNmPerMm, 5 * kNmPerMm) == Point2{60 * kNmPerMm, 5 * kNmPerMm});
  const ProgramPlan coarse = plan_text("G01 X1 Y0.5\n", Machine::Mill, 10000);  // 0.01 mm
  CHECK(coarse.blocks[0].to == Point{100, 50});
}

TEST_CASE("program plan: refusals name the block", "[program]") {
  // Nothing to run.
  CHECK(error_of("G21\n") == "p.nc:1:1: the program has no motion block: nothing to run");
  // A circle of 200 mm: its quarter sections need more steps than the counters hold.
  const std::string big = "N10 G00 X200 Y0\nN20 G03 X-200 Y0 R200\n";
  CHECK(error_of(big).empty());  // the golden model runs it
  CHECK(error_of(big, true) ==
        "p.nc:2:5: block N20 (arc ccw): beyond the hardware's widths: cnt_x = 200000 does not fit the hardware's "
        "17-bit field: it must be in [0, 2^17) (hw_params.hpp)");
  // An ellipse too thin for the fixed-point coefficients at any width, at the block.
  CHECK(error_of("N5 G01 X100 Y0\nN6 G6.3 X-100 Y0 A100 B0.00001 I-100 J0\n") ==
        "p.nc:2:4: block N6 (ellipse ccw): the ellipse is too thin for the datapath at --step 0.001 mm: semi-axes "
        "100 mm and 9.76563e-06 mm (100000 and 0.00976562 steps); the rounding of its fixed-point coefficients "
        "could move the curve by 238 steps (at most 0.125); a coarser --step lowers it");
  // A thin one (aspect 1000) runs: its width is lowered until the coefficients hold it.
  CHECK(error_of("N5 G01 X30 Y0\nN6 G6.3 X-30 Y0 A30 B0.03 I-30 J0\n").empty());
}

TEST_CASE("program plan: large arcs keep the width where the targets hold", "[program]") {
  // A circle of 100 mm and an ellipse of 100 x 60 mm at 0.001 mm: the fixed-point
  // capacity does not shrink with the size, so the width stays 4 bits above the smallest.
  for (const std::string text :
       {"G01 X100 Y0\nG03 X100 Y0 I-100 J0\n", "G01 X100 Y0\nG6.3 X-100 Y0 A100 B60 I-100 J0\n"}) {
    const ProgramPlan pp = plan_text(text);
    const Measured m = measure(pp);
    INFO(text);
    CHECK(pp.blocks[1].plan.arc().spec.bits == smallest_valid_bits(100000, 100000) + 4);
    CHECK(m.max_dev[1] <= 0.8);
    CHECK(m.end[1] == pp.blocks[1].to);
  }
}

TEST_CASE("program plan: arcs beyond the datapath's radius run as chords within the target", "[program]") {
  // A quarter of a circle of radius 2 m and a 20 mm arc of radius 35 m, at 0.001 mm (2^20
  // steps is about 1048 mm): lines between lattice points next to the circle.
  for (const std::string text : {"G01 X2000 Y0\nG03 X0 Y2000 I-2000 J0\n", "G03 X20 Y0.3 R35000\n"}) {
    const ProgramPlan pp = plan_text(text);
    const BlockPlan& arc = pp.blocks.back();
    INFO(text);
    CHECK(beyond_datapath(arc.move, pp.lattice.step));
    CHECK(arc.plan.pieces.size() > 1);
    const Measured m = measure(pp);
    CHECK(m.max_dev.back() <= block_target(arc, 0, Preload::Half));
    CHECK(m.max_dev.back() > 0.2);  // the measure sees the path
    CHECK(m.end.back() == arc.to);
  }
}

TEST_CASE("program plan: an arc of several turns runs its full turns first", "[program]") {
  const ProgramPlan one = plan_text("G01 X10 Y0\nG03 X0 Y10 I-10 J0\n");
  ReadOptions lcnc;
  lcnc.dialect = Dialect::LinuxCnc;  // (P on an arc is LinuxCNC's)
  const ProgramPlan three =
      plan_program(read("F1\nG01 X10 Y0\nG03 X0 Y10 I-10 J0 P3\nM2\n", "p.nc", lcnc), LatticeOptions{}, "p.nc");
  const auto iterations = [](const ProgramPlan& pp) {
    std::uint64_t n = 0;
    run(pp.plan, [&](const Iteration&) { ++n; });
    return n;
  };
  const ProgramPlan full = plan_text("G01 X10 Y0\nG03 X10 Y0 I-10 J0\n");
  CHECK(iterations(three) - iterations(one) == 2 * (iterations(full) - iterations(plan_text("G01 X10 Y0\n"))));
  const Measured m = measure(three);
  CHECK(m.max_dev.back() <= 0.8);
  CHECK(m.end.back() == three.blocks.back().to);
  // Beyond the datapath's radius a turn is some 14000 chords: a block holds at most 2^20
  // pieces, so 100 turns of a 2 m circle are refused, naming the way out.
  const std::string big = "F1\nG01 X2000 Y0\nG03 X2000 Y0 I-2000 J0 P100\nM2\n";
  CHECK_THROWS_WITH(
      plan_program(read(big, "p.nc", lcnc), LatticeOptions{}, "p.nc"),
      Catch::Contains("100 turns of this arc take") && Catch::Contains("fewer turns (P), or a coarser --step"));
}

TEST_CASE("program plan: the axis normal to the plane runs on the third axis, an arc in another plane turned",
          "[program]") {
  ReadOptions lcnc;
  lcnc.dialect = Dialect::LinuxCnc;
  const auto planned = [&](const std::string& text) {
    return plan_program(read("F1\n" + text + "\nM2\n", "p.nc", lcnc), LatticeOptions{}, "p.nc");
  };
  // A plunge, a helix, a 3-D line: each block ends on its rounded end, the third axis too.
  const ProgramPlan pp = planned("G1 X1\nG1 Z-1\nG2 X3 I1 Z1\nG1 X0 Y2 Z0.5");
  REQUIRE(pp.blocks.size() == 4);
  CHECK(pp.blocks[1].to == Point{1000, 0, -1000});
  CHECK(pp.blocks[2].to == Point{3000, 0, 1000});
  CHECK(pp.blocks[3].to == Point{0, 2000, 500});
  const std::vector<Iteration> recs = run_records(pp.plan);
  CHECK(recs.back().pos == Point{0, 2000, 500});
  std::size_t at = 0;
  for (const BlockPlan& b : pp.blocks) {  // every block's last record on its end
    at += b.plan.pieces.size();
    std::size_t last = 0;
    for (std::size_t i = 0; i < recs.size(); ++i) last = recs[i].piece < at ? i : last;
    CHECK(recs[last].pos == b.to);
  }
  const auto refusal = [&](const std::string& text) {
    try {
      planned(text);
    } catch (const ProgramError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // Arcs in G18 and G19 (a helix along X) in a G17 run: planned in their own plane's
  // axes, turned onto the run's; every block on its end, the path within the targets
  // measured in each block's own plane.
  const ProgramPlan turned = planned("G1 X1\nG18 G2 X0 Z0 I-0.5 K0\nG19 G3 Y1 Z0 J0.5 K0 X0.3\nG17 G1 X0 Y0 Z0");
  REQUIRE(turned.blocks.size() == 4);
  CHECK(turned.blocks[1].rot == 2);  // G18's (Z, X, Y) onto (X, Y, Z)
  CHECK(turned.blocks[2].rot == 1);  // G19's (Y, Z, X)
  CHECK(turned.blocks[1].to == Point{0, 0, 0});
  CHECK(turned.blocks[2].to == Point{300, 1000, 0});
  const std::vector<Iteration> trecs = run_records(turned.plan);
  CHECK(trecs.back().pos == Point{0, 0, 0});
  bool z_moved = false, y_moved = false;
  for (const Iteration& it : trecs) {
    z_moved = z_moved || it.pos.z != 0;
    if (it.piece >= turned.blocks[2].first_piece && it.piece < turned.blocks[3].first_piece) {
      y_moved = y_moved || it.pos.y != 0;
    }
  }
  CHECK(z_moved);  // the G18 arc leaves the plane z = 0 and comes back
  CHECK(y_moved);
  std::ostringstream stats;
  BlockStatsSink sink(stats, LatticeOptions{}, Point2{}, BlockStatsFormat::Text, true);
  for (const BlockPlan& b : turned.blocks) sink.block(b);
  for (const Iteration& it : trecs) sink.record(it);
  sink.finish();
  CHECK_THAT(stats.str(), Catch::Contains("ends: every block on its rounded end"));
  CHECK_THAT(stats.str(), Catch::Contains("targets: every block within its target"));
  // A helix steeper than its arc: the third axis steps at most once per iteration.
  CHECK_THAT(refusal("G1 X0.01\nG2 X0.03 I0.01 Z5"), Catch::Contains("at most once per iteration"));
  CHECK(refusal("G1 X1 Z0\nG1 X2").empty());  // a Z word that leaves Z where it is
}

TEST_CASE("program plan: an arc end off its circle within LinuxCNC's tolerance runs to that end", "[program]") {
  ReadOptions lcnc;
  lcnc.dialect = Dialect::LinuxCnc;
  // 0.028 mm (28 steps) off a 5 mm radius: LinuxCNC accepts up to 0.0283 mm.
  const ProgramPlan pp = plan_program(read("F1\nG2 X10.028 Y0 I5 J0\nM2\n", "p.nc", lcnc), LatticeOptions{}, "p.nc");
  REQUIRE(pp.blocks.size() == 1);
  CHECK(run_records(pp.plan).back().pos == Point{10028, 0});
}

TEST_CASE("program plan: the block targets", "[program]") {
  const ProgramPlan pp = plan_text(
      "G01 X1 Y0.0005\nG02 X0 Y-1 I-1 J0\nG6.3 X-3 Y0 A3 B1 I0 J1\nG6.3 X3 Y0 A3 B0.5 I3 J0\nG6.2 X-3 Y0 A3 B2 Q1000 "
      "I-3 J0\n");
  REQUIRE(pp.blocks.size() == 5);
  CHECK(block_target(pp.blocks[0], 0, Preload::Half) == Approx(1.0));    // 0.5 + its end's rounding 0.5
  CHECK(block_target(pp.blocks[1], 0.5, Preload::Half) == Approx(1.3));  // an arc, after that end
  CHECK(block_target(pp.blocks[2], 0, Preload::Half) == Approx(0.8));    // aspect 3, axis-aligned
  CHECK(block_target(pp.blocks[3], 0, Preload::Half) == Approx(1.0));    // aspect 6
  CHECK(block_target(pp.blocks[4], 0, Preload::Half) == Approx(1.0));    // turned by 1 degree
  CHECK(std::isinf(block_target(pp.blocks[2], 0, Preload::Zero)));
}

namespace {

// Counts what a run tells a report; fails at block `fail_at` (1-based) if given.
struct CountingSink : RunSink {
  std::size_t blocks = 0, records = 0, fail_at = 0;
  void block(const BlockPlan&) override {
    if (++blocks == fail_at) throw GuardError("the report failed at block " + std::to_string(blocks));
  }
  void record(const Iteration&) override { ++records; }
  bool steps_only() const override { return true; }
};

// A rapid to the origin and n lines of a millimetre along X, then (if `refused`) an arc
// whose end is 1.4 mm off its circle.
std::string lines_program(int n, bool refused) {
  std::ostringstream s;
  s << "G21 G90 G17\nG00 X0 Y0\n";
  for (int k = 1; k <= n; ++k) s << "G01 X" << k << '\n';
  if (refused) s << "G02 X" << n + 2 << " Y0 I0.3 J0\n";
  s << "M30\n";
  return s.str();
}

}  // namespace

TEST_CASE("program plan: a refusal from the planner's thread stops the run where one thread would", "[program]") {
  // The reader and the planner run ahead in their own thread; the engine must still run
  // and report every block before the refused one, and then stop with its message.
  std::istringstream in(lines_program(300, true));
  ProgramRun run;
  run.read = options_for(Machine::Mill);
  run.file = "p.nc";
  CountingSink sink;
  GoldenEngine engine(sink);
  std::string what;
  try {
    run_program(in, run, engine, sink);
  } catch (const ProgramError& e) {
    what = e.what();
  }
  CHECK(what.rfind("p.nc:303:", 0) == 0);
  // As in one thread: the reader refuses the arc while the planner's window holds the
  // kDefaultWindow blocks before it (never planned), and the engine has run every piece
  // before the last one announced (a piece runs when the next one is known).
  CHECK(sink.blocks == 301 - kDefaultWindow);
  CHECK(sink.records == (sink.blocks - 2) * 1000);
}

TEST_CASE("program plan: a report that fails stops the planner's thread", "[program]") {
  // A failure on the engine's side ends the run at once with its own error; the planner,
  // far ahead or waiting for room, is stopped and joined (a hang would time out).
  for (const std::size_t fail_at : {std::size_t{1}, std::size_t{3}, std::size_t{200}}) {
    std::istringstream in(lines_program(2000, false));
    ProgramRun run;
    run.read = options_for(Machine::Mill);
    run.file = "p.nc";
    CountingSink sink;
    sink.fail_at = fail_at;
    GoldenEngine engine(sink);
    CHECK_THROWS_WITH(run_program(in, run, engine, sink), "the report failed at block " + std::to_string(fail_at));
    CHECK(sink.blocks == fail_at);
  }
}
