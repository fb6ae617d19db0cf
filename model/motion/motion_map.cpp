// SPDX-License-Identifier: Apache-2.0
#include "model/motion/motion_map.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cctype>

#include "model/datapath/errors.hpp"
#include "model/motion/build.hpp"

namespace dda::motion {

namespace {

std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u) c = char(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

std::string_view access_name(Access a) {
  switch (a) {
    case Access::RO:
      return "RO";
    case Access::RW:
      return "RW";
    case Access::W1C:
      return "W1C";
    case Access::WO:
      return "WO";
  }
  return "?";
}

std::string constants_comment() {
  return fmt::format(
      "ID 0x{:08X}, version {}.{}, entry {} words ({} command bits, {}-bit axes at bit {} of word {}, {} reserved, a "
      "{}-bit feed increment at bit {} of word {}, the pacing fields {} in words {}..{}), AccWidth {}, CntWidth {}",
      kId, kVersionMajor, kVersionMinor, kEntryWords, hw::kCmdWidth, kAxesWidth, kAxesLsb, kAxesWord,
      kEntrySpareBits - kFeedWidth - kAxesWidth, kFeedWidth, kFeedLsb, kFeedWord, fmt::join(kPaceFields, ", "),
      kPaceWord, kPaceWord + kPaceWords - 1, hw::kAccWidth, hw::kCntWidth);
}

}  // namespace

Map map() {
  Map m{std::vector<Register>(kRegisters.begin(), kRegisters.end()),
        std::vector<Field>(kFields.begin(), kFields.end())};
  // INPUTS, IN_POLARITY and TRIP: a bit per input (kInputs), TRIP's without the probe.
  for (const auto& in : kInputs) m.fields.push_back(Field{"INPUTS", in.name, in.bit, 1, in.meaning});
  for (const auto& in : kInputs) m.fields.push_back(Field{"IN_POLARITY", in.name, in.bit, 1, in.pin});
  for (const auto& in : kInputs) {
    if (in.bit < kTripBits) m.fields.push_back(Field{"TRIP", in.name, in.bit, 1, in.meaning});
  }
  return m;
}

void check(const Map& m) {
  for (std::size_t i = 0; i < m.regs.size(); ++i) {
    const auto& r = m.regs[i];
    if (r.offset % 4 != 0 || r.offset >= (1u << kAddrWidth)) {
      throw GuardError(
          fmt::format("motion map: register {} at 0x{:02X} is not a word inside the block", r.name, r.offset));
    }
    const unsigned span = r.name == "ENTRY" ? 4u * kEntryWords : 4u;
    for (std::size_t j = 0; j < i; ++j) {
      const auto& q = m.regs[j];
      const unsigned qspan = q.name == "ENTRY" ? 4u * kEntryWords : 4u;
      if (r.offset < q.offset + qspan && q.offset < r.offset + span) {
        throw GuardError(fmt::format("motion map: registers {} and {} overlap", q.name, r.name));
      }
    }
  }
  for (std::size_t i = 0; i < m.fields.size(); ++i) {
    const auto& f = m.fields[i];
    bool known = false;
    for (const auto& r : m.regs) known = known || r.name == f.reg;
    if (!known) throw GuardError(fmt::format("motion map: field {}.{} of no register", f.reg, f.name));
    if (f.width < 1 || f.lsb < 0 || f.lsb + f.width > 32) {
      throw GuardError(fmt::format("motion map: field {}.{} leaves its 32-bit word", f.reg, f.name));
    }
    for (std::size_t j = 0; j < i; ++j) {
      const auto& g = m.fields[j];
      if (g.reg == f.reg && f.lsb < g.lsb + g.width && g.lsb < f.lsb + f.width) {
        throw GuardError(fmt::format("motion map: fields {}.{} and {}.{} overlap", g.reg, g.name, f.reg, f.name));
      }
    }
  }
}

namespace {
// A register's reset value as the table gives it.
std::string reset_text(const Register& r) {
  if (r.access == Access::WO) return "-";
  if (r.reset == kResetBuild) return "the build's";
  return fmt::format("0x{:08X}", std::uint32_t(r.reset));
}
}  // namespace

std::string markdown(const Map& m) {
  std::string o = "Motion block registers (" + constants_comment() + "):\n\n";
  o += "| offset | register | access | reset | meaning |\n|---|---|---|---|---|\n";
  for (const auto& r : m.regs) {
    const std::string off = r.name == "ENTRY"
                                ? fmt::format("0x{:02X}..0x{:02X}", r.offset, r.offset + 4 * kEntryWords - 1)
                                : fmt::format("0x{:02X}", r.offset);
    o += fmt::format("| {} | `{}` | {} | {} | {} |\n", off, r.name, access_name(r.access), reset_text(r), r.meaning);
  }
  o += "\n(Reset: the value read out of reset with the machine's inputs inactive; a write-only register reads "
       "0.)\n";
  o += "\n| register | field | bits | meaning |\n|---|---|---|---|\n";
  for (const auto& f : m.fields) {
    o += fmt::format("| `{}` | `{}` | {}:{} | {} |\n", f.reg, f.name, f.lsb + f.width - 1, f.lsb, f.meaning);
  }
  o += fmt::format("\nSPI frame ({} rising SCK edges, bits numbered from the first):\n\n", kSpiFrameBits);
  o += "| part | bits | meaning |\n|---|---|---|\n";
  for (const auto& p : kSpiFrame) {
    o += fmt::format("| {} | {}..{} | {} |\n", p.name, p.first, p.first + p.width - 1, p.meaning);
  }
  o += "\n| status field | bits | meaning |\n|---|---|---|\n";
  for (const auto& p : kSpiStatus) {
    o += fmt::format("| {} | {}:{} | {} |\n", p.name, p.first + p.width - 1, p.first, p.meaning);
  }
  return o;
}

std::string c_header(const Map& m) {
  std::string o =
      "/* SPDX-License-Identifier: Apache-2.0 */\n"
      "/* Register map of the DDA motion block (rtl/dda_motion.v) for firmware.\n"
      " * Generated by `dda gen-params --kind motion-c` from model/motion/motion_map.hpp:\n"
      " * do not edit. The test \"motion_map: the checked-in files are generated\" fails if\n"
      " * they differ. " +
      constants_comment() +
      ".\n"
      " * Byte offsets from the block's base; every register is a 32-bit word. */\n"
      "#ifndef DDA_MOTION_REGS_H\n#define DDA_MOTION_REGS_H\n\n";
  o += fmt::format("#define DDA_MOTION_ID_VALUE 0x{:08X}u\n", kId);
  o += fmt::format("#define DDA_MOTION_VERSION_MAJOR {}u\n#define DDA_MOTION_VERSION_MINOR {}u\n", kVersionMajor,
                   kVersionMinor);
  o += fmt::format("#define DDA_MOTION_ENTRY_WORDS {}u\n#define DDA_MOTION_CMD_BITS {}u\n", kEntryWords, hw::kCmdWidth);
  o += fmt::format("#define DDA_MOTION_MAX_DEPTH {}u  /* entries of the largest queue */\n", 1u << kMaxDepthLog2);
  o += fmt::format(
      "#define DDA_MOTION_FEED_WORD {}u  /* the entry word holding the feed increment */\n"
      "#define DDA_MOTION_FEED_LSB {}u\n#define DDA_MOTION_FEED_MASK 0x{:08X}u\n#define DDA_MOTION_TIMING_WIDTH "
      "{}u\n\n",
      kFeedWord, kFeedLsb, ((std::uint64_t{1} << kFeedWidth) - 1) << kFeedLsb, kTimingWidth);
  // The core's command in the entry: its fields LSB first from bit 0 of word 0.
  o += fmt::format(
      "/* The core's command, the first DDA_MOTION_CMD_BITS bits of an entry: field NAME\n"
      " * occupies bits AT .. AT + WIDTH - 1, counted from bit 0 of entry word 0 (bit k in\n"
      " * word k / 32, bit k % 32); a negative value in two's complement of WIDTH bits. */\n");
  int at = 0;
  for (const auto& f : hw::kCmdFields) {
    o += fmt::format("#define DDA_MOTION_CMD_{}_AT {}u  /* {} */\n#define DDA_MOTION_CMD_{}_WIDTH {}u\n", upper(f.name),
                     at, f.meaning, upper(f.name), f.width);
    at += f.width;
  }
  o += "\n";
  o += fmt::format(
      "#define DDA_MOTION_AXES_WORD {}u  /* the entry word holding the axes: the core's x, y, z drive axes\n"
      "                                  (i + AXES) mod 3 of X, Y, Z */\n#define DDA_MOTION_AXES_LSB {}u\n"
      "#define DDA_MOTION_AXES_MASK 0x{:08X}u\n",
      kAxesWord, kAxesLsb, ((std::uint64_t{1} << kAxesWidth) - 1) << kAxesLsb);
  for (std::size_t i = 0; i < kPaceFields.size(); ++i) {
    o += fmt::format("#define DDA_MOTION_PACE_{}_WORD {}u  /* the entry word holding the pacing field {} */\n",
                     upper(kPaceFields[i]), kPaceWord + int(i), kPaceFields[i]);
  }
  o += fmt::format(
      "#define DDA_MOTION_OVERRIDE_ONE {}u  /* OVERRIDE of 100% */\n#define DDA_MOTION_OVERRIDE_MAX {}u\n\n",
      kOverrideOne, 2 * kOverrideOne);
  for (const auto& r : m.regs) {
    o += fmt::format("#define DDA_MOTION_{}_OFFSET 0x{:02X}u  /* {}: {} */\n", upper(r.name), r.offset,
                     access_name(r.access), r.meaning);
  }
  o += "\n/* The registers' values out of reset, the machine's inputs inactive (CONFIG: the build's; a\n"
       "   write-only register reads 0). */\n";
  for (const auto& r : m.regs) {
    if (r.access == Access::WO || r.reset == kResetBuild) continue;
    o += fmt::format("#define DDA_MOTION_{}_RESET 0x{:08X}u\n", upper(r.name), std::uint32_t(r.reset));
  }
  o += "\n";
  for (const auto& f : m.fields) {
    const std::string n = "DDA_MOTION_" + upper(f.reg) + "_" + upper(f.name);
    const std::uint64_t mask = ((std::uint64_t{1} << f.width) - 1) << f.lsb;
    o += fmt::format("#define {}_LSB {}u\n#define {}_MASK 0x{:08X}u\n", n, f.lsb, n, mask);
  }
  o += fmt::format("\n/* The SPI bridge's frame: CS_n low for {} rising SCK edges, MSB first. */\n", kSpiFrameBits);
  o += fmt::format("#define DDA_MOTION_SPI_FRAME_BITS {}u\n#define DDA_MOTION_SPI_WRITE 0x{:02X}u\n", kSpiFrameBits,
                   1u << kSpiWriteBit);
  for (const auto& p : kSpiFrame) {
    o += fmt::format("#define DDA_MOTION_SPI_{}_AT {}u  /* {} */\n", upper(p.name), p.first, p.meaning);
  }
  for (const auto& p : kSpiStatus) {
    o += fmt::format("#define DDA_MOTION_SPI_ST_{}_LSB {}u\n#define DDA_MOTION_SPI_ST_{}_MASK 0x{:02X}u\n",
                     upper(p.name), p.first, upper(p.name), ((1u << p.width) - 1) << p.first);
  }
  o += "\n#endif /* DDA_MOTION_REGS_H */\n";
  return o;
}

std::string verilog_header(const Map& m) {
  std::string o =
      "// SPDX-License-Identifier: Apache-2.0\n"
      "// Register map of the motion block (rtl/dda_motion.v). Generated by `dda gen-params\n"
      "// --kind motion-verilog` from model/motion/motion_map.hpp: do not edit. The test\n"
      "// \"motion_map: the checked-in files are generated\" fails if they differ.\n"
      "// " +
      constants_comment() + ".\n`ifndef DDA_MOTION_REGS_VH\n`define DDA_MOTION_REGS_VH\n\n";
  o += fmt::format("`define DDA_MOTION_ADDR_WIDTH {}\n", kAddrWidth);
  o += fmt::format("`define DDA_MOTION_ID_VALUE 32'h{:08X}\n", kId);
  o += fmt::format("`define DDA_MOTION_VERSION_VALUE 32'h{:04X}{:04X}\n", kVersionMajor, kVersionMinor);
  o += fmt::format("`define DDA_MOTION_ENTRY_WORDS {}\n`define DDA_MOTION_LEVEL_WIDTH {}\n", kEntryWords, kLevelWidth);
  o += fmt::format(
      "`define DDA_MOTION_MAX_DEPTH_LOG2 {}\n`define DDA_MOTION_ENTRY_ROWS {}\n`define DDA_MOTION_ROW_WORDS {}\n",
      kMaxDepthLog2, kEntryRows, kRowWords);
  // The build-time choices' ranges (kBuildParams): rtl/dda_motion.v refuses a parameter
  // outside its range at elaboration.
  for (const auto& p : kBuildParams) {
    o += fmt::format("`define DDA_BUILD_{0}_MIN {1}\n`define DDA_BUILD_{0}_MAX {2}\n", upper(p.rtl), p.min, p.max);
  }
  o +=
      fmt::format("`define DDA_MOTION_FEED_WORD {}\n`define DDA_MOTION_FEED_LSB {}\n`define DDA_MOTION_FEED_WIDTH {}\n",
                  kFeedWord, kFeedLsb, kFeedWidth);
  o +=
      fmt::format("`define DDA_MOTION_AXES_WORD {}\n`define DDA_MOTION_AXES_LSB {}\n`define DDA_MOTION_AXES_WIDTH {}\n",
                  kAxesWord, kAxesLsb, kAxesWidth);
  for (std::size_t i = 0; i < kPaceFields.size(); ++i) {
    o += fmt::format("`define DDA_MOTION_PACE_{}_WORD {}\n", upper(kPaceFields[i]), kPaceWord + int(i));
  }
  o += fmt::format("`define DDA_MOTION_OVERRIDE_ONE {}\n`define DDA_MOTION_OVERRIDE_MAX {}\n", kOverrideOne,
                   2 * kOverrideOne);
  o += fmt::format("`define DDA_MOTION_TIMING_WIDTH {}\n", kTimingWidth);
  o += fmt::format("`define DDA_MOTION_INPUTS {}\n`define DDA_MOTION_TRIP_BITS {}\n", kNumInputs, kTripBits);
  o += fmt::format("`define DDA_MOTION_SPI_FRAME_BITS {}\n`define DDA_MOTION_SPI_WRITE_BIT {}\n", kSpiFrameBits,
                   kSpiWriteBit);
  for (const auto& p : kSpiFrame) {
    o += fmt::format("`define DDA_MOTION_SPI_{}_AT {}\n`define DDA_MOTION_SPI_{}_WIDTH {}\n", upper(p.name), p.first,
                     upper(p.name), p.width);
  }
  for (const auto& p : kSpiStatus) {
    o += fmt::format("`define DDA_MOTION_SPI_ST_{}_LSB {}\n`define DDA_MOTION_SPI_ST_{}_WIDTH {}\n", upper(p.name),
                     p.first, upper(p.name), p.width);
  }
  o += "\n";
  for (const auto& r : m.regs) {
    o += fmt::format("`define DDA_MOTION_{}_ADDR {}'h{:02X}  // {}\n", upper(r.name), kAddrWidth, r.offset,
                     access_name(r.access));
  }
  o += "\n";
  for (const auto& f : m.fields) {
    const std::string n = "DDA_MOTION_" + upper(f.reg) + "_" + upper(f.name);
    o += fmt::format("`define {}_LSB {}\n`define {}_WIDTH {}\n", n, f.lsb, n, f.width);
  }
  o += "\n`endif  // DDA_MOTION_REGS_VH\n";
  return o;
}

}  // namespace dda::motion
