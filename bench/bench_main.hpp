// SPDX-License-Identifier: Apache-2.0
// Speed measurement for scripts/bench: one long arc (a full circle, half preload,
// default width) run several times on one engine; prints one line per repetition:
//   rep K: N cycles (or iterations) in S s
// The golden engine runs Datapath::step (records off: the path cross-checks and vector
// generation use); the others run through the shared driver with the scoreboard off.
#pragma once

#include "tb/engines/core_driver.hpp"

namespace dda {

// h == nullptr: the golden model. usage: --radius R --reps N
int bench_main(CoreHarness* h, int argc, char** argv);

}  // namespace dda
