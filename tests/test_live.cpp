// SPDX-License-Identifier: Apache-2.0
// A live run's host side (host/run/, host/speed/entry_stream.hpp): the streamed entries
// are the whole program's (speed::program_entries) for the examples, and never faster
// where the window ends before the pieces that decide an exit; the control file's
// requests; the machine description's live keys.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "host/run/controls.hpp"
#include "host/run/live_run.hpp"
#include "host/speed/entry_stream.hpp"
#include "host/speed/pace_plan.hpp"
#include "model/datapath/errors.hpp"
#include "model/datapath/hw_command.hpp"

using namespace dda;
using namespace dda::speed;

namespace {

struct Example {
  const char* file;
  program::Machine machine;
};
const Example kExamples[] = {
    {"mill-contour.ngc", program::Machine::Mill}, {"circles.ngc", program::Machine::Mill},
    {"pocket.ngc", program::Machine::Mill},       {"helix.ngc", program::Machine::Mill},
    {"planes.ngc", program::Machine::Mill},       {"lathe-profile.ngc", program::Machine::Lathe},
    {"ellipses.ngc", program::Machine::Lathe}};

program::ReadOptions read_of(const Example& e) {
  program::ReadOptions read;
  read.machine = e.machine;
  if (e.machine == program::Machine::Lathe) read.start = program::start_point(e.machine, 60000000, 5000000);
  return read;
}

std::ifstream open(const Example& e) {
  std::ifstream in(std::string(DDA_EXAMPLES_DIR) + "/" + e.file);
  REQUIRE(in);
  return in;
}

}  // namespace

TEST_CASE("live: the streamed entries are the whole program's, piece by piece") {
  for (const program::Length step : {program::Length{1000}, program::Length{10000}}) {
    for (const Example& e : kExamples) {
      INFO(e.file << " at a step of " << step << " nm");
      MachineLimits lim = default_limits(e.machine);
      lim.default_feed = 100;
      program::LatticeOptions lattice;
      lattice.step = step;
      std::ifstream whole_in = open(e);
      const PlannedProgram pp = plan_program_pieces(whole_in, e.file, read_of(e), lattice, lim);
      const PaceSetup s = pace_setup(planner_limits(lim, e.machine), lim, step, 40e6);
      const std::vector<motion::PaceEntry> want = program_entries(pp, s);
      std::vector<StreamEntry> got;
      std::ifstream in = open(e);
      stream_program_entries(in, e.file, read_of(e), lattice, program::kDefaultWindow, lim, s,
                             [&](const StreamEntry& x) { got.push_back(x); });
      REQUIRE(got.size() == want.size());
      for (std::size_t k = 0; k < got.size(); ++k) {
        INFO("piece " << k);
        CHECK(hw::pack_command(got[k].piece.cmd) == hw::pack_command(pp.plan.pieces[k].cmd));
        CHECK(got[k].piece.rot == pp.plan.pieces[k].rot);
        CHECK(got[k].pace.cruise == want[k].cruise);
        CHECK(got[k].pace.exit == want[k].exit);
        CHECK(got[k].pace.length == want[k].length);
        CHECK(got[k].pace.brake_exit == want[k].brake_exit);
      }
      CHECK(got.front().piece.from == pp.plan.from);
      CHECK(got.back().piece.to == pp.plan.to);
    }
  }
}

TEST_CASE("live: a window too short to decide an exit sends it no faster than the whole program's") {
  const Example e = kExamples[1];
  MachineLimits lim = default_limits(e.machine);
  program::LatticeOptions lattice;
  lattice.step = 1000;
  std::ifstream whole_in = open(e);
  const PlannedProgram pp = plan_program_pieces(whole_in, e.file, read_of(e), lattice, lim);
  const PaceSetup s = pace_setup(planner_limits(lim, e.machine), lim, lattice.step, 40e6);
  const std::vector<motion::PaceEntry> want = program_entries(pp, s);
  std::vector<StreamEntry> got;
  EntryStream stream(
      s, [&](const StreamEntry& x) { got.push_back(x); }, 2);
  std::ifstream in = open(e);
  plan_program_speeds(
      in, e.file, read_of(e), lattice, program::kDefaultWindow, lim, [](const BlockSpeeds&) {},
      [&](const PlannedSegment& p) { stream.segment(p); }, [&](const program::BlockPlan& b) { stream.pieces(b); });
  stream.finish();
  REQUIRE(got.size() == want.size());
  std::size_t lower = 0;
  for (std::size_t k = 0; k < got.size(); ++k) {
    CHECK(got[k].pace.exit <= want[k].exit);
    CHECK(got[k].pace.brake_exit == motion::brake_distance(got[k].pace.exit, s.vmin, s.accel));
    lower += got[k].pace.exit < want[k].exit;
  }
  CHECK(lower > 0);  // (the circles' junctions: the short window costs speed there)
}

TEST_CASE("live: a control file's requests, at their times, and its errors") {
  const std::string path = "test_live_control.txt";
  {
    std::ofstream f(path);
    f << "# an operator\nhold\n@1.5 resume\n@2 override 150\n@2 override +\noverride -  # comment\n@3 stop\n";
  }
  live::ControlFile c(path);
  const auto next = [&](double t) { return c.poll(t); };
  REQUIRE(next(0));
  CHECK(next(0) == std::nullopt);  // resume waits for 1.5 s
  const auto r = next(1.5);
  REQUIRE(r);
  CHECK(r->what == live::Control::Resume);
  const auto o = next(2);
  REQUIRE(o);
  CHECK(o->what == live::Control::Override);
  CHECK(o->percent == 150);
  CHECK(next(2).value().what == live::Control::OverrideUp);
  CHECK(next(2).value().what == live::Control::OverrideDown);
  CHECK(next(2.5) == std::nullopt);
  CHECK(next(3).value().what == live::Control::SoftStop);
  CHECK(next(4) == std::nullopt);
  {
    std::ofstream f(path, std::ios::app);  // the file grows
    f << "hard-stop\n";
  }
  CHECK(next(4).value().what == live::Control::HardStop);
  for (const char* bad : {"jog\n", "override 250\n", "@x hold\n", "hold now\n", "@1\n"}) {
    INFO(bad);
    {
      std::ofstream f(path);
      f << bad;
    }
    live::ControlFile b(path);
    CHECK_THROWS_AS(b.poll(10), InputError);
  }
  std::remove(path.c_str());
}

TEST_CASE("live: the machine description's live keys and their errors") {
  const program::Machine mill = program::Machine::Mill;
  const MachineLimits l = parse_machine_config(
      R"({"clock_hz": 1e6, "watchdog_ms": 20, "port": "sim",
          "axes": {"x": {"steps_per_mm": 400, "step_len_ns": 3000, "invert_dir": true, "limit_pos_mm": 120},
                   "y": {"steps_per_mm": 400}},
          "inputs": {"invert": ["probe", "limit_x_pos"], "switch_filter_us": 500, "limit_decel": true}})",
      "m.json", default_limits(mill), mill);
  CHECK(l.live.clock_hz == 1e6);
  CHECK(l.live.watchdog_ms == 20);
  CHECK(l.live.port == "sim");
  CHECK(l.live.axes[0].step_len_ns == 3000);
  CHECK(l.live.axes[0].invert_dir);
  CHECK(*l.live.axes[0].limit_pos_mm == 120);
  CHECK(l.live.invert_inputs == (1u << motion::input_bit("probe") | 1u << motion::input_bit("limit_x_pos")));
  CHECK(l.live.limit_decel);
  CHECK(live::live_step(l, mill, 1000) == 2500);  // 400 steps per mm: 2.5 um
  for (const char* bad : {R"({"axes": {"x": {"steps_per_mm": 0}}})", R"({"axes": {"x": {"invert_step": 1}}})",
                          R"({"inputs": {"invert": ["probes"]}})", R"({"inputs": {"filter": 1}})",
                          R"({"clock_hz": 2e9})", R"({"port": ""})", R"({"axes": {"x": {"dir_hold_ns": -1}}})"}) {
    INFO(bad);
    CHECK_THROWS_AS(parse_machine_config(bad, "m.json", default_limits(mill), mill), InputError);
  }
  // Axes at different steps per mm, and a step that is not whole nanometres.
  MachineLimits d = default_limits(mill);
  d.live.axes[0].steps_per_mm = 400;
  d.live.axes[1].steps_per_mm = 200;
  CHECK_THROWS_AS(live::live_step(d, mill, 1000), InputError);
  d.live.axes[1].steps_per_mm = 0;
  d.live.axes[0].steps_per_mm = 3;
  CHECK_THROWS_AS(live::live_step(d, mill, 1000), InputError);
}
