// SPDX-License-Identifier: Apache-2.0
// The waveform of a verilated model (for the harnesses' .cpp files only: it includes
// Verilator's headers).
#pragma once

#include <verilated.h>
#include <verilated_vcd_c.h>

#include <memory>
#include <string>

#include "datapath/errors.hpp"

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

}  // namespace dda
