// Single source of truth for every hardware width and command field.
//
// The SystemC model, the Verilator harnesses and the generated Verilog header
// rtl/dda_params.vh all take their numbers from here. `dda gen-params` writes the
// Verilog header; the test `hw_params.rtl_header_in_sync` fails if the checked-in
// rtl/dda_params.vh differs from what this file generates.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace dda::hw {

// Accumulator, integrand, capacity and increment registers are AccWidth bits.
// Values are unsigned in [0, 2^AccWidth); increments are two's complement.
// The adder inside each integrator is AccWidth + 1 bits wide (sum < 2 * capacity).
inline constexpr int kAccWidth = 50;
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
    {"jv_x", kAccWidth, "initial X integrand (scaled)"},
    {"jv_y", kAccWidth, "initial Y integrand (scaled)"},
    {"jr_x", kAccWidth, "initial X accumulator (preload), < cap"},
    {"jr_y", kAccWidth, "initial Y accumulator (preload), < cap"},
    {"cap", kAccWidth, "accumulator capacity (2^n * a * b), > 0"},
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

}  // namespace dda::hw
