// A regression loop shared by the engines' regression drivers: random arcs back to back
// through one harness, in lockstep with the golden model, a share with random ce_i
// stalls and a share reset halfway. Prints the numbers of arcs, iterations and cycles
// compared; returns the process exit status (0, or 1 on the first mismatch).
#pragma once

#include "core_driver.hpp"

namespace dda {

int regress_main(CoreHarness& h, int argc, char* argv[]);

}  // namespace dda
