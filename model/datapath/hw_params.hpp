// SPDX-License-Identifier: Apache-2.0
// Single source of truth for every hardware width and command field.
//
// The SystemC model, the Verilator harnesses and the generated Verilog header
// rtl/dda_params.vh all take their numbers from here. `dda gen-params` writes the
// Verilog header; the test "hw_params: rtl/dda_params.vh is in sync with hw_params.hpp"
// fails if the checked-in rtl/dda_params.vh differs from what this file generates.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace dda::hw {

// Accumulator, integrand, capacity and increment registers are AccWidth bits.
// Integrands and increments are two's complement; an integrand with its top bit set is
// negative and its axis holds (adds nothing). Capacity and accumulators are unsigned,
// below 2^(AccWidth-1), so every positive integrand (at most the capacity) has its top
// bit clear. The adder inside each integrator is AccWidth + 1 bits wide.
// A build at other widths (the CMake options DDA_ACC_WIDTH and DDA_CNT_WIDTH, which
// define DDA_HW_ACC_WIDTH and DDA_HW_CNT_WIDTH; scripts/test-widths.sh) changes them
// here for the whole project: golden model, planner, SystemC model and, through the
// Verilog header CMake generates from this file, the RTL.
#ifdef DDA_HW_ACC_WIDTH
inline constexpr int kAccWidth = DDA_HW_ACC_WIDTH;
#else
inline constexpr int kAccWidth = 51;
#endif
// Remaining-step counters.
#ifdef DDA_HW_CNT_WIDTH
inline constexpr int kCntWidth = DDA_HW_CNT_WIDTH;
#else
inline constexpr int kCntWidth = 17;
#endif
// The widths this project is verified at lie in these ranges: at most 51 and 17 (the
// defaults; every sum the datapath forms stays in int64); at least 32 and 8 (rotated
// ellipses need a capacity of 2^(AccWidth - 2) with room for their coefficients).
static_assert(kAccWidth >= 32 && kAccWidth <= 51, "AccWidth (DDA_ACC_WIDTH) must be in [32, 51]");
static_assert(kCntWidth >= 8 && kCntWidth <= 17, "CntWidth (DDA_CNT_WIDTH) must be in [8, 17]");

inline constexpr std::uint64_t kAccMask = (std::uint64_t{1} << kAccWidth) - 1;
inline constexpr std::uint64_t kCntMax = (std::uint64_t{1} << kCntWidth) - 1;

// Direction encoding of the dir_* command fields and outputs.
inline constexpr unsigned kDirPos = 0;  // step towards +axis
inline constexpr unsigned kDirNeg = 1;  // step towards -axis

// Control state machine encoding (register state_q).
enum class State : unsigned { Idle = 0, Run = 1 };
inline constexpr int kStateWidth = 1;

// Command word: the fields of one arc command, packed LSB first in this order.
struct Field {
  std::string_view name;  // name in C++, SystemC and Verilog (cmd_<name>)
  int width;
  std::string_view meaning;
};

inline constexpr std::array<Field, 18> kCmdFields{{
    {"jv_x", kAccWidth, "initial X integrand (scaled, two's complement)"},
    {"jv_y", kAccWidth, "initial Y integrand (scaled, two's complement)"},
    {"jr_x", kAccWidth, "initial X accumulator (preload), < cap"},
    {"jr_y", kAccWidth, "initial Y accumulator (preload), < cap"},
    {"cap", kAccWidth, "accumulator capacity (2^n * a * b, or 2^(AccWidth-2) rotated), 0 < cap < 2^(AccWidth-1)"},
    {"cnt_x", kCntWidth, "X steps to emit"},
    {"cnt_y", kCntWidth, "Y steps to emit"},
    {"dir_x", 1, "X step direction (0 = +X, 1 = -X)"},
    {"dir_y", 1, "Y step direction (0 = +Y, 1 = -Y)"},
    {"inc_x_on_x", kAccWidth, "added to jv_x after an X step (two's complement)"},
    {"inc_x_on_y", kAccWidth, "added to jv_x after a Y step (two's complement)"},
    {"inc_y_on_x", kAccWidth, "added to jv_y after an X step (two's complement)"},
    {"inc_y_on_y", kAccWidth, "added to jv_y after a Y step (two's complement)"},
    {"jv_z", kAccWidth, "Z integrand (constant), 0 <= jv_z <= cap_z"},
    {"jr_z", kAccWidth, "initial Z accumulator (preload: the phase carried between pieces), < cap_z"},
    {"cap_z", kAccWidth, "Z accumulator capacity, 0 < cap_z < 2^(AccWidth-1)"},
    {"cnt_z", kCntWidth, "Z steps to emit"},
    {"dir_z", 1, "Z step direction (0 = +Z, 1 = -Z)"},
}};

// A field's width at other widths (formal proofs, synthesis at smaller widths): the
// fields that are kAccWidth or kCntWidth bits wide take acc_width or cnt_width bits.
constexpr int field_width(int width, int acc_width, int cnt_width) {
  static_assert(kAccWidth != kCntWidth, "field_width: the widths are told apart by value");
  return width == kAccWidth ? acc_width : width == kCntWidth ? cnt_width : width;
}
constexpr int cmd_width(int acc_width = kAccWidth, int cnt_width = kCntWidth) {
  int w = 0;
  for (const auto& f : kCmdFields) w += field_width(f.width, acc_width, cnt_width);
  return w;
}
constexpr int cmd_offset(std::string_view name) {
  int off = 0;
  for (const auto& f : kCmdFields) {
    if (f.name == name) return off;
    off += f.width;
  }
  return -1;
}
inline constexpr int kCmdWidth = cmd_width();

// The register table: every architectural register of the core (the state the
// scoreboards compare after every clock edge) and the combinational probes the
// harnesses sample, by their hierarchical names in the RTL and the SystemC model.
// Every consumer is generated from it or resolves its names at run time: the SystemC
// and Verilator samplers, the scoreboards, the vector writer, the GTKWave save files and
// the Verilog bench's field layout (docs/design.md, "Where to change what"). Adding a
// register is an edit here, in the RTL module and the SystemC module that hold it and
// in the reference model's next-state code (model/datapath/core_model.cpp); the test
// "registers: every consumer follows the table" fails while any of them lacks it.
enum class SigKind { Reg, Probe };  // a flip-flop, or a combinational net
struct Reg {
  std::string_view name;  // hierarchical name below dda_core
  int width;
  std::string_view meaning;
  std::string_view group = "";  // GTKWave group of the save files ("": not shown)
  bool show_signed = false;     // GTKWave shows it as signed decimal
  SigKind kind = SigKind::Reg;
};
inline constexpr std::array<Reg, 31> kSignals{{
    {"u_int_x.jv_q", kAccWidth, "X integrand (negative: the axis holds)", "Integrator X"},
    {"u_int_x.jr_q", kAccWidth, "X accumulator (after overflow removal)", "Integrator X"},
    {"u_int_x.inc_on_x_q", kAccWidth, "added to the X integrand after an X step"},
    {"u_int_x.inc_on_y_q", kAccWidth, "added to the X integrand after a Y step", "Integrator X", true},
    {"u_int_y.jv_q", kAccWidth, "Y integrand (negative: the axis holds)", "Integrator Y"},
    {"u_int_y.jr_q", kAccWidth, "Y accumulator (after overflow removal)", "Integrator Y"},
    {"u_int_y.inc_on_x_q", kAccWidth, "added to the Y integrand after an X step", "Integrator Y", true},
    {"u_int_y.inc_on_y_q", kAccWidth, "added to the Y integrand after a Y step"},
    {"u_cnt_x.cnt_q", kCntWidth, "X steps still owed", "Counters"},
    {"u_cnt_y.cnt_q", kCntWidth, "Y steps still owed", "Counters"},
    {"u_lin_z.jv_q", kAccWidth, "Z integrand (constant while the command runs)", "Integrator Z"},
    {"u_lin_z.jr_q", kAccWidth, "Z accumulator (after overflow removal)", "Integrator Z"},
    {"u_lin_z.cap_q", kAccWidth, "Z accumulator capacity", "Integrator Z"},
    {"u_cnt_z.cnt_q", kCntWidth, "Z steps still owed", "Counters"},
    {"cap_q", kAccWidth, "accumulator capacity", "Integrators"},
    {"cdir_x_q", 1, "X step direction of the running command", "Control"},
    {"cdir_y_q", 1, "Y step direction of the running command", "Control"},
    {"cdir_z_q", 1, "Z step direction of the running command", "Control"},
    {"dir_x_q", 1, "direction of the last X step (drives dir_x_o)"},
    {"dir_y_q", 1, "direction of the last Y step (drives dir_y_o)"},
    {"dir_z_q", 1, "direction of the last Z step (drives dir_z_o)"},
    {"step_x_q", 1, "X step pulse (drives step_x_o)"},
    {"step_y_q", 1, "Y step pulse (drives step_y_o)"},
    {"step_z_q", 1, "Z step pulse (drives step_z_o)"},
    {"u_ctrl.state_q", kStateWidth, "control state: 0 idle, 1 run", "Control"},
    {"u_ctrl.done_q", 1, "arc finished (drives done_o, one cycle)"},
    {"u_ctrl.err_q", 1, "arc aborted on a stall (drives err_o, one cycle)"},
    {"u_ctrl.iter_q", 1, "an iteration happened on the last edge (drives iter_o)"},
    {"u_int_x.sum", kAccWidth + 1, "X adder output jr_q + jv_q", "Integrator X", false, SigKind::Probe},
    {"u_int_y.sum", kAccWidth + 1, "Y adder output jr_q + jv_q", "Integrator Y", false, SigKind::Probe},
    {"u_lin_z.sum", kAccWidth + 1, "Z adder output jr_q + jv_q", "Integrator Z", false, SigKind::Probe},
}};
inline constexpr std::size_t kNumSignals = kSignals.size();

// Index of the entry named `name` in one of the tables; a name not in the table does
// not compile where the index is a constant expression (core_model.cpp).
template <typename Table>
constexpr std::size_t index_of(const Table& t, std::string_view name) {
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i].name == name) return i;
  }
  throw "hw::index_of: no such name in the table";
}
// How many entries of a table satisfy `pred`.
template <typename Table, typename Pred>
constexpr std::size_t count_if(const Table& t, Pred pred) {
  std::size_t n = 0;
  for (const auto& e : t) n += pred(e) ? 1 : 0;
  return n;
}
constexpr std::size_t sig(std::string_view name) { return index_of(kSignals, name); }
// The architectural registers come first in the table.
inline constexpr std::size_t kNumRegisters = count_if(kSignals, [](const Reg& r) { return r.kind == SigKind::Reg; });
constexpr bool regs_first() {
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    if ((kSignals[i].kind == SigKind::Reg) != (i < kNumRegisters)) return false;
  }
  return true;
}
static_assert(regs_first(), "kSignals: registers first, probes after them");

// The fast implementation's own registers (dda_core.Impl = "fast", docs/design.md
// "Implementations"), each derived from the architectural registers above and checked by
// an assertion beside the logic (simulation and formal). Both implementations hold the
// architectural registers, which the per-cycle tier, the scoreboards and the save files
// show; these are the fast one's, named as its own: the design doc's table is generated
// from this list, and a test finds each name at its width in the fast RTL and none of
// them in the small one ("rtl: the fast implementation's own registers").
inline constexpr std::array<Reg, 32> kFastRegisters{{
    {"u_int_x.g_fast.e_q", kAccWidth + 1, "`jr_q + jv_q - cap_q` (`jv_q` signed), while the axis is active"},
    {"u_int_x.g_fast.incmc_q", kAccWidth + 1, "`inc_on_x_q - cap_q` (the own axis' correction, signed)"},
    {"u_int_x.g_fast.incsum_q", kAccWidth + 1, "`inc_on_x_q + inc_on_y_q` (signed)"},
    {"u_int_x.g_fast.add_q", 1, "the axis adds: active and `jv_q` not negative"},
    {"u_int_x.g_fast.ce_a_q", 1, "a copy of `add_q` (for e's adder)"},
    {"u_int_x.g_fast.ovf_q", 1, "the carry `add & (jr_q + jv_q >= cap_q)`"},
    {"u_int_x.g_fast.jvz_q", 1, "`jv_q == 0`"},
    {"u_int_x.g_fast.cw_x_q", 1, "a copy of the X carry (the integrand's correction)"},
    {"u_int_x.g_fast.cw_y_q", 1, "a copy of the Y carry (the integrand's correction)"},
    {"u_int_x.g_fast.ce_x_q", 1, "a copy of the X carry (e's adder)"},
    {"u_int_x.g_fast.ce_y_q", 1, "a copy of the Y carry (e's adder)"},
    {"u_int_y.g_fast.e_q", kAccWidth + 1, "`jr_q + jv_q - cap_q` (`jv_q` signed), while the axis is active"},
    {"u_int_y.g_fast.incmc_q", kAccWidth + 1, "`inc_on_y_q - cap_q` (the own axis' correction, signed)"},
    {"u_int_y.g_fast.incsum_q", kAccWidth + 1, "`inc_on_x_q + inc_on_y_q` (signed)"},
    {"u_int_y.g_fast.add_q", 1, "the axis adds: active and `jv_q` not negative"},
    {"u_int_y.g_fast.ce_a_q", 1, "a copy of `add_q` (for e's adder)"},
    {"u_int_y.g_fast.ovf_q", 1, "the carry `add & (jr_q + jv_q >= cap_q)`"},
    {"u_int_y.g_fast.jvz_q", 1, "`jv_q == 0`"},
    {"u_int_y.g_fast.cw_x_q", 1, "a copy of the X carry (the integrand's correction)"},
    {"u_int_y.g_fast.cw_y_q", 1, "a copy of the Y carry (the integrand's correction)"},
    {"u_int_y.g_fast.ce_x_q", 1, "a copy of the X carry (e's adder)"},
    {"u_int_y.g_fast.ce_y_q", 1, "a copy of the Y carry (e's adder)"},
    {"u_cnt_x.g_fast.nz_q", 1, "`cnt_q != 0`"},
    {"u_cnt_x.g_fast.one_q", 1, "`cnt_q == 1`"},
    {"u_cnt_y.g_fast.nz_q", 1, "`cnt_q != 0`"},
    {"u_cnt_y.g_fast.one_q", 1, "`cnt_q == 1`"},
    {"u_lin_z.g_fast.e_q", kAccWidth + 1, "`jr_q + jv_q - cap_q`, while the axis is active"},
    {"u_lin_z.g_fast.jvmc_q", kAccWidth + 1, "`jv_q - cap_q` (signed)"},
    {"u_lin_z.g_fast.ovf_q", 1, "the carry `active & (jr_q + jv_q >= cap_q)`"},
    {"u_lin_z.g_fast.jvz_q", 1, "`jv_q == 0`"},
    {"u_cnt_z.g_fast.nz_q", 1, "`cnt_q != 0`"},
    {"u_cnt_z.g_fast.one_q", 1, "`cnt_q == 1`"},
}};

// The core's ports (rtl/dda_core.v), in the order of the vector sets' expected words
// for the outputs; `group` as for registers (clk_i and cmd_i are not in the vectors).
// Norm: an output the motion block's pacer reads (functions of the registers, which the
// scoreboards compare; not in the vector sets).
enum class PortDir { In, Out, Norm };
struct Port {
  std::string_view name;
  int width;
  PortDir dir;
  std::string_view meaning;
  std::string_view group = "";
};
inline constexpr std::array<Port, 21> kPorts{{
    {"clk_i", 1, PortDir::In, "clock, rising edge", "Command"},
    {"rst_ni", 1, PortDir::In, "reset, synchronous, active low", "Command"},
    {"cmd_valid_i", 1, PortDir::In, "a command is offered", "Command"},
    {"cmd_ready_o", 1, PortDir::Out, "ready during the cycle, before the edge (combinational)", "Command"},
    {"ce_i", 1, PortDir::In, "iteration enable", "Command"},
    {"cmd_i", kCmdWidth, PortDir::In, "the command word (kCmdFields)"},
    {"step_x_o", 1, PortDir::Out, "X step pulse after the edge", "Outputs"},
    {"step_y_o", 1, PortDir::Out, "Y step pulse after the edge", "Outputs"},
    {"dir_x_o", 1, PortDir::Out, "X direction after the edge (0 = +X)", "Outputs"},
    {"dir_y_o", 1, PortDir::Out, "Y direction after the edge (0 = +Y)", "Outputs"},
    {"step_z_o", 1, PortDir::Out, "Z step pulse after the edge", "Outputs"},
    {"dir_z_o", 1, PortDir::Out, "Z direction after the edge (0 = +Z)", "Outputs"},
    {"busy_o", 1, PortDir::Out, "running a command, after the edge", "Control"},
    {"done_o", 1, PortDir::Out, "a command finished on the edge", "Control"},
    {"err_o", 1, PortDir::Out, "a command stalled on the edge", "Control"},
    {"iter_o", 1, PortDir::Out, "an iteration happened on the edge", "Control"},
    {"norm_v_x_o", kAccWidth, PortDir::Norm, "X integrand while X runs and it is positive, else 0"},
    {"norm_v_y_o", kAccWidth, PortDir::Norm, "Y integrand while Y runs and it is positive, else 0"},
    {"norm_v_z_o", kAccWidth, PortDir::Norm, "Z integrand while Z runs and it is positive, else 0"},
    {"norm_cap_o", kAccWidth, PortDir::Norm, "the plane's capacity (cap_q)"},
    {"norm_cap_z_o", kAccWidth, PortDir::Norm, "Z's capacity (u_lin_z.cap_q)"},
}};
constexpr std::size_t port(std::string_view name) { return index_of(kPorts, name); }
inline constexpr std::size_t kNumOutputs = count_if(kPorts, [](const Port& p) { return p.dir == PortDir::Out; });
// Are these the output ports, in kPorts order? (A harness that lists the ports it reads
// checks its list with it at compile time.)
constexpr bool outputs_are(const std::array<std::string_view, kNumOutputs>& names) {
  std::size_t o = 0;
  for (const auto& p : kPorts) {
    if (p.dir != PortDir::Out) continue;
    if (names[o++] != p.name) return false;
  }
  return true;
}
constexpr std::size_t field(std::string_view name) { return index_of(kCmdFields, name); }

// A copy of the register table that the consumers' checks take (the drift test hands
// them a changed copy).
using SignalTable = std::vector<Reg>;
inline SignalTable signal_table() { return SignalTable(kSignals.begin(), kSignals.end()); }

// Text generated from the definitions above (model/datapath/hw_params.cpp).
std::string verilog_header();  // rtl/dda_params.vh
// The same header at other widths (formal proofs at reduced widths): the fields that are
// kAccWidth or kCntWidth bits wide take acc_width or cnt_width bits.
std::string verilog_header(int acc_width, int cnt_width);
std::string markdown_tables(const SignalTable& t = signal_table());  // docs/design.md
// GTKWave save file for a waveform whose core is at `top` (e.g. "SystemC.dut").
std::string gtkw(const SignalTable& t, std::string_view file, std::string_view top);
// A GTKWave save file of groups of signals below `top` (the core's above; the motion
// block's: motion_model.hpp). `what` names the design in its header.
struct WaveSignal {
  std::string name;
  int width;
  bool is_signed = false;
};
struct WaveGroup {
  std::string name;
  std::vector<WaveSignal> signals;
};
std::string gtkw_file(const std::vector<WaveGroup>& groups, std::string_view what, std::string_view file,
                      std::string_view top);

}  // namespace dda::hw
