// SPDX-License-Identifier: Apache-2.0
// The speed planner (host/speed/, docs/programs.md "Feeds and speeds"): each rule on a
// small program (F in mm and inch, inverse time, rapids, dwell, exact stop and
// continuous, a corner at its junction speed, a reversal at rest, a tight arc held by
// its curvature, a window too short to reach the feed), and on random programs the
// plan's consistency (no ramp steeper than the acceleration, every junction at or
// below its speed, rest at the end) and its time against a time-optimal profile
// computed here, independently, by integrating the speed limit along the path densely
// (the programs and their geometry from tb/random/random_program.hpp).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "host/speed/speed_run.hpp"
#include "tb/random/random_program.hpp"

using namespace dda;
using namespace dda::speed;
using program::Machine;
using randgen::Curve;
using randgen::curve_block;
using randgen::random_program;
using randgen::RandomProgram;

namespace {

struct Result {
  std::vector<BlockSpeeds> blocks;
  std::vector<PlannedSegment> pieces;
  SpeedTotals totals;
};

Result plan(const std::string& text, MachineLimits lim, Machine m = Machine::Mill,
            program::Dialect d = program::Dialect::LinuxCnc) {
  std::istringstream in(text);
  program::ReadOptions read;
  read.machine = m;
  read.dialect = d;
  program::LatticeOptions lattice;
  Result r;
  r.totals = plan_program_speeds(
      in, "p.ngc", read, lattice, program::kDefaultWindow, lim, [&](const BlockSpeeds& b) { r.blocks.push_back(b); },
      [&](const PlannedSegment& p) { r.pieces.push_back(p); });
  return r;
}

Result plan(const std::string& text) { return plan(text, default_limits(Machine::Mill)); }

double mm_min(double mm_s) { return mm_s * 60; }

std::string error_of(const std::string& text, MachineLimits lim = default_limits(Machine::Mill)) {
  try {
    plan(text, lim);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("speed: F in mm and in inch per minute, the cruise at the feed") {
  const Result mm = plan("G21 G90 G1 X50 F600\nM2\n");
  REQUIRE(mm.blocks.size() == 1);
  CHECK(mm_min(mm.blocks[0].cruise) == Approx(600));
  CHECK(mm.blocks[0].limit == Limit::None);
  CHECK(mm.blocks[0].entry == 0);
  CHECK(mm.blocks[0].exit == 0);
  const Result in = plan("G20 G90 G1 X2 F24\nM2\n");
  REQUIRE(in.blocks.size() == 1);
  CHECK(mm_min(in.blocks[0].cruise) == Approx(24 * 25.4));
  CHECK(in.blocks[0].length == Approx(50.8).margin(1e-3));
  // 50 mm at 10 mm/s with ramps at 250 mm/s^2 (half of 500): 5 s plus 10/250 s.
  CHECK(mm.totals.time == Approx(5 + 10.0 / 250).epsilon(1e-6));
}

TEST_CASE("speed: G93 inverse time, the move in 1/F minutes") {
  const Result r = plan("G21 G90 G93 G1 X10 F6\nG1 X30 F3\nM2\n");
  REQUIRE(r.blocks.size() == 2);
  CHECK(r.blocks[0].feed == Approx(1.0));  // 10 mm in 10 s
  CHECK(r.blocks[1].feed == Approx(1.0));  // 20 mm in 1/3 minute
  CHECK(r.blocks[1].cruise == Approx(1.0));
}

TEST_CASE("speed: rapids at the rapid rate, each axis within its vmax") {
  const Result r = plan("G21 G90 G0 X100 Y100\nG0 Z-50\nG1 X0 F600\nM2\n");
  REQUIRE(r.blocks.size() == 3);
  CHECK(mm_min(r.blocks[0].cruise) == Approx(6000));  // X and Y at 4243 mm/min each
  CHECK(r.blocks[0].limit == Limit::None);
  CHECK(mm_min(r.blocks[1].cruise) == Approx(3000));  // Z's vmax
  CHECK(r.blocks[1].limit == Limit::VelocityZ);
  CHECK(mm_min(r.blocks[2].cruise) == Approx(600));
  MachineLimits slow = default_limits(Machine::Mill);
  slow.rapid = 1200;
  CHECK(mm_min(plan("G21 G0 X100\nM2\n", slow).blocks[0].cruise) == Approx(1200));
}

TEST_CASE("speed: a dwell rests the tool and adds its time, in each dialect's unit") {
  const Result r = plan("G21 G90 G1 X10 F600\nG4 P2.5\nG1 X20\nM2\n");
  REQUIRE(r.blocks.size() == 2);
  CHECK(r.blocks[0].exit == 0);
  CHECK(r.blocks[1].entry == 0);
  CHECK(r.blocks[1].dwell == Approx(2.5));
  CHECK(r.totals.time == Approx(r.blocks[0].time + r.blocks[1].time + 2.5));
  const Result fanuc = plan("O1\nG21 G90 G1 X10 F600\nG04 P1500\nG1 X20\nG04 X2\nM30\n", default_limits(Machine::Mill),
                            Machine::Mill, program::Dialect::Fanuc);
  CHECK(fanuc.blocks[1].dwell == Approx(1.5));
  CHECK(fanuc.totals.dwell == Approx(3.5));
  // A dwell before a last move shorter than a step still counts.
  const Result tail = plan("G21 G90 G1 X10 F600\nG4 P2\nG1 X10.0001\nM2\n");
  CHECK(tail.totals.dwell == Approx(2));
  const Result stop = plan("G21 G90 G1 X10 F600\nM0\nG1 X20\nM2\n");
  CHECK(stop.blocks[0].exit == 0);
  CHECK(stop.blocks[1].stop);
}

TEST_CASE("speed: exact stop (G61) rests at every block end, continuous (G64) blends") {
  const std::string square = "G1 X10 F3000\nG1 X10 Y10\nG1 X0 Y10\nG1 X0 Y0\nM2\n";
  const Result exact = plan("G21 G90 G61\n" + square);
  const Result blend = plan("G21 G90 G64\n" + square);
  const Result tight = plan("G21 G90 G64 P0.001\n" + square);
  REQUIRE(exact.blocks.size() == 4);
  for (const BlockSpeeds& b : exact.blocks) CHECK(b.exit == 0);
  for (std::size_t k = 0; k + 1 < blend.blocks.size(); ++k) CHECK(blend.blocks[k].exit > 0);
  CHECK(blend.totals.time < exact.totals.time);
  // P bounds the junction deviation: a tenth of it, sqrt(0.1) of the speed.
  CHECK(tight.blocks[0].exit == Approx(blend.blocks[0].exit * std::sqrt(0.1)).epsilon(1e-9));
}

TEST_CASE("speed: a 90-degree corner at Grbl's junction speed") {
  const Result r = plan("G21 G90 G1 X20 F3000\nG1 X20 Y20\nM2\n");
  // The junction's direction (-1, 1)/sqrt 2 lets each axis' 500 mm/s^2 give 707 along
  // it; sin(45 deg) / (1 - sin(45 deg)) = 2.414; deviation 0.01 mm.
  const double v = std::sqrt(500 * std::sqrt(2.0) * 0.01 * std::sqrt(0.5) / (1 - std::sqrt(0.5)));
  CHECK(r.blocks[0].exit == Approx(v));
  CHECK(r.blocks[1].entry == Approx(v));
  CHECK(junction_speed({1, 0, 0}, {0, 1, 0}, 0.01, {500, 500, 500}) == Approx(v));
}

TEST_CASE("speed: a reversal passes at rest, straight on at full speed") {
  const Result back = plan("G21 G90 G1 X20 F3000\nG1 X5\nM2\n");
  CHECK(back.blocks[0].exit == 0);
  const Result on = plan("G21 G90 G1 X20 F3000\nG1 X40\nM2\n");
  CHECK(mm_min(on.blocks[0].exit) == Approx(3000));
}

TEST_CASE("speed: a tight arc is held by its curvature") {
  // Radius 0.2 mm at 3000 mm/min: sqrt(A_n r) with A_n = sqrt(500^2 - 250^2).
  const Result r = plan("G21 G90 G1 X10 F3000\nG2 X10.4 Y0 I0.2 J0\nG1 X20\nM2\n");
  REQUIRE(r.blocks.size() == 3);
  const double an = std::sqrt(500.0 * 500 - 250.0 * 250);
  CHECK(r.blocks[1].limit == Limit::Curvature);
  CHECK(r.blocks[1].cruise == Approx(std::sqrt(an * 0.2)).epsilon(1e-3));
  // A wide arc at the same feed is not held.
  const Result wide = plan("G21 G90 G1 X10 F3000\nG2 X110 Y0 I50 J0\nM2\n");
  CHECK(wide.blocks[1].limit == Limit::None);
  CHECK(mm_min(wide.blocks[1].cruise) == Approx(3000));
}

TEST_CASE("speed: a window too short to reach the feed plans to rest within it") {
  std::string text = "G21 G90\n";
  for (int k = 1; k <= 200; ++k) text += "G1 X" + std::to_string(k * 0.1) + " F1200\n";
  text += "M2\n";
  MachineLimits lim = default_limits(Machine::Mill);
  lim.window = 2;
  const Result short_w = plan(text, lim);
  lim.window = 64;
  const Result long_w = plan(text, lim);
  // With 2 pieces ahead the tool must be able to stop within 0.2 mm: it leaves a piece
  // at sqrt(2 * 250 * 0.2) = 10 mm/s at most, and peaks within it below sqrt(2 * 250 *
  // 0.3); 64 pieces (6.4 mm) are room to reach 20 mm/s (0.8 mm up, 0.8 down).
  double top_short = 0, top_long = 0;
  for (const PlannedSegment& p : short_w.pieces) top_short = std::max(top_short, p.peak);
  for (const PlannedSegment& p : long_w.pieces) top_long = std::max(top_long, p.peak);
  CHECK(top_short <= std::sqrt(2 * 250 * 0.3) + 1e-9);
  CHECK(top_long == Approx(20));
  CHECK(short_w.blocks[50].limit == Limit::Length);
  CHECK(long_w.totals.time < short_w.totals.time);
}

TEST_CASE("speed: feed errors name the block and the rule") {
  CHECK_THAT(error_of("G21 G95 G1 X10 F0.1\nM2\n"), Catch::Contains("no spindle speed"));
  CHECK_THAT(error_of("G21 G95 G96 S100 G1 X10 F0.1\nM2\n"), Catch::Contains("constant surface speed"));
  CHECK(error_of("G21 G95 S1000 G1 X10 F0.1\nM2\n").empty());
  CHECK(plan("G21 G95 S1000 G1 X50 F0.1\nM2\n").blocks[0].cruise == Approx(100.0 / 60));
  // F given per minute, then the mode changed: F must be given again.
  CHECK_THAT(error_of("G21 G94 G1 X10 F300\nG95 S1000 G1 X20\nM2\n"),
             Catch::Contains("the feed mode changed to per revolution (G95, G99) since F was given"));
  CHECK(error_of("G21 G94 G1 X10 F300\nG95 S1000 G1 X20 F0.1\nM2\n").empty());
  // Below the minimum speed (1 mm/min by default) the block would pace faster than asked.
  CHECK_THAT(error_of("G21 G1 X1 F0.5\nM2\n"), Catch::Contains("below the machine's minimum speed"));
  // On a Fanuc lathe S with G50 is the spindle's clamp, not its speed.
  const Result clamp = plan("O1\nG21 G97 S800 G99\nG50 S3000\nG1 Z-50 F0.1\nM30\n", default_limits(Machine::Lathe),
                            Machine::Lathe, program::Dialect::Fanuc);
  CHECK(mm_min(clamp.blocks[0].feed) == Approx(80));
  CHECK_THAT(error_of("G21 G96 S200 G95\nG97 G1 X10 F0.1\nM2\n"), Catch::Contains("no spindle speed"));
  MachineLimits bad = default_limits(Machine::Mill);
  bad.tangential_share = 1;
  CHECK_THAT(error_of("G21 G1 X1 F1\nM2\n", bad), Catch::Contains("tangential_share"));
}

TEST_CASE("speed: the machine description file, and what it refuses") {
  const MachineLimits l =
      parse_machine_config(R"({"axes": {"x": {"accel_mm_per_s2": 1000}}, "rapid_mm_per_min": 9000, "window": 32})",
                           "m.json", default_limits(Machine::Mill), Machine::Mill);
  CHECK(l.axes[0].accel == 1000);
  CHECK(l.axes[0].vmax == 6000);  // kept from the base
  CHECK(l.rapid == 9000);
  CHECK(l.window == 32);
  const auto refused = [](const std::string& text, Machine m = Machine::Mill) {
    try {
      parse_machine_config(text, "m.json", default_limits(m), m);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(refused("{"), Catch::Contains("not JSON"));
  CHECK_THAT(refused(R"({"rapid": 1})"), Catch::Contains("unknown key 'rapid'"));
  CHECK_THAT(refused(R"({"axes": {"a": {}}})"), Catch::Contains("unknown axis 'a'"));
  CHECK_THAT(refused(R"({"junction_deviation_mm": -1})"), Catch::Contains("must be positive"));
  CHECK_THAT(refused(R"({"window": 1})"), Catch::Contains("window"));
  // A lathe's file with a Y axis (one written for a mill) is refused, not half read.
  CHECK_THAT(refused(R"({"axes": {"y": {"accel_mm_per_s2": 800}}})", Machine::Lathe),
             Catch::Contains("axes.y: a lathe has no Y axis"));
  CHECK(refused(R"({"axes": {"x": {"accel_mm_per_s2": 800}, "z": {}}})", Machine::Lathe).empty());
}

namespace {

// The time-optimal profile along the program's curves with the planner's limits: the
// speed limit at points 0.005 mm apart (the feed, each axis' vmax over its share of the
// tangent, sqrt(A_n rho) at the point's radius of curvature), Grbl's junction speed
// from the curves' own end tangents, rest at both ends, then the forward pass (v^2 grows
// by at most 2 a ds) and the backward pass; the time sums ds over the mean speed.
double optimal_time(const std::vector<Curve>& curves, const PlannerLimits& lim, double deviation) {
  std::vector<double> ds, vmax;  // vmax[k]: the limit at point k; ds[k]: from point k to k + 1
  const auto limit_at = [&](const Curve& c, double t) {
    const auto tg = c.tangent(t);
    double v = c.feed;
    for (int i = 0; i < 2; ++i) {
      if (std::abs(tg[std::size_t(i)]) > 1e-12)
        v = std::min(v, lim.vmax[std::size_t(i)] / std::abs(tg[std::size_t(i)]));
    }
    return std::min(v, std::sqrt(lim.normal_accel * c.radius(t)));
  };
  const auto junction = [&](const Curve& p, const Curve& c) {
    const auto in = p.tangent(p.t0 + p.sweep), out = c.tangent(c.t0);
    const double cos_t = -(in[0] * out[0] + in[1] * out[1]);
    if (cos_t > 0.999999) return 0.0;
    if (cos_t < -0.999999) return kInfinity;
    const double jx = out[0] - in[0], jy = out[1] - in[1], n = std::hypot(jx, jy);
    double a = kInfinity;
    if (std::abs(jx / n) > 1e-12) a = std::min(a, lim.axis_accel[0] / std::abs(jx / n));
    if (std::abs(jy / n) > 1e-12) a = std::min(a, lim.axis_accel[1] / std::abs(jy / n));
    const double sh = std::sqrt(0.5 * (1 - cos_t));
    return std::sqrt(a * deviation * sh / (1 - sh));
  };
  vmax.push_back(0);
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const Curve& c = curves[k];
    const double len = c.length();
    const int n = std::max(2, int(std::ceil(len / 0.005)));
    if (k > 0) vmax.back() = std::min({vmax.back(), junction(curves[k - 1], c), limit_at(c, c.t0)});
    for (int i = 1; i <= n; ++i) {
      // (Points evenly spaced in the parameter: on a curve each ds is its own arc length.)
      ds.push_back(c.line ? len / n : c.speed(c.t0 + c.sweep * (i - 0.5) / n) * std::abs(c.sweep) / n);
      vmax.push_back(limit_at(c, c.t0 + c.sweep * i / n));
    }
  }
  vmax.back() = 0;
  std::vector<double> v = vmax;
  for (std::size_t k = 0; k + 1 < v.size(); ++k)
    v[k + 1] = std::min(v[k + 1], std::sqrt(v[k] * v[k] + 2 * lim.accel * ds[k]));
  for (std::size_t k = v.size() - 1; k > 0; --k)
    v[k - 1] = std::min(v[k - 1], std::sqrt(v[k] * v[k] + 2 * lim.accel * ds[k - 1]));
  double t = 0;
  for (std::size_t k = 0; k < ds.size(); ++k) t += 2 * ds[k] / (v[k] + v[k + 1]);
  return t;
}

// The plan's own rules, piece by piece: every ramp within the acceleration, every
// junction at or below its speed, the entry of each piece the exit of the one before,
// at rest at the start and the end, the speed never above the cap.
void check_plan(const Result& r, double accel) {
  REQUIRE(!r.pieces.empty());
  CHECK(r.pieces.front().entry == 0);
  CHECK(r.pieces.back().exit == 0);
  for (std::size_t k = 0; k < r.pieces.size(); ++k) {
    const PlannedSegment& p = r.pieces[k];
    const double reach = 2 * accel * p.seg.length * (1 + 1e-9) + 1e-12;
    CHECK(p.exit * p.exit <= p.entry * p.entry + reach);
    CHECK(p.entry * p.entry <= p.exit * p.exit + reach);
    CHECK(p.entry <= p.junction * (1 + 1e-12));
    CHECK(p.peak <= p.cap * (1 + 1e-12));
    if (k > 0) CHECK(p.entry == r.pieces[k - 1].exit);
  }
}

}  // namespace

TEST_CASE("speed: random programs keep every rule, within 5% of the time-optimal profile") {
  const std::uint64_t seed = std::getenv("DDA_SEED") ? std::stoull(std::getenv("DDA_SEED")) : 1;
  std::mt19937_64 rng(seed);
  const MachineLimits lim = default_limits(Machine::Mill);
  const PlannerLimits pl = planner_limits(lim, Machine::Mill);
  double worst = 0;
  for (int n = 0; n < 40; ++n) {
    const RandomProgram prog = random_program(rng, 30, n % 2 == 1);
    INFO("seed " << seed << ", program " << n << ":\n" << prog.text);
    const Result r = plan(prog.text, lim);
    check_plan(r, pl.accel);
    const double best = optimal_time(prog.curves, pl, lim.junction_deviation);
    const double ratio = r.totals.time / best;
    worst = std::max(worst, ratio);
    CHECK(ratio >= 0.995);
    CHECK(ratio <= 1.05);
  }
  WARN("worst ratio of the planned time to the optimum: " << worst);
}

TEST_CASE("speed: a thin ellipse at a high feed, its curvature changing along each piece") {
  // a = 15, b = 2: the radius of curvature runs from 0.27 mm at the tips to 112 mm.
  Curve c;
  c.line = false;
  c.a = 15, c.b = 2, c.q = 0, c.t0 = 0, c.sweep = 3.14159265358979323846;
  c.feed = 6000.0 / 60;
  double x = 15, y = 0;
  const std::string text = "G21 G90 G0 X15 Y0\nG1 X15 Y0 F6000\n" + curve_block(c, x, y, false, true) + " F6000\nM2\n";
  const MachineLimits lim = default_limits(Machine::Mill);
  const PlannerLimits pl = planner_limits(lim, Machine::Mill);
  INFO(text);
  const Result r = plan(text, lim);
  check_plan(r, pl.accel);
  const double best = optimal_time({c}, pl, lim.junction_deviation);
  const double ellipse_time = r.blocks.back().time;
  WARN("pieces " << r.blocks.back().pieces << ", planned " << ellipse_time << " s, optimum " << best << " s");
  CHECK(ellipse_time / best <= 1.05);
}
