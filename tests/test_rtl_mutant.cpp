// SPDX-License-Identifier: Apache-2.0
// A deliberately broken copy of the RTL (tests/CMakeLists.txt mutates a copy of
// rtl/dda_counter.v so that its counter never stops: active_o stays high at 0) must be
// caught by the golden-model scoreboard with a message naming the register.
#define CATCH_CONFIG_MAIN
#include "tb/engines/rtl_harness.hpp"
#include "tests/core_checks.hpp"

using namespace dda;
using namespace dda::checks;

TEST_CASE("rtl mutant: a counter that does not stop at zero is caught", "[rtl][mutant]") {
  rtl::RtlHarness h;
  const std::string message = mismatch_message(h, paper_plan());
  INFO(message);
  // Y's counter reaches 0 at iteration 18; the mutant's Y accumulator keeps adding.
  CHECK(message.find("rtl mismatch: register u_int_y.jr_q at iteration 19") != std::string::npos);
}
