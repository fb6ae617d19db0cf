// SPDX-License-Identifier: Apache-2.0
// The motion block's SystemC model and RTL co-simulated every cycle (ports, block
// registers, the core's registers) and compared with the block's reference model, under
// random queued work with aborts, resets, partial commits and overflows; the position
// counters end on every batch's end point. Every TEST_CASE is its own ctest entry and
// process (SystemC elaborates once).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <systemc>

#include "dda_random.hpp"
#include "motion_cosim.hpp"
#include "motion_mix.hpp"

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

using namespace dda;
using namespace dda::motion;

TEST_CASE("motion cosim: 60 random arcs queued on classic cycles, SystemC model and RTL equal every cycle",
          "[motion][cosim]") {
  const std::uint64_t seed = test_seed(71);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  MotionCosim h;
  const MixStats st = run_motion_mix(h, seed, 60, false);
  INFO(st.pieces << " pieces, " << h.cycle() << " cycles");
  CHECK(st.arcs == 60);
  CHECK(st.position_checks > 0);
  CHECK(st.piece_checks > 0);
  CHECK(st.pulses_z > 0);      // the third axis' stage ran
  CHECK(st.paced_pieces > 0);  // the pacer ran, with a hold and an override change
}

TEST_CASE("motion cosim: 60 random arcs queued on pipelined cycles, SystemC model and RTL equal every cycle",
          "[motion][cosim]") {
  const std::uint64_t seed = test_seed(73);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  MotionCosim h;
  const MixStats st = run_motion_mix(h, seed, 60, true);
  CHECK(st.arcs == 60);
  CHECK(st.position_checks > 0);
  CHECK(st.piece_checks > 0);
  CHECK(st.pulses_z > 0);      // the third axis' stage ran
  CHECK(st.paced_pieces > 0);  // the pacer ran, with a hold and an override change
}
