// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_bridges.hpp"

#include "model/motion/bridges.hpp"

namespace dda::sc {

namespace {
constexpr std::uint32_t kAdrMask = (1u << motion::kAddrWidth) - 1;
constexpr std::uint64_t mask(int bits) { return bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1; }
bool bit(std::uint64_t v, int i) { return ((v >> i) & 1u) != 0; }
}  // namespace

dda_axil::dda_axil(sc_core::sc_module_name name) : sc_core::sc_module(name) {
  SC_METHOD(comb);
  sensitive << aw_q << w_q << ar_q << bvalid_q << rvalid_q << rdata_q << cyc_q << stb_q << we_q << awaddr_q << araddr_q
            << wdata_q << wstrb_q;
  SC_METHOD(seq);
  sensitive << clk_i.pos();
  dont_initialize();
}

void dda_axil::comb() {
  s_awready_o.write(!aw_q.read());
  s_wready_o.write(!w_q.read());
  s_arready_o.write(!ar_q.read());
  s_bvalid_o.write(bvalid_q.read());
  s_bresp_o.write(0);
  s_rvalid_o.write(rvalid_q.read());
  s_rdata_o.write(rdata_q.read());
  s_rresp_o.write(0);
  wb_cyc_o.write(cyc_q.read());
  wb_stb_o.write(stb_q.read());
  wb_we_o.write(we_q.read());
  wb_adr_o.write(we_q.read() ? awaddr_q.read() : araddr_q.read());
  wb_dat_o.write(wdata_q.read());
  wb_sel_o.write(wstrb_q.read());
}

void dda_axil::seq() {
  if (!rst_ni.read()) {
    for (auto* r : {&aw_q, &w_q, &ar_q, &cyc_q, &stb_q, &we_q, &rd_first_q, &bvalid_q, &rvalid_q}) r->write(false);
    for (auto* r : {&awaddr_q, &wdata_q, &wstrb_q, &araddr_q, &rdata_q}) r->write(0);
    return;
  }
  if (s_awvalid_i.read() && !aw_q.read()) {
    aw_q.write(true);
    awaddr_q.write(s_awaddr_i.read() & kAdrMask);
  }
  if (s_wvalid_i.read() && !w_q.read()) {
    w_q.write(true);
    wdata_q.write(s_wdata_i.read());
    wstrb_q.write(s_wstrb_i.read() & 0xFu);
  }
  if (s_arvalid_i.read() && !ar_q.read()) {
    ar_q.write(true);
    araddr_q.write(s_araddr_i.read() & kAdrMask);
  }
  if (s_bready_i.read()) bvalid_q.write(false);
  if (s_rready_i.read()) rvalid_q.write(false);
  const bool can_wr = aw_q.read() && w_q.read() && !bvalid_q.read(), can_rd = ar_q.read() && !rvalid_q.read();
  const bool go_rd = can_rd && (rd_first_q.read() || !can_wr);
  if (!cyc_q.read()) {
    if (can_wr || can_rd) {
      cyc_q.write(true);
      stb_q.write(true);
      we_q.write(!go_rd);
      rd_first_q.write(!go_rd);
    }
    return;
  }
  if (!wb_stall_i.read()) stb_q.write(false);
  if (wb_ack_i.read() && !stb_q.read()) {
    cyc_q.write(false);
    if (we_q.read()) {
      aw_q.write(false);
      w_q.write(false);
      bvalid_q.write(true);
    } else {
      ar_q.write(false);
      rvalid_q.write(true);
      rdata_q.write(wb_dat_i.read());
    }
  }
}

dda_spi::dda_spi(sc_core::sc_module_name name) : sc_core::sc_module(name) {
  SC_METHOD(comb);
  sensitive << miso_q << cyc_q << stb_q << we_q << adr_q << dat_q << sel_q;
  SC_METHOD(seq);
  sensitive << clk_i.pos();
  dont_initialize();
}

void dda_spi::comb() {
  spi_miso_o.write(miso_q.read());
  wb_cyc_o.write(cyc_q.read());
  wb_stb_o.write(stb_q.read());
  wb_we_o.write(we_q.read());
  wb_adr_o.write(adr_q.read());
  wb_dat_o.write(dat_q.read());
  wb_sel_o.write(sel_q.read());
}

void dda_spi::seq() {
  if (!rst_ni.read()) {
    csn_q.write(7);
    for (auto* r : {&sck_q, &mosi_q, &cnt_q, &adr_q, &dat_q, &sel_q, &rdata_q, &count_q}) r->write(0);
    in_q.write(0);
    out_q.write(0);
    for (auto* r : {&miso_q, &cyc_q, &stb_q, &we_q, &done_q, &bad_q}) r->write(false);
    return;
  }
  const std::uint32_t csn = csn_q.read(), sck = sck_q.read(), cnt = cnt_q.read();
  csn_q.write(((csn << 1) | std::uint32_t(spi_csn_i.read())) & 7u);
  sck_q.write(((sck << 1) | std::uint32_t(spi_sck_i.read())) & 7u);
  mosi_q.write(((mosi_q.read() << 1) | std::uint32_t(spi_mosi_i.read())) & 3u);
  const bool start = bit(csn, 2) && !bit(csn, 1), rise = !bit(csn, 1) && bit(sck, 1) && !bit(sck, 2);
  const std::uint32_t next = (cnt + 1) & 0x7Fu, bits = motion::kSpiFrameBits;
  const std::uint32_t data_at = std::uint32_t(motion::spi_part("data").first);
  if (start) {
    const auto st = [&](const char* f, bool v) { return std::uint64_t(v) << motion::spi_part(f).first; };
    const std::uint64_t status = st("done", done_q.read() && !cyc_q.read()) | st("bad", bad_q.read()) |
                                 st("irq", irq_i.read()) | st("busy", busy_i.read()) |
                                 std::uint64_t(count_q.read()) << motion::spi_part("count").first;
    out_q.write((std::uint64_t(rdata_q.read()) << motion::spi_part("status").width | status) &
                mask(motion::kSpiOutBits));
    cnt_q.write(0);
    miso_q.write(false);
  } else if (rise) {
    if (cnt <= bits) cnt_q.write(next);
    if (cnt < std::uint32_t(motion::kSpiInBits)) {
      in_q.write(((in_q.read() << 1) | std::uint64_t(bit(mosi_q.read(), 1))) & mask(motion::kSpiInBits));
    }
    const bool shift = next >= data_at && next < bits;
    miso_q.write(shift && bit(out_q.read(), motion::kSpiOutBits - 1));
    if (shift) out_q.write((out_q.read() << 1) & mask(motion::kSpiOutBits));
  }
  wishbone();
  frame();
}

void dda_spi::wishbone() {
  if (!cyc_q.read()) return;
  if (!wb_stall_i.read()) stb_q.write(false);
  if (wb_ack_i.read() && !stb_q.read()) {
    cyc_q.write(false);
    if (!we_q.read()) rdata_q.write(wb_dat_i.read());
  }
}

void dda_spi::frame() {
  const std::uint32_t csn = csn_q.read();
  if (!(!bit(csn, 2) && bit(csn, 1))) return;  // CS_n rose
  const bool whole = cnt_q.read() == std::uint32_t(motion::kSpiFrameBits), busy = cyc_q.read();
  done_q.write(whole && !busy);
  bad_q.write(!whole || busy);
  if (!whole || busy) return;
  const std::uint64_t in = in_q.read();
  const auto lsb = [](const char* part) {
    return motion::kSpiInBits - motion::spi_part(part).first - motion::spi_part(part).width;
  };
  cyc_q.write(true);
  stb_q.write(true);
  we_q.write(bit(in, lsb("command") + motion::kSpiWriteBit));
  sel_q.write(std::uint32_t(in >> lsb("command")) & 0xFu);
  adr_q.write(std::uint32_t(in >> lsb("address")) & kAdrMask);
  dat_q.write(std::uint32_t(in >> lsb("data")));
  count_q.write((count_q.read() + 1) & 0xFu);
}

}  // namespace dda::sc
