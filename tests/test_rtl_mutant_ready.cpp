// SPDX-License-Identifier: Apache-2.0
// A broken copy of the RTL that takes a command only when idle (tests/CMakeLists.txt):
// the pieces of an arc then run with an idle cycle between them, which the scoreboard
// catches as cmd_ready_o low in the cycle of piece 0's last iteration (edge 30: two reset
// edges, the load, 27 iterations), where the reference model is ready for the next.
#define CATCH_CONFIG_MAIN
#include "tb/engines/rtl_harness.hpp"
#include "tests/core_checks.hpp"

using namespace dda;
using namespace dda::checks;

TEST_CASE("rtl mutant: a core that does not load back to back is caught", "[rtl][mutant]") {
  rtl::RtlHarness h;
  ArcSpec s;
  s.a = 10;
  s.b = 6;
  s.bits = 4;
  s.from = Point{10, 0};
  s.to = Point{-10, 0};  // two pieces, meeting at (0,6)
  const std::string message = mismatch_message(h, plan_arc(s));
  INFO(message);
  CHECK(message.find("rtl mismatch: output cmd_ready_o before cycle 30: golden 1, rtl 0") != std::string::npos);
}
