// SPDX-License-Identifier: Apache-2.0
// libFuzzer target of the part-program reader (model/program/program.hpp): any bytes,
// read on a mill and on a lathe. Bad input must end in ProgramError (an InputError);
// any other exception, a crash or a sanitizer report is a bug. Macro loops stop after
// 100,000 executed lines (not the default 10,000,000) so that each input runs fast; the
// limit's own path is the same. Built and run by scripts/fuzz-program.sh (clang,
// -fsanitize=fuzzer,address,undefined).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "program/program.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (const auto m : {dda::program::Machine::Mill, dda::program::Machine::Lathe}) {
    try {
      dda::program::ReadOptions ro;
      ro.machine = m;
      ro.max_lines = 100000;
      dda::program::read(text, "fuzz.nc", ro);
    } catch (const dda::program::ProgramError&) {
    }
  }
  return 0;
}
