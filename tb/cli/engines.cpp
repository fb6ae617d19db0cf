#include "engines.hpp"

#include <utility>

#include "core_driver.hpp"
#include "dda/hw_command.hpp"
#include "rtl_harness.hpp"
#include "sc_harness.hpp"

namespace dda::cli {

namespace {

std::vector<Iteration> golden_engine(const Plan& plan, const EngineOptions&) {
  return run_records(plan);
}

// The SystemC model, driven over its ports with ce_i high; rows are built from its
// registers sampled after every edge, and a scoreboard checks them against the golden
// model as they come (a mismatch is a run-time failure, exit status 1).
std::vector<Iteration> systemc_engine(const Plan& plan, const EngineOptions& opt) {
  hw::pack_command(plan.cmd);  // throws InputError if the arc exceeds the hardware widths
  sc::ScHarness h(opt.vcd);
  reset_core(h);
  return drive_arc(h, plan).records;
}

// The RTL under Verilator (--cc), driven and checked the same way.
std::vector<Iteration> rtl_engine(const Plan& plan, const EngineOptions& opt) {
  hw::pack_command(plan.cmd);
  rtl::RtlHarness h(opt.vcd);
  reset_core(h);
  return drive_arc(h, plan).records;
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
