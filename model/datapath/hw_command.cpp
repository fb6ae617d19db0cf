// SPDX-License-Identifier: Apache-2.0
#include "model/datapath/hw_command.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace dda::hw {

namespace {

// A field of `width` bits whose value must be below 2^value_bits (value_bits <= width).
void unsigned_field(const char* name, std::int64_t v, int width, int value_bits) {
  const std::uint64_t max = (std::uint64_t{1} << value_bits) - 1;
  if (v < 0 || static_cast<std::uint64_t>(v) > max) {
    throw InputError(std::string(name) + " = " + std::to_string(v) + " does not fit the hardware's " +
                     std::to_string(width) + "-bit field: it must be in [0, 2^" + std::to_string(value_bits) +
                     ") (hw_params.hpp)");
  }
}

void signed_field(const char* name, std::int64_t v, int width) {
  const std::int64_t lim = std::int64_t{1} << (width - 1);
  if (v < -lim || v >= lim) {
    throw InputError(std::string(name) + " = " + std::to_string(v) + " does not fit the hardware's " +
                     std::to_string(width) + "-bit two's complement field (hw_params.hpp)");
  }
}

}  // namespace

CmdFields command_fields(const Command& c) {
  // The capacity first: when it is out of range, it is the cause of the rest.
  unsigned_field("cap", c.cap, kAccWidth, kAccWidth - 1);
  // cap and jr are below 2^(AccWidth-1) so that every integrand up to cap is positive
  // in the AccWidth-bit two's complement integrand registers.
  signed_field("jv_x", c.jv_x, kAccWidth);
  signed_field("jv_y", c.jv_y, kAccWidth);
  unsigned_field("jr_x", c.jr_x, kAccWidth, kAccWidth - 1);
  unsigned_field("jr_y", c.jr_y, kAccWidth, kAccWidth - 1);
  unsigned_field("cnt_x", c.cnt_x, kCntWidth, kCntWidth);
  unsigned_field("cnt_y", c.cnt_y, kCntWidth, kCntWidth);
  signed_field("inc_x_on_x", c.inc_x_on_x, kAccWidth);
  signed_field("inc_x_on_y", c.inc_x_on_y, kAccWidth);
  signed_field("inc_y_on_x", c.inc_y_on_x, kAccWidth);
  signed_field("inc_y_on_y", c.inc_y_on_y, kAccWidth);
  unsigned_field("cap_z", c.cap_z, kAccWidth, kAccWidth - 1);
  if (c.cap_z == 0) throw InputError("cap_z = 0: the Z capacity must be positive (hw_params.hpp)");
  unsigned_field("jv_z", c.jv_z, kAccWidth, kAccWidth - 1);
  unsigned_field("jr_z", c.jr_z, kAccWidth, kAccWidth - 1);
  unsigned_field("cnt_z", c.cnt_z, kCntWidth, kCntWidth);
  if (c.jv_z > c.cap_z || c.jr_z >= c.cap_z) {
    throw InputError("jv_z = " + std::to_string(c.jv_z) + ", jr_z = " + std::to_string(c.jr_z) +
                     ": the Z axis needs jv_z <= cap_z and jr_z < cap_z = " + std::to_string(c.cap_z) +
                     " (one step per iteration at most)");
  }
  return command_fields_unchecked(c);
}

std::vector<std::uint32_t> pack_fields(const CmdFields& v) {
  std::vector<std::uint32_t> w((kCmdWidth + 31) / 32, 0);
  int bit = 0;
  for (std::size_t i = 0; i < kCmdFields.size(); ++i) {
    for (int k = 0; k < kCmdFields[i].width; ++k, ++bit) {
      if ((v[i] >> k) & 1u) w[bit / 32] |= 1u << (bit % 32);
    }
  }
  return w;
}

CmdFields unpack_fields(const std::vector<std::uint32_t>& words) {
  CmdFields v{};
  std::size_t bit = 0;
  for (std::size_t i = 0; i < kCmdFields.size(); ++i) {
    for (int k = 0; k < kCmdFields[i].width; ++k, ++bit) {
      const std::uint32_t w = bit / 32 < words.size() ? words[bit / 32] : 0;
      v[i] |= std::uint64_t{(w >> (bit % 32)) & 1u} << k;
    }
  }
  return v;
}

std::vector<std::uint32_t> pack_command(const Command& c) { return pack_fields(command_fields(c)); }

std::int64_t max_semi_axis(int extra_bits, int acc_width, int cnt_width) {
  // Largest m such that a = b = m (the worst case) fits: cap = 2^n * m^2 < 2^(AccWidth-1)
  // with n = smallest_valid_bits(m) + extra_bits, and a quarter arc's m steps fit the
  // counters. For m in (2^(k-1), 2^k] the smallest valid n is k.
  std::int64_t best = 1;
  for (int k = 1; k < 31; ++k) {
    const int n = k + extra_bits;
    if (n >= acc_width - 1) break;
    const std::uint64_t room = (std::uint64_t{1} << (acc_width - 1 - n)) - 1;  // m^2 <= room
    auto m = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(room)));
    while (m * m > room) --m;
    while ((m + 1) * (m + 1) <= room) ++m;
    m = std::min(m, std::uint64_t{1} << k);
    if (m > (std::uint64_t{1} << (k - 1))) best = std::max<std::int64_t>(best, std::int64_t(m));
  }
  return std::min<std::int64_t>(best, (std::int64_t{1} << cnt_width) - 1);
}

}  // namespace dda::hw
