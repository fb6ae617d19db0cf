// SPDX-License-Identifier: Apache-2.0
#include "engines.hpp"

#include <utility>

#include "core_driver.hpp"
#include "dda/hw_command.hpp"
#include "rtl_harness.hpp"
#include "sc_harness.hpp"

namespace dda::cli {

namespace {

EngineRun golden_engine(const Plan& plan, const EngineOptions&) {
  return EngineRun{initial_regs(plan.cmd()), run_records(plan)};
}

// The SystemC model, driven over its ports with ce_i high; rows are built from its
// registers sampled after every edge, and a scoreboard checks them against the golden
// model as they come (a mismatch is a run-time failure, exit status 1).
EngineRun systemc_engine(const Plan& plan, const EngineOptions& opt) {
  for (const auto& sg : plan.pieces) hw::pack_command(sg.cmd);  // InputError if too wide for the hardware
  sc::ScHarness h(opt.vcd);
  reset_core(h);
  DriveResult r = drive_arc(h, plan);
  h.close_trace();
  return EngineRun{r.initial, std::move(r.records)};
}

// The RTL under Verilator (--cc), driven and checked the same way.
EngineRun rtl_engine(const Plan& plan, const EngineOptions& opt) {
  for (const auto& sg : plan.pieces) hw::pack_command(sg.cmd);
  rtl::RtlHarness h(opt.vcd);
  reset_core(h);
  DriveResult r = drive_arc(h, plan);
  h.close_trace();
  return EngineRun{r.initial, std::move(r.records)};
}

constexpr std::pair<const char*, EngineFn> kEngines[] = {
    {"golden", &golden_engine},
    {"systemc", &systemc_engine},
    {"rtl", &rtl_engine},
};

}  // namespace

EngineFn find_engine(const std::string& name) {
  for (const auto& [n, fn] : kEngines) {
    if (name == n) return fn;
  }
  return nullptr;
}

std::string engine_names() {
  std::string s;
  for (const auto& [n, fn] : kEngines) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

}  // namespace dda::cli
