// SPDX-License-Identifier: Apache-2.0
// The waveform of a verilated model (for the harnesses' .cpp files only: it includes
// Verilator's headers).
#pragma once

#include <verilated.h>
#include <verilated_vcd_c.h>

#include <memory>
#include <string>

#include "model/datapath/errors.hpp"

namespace dda {

// A VCD of `top` into `path` from the context's present time on; none if path is empty.
// GuardError if the file cannot be written.
template <typename Top>
std::unique_ptr<VerilatedVcdC> open_waveform(Top& top, const VerilatedContext& ctx, const std::string& path) {
  if (path.empty()) return nullptr;
  auto vcd = std::make_unique<VerilatedVcdC>();
  top.trace(vcd.get(), 99);
  vcd->open(path.c_str());
  if (!vcd->isOpen()) throw GuardError("cannot write the waveform '" + path + "'");
  vcd->dump(ctx.time());
  return vcd;
}

// Half a clock period of `top`: the clock set to `high`, the model evaluated, 5 time
// units on, and the waveform (if any) dumped there. Two make the 10-unit period both
// harnesses run, inputs set while the clock is low, the rising edge in the middle.
template <typename Top>
void half_period(Top& top, VerilatedContext& ctx, VerilatedVcdC* vcd, bool high) {
  top.clk_i = high;
  top.eval();
  ctx.timeInc(5);
  if (vcd) vcd->dump(ctx.time());
}

}  // namespace dda
