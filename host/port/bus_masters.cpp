// SPDX-License-Identifier: Apache-2.0
// The bus masters of bus_master.hpp.
#include <algorithm>
#include <string>

#include "host/port/bus_master.hpp"
#include "model/datapath/errors.hpp"

namespace dda::motion {

std::uint32_t WishboneMaster::run(const Transfer& t) {
  std::uniform_int_distribution<int> pct(0, 99);
  while (pct(rng_) < idle_percent_) idle(1);
  bool taken = false;
  for (int guard = 0; guard < 64; ++guard) {
    BusIn b;
    b.cyc = true;
    b.stb = pipelined_ ? !taken : true;
    b.we = t.we;
    b.adr = t.adr;
    b.dat = t.dat;
    b.sel = t.sel;
    const bool stall = t_.outputs().stall;
    tick(b);
    if (b.stb && !stall) taken = true;
    if (taken && t_.outputs().ack) {
      const std::uint32_t data = t.we ? 0 : t_.outputs().dat;
      // Classic: the request stays on the bus through the ack cycle (the block stalls
      // it, so it is not taken twice). Pipelined: the next request may start now.
      if (!pipelined_) tick(b);
      return data;
    }
  }
  throw GuardError("Wishbone master: no ack within 64 cycles");
}

void BusMaster::idle(int cycles) {
  for (int i = 0; i < cycles; ++i) tick(BusIn{});
}

namespace {

constexpr int kGuard = 64;  // cycles an AXI access may take

// The bits of a frame part's value in a 64-bit frame word (the frame's first bit is the
// word's most significant).
std::uint64_t place(std::string_view part, std::uint64_t v) {
  const SpiPart& p = spi_part(part);
  return (v & ((std::uint64_t{1} << p.width) - 1)) << (kSpiFrameBits - p.first - p.width);
}
std::uint32_t take(std::string_view part, std::uint64_t word) {
  const SpiPart& p = spi_part(part);
  return std::uint32_t((word >> (kSpiFrameBits - p.first - p.width)) & ((std::uint64_t{1} << p.width) - 1));
}
std::uint32_t status_field(std::string_view name, std::uint32_t status) {
  const SpiPart& p = spi_part(name);
  return (status >> p.first) & ((1u << p.width) - 1);
}

}  // namespace

void AxilMaster::take_response() {
  for (int guard = 0; guard < kGuard; ++guard) {
    const AxilOut o = t_.outputs().axil;
    BusIn b;
    b.axil.bready = true;
    tick(b);
    if (o.bvalid) {
      b_waiting_ = false;
      if (o.bresp != 0) throw GuardError("AXI4-Lite master: BRESP " + std::to_string(o.bresp));
      return;
    }
  }
  throw GuardError("AXI4-Lite master: no response within " + std::to_string(kGuard) + " cycles");
}

std::uint32_t AxilMaster::run(const Transfer& t) {
  std::uniform_int_distribution<int> pct(0, 99);
  while (pct(rng_) < idle_percent_) idle(1);
  // (The slave takes no write while a response waits.)
  if (t.we && b_waiting_) take_response();
  reads_past_response_ += !t.we && b_waiting_;
  const bool leave = t.we && rng_() % 4 == 0;  // its response left waiting
  int aw_wait = t.we ? int(rng_() % 3) : 0, w_wait = t.we ? int(rng_() % 3) : 0;
  bool aw_done = !t.we, w_done = !t.we, ar_done = t.we;
  for (int guard = 0; guard < kGuard; ++guard) {
    const AxilOut o = t_.outputs().axil;  // this cycle's ready and valid
    if (leave && o.bvalid) {              // the write is done; its response left waiting
      b_waiting_ = true;
      return 0;
    }
    BusIn b;
    AxilIn& a = b.axil;
    a.awvalid = !aw_done && aw_wait == 0;
    a.awaddr = t.adr;
    a.wvalid = !w_done && w_wait == 0;
    a.wdata = t.dat;
    a.wstrb = t.sel;
    a.arvalid = !ar_done;
    a.araddr = t.adr;
    const bool ready = rng_() % 3 != 0;  // the response is taken, or not yet
    a.bready = t.we && ready && !leave;
    a.rready = !t.we && ready;
    tick(b);
    aw_done = aw_done || (a.awvalid && o.awready);
    w_done = w_done || (a.wvalid && o.wready);
    ar_done = ar_done || (a.arvalid && o.arready);
    aw_wait = std::max(0, aw_wait - 1);
    w_wait = std::max(0, w_wait - 1);

    if (a.bready && o.bvalid) {
      if (o.bresp != 0) throw GuardError("AXI4-Lite master: BRESP " + std::to_string(o.bresp));
      return 0;
    }
    if (a.rready && o.rvalid) {
      if (o.rresp != 0) throw GuardError("AXI4-Lite master: RRESP " + std::to_string(o.rresp));
      return o.rdata;
    }
  }
  throw GuardError("AXI4-Lite master: no response within " + std::to_string(kGuard) + " cycles");
}

int SpiMaster::half() { return jitter_ ? half_ + int(rng_() % unsigned(half_ + 1)) : half_; }

void SpiMaster::hold(BusIn& b, int cycles) {
  for (int i = 0; i < cycles; ++i) tick(b);
}

std::uint64_t SpiMaster::frame(std::uint64_t mosi, int bits) {
  BusIn b;
  b.spi.csn = false;
  hold(b, 2 + int(rng_() % 3));  // CS_n's setup before the first rising edge
  std::uint64_t miso = 0;
  for (int i = 0; i < bits; ++i) {
    const int at = kSpiFrameBits - 1 - i;  // past the frame's bits (a frame too long): MOSI low
    b.spi.mosi = at >= 0 && ((mosi >> at) & 1u) != 0;
    hold(b, half());
    // Mode 0: the master samples MISO as SCK rises.
    if (at >= 0) miso |= std::uint64_t(t_.outputs().spi.miso) << at;
    b.spi.sck = true;
    hold(b, half());
    b.spi.sck = false;
  }
  hold(b, half());
  b.spi.csn = true;
  hold(b, 4 + int(rng_() % 4));  // CS_n high between frames
  return miso;
}

namespace {
std::uint64_t spi_frame_word(bool we, std::uint32_t sel, std::uint32_t adr, std::uint32_t dat) {
  const std::uint32_t cmd = (we ? 1u << kSpiWriteBit : 0u) | (we ? sel & 0xFu : 0u);
  return place("command", cmd) | place("address", adr) | place("data", dat);
}
}  // namespace

void SpiMaster::stray_write(std::uint32_t adr, std::uint32_t dat) {
  static constexpr int kOff[] = {-1, 1, 9};
  frame(spi_frame_word(true, 0xFu, adr, dat), kSpiFrameBits + kOff[rng_() % 3]);
  stray_ = true;
  ++strays_;
}

std::uint32_t SpiMaster::run(const Transfer& t) {
  const auto check = [](std::uint32_t status, const char* what) {
    if (status_field("bad", status)) throw LinkError(std::string("SPI master: the status says bad ") + what);
  };
  const std::uint32_t s1 = take("status", frame(spi_frame_word(t.we, t.sel, t.adr, t.dat))) & 0xFFu;
  status_ = s1;
  if (stray_) {
    if (!status_field("bad", s1)) throw LinkError("SPI master: a frame of the wrong length, and the status not bad");
    stray_ = false;
  } else {
    check(s1, "before this access");
  }
  if (t.we) return 0;
  // The read's data comes back in the next frame: a read of ID.
  const std::uint64_t back = frame(spi_frame_word(false, 0, reg_offset("ID"), 0));
  const std::uint32_t s2 = take("status", back);
  status_ = s2;
  check(s2, "for a read");
  if (!status_field("done", s2) || status_field("count", s2) != ((status_field("count", s1) + 1) & 0xFu)) {
    throw LinkError("SPI master: a read frame made no access (status 0x" + std::to_string(s2) + ")");
  }
  return take("data", back);
}

std::unique_ptr<BusMaster> make_master(Bus bus, BusTarget& t, std::uint64_t seed, bool pipelined, int idle_percent) {
  switch (bus) {
    case Bus::axil:
      return std::make_unique<AxilMaster>(t, seed, idle_percent);
    case Bus::spi:
      return std::make_unique<SpiMaster>(t, seed);
    default:
      return std::make_unique<WishboneMaster>(t, seed, pipelined, idle_percent);
  }
}

}  // namespace dda::motion
