// SPDX-License-Identifier: Apache-2.0
// The co-simulation against a deliberately broken copy of the RTL (the counter never
// stops, see tests/CMakeLists.txt): the cycle-by-cycle comparison must name what differs first.
#define CATCH_CONFIG_RUNNER
#include <systemc>

#include "tb/cosim/cosim_harness.hpp"
#include "tests/core_checks.hpp"

using namespace dda;
using namespace dda::checks;

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

TEST_CASE("cosim mutant: a counter that does not stop at zero is caught", "[cosim][mutant]") {
  cosim::CosimHarness h;
  const std::string message = mismatch_message(h, paper_plan());
  INFO(message);
  // The Y counter reaches 0 at iteration 18 (edge 18 after the load); the mutant's Y
  // stays active, which its norm operand (the integrand while the axis runs) shows after
  // that edge, before the accumulator adds on the next one.
  CHECK(message.find("cosim mismatch at cycle") != std::string::npos);
  CHECK(message.find("output norm_v_y_o") != std::string::npos);
  CHECK(message.find("(systemc vs rtl)") != std::string::npos);
}
