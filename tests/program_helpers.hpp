// SPDX-License-Identifier: Apache-2.0
// Helpers of the reader's tests: a program read in LinuxCNC's dialect, and the error a
// program raises ("" when it reads).
#pragma once

#include <string>

#include "host/program/program.hpp"

namespace dda::program::testing {

inline Program lcnc(const std::string& text, Machine m = Machine::Mill) {
  ReadOptions o;
  o.dialect = Dialect::LinuxCnc;
  o.machine = m;
  return read(text, "p.ngc", o);
}

inline std::string error_in(const std::string& text, Machine m = Machine::Mill) {
  try {
    lcnc(text, m);
  } catch (const ProgramError& e) {
    return e.what();
  }
  return "";
}

}  // namespace dda::program::testing
