// SPDX-License-Identifier: Apache-2.0
// The motion block behind its AXI4-Lite and SPI bridges (rtl/dda_motion_axil.v,
// rtl/dda_motion_spi.v), the RTL in lockstep with the reference models of the block and
// the bridge every edge (tb/engines/motion_harness.hpp): the same random work over the
// three buses does the same, iteration by iteration; the SPI frame rules; the AXI4-Lite
// channel orders and held responses; the register map the same on every bus.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include "host/port/bus_master.hpp"
#include "tb/engines/motion_harness.hpp"
#include "tb/random/bus_work.hpp"
#include "tb/random/dda_random.hpp"

using namespace dda;
using namespace dda::motion;

namespace {

constexpr std::array<Bus, 3> kBuses{{Bus::wishbone, Bus::axil, Bus::spi}};

// A frame word for SpiMaster::frame: the command, address and data in their places.
std::uint64_t spi_word(bool we, std::uint32_t adr, std::uint32_t dat) {
  const auto at = [](std::string_view part, std::uint64_t v) {
    const SpiPart& p = spi_part(part);
    return (v & ((std::uint64_t{1} << p.width) - 1)) << (kSpiFrameBits - p.first - p.width);
  };
  return at("command", we ? (1u << kSpiWriteBit) | 0xFu : 0u) | at("address", adr) | at("data", dat);
}
std::uint32_t spi_status(std::uint64_t miso, std::string_view field) {
  const SpiPart& f = spi_part(field);
  return std::uint32_t(miso >> (f.first)) & ((1u << f.width) - 1);  // the status byte is the word's last
}

}  // namespace

TEST_CASE("bridges: the same random work over Wishbone, AXI4-Lite and SPI does the same, iteration by iteration",
          "[bridges]") {
  const std::uint64_t seed = test_seed(91);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  std::vector<BusWork> w;
  for (const Bus bus : kBuses) {
    MotionHarness h("", bus);
    w.push_back(run_bus_work(h, bus, seed, 8));
    INFO(bus_name(bus) << ": " << w.back().cycles << " cycles, " << w.back().iterations.size() << " iterations");
    CHECK(w.back().end == w.back().want);
    CHECK(w.back().snap == w.back().end);
    CHECK(w.back().entry_read == 0);
    CHECK(w.back().snap_after_write == w.back().snap);
    CHECK(w.back().irq_seen);
    CHECK(w.back().irq_cleared);
    // Reads while a write's response waits (AXI4-Lite), frames of the wrong length (SPI).
    CHECK((w.back().reads_past_response > 0) == (bus == Bus::axil));
    CHECK((w.back().stray_frames > 0) == (bus == Bus::spi));
  }
  CHECK(w[0].pieces >= 8);
  CHECK(w[0].iterations.size() > 100);
  CHECK(w[0].pulses[0].size() + w[0].pulses[1].size() > 100);
  CHECK(!w[0].pulses[2].empty());
  CHECK(compare_work(w[0], w[1]) == "");
  CHECK(compare_work(w[0], w[2]) == "");
  CHECK(w[2].cycles > 4 * w[0].cycles);  // the same work, however slow the bus
}

TEST_CASE("bridges: SPI, a frame one edge short or one or more edges long makes no access, a whole one exactly one",
          "[bridges]") {
  MotionHarness h("", Bus::spi);
  SpiMaster m(h, 5);
  h.set_reset(false);
  m.idle(2);
  h.set_reset(true);
  const std::uint32_t accel = reg_offset("ACCEL");
  const std::uint64_t first = m.frame(spi_word(false, 0, 0));
  CHECK(spi_status(first, "done") == 0);  // nothing before it since the reset
  CHECK(spi_status(first, "count") == 0);
  // (Nine edges long: the edge counter stops one past the frame's edges.)
  for (const int bits : {kSpiFrameBits - 1, kSpiFrameBits + 1, kSpiFrameBits + 9, 1}) {
    INFO(bits << " edges");
    m.frame(spi_word(true, accel, 0x1234u + std::uint32_t(bits)), bits);
    const std::uint64_t s = m.frame(spi_word(false, accel, 0));
    CHECK(spi_status(s, "bad") == 1);
    CHECK(spi_status(s, "done") == 0);
    CHECK(spi_status(s, "count") == 1);  // the first read only
    const std::uint64_t back = m.frame(spi_word(false, accel, 0));
    CHECK(std::uint32_t(back >> 8) == 0);  // ACCEL as after the reset
    m.idle(1);
    // (the two reads count 2 more: start the next round from a known count)
    h.set_reset(false);
    m.idle(1);
    h.set_reset(true);
    m.frame(spi_word(false, 0, 0));
  }
  m.frame(spi_word(true, accel, 0xCAFEu));
  CHECK(m.read(accel) == 0xCAFEu);
  CHECK(h.model().regs()[breg("accel_q")] == 0xCAFEu);
  // SCK at exactly a quarter of the clock, every half period two clocks.
  SpiMaster fast(h, 6, 2, false);
  fast.write(accel, 0x5A5A1234u);
  CHECK(fast.read(accel) == 0x5A5A1234u);
}

TEST_CASE("bridges: AXI4-Lite, data before address, a read between, responses held until taken", "[bridges]") {
  MotionHarness h("", Bus::axil);
  h.set_reset(false);
  h.tick(BusIn{});
  h.set_reset(true);
  const std::uint32_t vmin = reg_offset("VMIN"), id = reg_offset("ID");
  BusIn b;
  b.axil.wvalid = true;  // the data first, then a read address, then the write's address
  b.axil.wdata = 0xBEEFu;
  h.tick(b);
  b.axil.wvalid = false;
  CHECK(!h.outputs().axil.wready);  // its buffer holds it
  b.axil.arvalid = true;
  b.axil.araddr = id;
  h.tick(b);
  b.axil.arvalid = false;
  b.axil.awvalid = true;
  b.axil.awaddr = vmin;
  h.tick(b);
  b.axil.awvalid = false;
  for (int i = 0; i < 12; ++i) h.tick(b);  // nobody takes the responses yet
  CHECK(h.outputs().axil.rvalid);
  CHECK(h.outputs().axil.rdata == kId);
  CHECK(h.outputs().axil.bvalid);
  CHECK(h.model().regs()[breg("vmin_q")] == 0xBEEFu);
  b.axil.rready = b.axil.bready = true;
  h.tick(b);
  CHECK(!h.outputs().axil.rvalid);
  CHECK(!h.outputs().axil.bvalid);
}

TEST_CASE("bridges: AXI4-Lite, the response after the fourth edge from the one that takes the request", "[bridges]") {
  MotionHarness h("", Bus::axil);
  h.set_reset(false);
  h.tick(BusIn{});
  h.set_reset(true);
  for (const bool we : {true, false}) {
    INFO((we ? "write" : "read"));
    BusIn b;
    b.axil.awvalid = b.axil.wvalid = we;
    b.axil.arvalid = !we;
    b.axil.awaddr = b.axil.araddr = reg_offset("ACCEL");
    h.tick(b);  // edge 1 takes it
    b = BusIn{};
    int edges = 1;
    while (!(we ? h.outputs().axil.bvalid : h.outputs().axil.rvalid) && edges < 20) {
      h.tick(b);
      ++edges;
    }
    CHECK(edges == 4);
    b.axil.bready = b.axil.rready = true;
    h.tick(b);
  }
}

TEST_CASE("bridges: the register map reads the same on every bus, byte lanes and all", "[bridges]") {
  for (const Bus bus : kBuses) {
    INFO(bus_name(bus));
    MotionHarness h("", bus);
    const std::unique_ptr<BusMaster> m = make_master(bus, h, 11, true, 30);
    h.set_reset(false);
    m->idle(2);
    h.set_reset(true);
    CHECK(m->read(reg_offset("ID")) == kId);
    CHECK(m->read(reg_offset("VERSION")) == (std::uint32_t(kVersionMajor) << 16 | std::uint32_t(kVersionMinor)));
    m->write(reg_offset("ACCEL"), 0x11223344u);
    m->write(reg_offset("ACCEL"), 0xAABBCCDDu, 0x5);  // lanes 0 and 2 only
    CHECK(m->read(reg_offset("ACCEL")) == 0x11BB33DDu);
  }
}
