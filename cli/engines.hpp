// SPDX-License-Identifier: Apache-2.0
// Engines the `dda` command can run: each turns a Plan into Iteration records
// sampled from its own state (golden model, SystemC model, Verilated RTL).
#pragma once

#include <string>
#include <vector>

#include "dda/golden.hpp"

namespace dda::cli {

struct EngineOptions {
  std::string vcd;  // waveform file, empty for none
};
struct EngineRun {
  RegState initial;                // the registers before the first iteration (trace row 0)
  std::vector<Iteration> records;  // one per iteration
};
using EngineFn = EngineRun (*)(const Plan&, const EngineOptions&);

EngineFn find_engine(const std::string& name);
std::string engine_names();

}  // namespace dda::cli
