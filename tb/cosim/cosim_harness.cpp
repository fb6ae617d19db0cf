// SPDX-License-Identifier: Apache-2.0
#include "tb/cosim/cosim_harness.hpp"

#include <verilated.h>

#include <sstream>

#include "Vdda_core_sc.h"
#include "tb/engines/sc_harness.hpp"
#include "tb/engines/vl_coverage.hpp"

namespace dda::cosim {

namespace {

template <typename Core, typename Outputs>
void bind_outputs(Core& c, Outputs& o) {
  c.cmd_ready_o(o.cmd_ready);
  c.step_x_o(o.step_x);
  c.dir_x_o(o.dir_x);
  c.step_y_o(o.step_y);
  c.dir_y_o(o.dir_y);
  c.step_z_o(o.step_z);
  c.dir_z_o(o.dir_z);
  c.busy_o(o.busy);
  c.done_o(o.done);
  c.err_o(o.err);
  c.iter_o(o.iter);
  c.norm_v_x_o(o.norm[0]);
  c.norm_v_y_o(o.norm[1]);
  c.norm_v_z_o(o.norm[2]);
  c.norm_cap_o(o.norm[3]);
  c.norm_cap_z_o(o.norm[4]);
}
constexpr std::array<std::string_view, 5> kNormPorts{"norm_v_x_o", "norm_v_y_o", "norm_v_z_o", "norm_cap_o",
                                                     "norm_cap_z_o"};
constexpr bool norm_ports_listed() {
  std::size_t k = 0;
  for (const auto& p : hw::kPorts) {
    if (p.dir == hw::PortDir::Norm && (k >= kNormPorts.size() || kNormPorts[k++] != p.name)) return false;
  }
  return k == kNormPorts.size();
}
static_assert(norm_ports_listed(), "kNormPorts no longer lists hw::kPorts' norm outputs in order");

}  // namespace

CosimHarness::CosimHarness() {
  sc_ = std::make_unique<sc::dda_core>("sc_dut");
  rtl_ = std::make_unique<Vdda_core_sc>("rtl_dut");
  sc_->clk_i(clk_);
  sc_->rst_ni(rst_n_);
  sc_->ce_i(ce_);
  sc_->cmd_valid_i(cmd_valid_);
  sc_->cmd_i(cmd_);
  bind_outputs(*sc_, sc_out_);
  rtl_->clk_i(clk_);
  rtl_->rst_ni(rst_n_);
  rtl_->ce_i(ce_);
  rtl_->cmd_valid_i(cmd_valid_);
  rtl_->cmd_i(cmd_);
  bind_outputs(*rtl_, rtl_out_);
  sc_sampler_ = std::make_unique<sc::ScSampler>(sc_->name(), hw::signal_table());
  rtl_sampler_ = std::make_unique<rtl::VlSampler>(*Verilated::threadContextp(), std::string(rtl_->name()) + ".dda_core",
                                                  hw::signal_table());
}

void CosimHarness::resolve(const hw::SignalTable& t) const {
  sc::ScSampler(sc_->name(), t);
  rtl::VlSampler(*Verilated::threadContextp(), std::string(rtl_->name()) + ".dda_core", t);
}

CosimHarness::~CosimHarness() {
  if (rtl_) rtl_->final();
  write_coverage(*Verilated::threadContextp(), "cosim");
}

void CosimHarness::apply(const CoreInputs& in, bool cmd_changed) {
  rst_n_.write(in.rst_n);
  ce_.write(in.ce);
  cmd_valid_.write(in.cmd_valid);
  if (cmd_changed) cmd_.write(sc::command_bits(in.cmd));
}

bool CosimHarness::cmd_ready() {
  sc::settle();
  if (sc_out_.cmd_ready.read() != rtl_out_.cmd_ready.read()) {
    throw MismatchError("cosim mismatch: output cmd_ready_o at cycle " + std::to_string(cycle()));
  }
  return sc_out_.cmd_ready.read();
}

bool CosimHarness::edge() {
  const bool ready = cmd_ready();  // both models' cmd_ready_o, compared
  sc_core::sc_start(10, sc_core::SC_NS);
  const std::uint64_t edge_no = cycle() + 1;  // the edge's number, as tick() counts it
  // Every register and every output, every cycle.
  const std::string diff = compare_samples(sc_sample(), rtl_sample());
  const struct {
    const char* name;
    bool a, b;
  } outs[] = {
      {"cmd_ready_o", sc_out_.cmd_ready.read(), rtl_out_.cmd_ready.read()},
      {"step_x_o", sc_out_.step_x.read(), rtl_out_.step_x.read()},
      {"dir_x_o", sc_out_.dir_x.read(), rtl_out_.dir_x.read()},
      {"step_y_o", sc_out_.step_y.read(), rtl_out_.step_y.read()},
      {"dir_y_o", sc_out_.dir_y.read(), rtl_out_.dir_y.read()},
      {"step_z_o", sc_out_.step_z.read(), rtl_out_.step_z.read()},
      {"dir_z_o", sc_out_.dir_z.read(), rtl_out_.dir_z.read()},
      {"busy_o", sc_out_.busy.read(), rtl_out_.busy.read()},
      {"done_o", sc_out_.done.read(), rtl_out_.done.read()},
      {"err_o", sc_out_.err.read(), rtl_out_.err.read()},
      {"iter_o", sc_out_.iter.read(), rtl_out_.iter.read()},
  };
  bool same = diff.empty();
  for (const auto& o : outs) same = same && o.a == o.b;
  for (std::size_t k = 0; k < kNormPorts.size(); ++k) same = same && sc_out_.norm[k].read() == rtl_out_.norm[k].read();
  if (same) {
    ++compared_;
    return ready;
  }
  std::ostringstream m;  // built only for a difference
  if (!diff.empty()) {
    m << "cosim mismatch at cycle " << edge_no << ": " << diff << " (systemc vs rtl)";
  } else {
    for (const auto& o : outs) {
      if (o.a != o.b) {
        m << "cosim mismatch at cycle " << edge_no << ": output " << o.name << ": " << o.a << " vs " << o.b
          << " (systemc vs rtl)";
        break;
      }
    }
    for (std::size_t k = 0; k < kNormPorts.size() && m.tellp() == 0; ++k) {
      if (sc_out_.norm[k].read() != rtl_out_.norm[k].read()) {
        m << "cosim mismatch at cycle " << edge_no << ": output " << kNormPorts[k] << ": " << sc_out_.norm[k].read()
          << " vs " << rtl_out_.norm[k].read() << " (systemc vs rtl)";
      }
    }
  }
  throw MismatchError(m.str());
}

PortValues CosimHarness::read_ports() {  // the SystemC model's (the RTL's are compared with them)
  const Outputs& o = sc_out_;
  // The order of kHarnessOutputs.
  return {o.cmd_ready.read(), o.step_x.read(), o.step_y.read(), o.dir_x.read(), o.dir_y.read(), o.step_z.read(),
          o.dir_z.read(),     o.busy.read(),   o.done.read(),   o.err.read(),   o.iter.read()};
}

}  // namespace dda::cosim
