// SPDX-License-Identifier: Apache-2.0
#include "model/motion/bridges.hpp"

namespace dda::motion {

namespace {

constexpr std::uint32_t kAdrMask = (1u << kAddrWidth) - 1;
constexpr std::uint64_t mask(int bits) { return bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1; }

// rtl/dda_axil.v
class AxilBridge : public Bridge {
 public:
  BusIn wishbone() const override {
    BusIn b;
    b.cyc = r_.cyc;
    b.stb = r_.stb;
    b.we = r_.we;
    b.adr = r_.we ? r_.awaddr : r_.araddr;
    b.dat = r_.wdata;
    b.sel = r_.wstrb;
    return b;
  }

  void edge(bool rst_n, const BusIn& host, const BlockOutputs& blk) override {
    if (!rst_n) {
      r_ = {};
      return;
    }
    const AxilIn& a = host.axil;
    R n = r_;
    if (a.awvalid && !r_.aw) {
      n.aw = true;
      n.awaddr = a.awaddr & kAdrMask;
    }
    if (a.wvalid && !r_.w) {
      n.w = true;
      n.wdata = a.wdata;
      n.wstrb = a.wstrb & 0xFu;
    }
    if (a.arvalid && !r_.ar) {
      n.ar = true;
      n.araddr = a.araddr & kAdrMask;
    }
    if (a.bready) n.bvalid = false;
    if (a.rready) n.rvalid = false;
    const bool can_wr = r_.aw && r_.w && !r_.bvalid, can_rd = r_.ar && !r_.rvalid;
    const bool go_rd = can_rd && (r_.rd_first || !can_wr);
    if (!r_.cyc) {
      if (can_wr || can_rd) {
        n.cyc = n.stb = true;
        n.we = !go_rd;
        n.rd_first = !go_rd;
      }
    } else {
      if (!blk.stall) n.stb = false;
      if (blk.ack && !r_.stb) {
        n.cyc = false;
        if (r_.we) {
          n.aw = n.w = false;
          n.bvalid = true;
        } else {
          n.ar = false;
          n.rvalid = true;
          n.rdata = blk.dat;
        }
      }
    }
    r_ = n;
  }

  void outputs(BlockOutputs& o) const override {
    o.axil.awready = !r_.aw;
    o.axil.wready = !r_.w;
    o.axil.arready = !r_.ar;
    o.axil.bvalid = r_.bvalid;
    o.axil.rvalid = r_.rvalid;
    o.axil.rdata = r_.rdata;
    o.axil.bresp = o.axil.rresp = 0;  // OKAY
  }

  std::vector<std::uint64_t> regs() const override {
    return {r_.aw,  r_.awaddr, r_.w,  r_.wdata,    r_.wstrb,  r_.ar,     r_.araddr,
            r_.cyc, r_.stb,    r_.we, r_.rd_first, r_.bvalid, r_.rvalid, r_.rdata};
  }

 private:
  struct R {
    bool aw = false, w = false, ar = false, cyc = false, stb = false, we = false, rd_first = false;
    bool bvalid = false, rvalid = false;
    std::uint32_t awaddr = 0, wdata = 0, araddr = 0, rdata = 0;
    std::uint8_t wstrb = 0;
  } r_;
};

// rtl/dda_spi.v
class SpiBridge : public Bridge {
 public:
  BusIn wishbone() const override {
    BusIn b;
    b.cyc = r_.cyc;
    b.stb = r_.stb;
    b.we = r_.we;
    b.adr = r_.adr;
    b.dat = r_.dat;
    b.sel = r_.sel;
    return b;
  }

  void edge(bool rst_n, const BusIn& host, const BlockOutputs& blk) override;

  void outputs(BlockOutputs& o) const override {
    o.spi.miso = r_.miso;
    o.spi.miso_oe = !csn_;  // spi_miso_oe_o = ~spi_csn_i
  }

  std::vector<std::uint64_t> regs() const override {
    return {r_.csn, r_.sck, r_.mosi, r_.cnt, r_.in,    r_.out,  r_.miso, r_.cyc,  r_.stb,
            r_.we,  r_.adr, r_.dat,  r_.sel, r_.rdata, r_.done, r_.bad,  r_.count};
  }

 private:
  static bool bit(std::uint64_t v, int i) { return ((v >> i) & 1u) != 0; }
  // The frame's MOSI bit k sits at in_q[kSpiInBits-1-k]: a part's lowest bit.
  static int in_lsb(std::string_view part) { return kSpiInBits - spi_part(part).first - spi_part(part).width; }
  struct R {
    std::uint64_t csn = 7, sck = 0, mosi = 0, cnt = 0, in = 0, out = 0;
    bool miso = false, cyc = false, stb = false, we = false, done = false, bad = false;
    std::uint32_t adr = 0, dat = 0, rdata = 0;
    std::uint8_t sel = 0, count = 0;
  } r_;
  bool csn_ = true;  // the pin, as last driven
};

void SpiBridge::edge(bool rst_n, const BusIn& host, const BlockOutputs& blk) {
  csn_ = host.spi.csn;
  if (!rst_n) {
    r_ = {};
    return;
  }
  R n = r_;
  n.csn = ((r_.csn << 1) | std::uint64_t(host.spi.csn)) & 7u;
  n.sck = ((r_.sck << 1) | std::uint64_t(host.spi.sck)) & 7u;
  n.mosi = ((r_.mosi << 1) | std::uint64_t(host.spi.mosi)) & 3u;
  const bool start = bit(r_.csn, 2) && !bit(r_.csn, 1), stop = !bit(r_.csn, 2) && bit(r_.csn, 1);
  const bool rise = !bit(r_.csn, 1) && bit(r_.sck, 1) && !bit(r_.sck, 2);
  const std::uint64_t next = (r_.cnt + 1) & 0x7Fu;
  const auto frame = std::uint64_t(kSpiFrameBits), data_at = std::uint64_t(spi_part("data").first);
  const bool whole = r_.cnt == frame;
  const std::uint64_t status =
      std::uint64_t(r_.done && !r_.cyc) << spi_part("done").first | std::uint64_t(r_.bad) << spi_part("bad").first |
      std::uint64_t(blk.irq) << spi_part("irq").first | std::uint64_t(blk.busy) << spi_part("busy").first |
      std::uint64_t(r_.count) << spi_part("count").first;
  if (start) {
    n.cnt = 0;
    n.out = (std::uint64_t(r_.rdata) << spi_part("status").width | status) & mask(kSpiOutBits);
    n.miso = false;
  } else if (rise) {
    if (r_.cnt <= frame) n.cnt = next;
    if (r_.cnt < std::uint64_t(kSpiInBits)) n.in = ((r_.in << 1) | std::uint64_t(bit(r_.mosi, 1))) & mask(kSpiInBits);
    if (next >= data_at && next < frame) {
      n.miso = bit(r_.out, kSpiOutBits - 1);
      n.out = (r_.out << 1) & mask(kSpiOutBits);
    } else {
      n.miso = false;
    }
  }
  if (r_.cyc) {
    if (!blk.stall) n.stb = false;
    if (blk.ack && !r_.stb) {
      n.cyc = false;
      if (!r_.we) n.rdata = blk.dat;
    }
  }
  if (stop) {
    n.done = whole && !r_.cyc;
    n.bad = !whole || r_.cyc;
    if (whole && !r_.cyc) {
      n.cyc = n.stb = true;
      n.we = bit(r_.in, in_lsb("command") + kSpiWriteBit);
      n.sel = std::uint8_t((r_.in >> in_lsb("command")) & 0xFu);
      n.adr = std::uint32_t(r_.in >> in_lsb("address")) & kAdrMask;
      n.dat = std::uint32_t(r_.in >> in_lsb("data"));
      n.count = std::uint8_t((r_.count + 1) & 0xFu);
    }
  }
  r_ = n;
}

}  // namespace

std::unique_ptr<Bridge> make_bridge(Bus bus) {
  switch (bus) {
    case Bus::axil:
      return std::make_unique<AxilBridge>();
    case Bus::spi:
      return std::make_unique<SpiBridge>();
    default:
      return nullptr;
  }
}

std::vector<BridgeReg> bridge_regs(Bus bus) {
  switch (bus) {
    case Bus::axil:
      return {kAxilRegs.begin(), kAxilRegs.end()};
    case Bus::spi:
      return {kSpiRegs.begin(), kSpiRegs.end()};
    default:
      return {};
  }
}

std::string_view bus_name(Bus b) {
  switch (b) {
    case Bus::axil:
      return "axil";
    case Bus::spi:
      return "spi";
    default:
      return "wishbone";
  }
}

}  // namespace dda::motion
