// SPDX-License-Identifier: Apache-2.0
// dda gen-params: the text generated from the one definition of the widths, the command
// fields, the register table and the motion block's register map (hw_params.hpp,
// motion_map.hpp): the RTL headers, the firmware header, the design doc's tables, the
// GTKWave save files and the benches' field layouts.
#pragma once

#include <string>

#include "model/datapath/hw_params.hpp"

namespace CLI {
class App;
}

namespace dda::cli {

struct GenParamsCli {
  std::string kind = "verilog", out;
  int acc_width = hw::kAccWidth, cnt_width = hw::kCntWidth;
};

void add_gen_params_options(CLI::App* sub, GenParamsCli& g);
void run_gen_params(const GenParamsCli& g);

}  // namespace dda::cli
