// SPDX-License-Identifier: Apache-2.0
// The block at the queue depth every user builds (rtl/dda_motion.v's default DepthLog2,
// 128 entries; the other lockstep tests run a queue of 8 to keep their runs short): the
// queue filled to its depth behind a slow line and one entry more refused, the RTL in
// lockstep with the reference model (tb/engines/motion_harness.hpp at the default depth).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include "tb/engines/motion_harness.hpp"
#include "tb/scenarios/io_scenarios.hpp"

using namespace dda::motion;

TEST_CASE("io: at the default depth the queue fills to its 128 entries and refuses one more", "[io]") {
  STATIC_REQUIRE(kHarnessDepthLog2 == kMaxDepthLog2);
  MotionHarness h;
  queue_overflow(h, Expect([](bool ok, const std::string& what) {
                   INFO(what);
                   CHECK(ok);
                 }));
}
