// SPDX-License-Identifier: Apache-2.0
// The motion block's builds other than the default (motion::Build; docs/design.md
// "Builds"): the reference model, the SystemC model and the RTL verilated with the
// build's parameters, side by side every cycle (MotionCosim). One program per build
// (tests/CMakeLists.txt), each registering its own build's cases:
//   without the machine inputs: CONFIG.inputs reads 0, an input held active stops and
//     latches nothing, the input registers read 0 and take no write; the random work of
//     the default build runs on it (its input trips replaced by inputs held active that
//     must act on nothing), and a paced line ends on its end point with the E-stop and
//     every limit held active;
//   the lathe's, two axes with the inputs: CONFIG.axes reads 2, Z's registers read 0
//     and take no write, an entry's linear axis and axes field are not read (a 3-D line
//     queued as is moves X and Y only, Z's pins stay low), a Z limit held active stops
//     nothing while an X limit does; the random work runs on it (planar arcs only);
//   the board's, without the pacer (rtl/board/): CONFIG.pacer reads 0, ACCEL, VMIN and
//     OVERRIDE take no write, an entry with a cruise speed runs at its feed increment
//     clock for clock as one without, a feed hold stops at once and the resume goes on to
//     the end point; the random work runs on it (its paced batches fed, with a hold), and
//     behind the SPI bridge as the board has it;
//   two axes combined with another choice, without the inputs or without the pacer (the
//     builds of docs/results.md's figures): CONFIG reads the build, and the random work
//     runs on it (planar arcs, no Z pulse; without the pacer, fed batches and the random
//     bus work behind the SPI bridge too).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <systemc>

#include "host/driver/motion_driver.hpp"
#include "host/planner/planner.hpp"
#include "host/speed/pace_plan.hpp"
#include "model/datapath/errors.hpp"
#include "tb/cosim/bridge_cosim.hpp"
#include "tb/cosim/motion_cosim.hpp"
#include "tb/measure/pace_report.hpp"
#include "tb/monitors/bus_monitors.hpp"
#include "tb/random/bus_work.hpp"
#include "tb/random/dda_random.hpp"
#include "tb/random/motion_mix.hpp"

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

using namespace dda;
using namespace dda::motion;

#if DDA_MOTION_TEST_INPUTS == 0 && DDA_MOTION_TEST_AXES == 3
namespace {

// Every input active at the pins: the E-stop low, the others high.
MachinePins all_active() {
  MachinePins p;
  p.estop_n = false;
  p.limit = 0x3F;
  p.home = 0x7;
  p.probe = true;
  return p;
}

}  // namespace

TEST_CASE("build: without the inputs, the three engines equal and an active input acts on nothing",
          "[motion][cosim][build]") {
  STATIC_REQUIRE(!kHarnessInputs);
  MotionCosim h;
  WishboneMaster m(h, 3, true, 10);
  MotionDriver d(m, 4);
  h.set_reset(false);
  m.idle(2);
  h.set_reset(true);
  m.idle(2);
  CHECK(get_field("CONFIG", "inputs", d.read("CONFIG")) == 0);
  CHECK(get_field("CONFIG", "depth_log2", d.read("CONFIG")) == std::uint32_t(kHarnessDepthLog2));
  // The input registers take no write and read 0; CTRL.snapshot and probe_arm do nothing.
  d.set_inputs(0x7FF, 5, 3, 0x1F, 1);
  for (const char* r : {"IN_POLARITY", "IN_FILTER", "IN_MODE"}) {
    INFO(r);
    CHECK(d.read(r) == 0);
  }
  d.preset(Point{10, -20, 30});
  d.arm_probe();
  const MotionDriver::Snapshot s = d.snapshot();
  CHECK(s.pos == Point{});
  CHECK(d.read("SNAP_CYCLE") == 0);
  // A paced line runs to its end with every input active from the start.
  const double clock = 16e6, feed = 1e5, accel = 2e7, vmin = 2000;
  h.set_pins(all_active());
  d.set_pacing(std::uint32_t(accel_field(accel, clock)), speed_field(vmin, clock));
  const Plan line = plan_line(Point{10, -20, 30}, Point{1010, 380, 30}, Preload::Half);
  std::vector<Command> cmds;
  for (const auto& p : line.pieces) cmds.push_back(p.cmd);
  const auto e = pace_entries(cmds, speed_field(feed, clock), speed_field(vmin, clock), accel_field(accel, clock));
  for (std::size_t i = 0; i < line.pieces.size(); ++i) d.queue(line.pieces[i].cmd, 0, 0, e[i]);
  d.drain();
  CHECK(d.position() == line.to);
  const std::uint32_t st = d.read("STATUS");
  for (const char* f : {"err", "aborted", "err_estop", "err_limit", "probed", "probe_armed"}) {
    INFO(f);
    CHECK(get_field("STATUS", f, st) == 0);
  }
  for (const char* r : {"INPUTS", "TRIP", "LATCH_X", "PROBE_X"}) {
    INFO(r);
    CHECK(d.read(r) == 0);
  }
  // A driver that has read the build refuses what would do nothing.
  d.read_build();
  CHECK(!d.inputs());
  CHECK_THROWS_AS(d.arm_probe(), GuardError);
  CHECK_THROWS_AS(d.snapshot(), GuardError);
  CHECK_THROWS_AS(d.set_inputs(0, 1, 1, 0), GuardError);
}

TEST_CASE("build: without the inputs, 24 random arcs, the three engines equal every cycle", "[motion][cosim][build]") {
  const std::uint64_t seed = test_seed(79);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  MotionCosim h;
  const MixStats st = run_motion_mix(h, seed, 24, true);
  INFO(st.pieces << " pieces, " << h.cycle() << " cycles");
  CHECK(st.arcs == 24);
  CHECK(st.position_checks > 0);
  CHECK(st.paced_pieces > 0);
  CHECK(st.input_trips > 0);  // inputs held active, checked to act on nothing
}
#endif

#if DDA_MOTION_TEST_AXES == 2 && DDA_MOTION_TEST_INPUTS == 1 && DDA_MOTION_TEST_PACER == 1
TEST_CASE("build: two axes, the three engines equal, Z not built", "[motion][cosim][build]") {
  STATIC_REQUIRE(kHarnessAxes == 2);
  MotionCosim h;
  WishboneMaster m(h, 3, true, 10);
  MotionDriver d(m, 4);
  h.set_reset(false);
  m.idle(2);
  h.set_reset(true);
  m.idle(2);
  CHECK(get_field("CONFIG", "axes", d.read("CONFIG")) == 2);
  CHECK(get_field("CONFIG", "inputs", d.read("CONFIG")) == 1);
  d.set_timings('z', StageTimings{5, 5, 5, 5});
  d.set_timings('x', StageTimings{2, 2, 1, 1});
  d.set_polarity(0x3F);
  CHECK(d.read("STEP_Z") == 0);
  CHECK(d.read("DIR_Z") == 0);
  CHECK(d.read("POLARITY") == 0x0F);
  d.set_polarity(0);
  d.preset(Point{100, 200, 300});
  CHECK(d.position() == Point{100, 200, 0});
  // A 3-D line queued as is: the core's linear axis is not read, Z never steps.
  const Plan line = plan_line(Point{100, 200, 0}, Point{400, 50, 250}, Preload::Half);
  for (const auto& p : line.pieces) d.queue(p.cmd);
  std::uint64_t z_edges = 0;
  for (int i = 0; i < 20000; ++i) {
    m.idle(1);
    z_edges += h.outputs().step_z || h.outputs().dir_z;
  }
  d.drain();
  CHECK(z_edges == 0);
  CHECK(d.position() == Point{400, 50, 0});
  // An axes field is not read: a line queued with axes 1 (the core's X on the block's Y)
  // runs on X and Y as queued with 0.
  const Plan turned = plan_line(Point{400, 50, 0}, Point{450, 80, 0}, Preload::Half);
  for (const auto& p : turned.pieces) d.queue(p.cmd, 0, 1);
  d.drain();
  CHECK(d.position() == Point{450, 80, 0});
  // A driver that has read the build refuses both, before a word is written.
  d.read_build();
  REQUIRE(d.axes() == 2);
  CHECK_THROWS_AS(d.queue(line.pieces.front().cmd), GuardError);
  CHECK_THROWS_AS(d.queue(turned.pieces.front().cmd, 0, 1), GuardError);
  CHECK(get_field("STATUS", "empty", d.read("STATUS")) == 1);
  // A Z limit held active stops nothing; an X limit does.
  d.set_inputs(0, 1, 1, 0, 0);
  MachinePins pins;
  pins.limit = 0x30;  // z-, z+
  h.set_pins(pins);
  const Plan back = plan_line(Point{450, 80, 0}, Point{300, 0, 0}, Preload::Half);
  for (const auto& p : back.pieces) d.queue(p.cmd);
  d.drain();
  CHECK(d.position() == Point{300, 0, 0});
  CHECK(get_field("STATUS", "err_limit", d.read("STATUS")) == 0);
  CHECK(d.read("INPUTS") == 0);
  pins.limit = 0x03;  // x-, x+
  h.set_pins(pins);
  m.idle(20);
  const Plan more = plan_line(Point{300, 0, 0}, Point{200, 10, 0}, Preload::Half);
  for (const auto& p : more.pieces) d.queue(p.cmd);
  m.idle(5000);
  CHECK(get_field("STATUS", "err_limit", d.read("STATUS")) == 1);
  CHECK(d.position().x == 300);
}

TEST_CASE("build: two axes, 32 random planar arcs, the three engines equal every cycle", "[motion][cosim][build]") {
  const std::uint64_t seed = test_seed(83);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  MotionCosim h;
  const MixStats st = run_motion_mix(h, seed, 32, false);
  INFO(st.pieces << " pieces, " << h.cycle() << " cycles");
  CHECK(st.arcs == 32);
  CHECK(st.position_checks > 0);
  CHECK(st.paced_pieces > 0);
  CHECK(st.spatial == 0);
  CHECK(st.pulses_z == 0);
}
#endif

#if DDA_MOTION_TEST_PACER == 0 && DDA_MOTION_TEST_AXES == 3
namespace {

// Clocks from the last commit to the last step pulse's rise, a line queued with a feed
// increment and the given pacing fields (the driver not told the build), from a reset
// (the feed's phase accumulator at 0).
std::uint64_t run_line(MotionCosim& h, WishboneMaster& m, MotionDriver& d, const Plan& line, std::uint32_t feed,
                       const std::vector<PaceEntry>& pace) {
  h.set_reset(false);
  m.idle(2);
  h.set_reset(true);
  m.idle(2);
  d.preset(line.from);
  for (std::size_t i = 0; i < line.pieces.size(); ++i) d.queue(line.pieces[i].cmd, feed, 0, pace[i]);
  const std::uint64_t start = h.cycle();
  std::uint64_t last = start;
  bool was = false;
  for (int i = 0; i < 40000; ++i) {
    m.idle(1);
    const BlockOutputs& o = h.outputs();
    const bool any = o.step_x || o.step_y || o.step_z;
    if (any && !was) last = h.cycle();
    was = any;
  }
  d.drain();
  CHECK(d.position() == line.to);
  return last - start;
}

}  // namespace

TEST_CASE("build: without the pacer, the three engines equal and every entry runs at its feed increment",
          "[motion][cosim][build]") {
  STATIC_REQUIRE(!kHarnessPacer);
  MotionCosim h;
  WishboneMaster m(h, 3, false, 10);  // (no random waits: the two runs' clocks compare)
  MotionDriver d(m, 4, false);
  h.set_reset(false);
  m.idle(2);
  h.set_reset(true);
  m.idle(2);
  CHECK(get_field("CONFIG", "pacer", d.read("CONFIG")) == 0);
  CHECK(get_field("CONFIG", "inputs", d.read("CONFIG")) == 1);
  CHECK(get_field("CONFIG", "axes", d.read("CONFIG")) == 3);
  // The pacer's settings take no write.
  d.set_pacing(1000, 2000);
  d.set_override(100);
  CHECK(d.read("ACCEL") == 0);
  CHECK(d.read("VMIN") == 0);
  CHECK(d.read("OVERRIDE") == kOverrideOne);
  // A line with cruise speeds runs as the same line without, clock for clock: its feed
  // increment paces it (a quarter of the full rate).
  const Plan line = plan_line(Point{0, 0, 0}, Point{700, -260, 90}, Preload::Half);
  std::vector<Command> cmds;
  for (const auto& p : line.pieces) cmds.push_back(p.cmd);
  const std::uint32_t feed = 0x40000000u;
  const auto paced = pace_entries(cmds, 1u << 28, 1u << 22, 1u << 20);
  REQUIRE(paced.front().cruise != 0);
  const std::uint64_t with = run_line(h, m, d, line, feed, paced);
  const std::uint64_t without = run_line(h, m, d, line, feed, std::vector<PaceEntry>(cmds.size()));
  CHECK(with == without);
  CHECK(with > 4 * 700);  // (700 iterations at least, each four clocks)
  // A feed hold stops the steps at once; the resume goes on to the end point.
  d.preset(line.from);
  for (const auto& p : line.pieces) d.queue(p.cmd, feed);
  m.idle(600);
  d.hold();
  CHECK(get_field("STATUS", "held", d.read("STATUS")) == 1);
  const Point at = d.position();
  CHECK(at != line.from);
  m.idle(2000);
  CHECK(d.position() == at);
  CHECK(get_field("STATUS", "busy", d.read("STATUS")) == 1);
  d.resume();
  d.drain();
  CHECK(d.position() == line.to);
  // A driver that has read the build refuses a cruise speed and the pacer's settings.
  d.read_build();
  CHECK(!d.pacer());
  CHECK_THROWS_AS(d.queue(cmds.front(), feed, 0, paced.front()), GuardError);
  CHECK_THROWS_AS(d.set_pacing(1, 1), GuardError);
  CHECK_THROWS_AS(d.set_override(kOverrideOne), GuardError);
  CHECK(get_field("STATUS", "empty", d.read("STATUS")) == 1);
}

TEST_CASE("build: without the pacer, 24 random arcs, the three engines equal every cycle", "[motion][cosim][build]") {
  const std::uint64_t seed = test_seed(89);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  MotionCosim h;
  const MixStats st = run_motion_mix(h, seed, 24, true);
  INFO(st.pieces << " pieces, " << h.cycle() << " cycles");
  CHECK(st.arcs == 24);
  CHECK(st.position_checks > 0);
  CHECK(st.paced_pieces == 0);
  CHECK(st.fed_pieces > 0);
  CHECK(st.holds > 0);  // (the paced batches' holds, on fed batches)
}
#endif

#if DDA_MOTION_TEST_AXES == 2 && (DDA_MOTION_TEST_INPUTS == 0 || DDA_MOTION_TEST_PACER == 0)
#if DDA_MOTION_TEST_INPUTS == 0
#define DDA_TWO_AXES_AND "two axes without the inputs"
#else
#define DDA_TWO_AXES_AND "two axes without the pacer"
#endif
TEST_CASE("build: " DDA_TWO_AXES_AND ", CONFIG reads it, 32 random planar arcs, the three engines equal every cycle",
          "[motion][cosim][build]") {
  const std::uint64_t seed = test_seed(107);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  MotionCosim h;
  WishboneMaster m(h, 3, true, 10);
  MotionDriver d(m, 4);
  h.set_reset(false);
  m.idle(2);
  h.set_reset(true);
  m.idle(2);
  const std::uint32_t config = d.read("CONFIG");
  CHECK(get_field("CONFIG", "axes", config) == 2);
  CHECK(get_field("CONFIG", "inputs", config) == std::uint32_t(kHarnessInputs));
  CHECK(get_field("CONFIG", "pacer", config) == std::uint32_t(kHarnessPacer));
  CHECK(get_field("CONFIG", "depth_log2", config) == std::uint32_t(kHarnessDepthLog2));
  d.read_build();
  CHECK(d.axes() == 2);
  CHECK(d.inputs() == kHarnessInputs);
  CHECK(d.pacer() == kHarnessPacer);
  const MixStats st = run_motion_mix(h, seed, 32, true);
  INFO(st.pieces << " pieces, " << h.cycle() << " cycles");
  CHECK(st.arcs == 32);
  CHECK(st.position_checks > 0);
  CHECK(st.spatial == 0);
  CHECK(st.pulses_z == 0);
  if (kHarnessPacer) {
    CHECK(st.paced_pieces > 0);
  } else {
    CHECK(st.paced_pieces == 0);
    CHECK(st.fed_pieces > 0);
    CHECK(st.holds > 0);
  }
  if (!kHarnessInputs) CHECK(st.input_trips > 0);  // inputs held active, checked to act on nothing
}
#endif

#if DDA_MOTION_TEST_PACER == 0
// The board's build and the UP5K's (two axes) behind the SPI bridge.
#if DDA_MOTION_TEST_AXES == 2
#define DDA_NO_PACER "two axes without the pacer"
#else
#define DDA_NO_PACER "without the pacer"
#endif
TEST_CASE("build: " DDA_NO_PACER ", random work over SPI, SystemC model and RTL equal every cycle, as over Wishbone",
          "[motion][cosim][build][bridges]") {
  const std::uint64_t seed = test_seed(97);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  BridgeCosim h(Bus::spi);
  const BusWork got = run_bus_work(h, Bus::spi, seed, 3);
  ModelTarget ref(harness_build());
  const BusWork want = run_bus_work(ref, Bus::wishbone, seed, 3);
  INFO(h.cycle() << " cycles");
  CHECK(got.end == got.want);
  CHECK(got.iterations.size() > 100);
  CHECK(compare_work(want, got) == "");
}
#endif
