// SPDX-License-Identifier: Apache-2.0
// The clock of the DPI-C bench (tb/dpi/dda_dpi_tb.sv) under Verilator: edges until the
// bench's $finish, at most +max_cycles=N of them (default 100,000,000). Exit status 0
// when dda_finish() found nothing to report, 1 otherwise.
#include <verilated.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "Vdda_dpi_tb.h"
#include "tb/dpi/dda_dpi.h"
#include "tb/engines/vl_coverage.hpp"

int main(int argc, char** argv) {
  auto ctx = std::make_unique<VerilatedContext>();
  ctx->commandArgs(argc, argv);
  std::uint64_t max_cycles = 100000000;
  if (const char* m = ctx->commandArgsPlusMatch("max_cycles=")) {
    if (*m) max_cycles = std::strtoull(m + std::string("+max_cycles=").size(), nullptr, 10);
  }
  Vdda_dpi_tb top{ctx.get()};
  top.clk = 0;
  top.eval();
  for (std::uint64_t c = 0; !ctx->gotFinish(); ++c) {
    if (c >= max_cycles) {
      std::fprintf(stderr, "dda_dpi: no end after %llu cycles (+max_cycles)\n", static_cast<unsigned long long>(c));
      return 1;
    }
    top.clk = 1;
    top.eval();
    ctx->timeInc(5);
    top.clk = 0;
    top.eval();
    ctx->timeInc(5);
  }
  top.final();
  dda::write_coverage(*ctx, "dpi");
  return dda_dpi_result() == 0 ? 0 : 1;
}
