// SPDX-License-Identifier: Apache-2.0
// Reads the signals of the register table (hw_params.hpp) from a SystemC dda_core by
// their hierarchical names, resolved once with sc_find_object: the table is the only
// list of them. A name the model lacks, or a width that differs, is an error here.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "model/datapath/core_model.hpp"

namespace dda::sc {

class ScSampler {
 public:
  // core: the SystemC name of the dda_core instance (e.g. "dut"). Throws GuardError.
  ScSampler(const std::string& core, const hw::SignalTable& table);
  // The signals now (the table must be hw::kSignals).
  Signals read() const;

 private:
  std::vector<std::function<std::uint64_t()>> readers_;
};

}  // namespace dda::sc
