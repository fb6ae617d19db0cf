// The Verilated RTL (verilator --cc) in a C++ test bench: the CoreHarness interface the
// shared driver and scoreboard use, with an optional VCD waveform. Each harness owns its
// own VerilatedContext, so many can run in one process, one after another.
#pragma once

#include <memory>
#include <string>

#include "core_driver.hpp"

class VerilatedContext;
class VerilatedVcdC;
class Vdda_core;

namespace dda::rtl {

class RtlHarness : public CoreHarness {
 public:
  explicit RtlHarness(const std::string& vcd = "");
  ~RtlHarness() override;

  void set_reset(bool rst_n) override;
  void set_ce(bool ce) override;
  void set_command(bool valid, const std::vector<std::uint32_t>& words) override;
  bool cmd_ready() override;
  void tick() override;
  CoreSample sample() override;
  const char* name() const override { return "rtl"; }
  void close_trace();

 private:
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Vdda_core> top_;
  std::unique_ptr<VerilatedVcdC> vcd_;
};

}  // namespace dda::rtl
