// SPDX-License-Identifier: Apache-2.0
// Writes the RTL's headers at this build's widths into OUTDIR: dda_params.vh (the core's
// widths and command fields, as rtl/dda_params.vh) and dda_motion_regs.vh (the motion
// block's register map, as rtl/dda_motion_regs.vh). A build at other widths (CMake
// options DDA_ACC_WIDTH, DDA_CNT_WIDTH) verilates the RTL with them. The same text as
// `dda gen-params --kind verilog` and `--kind motion-verilog`; CMake compiles and runs
// this while configuring (try_run in the top CMakeLists.txt), because verilate() runs
// Verilator then, before the dda tool can be built.
//   usage: dda_rtl_params OUTDIR
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "model/datapath/hw_params.hpp"
#include "model/motion/motion_map.hpp"

namespace {

bool write(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << text;
    if (!out) return false;
  }
  return std::rename(tmp.c_str(), path.c_str()) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: dda_rtl_params OUTDIR\n";
    return 2;
  }
  const std::string dir = argv[1];
  if (!write(dir + "/dda_params.vh", dda::hw::verilog_header()) ||
      !write(dir + "/dda_motion_regs.vh", dda::motion::verilog_header())) {
    std::cerr << "dda_rtl_params: cannot write into " << dir << "\n";
    return 1;
  }
  return 0;
}
