// SPDX-License-Identifier: Apache-2.0
// Reads the signals of the register table (hw_params.hpp) from a Verilated dda_core
// (--cc or --sc) by their hierarchical names, through Verilator's scope tables (the RTL
// marks them public_flat_rd): the table is the only list of them. A name the RTL lacks,
// or a width that differs, is an error here.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/datapath/core_model.hpp"

class VerilatedContext;

namespace dda::rtl {

class VlSampler {
 public:
  // top: the scope of the dda_core instance (e.g. "dut.dda_core"). Throws GuardError.
  VlSampler(const VerilatedContext& ctx, const std::string& top, const hw::SignalTable& table);
  // The signals now (the table must be hw::kSignals).
  Signals read() const;

 private:
  struct Var {
    const void* p;
    int bytes;
  };
  std::vector<Var> vars_;
};

}  // namespace dda::rtl
