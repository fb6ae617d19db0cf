// SPDX-License-Identifier: Apache-2.0
// The reference models of the bus bridges (docs/design.md, "Bus bridges"): the AXI4-Lite
// slave (rtl/dda_axil.v) and the SPI slave (rtl/dda_spi.v), each a Wishbone master of
// the block in front of it, register for register as the RTL (below u_bridge of
// dda_motion_axil and dda_motion_spi).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "model/motion/motion_map.hpp"
#include "model/motion/motion_model.hpp"

namespace dda::motion {

struct BridgeReg {
  std::string_view name;
  int width;
};
// MOSI bits an SPI frame's in_q keeps (up to the data's last), MISO bits of out_q.
inline constexpr int kSpiInBits = spi_part("data").first + spi_part("data").width;
inline constexpr int kSpiOutBits = spi_part("data").width + spi_part("status").width;
inline constexpr std::array<BridgeReg, 14> kAxilRegs{{
    {"aw_q", 1},
    {"awaddr_q", kAddrWidth},
    {"w_q", 1},
    {"wdata_q", 32},
    {"wstrb_q", 4},
    {"ar_q", 1},
    {"araddr_q", kAddrWidth},
    {"cyc_q", 1},
    {"stb_q", 1},
    {"we_q", 1},
    {"rd_first_q", 1},
    {"bvalid_q", 1},
    {"rvalid_q", 1},
    {"rdata_q", 32},
}};
inline constexpr std::array<BridgeReg, 17> kSpiRegs{{
    {"csn_q", 3},
    {"sck_q", 3},
    {"mosi_q", 2},
    {"cnt_q", 7},
    {"in_q", kSpiInBits},
    {"out_q", kSpiOutBits},
    {"miso_q", 1},
    {"cyc_q", 1},
    {"stb_q", 1},
    {"we_q", 1},
    {"adr_q", kAddrWidth},
    {"dat_q", 32},
    {"sel_q", 4},
    {"rdata_q", 32},
    {"done_q", 1},
    {"bad_q", 1},
    {"count_q", 4},
}};

class Bridge {
 public:
  virtual ~Bridge() = default;
  // The Wishbone inputs the block sees this cycle (from the bridge's registers).
  virtual BusIn wishbone() const = 0;
  // One rising edge: the host's inputs, and the block's outputs before the edge.
  virtual void edge(bool rst_n, const BusIn& host, const BlockOutputs& block) = 0;
  // Its host-side outputs (after the last edge) into o.
  virtual void outputs(BlockOutputs& o) const = 0;
  // Its registers, in the order of its table (kAxilRegs, kSpiRegs).
  virtual std::vector<std::uint64_t> regs() const = 0;
};

// The bridge of a bus, or none for Wishbone (the block's own slave).
std::unique_ptr<Bridge> make_bridge(Bus bus);
// The register table of a bus' bridge (empty for Wishbone).
std::vector<BridgeReg> bridge_regs(Bus bus);

}  // namespace dda::motion
