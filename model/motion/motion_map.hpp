// SPDX-License-Identifier: Apache-2.0
// The register map of the motion block (rtl/dda_motion.v, docs/design.md "Motion block"):
// the one definition of its bus registers and their fields. Generated from it (and
// checked against it by "motion_map: ..." tests): the tables of docs/design.md, the
// firmware header fw/dda_motion_regs.h and the Verilog include rtl/dda_motion_regs.vh
// the RTL decodes the bus with (`dda gen-params --kind motion-markdown|motion-c|
// motion-verilog`).
//
// Wishbone B4, 32-bit data, byte addresses (word aligned). A command entry is
// kEntryWords words: word k < kCmdEntryWords holds bits 32k .. 32k+31 of the core's
// command word (hw::kCmdFields, LSB first) and the entry's spare bits above it
// (kEntrySpareBits): the kAxesWidth bits right above the command are the entry's axes
// (which of the block's axes the core's drive), word kCmdEntryWords - 1 its feed
// increment, the bits between them reserved (written as 0); the last kPaceWords words
// its pacing fields (kPaceFields).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "model/datapath/hw_params.hpp"
#include "model/motion/pace_params.hpp"

namespace dda::motion {

inline constexpr std::uint32_t kId = 0x44444131;  // "DDA1"
inline constexpr int kVersionMajor = 6;
inline constexpr int kVersionMinor = 2;
// Bits an entry keeps above the command word for per-command fields of later blocks.
inline constexpr int kEntryReservedBits = 16;
inline constexpr int kCmdEntryWords = (hw::kCmdWidth + kEntryReservedBits + 31) / 32;
inline constexpr int kEntrySpareBits = 32 * kCmdEntryWords - hw::kCmdWidth;
// The pacing fields of an entry (motion::PaceEntry, docs/design.md "Pacer"), one word
// each from word kPaceWord on, in this order. A cruise speed of 0 leaves the piece to
// the feed increment (the pacer idles while it runs).
inline constexpr std::array<std::string_view, 5> kPaceFields{{"cruise", "limit", "exit", "length", "brake_exit"}};
inline constexpr int kPaceWords = int(kPaceFields.size());
inline constexpr int kPaceWord = kCmdEntryWords;
inline constexpr int kEntryWords = kCmdEntryWords + kPaceWords;
inline constexpr int kAddrWidth = 9;           // byte address bits the block decodes
inline constexpr unsigned kEntryBase = 0x100;  // ENTRY0; ENTRYk at kEntryBase + 4k
inline constexpr int kLevelWidth = 8;          // queue level: 0 .. 128 entries
inline constexpr int kMaxDepthLog2 = kLevelWidth - 1;
// The queue holds an entry in kEntryRows rows of the block RAM (kRowWords words each,
// two 16-bit lanes per word): the HX8K's 32 block RAMs are 16 bits wide at most, too few
// for a whole entry in one row. The block reads an entry's rows one per clock, so the
// core takes at most one entry every kEntryRows clocks.
inline constexpr int kEntryRows = 2;
inline constexpr int kRowWords = (kEntryWords + kEntryRows - 1) / kEntryRows;
// The feed increment of an entry: bits kFeedLsb .. kFeedLsb + kFeedWidth - 1 of entry word
// kFeedWord. The phase accumulator of the same width adds it every cycle the core may go
// on and lets the core iterate on its carry: feed / 2^kFeedWidth iterations per clock
// (0: one per clock, the core's full rate), a rate resolved to 2^-32 of the clock.
inline constexpr int kFeedWidth = 32;
inline constexpr int kFeedWord = kCmdEntryWords - 1;
inline constexpr int kFeedLsb = 32 - kFeedWidth;
// The entry's axes: bits kAxesLsb .. kAxesLsb + kAxesWidth - 1 of entry word kAxesWord,
// right above the command. Value r: the core's axis i (x, y, z: a piece's plane and its
// normal) drives the block's axis (i + r) mod 3 (to_run_axes: 0 X, Y, Z; 1 Y, Z, X;
// 2 Z, X, Y; 3 as 0), so an arc in another plane than the run's runs on the core's
// ellipse integrators.
inline constexpr int kAxesWidth = 2;
inline constexpr int kAxesWord = hw::kCmdWidth / 32;
inline constexpr int kAxesLsb = hw::kCmdWidth % 32;
static_assert(kAxesLsb + kAxesWidth <= 32, "the axes field sits in one word");
static_assert(kEntrySpareBits >= kFeedWidth + kAxesWidth, "the feed and the axes sit in the entry's spare bits");
static_assert(kAxesWord < kFeedWord || kAxesLsb + kAxesWidth <= kFeedLsb, "the axes field lies below the feed");
// The axes of the block, each with a step/dir stage, a position counter and its timings.
inline constexpr std::array<char, 3> kAxes{{'x', 'y', 'z'}};
// The step/dir stages' timings (STEP_X/Y/Z, DIR_X/Y/Z fields), in clock cycles: each is
// field `name` of register `reg`_X / `reg`_Y / `reg`_Z, held in the block register
// `name`_x_q / `name`_y_q / `name`_z_q.
inline constexpr int kTimingWidth = 12;
struct TimingField {
  std::string_view reg, name;
};
inline constexpr std::array<TimingField, 4> kTimingFields{
    {{"STEP", "steplen"}, {"STEP", "stepspace"}, {"DIR", "dirsetup"}, {"DIR", "dirhold"}}};
static_assert(kEntryWords <= 32, "the entry window holds at most 32 words");
// The machine's inputs (docs/design.md, "Machine inputs"), bit `bit` of INPUTS,
// IN_POLARITY and TRIP (the probe is not a trip: TRIP's bits end below it). Each goes
// through a two-flip-flop synchronizer and a glitch filter (a level must hold IN_FILTER's
// ticks) in rtl/dda_input.v, instance `inst` of rtl/dda_motion_io.v; a bit set in
// IN_POLARITY inverts the pin's default sense (estop_ni is active low, the others high).
struct Input {
  std::string_view name;
  int bit;
  std::string_view pin, inst, meaning;
};
inline constexpr std::array<Input, 11> kInputs{{
    {"estop", 0, "estop_ni", "u_estop", "E-stop"},
    {"limit_x_neg", 1, "limit_i[0]", "u_lxn", "X limit, negative end"},
    {"limit_x_pos", 2, "limit_i[1]", "u_lxp", "X limit, positive end"},
    {"limit_y_neg", 3, "limit_i[2]", "u_lyn", "Y limit, negative end"},
    {"limit_y_pos", 4, "limit_i[3]", "u_lyp", "Y limit, positive end"},
    {"limit_z_neg", 5, "limit_i[4]", "u_lzn", "Z limit, negative end"},
    {"limit_z_pos", 6, "limit_i[5]", "u_lzp", "Z limit, positive end"},
    {"home_x", 7, "home_i[0]", "u_hx", "X home switch"},
    {"home_y", 8, "home_i[1]", "u_hy", "Y home switch"},
    {"home_z", 9, "home_i[2]", "u_hz", "Z home switch"},
    {"probe", 10, "probe_i", "u_probe", "touch probe"},
}};
inline constexpr int kNumInputs = int(kInputs.size());
inline constexpr int kTripBits = kNumInputs - 1;  // TRIP: every input but the probe
inline constexpr int kLimitBit = 1, kHomeBit = 7, kProbeBit = 10;
// IN_FILTER. The probe's filter counts clocks (kFilterWidth bits: its latch is exact to
// the clock). The ten switches share a tick, every 2^tick clocks (the low `tick` bits of
// the cycle counter all 1), and count ticks in kSwitchFilterWidth bits: a debounce of up
// to 15 x 2^15 clocks (12 ms at 40 MHz) for a 4-bit counter per switch.
inline constexpr int kFilterWidth = 16;
inline constexpr int kSwitchFilterWidth = 4;
inline constexpr int kFilterTickWidth = 4;
constexpr int input_bit(std::string_view name) {
  for (const auto& i : kInputs) {
    if (i.name == name) return i.bit;
  }
  throw "motion_map: no such input";
}

// The SPI bridge's frame (rtl/dda_spi.v, docs/design.md "Bus bridges"): CS_n low for
// kSpiFrameBits rising SCK edges, most significant bit first; each part numbered from the
// frame's first bit. MOSI carries the command, the address and the write data, MISO the
// previous frame's read data and the status byte.
struct SpiPart {
  std::string_view name;
  int first, width;
  std::string_view meaning;
};
inline constexpr int kSpiFrameBits = 64;
inline constexpr std::array<SpiPart, 4> kSpiFrame{{
    {"command", 0, 8, "MOSI: bit 7 write (1) or read (0), bits 3:0 a write's lanes, bits 6:4 reserved (0, ignored)"},
    {"address", 8, 16, "MOSI: the register's byte address (the bits above the block's ignored)"},
    {"data", 24, 32, "MOSI: a write's data; MISO: the previous frame's read data"},
    {"status", 56, 8, "MISO: the status byte (kSpiStatus)"},
}};
inline constexpr int kSpiWriteBit = 7;  // of the command byte
// The status byte's fields, sampled as the frame starts.
inline constexpr std::array<SpiPart, 5> kSpiStatus{{
    {"done", 0, 1, "the previous frame's access has completed (the read data is its)"},
    {"bad", 1, 1, "the previous frame had the wrong length: no access"},
    {"irq", 2, 1, "the block's irq_o"},
    {"busy", 3, 1, "the block's busy_o"},
    {"count", 4, 4, "accesses made, modulo 16"},
}};
constexpr const SpiPart& spi_part(std::string_view name) {
  for (const auto& p : kSpiFrame) {
    if (p.name == name) return p;
  }
  for (const auto& p : kSpiStatus) {
    if (p.name == name) return p;
  }
  throw "motion_map: no such SPI frame part";
}

enum class Access { RO, RW, W1C, WO };  // WO: reads 0; W1C: write 1 to clear a bit

// A register's value out of reset, with the machine's inputs inactive (a write-only one
// reads 0); kResetBuild: the build's (CONFIG).
inline constexpr std::int64_t kResetBuild = -1;
struct Register {
  std::string_view name;
  unsigned offset;
  Access access;
  std::string_view meaning;
  std::int64_t reset = 0;
};
inline constexpr std::array<Register, 43> kRegisters{{
    {"ID", 0x00, Access::RO, "identifies the block: 0x44444131 (\"DDA1\")", kId},
    {"VERSION", 0x04, Access::RO, "register map version", std::int64_t{kVersionMajor} << 16 | kVersionMinor},
    {"CONFIG", 0x08, Access::RO,
     "the block's build: entry size, queue depth, widths, the pacer, the machine inputs, the axes", kResetBuild},
    {"CTRL", 0x0C, Access::WO, "commands to the block (each bit acts when written 1)"},
    {"STATUS", 0x10, Access::RO, "state, queue level, the sticky error and its causes", 0x2 /* empty */},
    {"IRQ_STATUS", 0x14, Access::W1C, "interrupt causes (events), write 1 to clear"},
    {"IRQ_ENABLE", 0x18, Access::RW, "interrupt mask: irq_o = |(IRQ_STATUS & IRQ_ENABLE)"},
    {"IRQ_LEVEL", 0x1C, Access::RW, "queue level under which a dequeue raises IRQ_STATUS.low"},
    {"DONE_COUNT", 0x20, Access::RO, "commands finished (the core's done_o pulses), wraps"},
    {"ERR_COUNT", 0x24, Access::RO, "commands stalled (the core's err_o pulses), wraps"},
    {"POS_X", 0x28, Access::RW, "X position in steps, signed; counts the steps sent out; a write presets it"},
    {"POS_Y", 0x2C, Access::RW, "Y position in steps, signed; counts the steps sent out; a write presets it"},
    {"ENTRY_MASK", 0x30, Access::RO, "the words of the entry being written since the last commit"},
    {"STEP_X", 0x34, Access::RW, "X step/dir stage: step pulse length and space (clock cycles)"},
    {"DIR_X", 0x38, Access::RW, "X step/dir stage: direction setup and hold (clock cycles)"},
    {"STEP_Y", 0x3C, Access::RW, "Y step/dir stage: step pulse length and space (clock cycles)"},
    {"DIR_Y", 0x40, Access::RW, "Y step/dir stage: direction setup and hold (clock cycles)"},
    {"POLARITY", 0x44, Access::RW, "output polarity: a bit set inverts that output"},
    {"POS_Z", 0x48, Access::RW, "Z position in steps, signed; counts the steps sent out; a write presets it"},
    {"STEP_Z", 0x4C, Access::RW, "Z step/dir stage: step pulse length and space (clock cycles)"},
    {"DIR_Z", 0x50, Access::RW, "Z step/dir stage: direction setup and hold (clock cycles)"},
    {"ACCEL", 0x54, Access::RW, "the pacer's tangential acceleration"},
    {"VMIN", 0x58, Access::RW, "the pacer's minimum speed"},
    {"OVERRIDE", 0x5C, Access::RW, "feed override of the paced pieces (reset: 100%)", kOverrideOne},
    {"WATCHDOG", 0x60, Access::RW, "the watchdog's timeout; every write restarts it"},
    {"INPUTS", 0x64, Access::RO, "the machine's inputs as filtered, 1: active"},
    {"IN_POLARITY", 0x68, Access::RW, "a bit set inverts that input's sense (estop_ni: active high)"},
    {"IN_FILTER", 0x6C, Access::RW, "how long an input's level must hold before the block sees it"},
    {"IN_MODE", 0x70, Access::RW, "how the limit, home and probe inputs stop the motion"},
    {"TRIP", 0x74, Access::RO, "the inputs that stopped the motion since the last clear"},
    {"LATCH_X", 0x78, Access::RO, "X position at the first trip after TRIP was 0"},
    {"LATCH_Y", 0x7C, Access::RO, "Y position at the first trip after TRIP was 0"},
    {"LATCH_Z", 0x80, Access::RO, "Z position at the first trip after TRIP was 0"},
    {"PROBE_X", 0x84, Access::RO, "X position at the probe's active edge (while armed)"},
    {"PROBE_Y", 0x88, Access::RO, "Y position at the probe's active edge (while armed)"},
    {"PROBE_Z", 0x8C, Access::RO, "Z position at the probe's active edge (while armed)"},
    {"SNAP_X", 0x90, Access::RO, "X position at the last CTRL.snapshot"},
    {"SNAP_Y", 0x94, Access::RO, "Y position at the last CTRL.snapshot"},
    {"SNAP_Z", 0x98, Access::RO, "Z position at the last CTRL.snapshot"},
    {"SNAP_CYCLE", 0x9C, Access::RO, "the free-running cycle counter at the last CTRL.snapshot"},
    {"SNAP_LEVEL", 0xA0, Access::RO, "the queue level at the last CTRL.snapshot"},
    {"SNAP_DONE", 0xA4, Access::RO, "DONE_COUNT at the last CTRL.snapshot"},
    {"ENTRY", kEntryBase, Access::WO, "the entry being written, word k at ENTRY + 4k (into the queue's free slot)"},
}};

struct Field {
  std::string_view reg;
  std::string_view name;
  int lsb;
  int width;
  std::string_view meaning;
};
inline constexpr std::array<Field, 99> kFields{{
    {"ID", "id", 0, 32, "0x44444131"},
    {"VERSION", "minor", 0, 16, "minor version"},
    {"VERSION", "major", 16, 16, "major version"},
    {"CONFIG", "entry_words", 0, 6, "words of an entry (kEntryWords)"},
    {"CONFIG", "depth_log2", 8, 4, "log2 of the queue depth (entries)"},
    {"CONFIG", "entry_rows", 12, 2,
     "block-RAM rows an entry takes (kEntryRows): the core takes one entry per as many clocks at most"},
    {"CONFIG", "acc_width", 16, 6, "the core's AccWidth"},
    {"CONFIG", "cnt_width", 24, 5, "the core's CntWidth"},
    {"CONFIG", "pacer", 14, 1, "1: the pacer is built in; 0: every entry runs at its feed increment (Build::pacer)"},
    {"CONFIG", "inputs", 29, 1, "1: the machine inputs, their latches and the snapshot are built in (Build::inputs)"},
    {"CONFIG", "axes", 30, 2, "the block's axes: 3 (X, Y, Z) or 2 (X, Y) (Build::axes)"},
    {"CTRL", "commit", 0, 1, "append the entry written to the queue (refused: partial entry or full queue)"},
    {"CTRL", "abort", 1, 1,
     "stop the core on this edge, flush the queue, the entry being written and the waiting steps"},
    {"CTRL", "clear", 2, 1, "clear STATUS.err, its causes and STATUS.aborted"},
    {"CTRL", "hold", 3, 1, "feed hold: paced pieces ramp to rest at ACCEL (others stop), every register kept"},
    {"CTRL", "resume", 4, 1, "end a feed hold: the speed ramps back up at ACCEL (hold and resume together: hold)"},
    {"CTRL", "soft_stop", 5, 1,
     "paced pieces ramp to rest at ACCEL (others stop), then, once no step is on its way, a flush as by abort"},
    {"CTRL", "hard_stop", 6, 1, "stop on this edge as by abort, and set STATUS.err_hard_stop"},
    {"CTRL", "snapshot", 7, 1, "latch the positions, the cycle counter, the queue level and DONE_COUNT (SNAP_*)"},
    {"CTRL", "probe_arm", 8, 1, "arm the probe: its next active edge latches PROBE_* (clears STATUS.probed)"},
    {"STATUS", "busy", 0, 1, "the core runs a command, or a step is on its way to the pins or a pulse is out"},
    {"STATUS", "empty", 1, 1, "the queue is empty"},
    {"STATUS", "full", 2, 1, "the queue is full"},
    {"STATUS", "err", 3, 1, "sticky error: one of the causes below happened since the last clear"},
    {"STATUS", "err_overflow", 4, 1, "cause: an entry word or a commit while the queue was full"},
    {"STATUS", "err_partial", 5, 1, "cause: a commit before every word of the entry was written"},
    {"STATUS", "err_stall", 6, 1, "cause: the core stopped a command that could not go on (err_o)"},
    {"STATUS", "aborted", 7, 1, "an abort happened since the last clear"},
    {"STATUS", "err_lanes", 8, 1, "cause: an entry word written with other byte lanes than all four (not written)"},
    {"STATUS", "holding", 9, 1, "a feed hold is on and the commanded speed is not 0 yet"},
    {"STATUS", "held", 10, 1, "a feed hold is on and the commanded speed is 0: the core waits"},
    {"STATUS", "stopping", 11, 1, "a soft stop (CTRL.soft_stop or the watchdog) ramps down toward its flush"},
    {"STATUS", "err_hard_stop", 12, 1, "cause: a hard stop (CTRL.hard_stop)"},
    {"STATUS", "err_watchdog", 13, 1, "cause: the watchdog ran out (and started a soft stop)"},
    {"STATUS", "err_estop", 14, 1, "cause: the E-stop input was active (the block stops and stays stopped)"},
    {"STATUS", "err_limit", 15, 1, "cause: a step toward an active limit input"},
    {"STATUS", "level", 16, kLevelWidth, "entries in the queue (not counting the one the core runs)"},
    {"STATUS", "probe_armed", 24, 1, "the probe is armed (CTRL.probe_arm) and has not latched yet"},
    {"STATUS", "probed", 25, 1, "the probe latched PROBE_* since it was last armed"},
    {"IRQ_STATUS", "done", 0, 1, "a command finished"},
    {"IRQ_STATUS", "err", 1, 1, "STATUS.err was set"},
    {"IRQ_STATUS", "low", 2, 1, "a dequeue left fewer than IRQ_LEVEL entries"},
    {"IRQ_STATUS", "probe", 3, 1, "the armed probe latched PROBE_*"},
    {"IRQ_STATUS", "home", 4, 1, "a home input in homing mode stopped the motion"},
    {"IRQ_ENABLE", "done", 0, 1, "enable IRQ_STATUS.done"},
    {"IRQ_ENABLE", "err", 1, 1, "enable IRQ_STATUS.err"},
    {"IRQ_ENABLE", "low", 2, 1, "enable IRQ_STATUS.low"},
    {"IRQ_ENABLE", "probe", 3, 1, "enable IRQ_STATUS.probe"},
    {"IRQ_ENABLE", "home", 4, 1, "enable IRQ_STATUS.home"},
    {"IRQ_LEVEL", "level", 0, kLevelWidth, "threshold of IRQ_STATUS.low"},
    {"DONE_COUNT", "count", 0, 32, "done pulses"},
    {"ERR_COUNT", "count", 0, 32, "err pulses"},
    {"POS_X", "pos", 0, 32, "two's complement"},
    {"POS_Y", "pos", 0, 32, "two's complement"},
    {"ENTRY_MASK", "words", 0, kEntryWords, "bit k: word k written"},
    {"STEP_X", "steplen", 0, kTimingWidth, "step high for max(steplen, 1) cycles"},
    {"STEP_X", "stepspace", 16, kTimingWidth, "step low for at least max(stepspace, 1) cycles between pulses"},
    {"DIR_X", "dirsetup", 0, kTimingWidth,
     "direction stable this many cycles before a rising step edge (0: may change on it)"},
    {"DIR_X", "dirhold", 16, kTimingWidth,
     "direction stable this many cycles after a falling step edge (0: may change on it)"},
    {"STEP_Y", "steplen", 0, kTimingWidth, "as STEP_X.steplen"},
    {"STEP_Y", "stepspace", 16, kTimingWidth, "as STEP_X.stepspace"},
    {"DIR_Y", "dirsetup", 0, kTimingWidth, "as DIR_X.dirsetup"},
    {"DIR_Y", "dirhold", 16, kTimingWidth, "as DIR_X.dirhold"},
    {"POLARITY", "step_x", 0, 1, "step_x_o active low"},
    {"POLARITY", "dir_x", 1, 1, "dir_x_o inverted (low: negative)"},
    {"POLARITY", "step_y", 2, 1, "step_y_o active low"},
    {"POLARITY", "dir_y", 3, 1, "dir_y_o inverted (low: negative)"},
    {"POLARITY", "step_z", 4, 1, "step_z_o active low"},
    {"POLARITY", "dir_z", 5, 1, "dir_z_o inverted (low: negative)"},
    {"POS_Z", "pos", 0, 32, "two's complement"},
    {"STEP_Z", "steplen", 0, kTimingWidth, "as STEP_X.steplen"},
    {"STEP_Z", "stepspace", 16, kTimingWidth, "as STEP_X.stepspace"},
    {"DIR_Z", "dirsetup", 0, kTimingWidth, "as DIR_X.dirsetup"},
    {"DIR_Z", "dirhold", 16, kTimingWidth, "as DIR_X.dirhold"},
    {"ACCEL", "accel", 0, kAccelWidth, "steps per clock per clock x 2^-48 (0: no ramp, the speed jumps)"},
    {"VMIN", "vmin", 0, 32, "steps per clock x 2^-32: no paced piece runs slower, the last one ends at it"},
    {"OVERRIDE", "override", 0, kOverrideBits, "x 1/256 (256: 100%); a write above 512 (200%) takes 512"},
    {"WATCHDOG", "clocks", 0, 32,
     "0: off; else a soft stop, STATUS.err_watchdog and IRQ_STATUS.err this many clocks after the last write"},
    {"IN_FILTER", "switches", 0, kSwitchFilterWidth,
     "the E-stop, limit and home inputs: a level holds this many ticks (0 as 1) before it counts"},
    {"IN_FILTER", "tick", 4, kFilterTickWidth,
     "the switches' tick: the clocks whose cycle count has its low `tick` bits all 1 (0: every clock)"},
    {"IN_FILTER", "probe", 16, kFilterWidth, "the probe input: a level holds this many clocks (0 as 1)"},
    {"IN_MODE", "limit_decel", 0, 1, "0: a step toward an active limit stops as by hard_stop; 1: as by soft_stop"},
    {"IN_MODE", "home_x", 1, 1, "X homing: the X home input's active edge stops as by soft_stop (IRQ_STATUS.home)"},
    {"IN_MODE", "home_y", 2, 1, "Y homing: as home_x"},
    {"IN_MODE", "home_z", 3, 1, "Z homing: as home_x"},
    {"IN_MODE", "probe_stop", 4, 1, "the armed probe's active edge stops as by soft_stop (G38.2)"},
    {"LATCH_X", "pos", 0, 32, "two's complement"},
    {"LATCH_Y", "pos", 0, 32, "two's complement"},
    {"LATCH_Z", "pos", 0, 32, "two's complement"},
    {"PROBE_X", "pos", 0, 32, "two's complement"},
    {"PROBE_Y", "pos", 0, 32, "two's complement"},
    {"PROBE_Z", "pos", 0, 32, "two's complement"},
    {"SNAP_X", "pos", 0, 32, "two's complement"},
    {"SNAP_Y", "pos", 0, 32, "two's complement"},
    {"SNAP_Z", "pos", 0, 32, "two's complement"},
    {"SNAP_CYCLE", "cycle", 0, 32, "clock edges since reset, wraps"},
    {"SNAP_LEVEL", "level", 0, kLevelWidth, "as STATUS.level"},
    {"SNAP_DONE", "count", 0, 32, "as DONE_COUNT"},
    {"ENTRY", "data", 0, 32,
     "entry word k: command bits 32k .. 32k+31; above the command the axes, then the feed, the pacing fields"},
}};
// A register's offset and a field by name (a name not in the map does not compile where
// the result is a constant expression; at run time it throws).
constexpr std::uint32_t reg_offset(std::string_view name) {
  for (const auto& r : kRegisters) {
    if (r.name == name) return r.offset;
  }
  throw "motion_map: no such register";
}
// reg_offset of a name the code spells out, found when it compiles (the model decodes
// the bus on every edge).
#define DDA_REG_OFFSET(name) (std::integral_constant<std::uint32_t, ::dda::motion::reg_offset(name)>::value)
constexpr const Field& field_of(std::string_view reg, std::string_view name) {
  for (const auto& f : kFields) {
    if (f.reg == reg && f.name == name) return f;
  }
  throw "motion_map: no such field";
}
// A field's lsb of names the code spells out, found when it compiles.
#define DDA_FIELD_LSB(reg, name) (std::integral_constant<int, ::dda::motion::field_of(reg, name).lsb>::value)

// Copies the checks take (a drift test hands them a changed copy).
struct Map {
  std::vector<Register> regs;
  std::vector<Field> fields;
};
Map map();

std::string markdown(const Map& m = map());        // docs/design.md, "Motion block"
std::string c_header(const Map& m = map());        // fw/dda_motion_regs.h
std::string verilog_header(const Map& m = map());  // rtl/dda_motion_regs.vh

// Throws GuardError naming the first register or field that overlaps another, leaves
// its 32-bit word, or whose register is unknown.
void check(const Map& m = map());

}  // namespace dda::motion
