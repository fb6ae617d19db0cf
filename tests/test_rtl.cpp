// The RTL (Verilator --cc) against the golden model, register by register, iteration by
// iteration. Each harness has its own VerilatedContext, so tests share one process.
#define CATCH_CONFIG_MAIN
#include <unistd.h>

#include <filesystem>

#include "core_checks.hpp"
#include "rtl_harness.hpp"

using namespace dda;
using namespace dda::checks;

TEST_CASE("rtl: paper example matches the golden model in every register", "[rtl]") {
  const auto vcd = std::filesystem::temp_directory_path() /
                   ("dda_test_rtl_paper_" + std::to_string(::getpid()) + ".vcd");
  std::filesystem::remove(vcd);
  {
    rtl::RtlHarness h(vcd.string());
    paper_example(h);
    h.close_trace();
  }
  const std::string v = slurp(vcd.string());
  for (const char* scope : {"u_int_x", "u_int_y", "u_cnt_x", "u_cnt_y", "u_ctrl"}) {
    CHECK(v.find(std::string("$scope module ") + scope + " $end") != std::string::npos);
  }
  for (const char* reg : {" jv_q ", " jr_q ", " cnt_q ", " state_q ", " step_x_q ", " cap_q "}) {
    CHECK(v.find(reg) != std::string::npos);
  }
  std::filesystem::remove(vcd);
}

TEST_CASE("rtl: 1,000 random arcs back to back in lockstep with the golden model", "[rtl][random]") {
  rtl::RtlHarness h;
  random_arcs(h, test_seed(41), 1000);
}

TEST_CASE("rtl: 300 random whole-ellipse arcs (every quadrant, both directions) in lockstep", "[rtl][random]") {
  rtl::RtlHarness h;
  random_arcs(h, test_seed(43), 300, ArcKind::Whole);
}

TEST_CASE("rtl: a random ce pattern stretches the same pulse sequence", "[rtl][random]") {
  rtl::RtlHarness h;
  ce_stretch(h, test_seed(6), 40);
}

TEST_CASE("rtl: reset in the middle of an arc returns to idle, next command runs", "[rtl]") {
  rtl::RtlHarness h;
  reset_midway(h);
}

TEST_CASE("rtl: empty and stalled commands end with done and err", "[rtl]") {
  rtl::RtlHarness h;
  finished_and_stalled(h);
}
