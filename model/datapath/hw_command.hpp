// SPDX-License-Identifier: Apache-2.0
// The golden model's Command as the hardware's command word (fields of hw_params.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "model/datapath/core_model.hpp"
#include "model/datapath/hw_params.hpp"

namespace dda::hw {

// Field values in kCmdFields order, each masked to its width (increments in two's
// complement). Throws InputError naming the field if a value does not fit the
// hardware's widths (the golden model itself has wider, 64-bit, limits).
CmdFields command_fields(const Command& c);

// Fields as 32-bit words, least significant first (Verilator's layout of cmd_i).
std::vector<std::uint32_t> pack_fields(const CmdFields& v);

// The inverse of pack_fields: a command word's fields (words least significant first).
CmdFields unpack_fields(const std::vector<std::uint32_t>& words);

// The command word as 32-bit words, least significant first (Verilator's layout).
std::vector<std::uint32_t> pack_command(const Command& c);

// Largest semi-axis the widths support at the smallest valid n (+ extra bits); by default
// the widths of hw_params.hpp (other widths: `dda gen-params --kind json --acc-width N`).
std::int64_t max_semi_axis(int extra_bits, int acc_width = kAccWidth, int cnt_width = kCntWidth);

}  // namespace dda::hw
