// SPDX-License-Identifier: Apache-2.0
// The coverage counts of a verilated model, written when it ends: in a coverage build
// (cmake -DDDA_COVERAGE=ON, verilator --coverage) and with DDA_COVERAGE_DIR set, each
// call writes a new file DIR/NAME-PID-N.dat; scripts/coverage.sh merges them with
// verilator_coverage. Otherwise nothing. Include it only in the sources of a target
// that verilate() builds (it reads that target's VM_COVERAGE).
#pragma once

#include <verilated.h>

#if VM_COVERAGE
#include <unistd.h>
#include <verilated_cov.h>

#include <atomic>
#include <cstdlib>
#include <string>
#endif

namespace dda {

inline void write_coverage([[maybe_unused]] VerilatedContext& ctx, [[maybe_unused]] const char* name) {
#if VM_COVERAGE
  const char* dir = std::getenv("DDA_COVERAGE_DIR");
  if (dir == nullptr || *dir == '\0') return;
  static std::atomic<unsigned> n{0};
  const std::string path =
      std::string(dir) + "/" + name + "-" + std::to_string(::getpid()) + "-" + std::to_string(n++) + ".dat";
  ctx.coveragep()->write(path.c_str());
#endif
}

}  // namespace dda
