// SPDX-License-Identifier: Apache-2.0
// libFuzzer target of the part-program reader (host/program/program.hpp): any bytes,
// read on a mill and on a lathe in the dialect detected, and on a mill in each dialect
// (the switch of block delete on in those). Bad input must end in ProgramError (an InputError);
// any other exception, a crash or a sanitizer report is a bug. Macro loops stop after
// 100,000 executed lines (not the default 10,000,000) so that each input runs fast; the
// limit's own path is the same. Built and run by scripts/fuzz-program.sh (clang,
// -fsanitize=fuzzer,address,undefined).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "host/program/program.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  using dda::program::Dialect;
  using dda::program::Machine;
  const auto read = [&](Machine m, std::optional<Dialect> d) {
    try {
      dda::program::ReadOptions ro;
      ro.machine = m;
      ro.dialect = d;
      ro.block_delete = d.has_value();
      ro.max_lines = 100000;
      dda::program::read(text, "fuzz.nc", ro);
    } catch (const dda::program::ProgramError&) {
    }
  };
  read(Machine::Mill, std::nullopt);
  read(Machine::Lathe, std::nullopt);
  for (const Dialect d : {Dialect::LinuxCnc, Dialect::Hnc, Dialect::Fanuc}) read(Machine::Mill, d);
  return 0;
}
