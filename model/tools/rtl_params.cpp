// SPDX-License-Identifier: Apache-2.0
// Writes the RTL's width header (rtl/dda_params.vh) at this build's widths: a build at
// other widths (CMake options DDA_ACC_WIDTH, DDA_CNT_WIDTH) verilates the RTL with it.
// The same text as `dda gen-params --kind verilog`; CMake compiles and runs it while
// configuring (try_run in the top CMakeLists.txt), because verilate() runs Verilator
// then, before the dda tool can be built.
//   usage: dda_rtl_params OUT.vh
#include <cstdio>
#include <fstream>
#include <iostream>

#include "dda/hw_params.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: dda_rtl_params OUT.vh\n";
    return 2;
  }
  const std::string tmp = std::string(argv[1]) + ".tmp";
  {
    std::ofstream out(tmp);
    out << dda::hw::verilog_header();
    if (!out) {
      std::cerr << "dda_rtl_params: cannot write " << tmp << "\n";
      return 1;
    }
  }
  if (std::rename(tmp.c_str(), argv[1]) != 0) {
    std::cerr << "dda_rtl_params: cannot write " << argv[1] << "\n";
    return 1;
  }
  return 0;
}
