// The SystemC model against the golden model, register by register, iteration by
// iteration. Every TEST_CASE is its own ctest entry and process (one elaboration each).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <systemc>

#include "core_driver.hpp"
#include "dda/report.hpp"
#include "dda_random.hpp"
#include "sc_harness.hpp"

using namespace dda;

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

namespace {

Plan paper_plan(Preload p = Preload::Zero) {
  ArcSpec s;
  s.a = 10;
  s.b = 6;
  s.bits = 4;
  s.preload = p;
  return plan_arc(s);
}

bool same(const Iteration& a, const Iteration& b) {
  return a.iter == b.iter && a.active_x == b.active_x && a.active_y == b.active_y &&
         a.jv_x == b.jv_x && a.jv_y == b.jv_y && a.sum_x == b.sum_x && a.sum_y == b.sum_y &&
         a.step_x == b.step_x && a.step_y == b.step_y && a.after == b.after && a.pos == b.pos;
}

void check_records_equal(const std::vector<Iteration>& got, const std::vector<Iteration>& want) {
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    INFO("iteration " << i + 1);
    CHECK(same(got[i], want[i]));
  }
}

std::string trace_csv(const Plan& plan, const std::vector<Iteration>& recs) {
  std::ostringstream os;
  write_trace(os, plan, recs, TraceFormat::Csv);
  return os.str();
}

// An accumulator whose carry test is `>` instead of `>=`: a deliberately wrong
// variant, built only here.
struct FaultyIntegrator : sc::dda_integrator {
  using sc::dda_integrator::dda_integrator;
  bool carry(const sc::sum_t& s, const sc::acc_t& cap) const override { return s > cap; }
};

}  // namespace

TEST_CASE("systemc: paper example matches the golden model in every register", "[systemc]") {
  const auto vcd = std::filesystem::temp_directory_path() / "dda_test_systemc_paper.vcd";
  std::filesystem::remove(vcd);
  const Plan plan = paper_plan();
  std::vector<Iteration> got;
  {
    sc::ScHarness h(vcd.string());
    reset_core(h);
    got = drive_arc(h, plan).records;  // the scoreboard checks every iteration
    h.close_trace();
  }
  check_records_equal(got, run_records(plan));
  CHECK(trace_csv(plan, got) == trace_csv(plan, run_records(plan)));

  // The waveform holds the architectural registers.
  std::ifstream f(vcd);
  REQUIRE(f.good());
  std::stringstream text;
  text << f.rdbuf();
  const std::string v = text.str();
  for (const char* scope : {"u_int_x", "u_int_y", "u_cnt_x", "u_cnt_y", "u_ctrl"}) {
    CHECK(v.find(std::string("$scope module ") + scope + " $end") != std::string::npos);
  }
  for (const char* reg : {" jv_q ", " jr_q ", " cnt_q ", " state_q ", " step_x_q ", " cap_q "}) {
    CHECK(v.find(reg) != std::string::npos);
  }
  // 27 iterations at 10 ns each leave value changes well past 270 ns.
  CHECK(v.find("\n#300\n") != std::string::npos);
  std::filesystem::remove(vcd);
}

TEST_CASE("systemc: 200 random arcs back to back in lockstep with the golden model", "[systemc][random]") {
  const std::uint64_t seed = test_seed(31);
  RandomArcs gen(seed, 4096);
  sc::ScHarness h;
  reset_core(h);
  int arcs = 0;
  std::uint64_t iters = 0, cycles = 0;
  while (arcs < 200) {
    const auto plan = gen.next();
    if (!plan) continue;
    INFO("seed " << seed << ", arc " << arcs << ": dda trace " << describe(*plan));
    DriveOptions opt;
    opt.keep_records = false;
    const DriveResult r = drive_arc(h, *plan, opt);
    CHECK(r.end == plan->to);
    iters += r.iterations;
    cycles += r.cycles;
    ++arcs;
  }
  INFO("compared " << iters << " iterations in " << cycles << " cycles");
  CHECK(iters > 0);
}

TEST_CASE("systemc: a random ce pattern stretches the same pulse sequence", "[systemc][random]") {
  const std::uint64_t seed = test_seed(5);
  std::mt19937_64 rng(seed);
  RandomArcs gen(seed, 512);
  sc::ScHarness h;
  reset_core(h);
  for (int arcs = 0; arcs < 20;) {
    const auto plan = gen.next();
    if (!plan) continue;
    ++arcs;
    INFO("seed " << seed << ": dda trace " << describe(*plan));
    const DriveResult ref = drive_arc(h, *plan);
    // ce low for runs of 1 to 40 cycles (sometimes 300), high for runs of 1 to 10.
    DriveOptions opt;
    std::uint64_t until = 0;
    bool level = true;
    opt.ce = [&](std::uint64_t c) {
      if (c >= until) {
        level = !level;
        const std::uint64_t len = level ? 1 + rng() % 10 : (rng() % 16 == 0 ? 300 : 1 + rng() % 40);
        until = c + len;
      }
      return level;
    };
    const DriveResult slow = drive_arc(h, *plan, opt);
    check_records_equal(slow.records, ref.records);
    CHECK(slow.cycles > ref.cycles);
  }
}

TEST_CASE("systemc: reset in the middle of an arc returns to idle, next command runs", "[systemc]") {
  sc::ScHarness h;
  reset_core(h);
  const Plan plan = paper_plan(Preload::Half);
  DriveOptions cut;
  cut.reset_after = 12;
  const DriveResult r = drive_arc(h, plan, cut);
  CHECK(r.iterations == 12);
  // Idle, and no pulse while ce is high for a while.
  h.set_ce(true);
  for (int i = 0; i < 50; ++i) {
    h.tick();
    const CoreSample s = h.sample();
    CHECK(s.state == 0);
    CHECK_FALSE(s.step_x);
    CHECK_FALSE(s.step_y);
    CHECK_FALSE(s.iter);
    CHECK_FALSE(s.done);
    CHECK(s.cnt_x == 0);
    CHECK(s.cnt_y == 0);
    CHECK(h.cmd_ready());
  }
  // The next command (the paper's example) runs in lockstep to its end.
  const Plan next = paper_plan();
  check_records_equal(drive_arc(h, next).records, run_records(next));
}

TEST_CASE("systemc: the scoreboard catches a wrong accumulator (> instead of >=)", "[systemc]") {
  // In the paper's example the Y accumulator sums to exactly the capacity at iteration 8
  // (JRY = 16.0), where the wrong variant does not carry.
  const auto faulty_y = [](const char* name) -> std::unique_ptr<sc::dda_integrator> {
    if (std::string(name) == "u_int_y") return std::make_unique<FaultyIntegrator>(name);
    return std::make_unique<sc::dda_integrator>(name);
  };
  sc::ScHarness h("", faulty_y);
  reset_core(h);
  const Plan plan = paper_plan();
  std::string message;
  try {
    drive_arc(h, plan);
  } catch (const MismatchError& e) {
    message = e.what();
  }
  INFO(message);
  CHECK(message.find("register u_int_y.jr_q at iteration 8") != std::string::npos);
  CHECK(message.find("golden 0, systemc 960") != std::string::npos);

  // Unchecked, the variant's trace rows differ from the golden model's.
  reset_core(h);
  DriveOptions unchecked;
  unchecked.check = false;
  const auto rows = trace_csv(plan, drive_arc(h, plan, unchecked).records);
  CHECK(rows != trace_csv(plan, run_records(plan)));
}
