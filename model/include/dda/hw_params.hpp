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

namespace dda::hw {

// Accumulator, integrand, capacity and increment registers are AccWidth bits.
// Integrands and increments are two's complement; an integrand with its top bit set is
// negative and its axis holds (adds nothing). Capacity and accumulators are unsigned,
// below 2^(AccWidth-1), so every positive integrand (at most the capacity) has its top
// bit clear. The adder inside each integrator is AccWidth + 1 bits wide.
inline constexpr int kAccWidth = 51;
// Remaining-step counters.
inline constexpr int kCntWidth = 17;

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
  std::string_view name;     // name in C++, SystemC and Verilog (cmd_<name>)
  int width;
  std::string_view meaning;
};

inline constexpr std::array<Field, 13> kCmdFields{{
    {"jv_x", kAccWidth, "initial X integrand (scaled, two's complement)"},
    {"jv_y", kAccWidth, "initial Y integrand (scaled, two's complement)"},
    {"jr_x", kAccWidth, "initial X accumulator (preload), < cap"},
    {"jr_y", kAccWidth, "initial Y accumulator (preload), < cap"},
    {"cap", kAccWidth, "accumulator capacity (2^n * a * b, or 2^49 rotated), 0 < cap < 2^(AccWidth-1)"},
    {"cnt_x", kCntWidth, "X steps to emit"},
    {"cnt_y", kCntWidth, "Y steps to emit"},
    {"dir_x", 1, "X step direction (0 = +X, 1 = -X)"},
    {"dir_y", 1, "Y step direction (0 = +Y, 1 = -Y)"},
    {"inc_x_on_x", kAccWidth, "added to jv_x after an X step (two's complement)"},
    {"inc_x_on_y", kAccWidth, "added to jv_x after a Y step (two's complement)"},
    {"inc_y_on_x", kAccWidth, "added to jv_y after an X step (two's complement)"},
    {"inc_y_on_y", kAccWidth, "added to jv_y after a Y step (two's complement)"},
}};

constexpr int cmd_width() {
  int w = 0;
  for (const auto& f : kCmdFields) w += f.width;
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

// Architectural registers: the state the scoreboards compare after every iteration
// (hierarchical names as in the RTL and the SystemC model).
struct Reg {
  std::string_view name;
  int width;
  std::string_view meaning;
};
inline constexpr std::array<Reg, 21> kRegisters{{
    {"u_int_x.jv_q", kAccWidth, "X integrand (negative: the axis holds)"},
    {"u_int_x.jr_q", kAccWidth, "X accumulator (after overflow removal)"},
    {"u_int_x.inc_on_x_q", kAccWidth, "added to the X integrand after an X step"},
    {"u_int_x.inc_on_y_q", kAccWidth, "added to the X integrand after a Y step"},
    {"u_int_y.jv_q", kAccWidth, "Y integrand (negative: the axis holds)"},
    {"u_int_y.jr_q", kAccWidth, "Y accumulator (after overflow removal)"},
    {"u_int_y.inc_on_x_q", kAccWidth, "added to the Y integrand after an X step"},
    {"u_int_y.inc_on_y_q", kAccWidth, "added to the Y integrand after a Y step"},
    {"u_cnt_x.cnt_q", kCntWidth, "X steps still owed"},
    {"u_cnt_y.cnt_q", kCntWidth, "Y steps still owed"},
    {"cap_q", kAccWidth, "accumulator capacity"},
    {"cdir_x_q", 1, "X step direction of the running command"},
    {"cdir_y_q", 1, "Y step direction of the running command"},
    {"dir_x_q", 1, "direction of the last X step (drives dir_x_o)"},
    {"dir_y_q", 1, "direction of the last Y step (drives dir_y_o)"},
    {"step_x_q", 1, "X step pulse (drives step_x_o)"},
    {"step_y_q", 1, "Y step pulse (drives step_y_o)"},
    {"u_ctrl.state_q", kStateWidth, "control state: 0 idle, 1 run"},
    {"u_ctrl.done_q", 1, "arc finished (drives done_o, one cycle)"},
    {"u_ctrl.err_q", 1, "arc aborted on a stall (drives err_o, one cycle)"},
    {"u_ctrl.iter_q", 1, "an iteration happened on the last edge (drives iter_o)"},
}};

// Text generated from the definitions above (model/src/hw_params.cpp).
std::string verilog_header();   // rtl/dda_params.vh
std::string markdown_tables();  // the tables in docs/design.md

}  // namespace dda::hw
