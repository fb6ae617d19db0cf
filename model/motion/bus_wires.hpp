// SPDX-License-Identifier: Apache-2.0
// What a host drives and sees on one cycle, on each of the block's buses: Wishbone (the
// block's own slave, rtl/dda_motion.v), AXI4-Lite (rtl/dda_axil.v) and SPI
// (rtl/dda_spi.v), the last two bridges in front of the Wishbone slave.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace dda::motion {

enum class Bus { wishbone, axil, spi };
// "wishbone", "axil", "spi".
std::string_view bus_name(Bus b);

struct AxilIn {
  bool awvalid = false;
  std::uint32_t awaddr = 0;
  bool wvalid = false;
  std::uint32_t wdata = 0;
  std::uint8_t wstrb = 0xF;
  bool bready = false, arvalid = false;
  std::uint32_t araddr = 0;
  bool rready = false;
};
struct AxilOut {
  bool awready = false, wready = false, bvalid = false;
  std::uint8_t bresp = 0;
  bool arready = false, rvalid = false;
  std::uint32_t rdata = 0;
  std::uint8_t rresp = 0;
  bool operator==(const AxilOut& o) const {
    return awready == o.awready && wready == o.wready && bvalid == o.bvalid && bresp == o.bresp &&
           arready == o.arready && rvalid == o.rvalid && rdata == o.rdata && rresp == o.rresp;
  }
};
struct SpiIn {
  bool csn = true, sck = false, mosi = false;
};
struct SpiOut {
  bool miso = false, miso_oe = false;
  bool operator==(const SpiOut& o) const { return miso == o.miso && miso_oe == o.miso_oe; }
};

// The bus inputs of one cycle: the Wishbone ones, or those of the bridge the block is
// behind (each target reads the ones of its bus).
struct BusIn {
  bool cyc = false, stb = false, we = false;
  std::uint32_t adr = 0, dat = 0;
  std::uint8_t sel = 0xF;
  AxilIn axil;
  SpiIn spi;
};

}  // namespace dda::motion
