// SPDX-License-Identifier: Apache-2.0
// The cycle-level reference model of the motion block (rtl/dda_motion.v, docs/design.md
// "Motion block"): the bus slave, the command queue, status, interrupts, counters and
// positions, around the core's reference model (CoreModel). The block harnesses compare
// the RTL (and later the SystemC model) with it after every edge: ports, the block's
// registers (kBlockRegs) and the core's register table.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dda/core_model.hpp"
#include "dda/motion_map.hpp"

namespace dda::motion {

// The Wishbone inputs of one cycle.
struct BusIn {
  bool cyc = false, stb = false, we = false;
  std::uint32_t adr = 0, dat = 0;
  std::uint8_t sel = 0xF;
};
struct BlockInputs {
  bool rst_n = true;
  bool ce = true;
  BusIn bus;
};
// The output ports (after an edge; all registered except wb_stall_o = wb_ack_o).
struct BlockOutputs {
  bool ack = false, stall = false;
  std::uint32_t dat = 0;
  bool step_x = false, step_y = false, dir_x = false, dir_y = false, busy = false, irq = false;
  // "" when equal, else the ports that differ ("ack 1/0, dat 5/0": this/other).
  std::string diff(const BlockOutputs& o) const;
  bool operator==(const BlockOutputs& o) const {
    return ack == o.ack && stall == o.stall && dat == o.dat && step_x == o.step_x && step_y == o.step_y &&
           dir_x == o.dir_x && dir_y == o.dir_y && busy == o.busy && irq == o.irq;
  }
};

// The block's own registers by their RTL names (below dda_motion), each masked to its
// width; the harness reads them by these names (public_flat_rd) and compares them with
// the model's after every edge, beside the core's register table.
enum class Width { One, Three, Word, Level, Index, Entry };
struct BlockReg {
  std::string_view name;
  Width width;
};
inline constexpr std::array<BlockReg, 19> kBlockRegs{{
    {"ack_q", Width::One},          {"dat_q", Width::Word},         {"head_q", Width::Index},
    {"tail_q", Width::Index},       {"level_q", Width::Level},      {"mask_q", Width::Entry},
    {"primed_q", Width::One},       {"err_q", Width::One},          {"err_overflow_q", Width::One},
    {"err_partial_q", Width::One},  {"err_stall_q", Width::One},    {"aborted_q", Width::One},
    {"irq_status_q", Width::Three}, {"irq_enable_q", Width::Three}, {"irq_level_q", Width::Level},
    {"done_count_q", Width::Word},  {"err_count_q", Width::Word},   {"pos_x_q", Width::Word},
    {"pos_y_q", Width::Word},
}};
inline constexpr std::size_t kNumBlockRegs = kBlockRegs.size();
constexpr std::size_t breg(std::string_view name) { return hw::index_of(kBlockRegs, name); }
int width_bits(Width w, int depth_log2);
using BlockRegs = std::array<std::uint64_t, kNumBlockRegs>;

class MotionModel {
 public:
  explicit MotionModel(int depth_log2 = kMaxDepthLog2);
  // One rising edge with these inputs (wb_stall_o of this cycle is outputs().stall).
  void edge(const BlockInputs& in);
  BlockOutputs outputs() const;
  const BlockRegs& regs() const { return r_; }
  const Signals& core() const { return core_.state(); }
  int depth_log2() const { return depth_log2_; }
  // What the last edge did: the core took a command; a bus read returned (with ack).
  bool took() const { return took_; }

 private:
  std::uint32_t read(std::uint32_t adr) const;
  std::uint64_t& reg(std::string_view name);
  std::uint64_t get(std::string_view name) const;

  int depth_log2_;
  CoreModel core_;
  std::vector<std::vector<std::uint32_t>> mem_;  // [slot][word]
  BlockRegs r_{};
  bool took_ = false;
};

// The GTKWave save file of the motion block (docs/dda_motion.gtkw: `dda gen-params
// --kind gtkw-motion`): the bus, the queue, status and interrupts, the axes and the
// core's control, below `top` (the RTL's scope, e.g. "dut.dda_motion"), for a queue of
// 2^depth_log2 entries.
std::string gtkw(std::string_view file, std::string_view top, int depth_log2);

// The entry words of a command: the core's command word LSB first, reserved bits 0.
std::vector<std::uint32_t> entry_words(const Command& c);
// The core's command fields of entry words (the inverse of entry_words on its bits).
CmdFields entry_fields(const std::vector<std::uint32_t>& words);

}  // namespace dda::motion
