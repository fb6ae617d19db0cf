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
#include <type_traits>
#include <vector>

#include "model/datapath/core_model.hpp"
#include "model/motion/build.hpp"
#include "model/motion/bus_wires.hpp"
#include "model/motion/motion_map.hpp"
#include "model/motion/pacer.hpp"

namespace dda::motion {

// The machine's input pins (kInputs) as wired: estop_ni high is released.
struct MachinePins {
  bool estop_n = true;
  std::uint8_t limit = 0;  // limit_i: {z+, z-, y+, y-, x+, x-}
  std::uint8_t home = 0;   // home_i: {z, y, x}
  bool probe = false;
  // The pins in INPUTS' bit order (kInputs), as wired (before IN_POLARITY).
  std::uint32_t bits() const {
    return std::uint32_t(estop_n) | std::uint32_t(limit & 0x3Fu) << kLimitBit | std::uint32_t(home & 7u) << kHomeBit |
           std::uint32_t(probe) << kProbeBit;
  }
  // The pins of a word in that order.
  static MachinePins from_bits(std::uint32_t wire) {
    MachinePins p;
    p.estop_n = (wire & 1u) != 0;
    p.limit = std::uint8_t((wire >> kLimitBit) & 0x3Fu);
    p.home = std::uint8_t((wire >> kHomeBit) & 7u);
    p.probe = ((wire >> kProbeBit) & 1u) != 0;
    return p;
  }
  bool operator==(const MachinePins& o) const { return bits() == o.bits(); }
  bool operator!=(const MachinePins& o) const { return !(*this == o); }
};
struct BlockInputs {
  bool rst_n = true;
  bool ce = true;
  BusIn bus;
  MachinePins pins;
};
// The inputs of one edge as the block sees them: the address cut to the bits it decodes.
inline BlockInputs block_inputs(bool rst_n, bool ce, const BusIn& bus, const MachinePins& pins = {}) {
  BlockInputs in{rst_n, ce, bus, pins};
  in.bus.adr &= (1u << kAddrWidth) - 1;
  return in;
}
// The output ports (after an edge; all registered except wb_stall_o = wb_ack_o).
struct BlockOutputs {
  bool ack = false, stall = false;
  std::uint32_t dat = 0;
  bool step_x = false, step_y = false, dir_x = false, dir_y = false, step_z = false, dir_z = false;
  bool busy = false, irq = false;
  // Behind a bridge (rtl/dda_motion_axil.v, rtl/dda_motion_spi.v): its host-side outputs
  // (left at their defaults by the block alone).
  AxilOut axil;
  SpiOut spi;
  // "" when equal, else the ports that differ ("ack 1/0, dat 5/0": this/other).
  std::string diff(const BlockOutputs& o) const;
  bool operator==(const BlockOutputs& o) const {
    return ack == o.ack && stall == o.stall && dat == o.dat && step_x == o.step_x && step_y == o.step_y &&
           dir_x == o.dir_x && dir_y == o.dir_y && step_z == o.step_z && dir_z == o.dir_z && busy == o.busy &&
           irq == o.irq && axil == o.axil && spi == o.spi;
  }
};

// The block's own registers by their RTL names (below dda_motion), each masked to its
// width; the harness reads them by these names (public_flat_rd) and compares them with
// the model's after every edge, beside the core's register table.
enum class Width {
  One,
  Two,
  Three,
  Six,
  Word,
  Level,
  Index,
  Entry,
  Timing,
  Feed,
  Override,
  Speed,     // the pacer's v and cruise speed (kRampFrac bits)
  Phase,     // kPhaseBits
  Distance,  // kDistWidth
  NormBusy,
  NormD,        // kNormFrac + 2: a d of the norm unit
  Provisional,  // kProvisionalWidth
  Correction,   // kCorrectionWidth
  OverrideCount,
  Five,
  Inputs,        // a bit per machine input (kNumInputs)
  Trip,          // kTripBits
  Filter,        // kFilterWidth: the probe's
  SwitchFilter,  // kSwitchFilterWidth
  FilterTick     // kFilterTickWidth
};
struct BlockReg {
  std::string_view name;
  Width width;
};
// Names with a dot are registers of a submodule (u_sx, u_sy, u_sz: the step/dir stages,
// rtl/dda_stepdir.v; u_pace: the pacer, rtl/dda_pace.v, the registers its reference
// model motion::Pacer holds; u_io: the machine's inputs, rtl/dda_motion_io.v, and below
// it each input's synchronizer and filter, rtl/dda_input.v).
inline constexpr std::array<BlockReg, 157> kBlockRegs{{
    {"ack_q", Width::One},
    {"dat_q", Width::Word},
    {"head_q", Width::Index},
    {"tail_q", Width::Index},
    {"level_q", Width::Level},
    {"mask_q", Width::Entry},
    {"fetch_q", Width::Two},
    {"err_q", Width::One},
    {"err_overflow_q", Width::One},
    {"err_partial_q", Width::One},
    {"err_stall_q", Width::One},
    {"aborted_q", Width::One},
    {"irq_status_q", Width::Five},
    {"irq_enable_q", Width::Five},
    {"irq_level_q", Width::Level},
    {"done_count_q", Width::Word},
    {"done_wait_q", Width::One},
    {"err_count_q", Width::Word},
    {"pos_x_q", Width::Word},
    {"pos_y_q", Width::Word},
    {"feed_q", Width::Feed},
    {"acc_q", Width::Feed},
    {"steplen_x_q", Width::Timing},
    {"stepspace_x_q", Width::Timing},
    {"dirsetup_x_q", Width::Timing},
    {"dirhold_x_q", Width::Timing},
    {"steplen_y_q", Width::Timing},
    {"stepspace_y_q", Width::Timing},
    {"dirsetup_y_q", Width::Timing},
    {"dirhold_y_q", Width::Timing},
    {"polarity_q", Width::Six},
    {"u_sx.step_q", Width::One},
    {"u_sx.dir_q", Width::One},
    {"u_sx.pend_q", Width::One},
    {"u_sx.pdir_q", Width::One},
    {"u_sx.tf_q", Width::Timing},
    {"u_sx.ts_q", Width::Timing},
    {"u_sx.tag_q", Width::One},
    {"u_sy.tag_q", Width::One},
    {"u_sy.step_q", Width::One},
    {"u_sy.dir_q", Width::One},
    {"u_sy.pend_q", Width::One},
    {"u_sy.pdir_q", Width::One},
    {"u_sy.tf_q", Width::Timing},
    {"u_sy.ts_q", Width::Timing},
    {"pos_z_q", Width::Word},
    {"steplen_z_q", Width::Timing},
    {"stepspace_z_q", Width::Timing},
    {"dirsetup_z_q", Width::Timing},
    {"dirhold_z_q", Width::Timing},
    {"u_sz.step_q", Width::One},
    {"u_sz.dir_q", Width::One},
    {"u_sz.pend_q", Width::One},
    {"u_sz.pdir_q", Width::One},
    {"u_sz.tf_q", Width::Timing},
    {"u_sz.ts_q", Width::Timing},
    {"u_sz.tag_q", Width::One},
    {"axes_q", Width::Two},
    {"route_q", Width::Two},
    {"err_lanes_q", Width::One},
    {"paced_q", Width::One},
    {"feed_hold_q", Width::One},
    {"accel_q", Width::Word},
    {"vmin_q", Width::Word},
    {"override_q", Width::Override},
    {"u_pace.v_q", Width::Speed},
    {"u_pace.ph_q", Width::Phase},
    {"u_pace.s_q", Width::Distance},
    {"u_pace.rem_q", Width::Distance},
    {"u_pace.cruise_q", Width::Word},
    {"u_pace.limit_q", Width::Word},
    {"u_pace.exit_q", Width::Word},
    {"u_pace.brake_q", Width::Word},
    {"u_pace.busy_q", Width::NormBusy},
    {"u_pace.pend_q", Width::One},
    {"u_pace.first_q", Width::One},
    {"u_pace.due_q", Width::One},
    {"u_pace.fresh_q", Width::One},
    {"u_pace.m_q", Width::Provisional},
    {"u_pace.cm_q", Width::Provisional},
    {"u_pace.cd_q", Width::Correction},
    {"u_pace.d_q", Width::NormD},
    {"u_pace.ovr_q", Width::Override},
    {"u_pace.mcnt_q", Width::OverrideCount},
    {"u_pace.eff_q", Width::Speed},
    {"stopping_q", Width::One},
    {"wd_q", Width::Word},
    {"wd_cnt_q", Width::Word},
    {"err_hard_q", Width::One},
    {"err_watchdog_q", Width::One},
    {"u_io.pol_q", Width::Inputs},
    {"u_io.filt_sw_q", Width::SwitchFilter},
    {"u_io.filt_tick_q", Width::FilterTick},
    {"u_io.filt_probe_q", Width::Filter},
    {"u_io.mode_q", Width::Five},
    {"u_io.err_estop_q", Width::One},
    {"u_io.err_limit_q", Width::One},
    {"u_io.trip_q", Width::Trip},
    {"u_io.latch_x_q", Width::Word},
    {"u_io.latch_y_q", Width::Word},
    {"u_io.latch_z_q", Width::Word},
    {"u_io.probe_armed_q", Width::One},
    {"u_io.probed_q", Width::One},
    {"u_io.probe_x_q", Width::Word},
    {"u_io.probe_y_q", Width::Word},
    {"u_io.probe_z_q", Width::Word},
    {"u_io.snap_x_q", Width::Word},
    {"u_io.snap_y_q", Width::Word},
    {"u_io.snap_z_q", Width::Word},
    {"u_io.snap_cycle_q", Width::Word},
    {"u_io.snap_level_q", Width::Level},
    {"u_io.snap_done_q", Width::Word},
    {"u_io.cycle_q", Width::Word},
    {"u_io.u_estop.s1_q", Width::One},
    {"u_io.u_estop.s2_q", Width::One},
    {"u_io.u_estop.lvl_q", Width::One},
    {"u_io.u_estop.cnt_q", Width::SwitchFilter},
    {"u_io.u_lxn.s1_q", Width::One},
    {"u_io.u_lxn.s2_q", Width::One},
    {"u_io.u_lxn.lvl_q", Width::One},
    {"u_io.u_lxn.cnt_q", Width::SwitchFilter},
    {"u_io.u_lxp.s1_q", Width::One},
    {"u_io.u_lxp.s2_q", Width::One},
    {"u_io.u_lxp.lvl_q", Width::One},
    {"u_io.u_lxp.cnt_q", Width::SwitchFilter},
    {"u_io.u_lyn.s1_q", Width::One},
    {"u_io.u_lyn.s2_q", Width::One},
    {"u_io.u_lyn.lvl_q", Width::One},
    {"u_io.u_lyn.cnt_q", Width::SwitchFilter},
    {"u_io.u_lyp.s1_q", Width::One},
    {"u_io.u_lyp.s2_q", Width::One},
    {"u_io.u_lyp.lvl_q", Width::One},
    {"u_io.u_lyp.cnt_q", Width::SwitchFilter},
    {"u_io.u_lzn.s1_q", Width::One},
    {"u_io.u_lzn.s2_q", Width::One},
    {"u_io.u_lzn.lvl_q", Width::One},
    {"u_io.u_lzn.cnt_q", Width::SwitchFilter},
    {"u_io.u_lzp.s1_q", Width::One},
    {"u_io.u_lzp.s2_q", Width::One},
    {"u_io.u_lzp.lvl_q", Width::One},
    {"u_io.u_lzp.cnt_q", Width::SwitchFilter},
    {"u_io.u_hx.s1_q", Width::One},
    {"u_io.u_hx.s2_q", Width::One},
    {"u_io.u_hx.lvl_q", Width::One},
    {"u_io.u_hx.cnt_q", Width::SwitchFilter},
    {"u_io.u_hy.s1_q", Width::One},
    {"u_io.u_hy.s2_q", Width::One},
    {"u_io.u_hy.lvl_q", Width::One},
    {"u_io.u_hy.cnt_q", Width::SwitchFilter},
    {"u_io.u_hz.s1_q", Width::One},
    {"u_io.u_hz.s2_q", Width::One},
    {"u_io.u_hz.lvl_q", Width::One},
    {"u_io.u_hz.cnt_q", Width::SwitchFilter},
    {"u_io.u_probe.s1_q", Width::One},
    {"u_io.u_probe.s2_q", Width::One},
    {"u_io.u_probe.lvl_q", Width::One},
    {"u_io.u_probe.cnt_q", Width::Filter},
}};
inline constexpr std::size_t kNumBlockRegs = kBlockRegs.size();
constexpr std::size_t breg(std::string_view name) { return hw::index_of(kBlockRegs, name); }
// breg of a name the code spells out, found when it compiles (the model reads its
// registers on every edge).
#define DDA_BREG(name) (std::integral_constant<std::size_t, ::dda::motion::breg(name)>::value)
int width_bits(Width w, int depth_log2);
using BlockRegs = std::array<std::uint64_t, kNumBlockRegs>;

// One step/dir stage (rtl/dda_stepdir.v) for one edge: its registers before the edge,
// the axis' timings and the core's step of this cycle; after() gives its registers
// after the edge.
struct StageRegs {
  bool step = false, dir = false, pend = false, pdir = false, tag = false;
  std::uint32_t tf = 0, ts = 0;
};
struct StageTimings {
  std::uint32_t steplen = 0, stepspace = 0, dirsetup = 0, dirhold = 0;
};
struct StageEdge {
  bool hold = false, rise = false, rise_dir = false, wait = false, tag_left = false, busy = false;
  StageRegs next;
};
StageRegs stage_reset();

// One machine input (rtl/dda_input.v) for one edge: its registers before the edge, the
// pin, whether it is inverted, whether the filter counts on this edge (the probe's on
// every edge, the switches' on their tick), the filter's count; next holds them after
// the edge.
struct InputRegs {
  bool s1 = false, s2 = false, lvl = false;
  std::uint32_t cnt = 0;
};
struct InputEdge {
  bool rise = false;  // the filtered level turns active on this edge
  InputRegs next;
};
InputEdge input_edge(const InputRegs& r, bool pin, bool invert, bool tick, std::uint32_t filter);
// The edge-by-edge diagram of docs/design.md ("Step and direction timing"): one stage
// with steplen 3, stepspace 2, dirsetup 2, dirhold 1, the core stepping + then - as
// fast as the stage lets it (`dda gen-params --kind stepdir-diagram`).
std::string stage_diagram();
StageEdge stage_edge(const StageRegs& r, const StageTimings& t, bool step_in, bool dir_in, bool tag_in, bool flush);

class MotionModel {
 public:
  explicit MotionModel(int depth_log2 = kMaxDepthLog2);  // with every choice's default but the depth
  explicit MotionModel(const Build& build);
  // One rising edge with these inputs (wb_stall_o of this cycle is outputs().stall).
  void edge(const BlockInputs& in);
  BlockOutputs outputs() const;
  const BlockRegs& regs() const { return r_; }
  const Signals& core() const { return core_.state(); }
  int depth_log2() const { return depth_log2_; }
  const Build& build() const { return build_; }
  // What the last edge did: the core took a command; a bus read returned (with ack).
  bool took() const { return took_; }
  // The core's ce_i on the last edge (the feed and the stages let it go on), and whether
  // the core iterated on it (ce_i while it ran a command).
  bool core_ce() const { return core_ce_; }
  bool iterated() const { return iterated_; }
  // The pulses the stages started on the last edge (+1, -1 or 0 per axis).
  int rise_x() const { return rise_x_; }
  int rise_y() const { return rise_y_; }
  int rise_z() const { return rise_z_; }
  // What a bus read of the register at byte address adr returns now (no side effect).
  std::uint32_t read(std::uint32_t adr) const;

 private:
  std::uint64_t& reg(std::string_view name);
  std::uint64_t get(std::string_view name) const;
  StageRegs stage(char axis) const;
  void set_stage(char axis, const StageRegs& s);
  StageTimings timings(char axis) const;
  bool busy() const;  // busy_o: the core runs or a stage holds a step

  // One edge in parts, in the order edge() runs them: the wires (the bus request and the
  // queue; the core's outputs, the stages and the feed), the core's edge, then the
  // registers group by group as rtl/dda_motion.v's always blocks hold them.
  struct Wires;
  Wires bus_wires(const BusIn& b, const MachinePins& pins) const;
  void core_wires(bool ce, Wires& w) const;
  void step_core(bool rst_n, const Wires& w);
  void note_edge(const Wires& w);  // took_, core_ce_, iterated_, rise_x_, rise_y_, rise_z_
  void load_bus(const BusIn& b, const Wires& w);
  void load_queue(const Wires& w);
  void load_status(const Wires& w);  // status, interrupts, counters
  void load_positions(const Wires& w);
  void load_feed(const Wires& w);
  void load_settings(const Wires& w);  // the timings and the polarity
  // The pacer (motion_pace.cpp): its inputs and decision of this cycle (before the take
  // is known, then with it), its edge, and the pacing settings.
  void pace_wires(bool take_known, Wires& w) const;
  void load_pace(const Wires& w);
  void load_pace_settings(const Wires& w);
  std::uint32_t read_pace(std::uint32_t adr) const;  // ACCEL, VMIN, OVERRIDE, WATCHDOG, STATUS' pace bits
  bool halt() const;                                 // the pace heads for rest: a feed hold or a soft stop
  bool soft_flush() const;             // a soft stop at rest with no step on its way: its flush on this edge
  void load_watchdog(const Wires& w);  // stopping_q, wd_q, wd_cnt_q
  // The machine's inputs (motion_io.cpp, rtl/dda_motion_io.v's u_io): the core's steps as
  // the stages take them this cycle (per stage: step, direction), the inputs' wires (on
  // the bus decode: the CTRL bits), their registers, their read data and STATUS bits.
  std::array<std::pair<bool, bool>, 3> routed_steps() const;
  void io_wires(const MachinePins& pins, Wires& w) const;
  void load_io(const Wires& w);
  InputRegs input(std::size_t i) const;
  std::uint32_t read_io(std::uint32_t adr) const;

  Build build_;
  int depth_log2_;
  CoreModel core_;
  Pacer pacer_;
  std::vector<std::vector<std::uint32_t>> mem_;  // [slot][word]
  BlockRegs r_{};
  bool took_ = false, core_ce_ = false, iterated_ = false;
  int rise_x_ = 0, rise_y_ = 0, rise_z_ = 0;
};

// The GTKWave save file of the motion block (docs/dda_motion.gtkw: `dda gen-params
// --kind gtkw-motion`): the bus, the queue, status and interrupts, the axes and the
// core's control, below `top` (the RTL's scope, e.g. "dut.dda_motion"), for a queue of
// 2^depth_log2 entries.
std::string gtkw(std::string_view file, std::string_view top, int depth_log2);

// The entry words of a command: the core's command word LSB first, the axes (0: X, Y, Z;
// Piece::rot), the feed increment (0: full rate) and the pacing fields (a cruise speed of
// 0: paced by the feed increment) in their fields, reserved bits 0.
std::vector<std::uint32_t> entry_words(const Command& c, std::uint32_t feed = 0, int axes = 0,
                                       const PaceEntry& pace = {});
// The pacing fields of entry words.
PaceEntry entry_pace(const std::vector<std::uint32_t>& words);
// The norm operands the core's norm_*_o ports show for its registers.
NormOperands core_norm_operands(const Signals& s);
// The core's command fields of entry words (the inverse of entry_words on its bits).
CmdFields entry_fields(const std::vector<std::uint32_t>& words);

}  // namespace dda::motion
