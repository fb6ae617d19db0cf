// SPDX-License-Identifier: Apache-2.0
// Engines the `dda` command can run (pipeline.hpp's Engine): the golden model, the
// SystemC model and the Verilated RTL, each turning pieces into Iteration records
// sampled from its own state.
#pragma once

#include <memory>
#include <string>

#include "host/pipeline/pipeline.hpp"

namespace dda::cli {

struct EngineOptions {
  std::string vcd;  // waveform file, empty for none
};

// The engines by name (engine_names.cpp: the option parsing needs the names, not the
// engines).
inline constexpr const char* kEngineNames[] = {"golden", "systemc", "rtl"};
bool known_engine(const std::string& name);
std::string engine_names();
// The named engine (a known one), reporting to `sink`.
std::unique_ptr<Engine> make_engine(const std::string& name, const EngineOptions& opt, RunSink& sink);

}  // namespace dda::cli
