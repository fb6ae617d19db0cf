// SPDX-License-Identifier: Apache-2.0
// Engines the `dda` command can run (pipeline.hpp's Engine): the golden model, the
// SystemC model and the Verilated RTL, each turning pieces into Iteration records
// sampled from its own state. Their names are cli/options/engine_names.hpp's; the engines
// are the library dda_cli's, the part of the command that links their harnesses
// (tb/engines/).
#pragma once

#include <memory>
#include <string>

#include "cli/options/engine_names.hpp"
#include "host/pipeline/pipeline.hpp"

namespace dda::cli {

struct EngineOptions {
  std::string vcd;  // waveform file, empty for none
};

// The named engine (a known one), reporting to `sink`.
std::unique_ptr<Engine> make_engine(const std::string& name, const EngineOptions& opt, RunSink& sink);

}  // namespace dda::cli
