// SPDX-License-Identifier: Apache-2.0
// The Verilated RTL (verilator --cc) in a C++ test bench: the CoreHarness interface the
// shared driver and scoreboard use, with an optional VCD waveform. Each harness owns its
// own VerilatedContext, so many can run in one process, one after another.
#pragma once

#include <memory>
#include <string>

#include "tb/engines/core_driver.hpp"
#include "tb/engines/vl_sampler.hpp"

class VerilatedContext;
class VerilatedVcdC;
class Vdda_core;

namespace dda::rtl {

class RtlHarness : public CoreHarness {
 public:
  explicit RtlHarness(const std::string& vcd = "");
  ~RtlHarness() override;

  bool cmd_ready() override;
  const char* name() const override { return "rtl"; }
  void close_trace();
  // Resolves the names of a table in this RTL (each public, at its width); throws
  // GuardError naming the first that is not.
  void resolve(const hw::SignalTable& t) const;

 protected:
  void apply(const CoreInputs& in, bool cmd_changed) override;
  bool edge() override;
  Signals read_signals() override { return sampler_->read(); }
  PortValues read_ports() override;

 private:
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Vdda_core> top_;
  std::unique_ptr<VerilatedVcdC> vcd_;
  std::unique_ptr<VlSampler> sampler_;
};

}  // namespace dda::rtl
