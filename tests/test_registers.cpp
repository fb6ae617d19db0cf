// SPDX-License-Identifier: Apache-2.0
// The register table (hw::kSignals) drives every consumer: the SystemC and Verilator
// samplers resolve its names at run time, the reference model's next-state code is
// checked against it at compile time, and the text consumers (the design doc's tables,
// the GTKWave save files, the Verilog bench's field layout) are generated from it. Each
// check below takes a table; the table as built passes all of them, and a copy with one
// register renamed, or one width changed, fails every one.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <systemc>

#include <deque>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/vectors.hpp"
#include "model/datapath/hw_params.hpp"
#include "tb/cosim/cosim_harness.hpp"

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

namespace {

using dda::hw::SignalTable;

std::string slurp(const std::string& rel) {
  std::ifstream f(std::string(DDA_SOURCE_DIR) + "/" + rel, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

struct Consumer {
  std::string name;
  std::function<bool(const SignalTable&)> follows;  // false: drifted from the table
};

std::vector<Consumer> consumers(const dda::cosim::CosimHarness& h) {
  const auto resolves = [&h](const SignalTable& t, int which) {
    try {
      if (which == 0) dda::sc::ScSampler("sc_dut", t);
      if (which == 1) h.resolve(t);
      return true;
    } catch (const dda::GuardError& e) {
      UNSCOPED_INFO(e.what());
      return false;
    }
  };
  return {
      {"SystemC model (sampler)", [=](const SignalTable& t) { return resolves(t, 0); }},
      {"SystemC model and RTL (samplers)", [=](const SignalTable& t) { return resolves(t, 1); }},
      {"reference model (next-state code)",
       [](const SignalTable& t) {
         // core_model.cpp is compiled against hw::kSignals (a static_assert checks that it
         // has next-state code for every signal): a table it was not built for drifts.
         if (t.size() != dda::hw::kNumSignals) return false;
         for (std::size_t i = 0; i < t.size(); ++i) {
           if (t[i].name != dda::hw::kSignals[i].name || t[i].width != dda::hw::kSignals[i].width) return false;
         }
         return true;
       }},
      {"docs/design.md tables",
       [](const SignalTable& t) {
         return slurp("docs/design.md").find(dda::hw::markdown_tables(t)) != std::string::npos;
       }},
      {"docs/dda_systemc.gtkw",
       [](const SignalTable& t) {
         return slurp("docs/dda_systemc.gtkw") == dda::hw::gtkw(t, "dda_systemc.gtkw", "SystemC");
       }},
      {"docs/dda_rtl.gtkw",
       [](const SignalTable& t) {
         return slurp("docs/dda_rtl.gtkw") == dda::hw::gtkw(t, "dda_rtl.gtkw", "dut.dda_core");
       }},
      {"tb/hdl/dda_vec_fields.vh",
       [](const SignalTable& t) { return slurp("tb/hdl/dda_vec_fields.vh") == dda::vec::verilog_fields(t); }},
  };
}

SignalTable changed(const std::string& name, const std::string& new_name, int width_delta) {
  SignalTable t = dda::hw::signal_table();
  static std::deque<std::string> keep;  // owners of the new names (stable addresses)
  for (auto& r : t) {
    if (r.name == name) {
      keep.push_back(new_name);
      r.name = keep.back();
      r.width += width_delta;
    }
  }
  return t;
}

}  // namespace

TEST_CASE("registers: every consumer follows the table, and a changed table fails each", "[registers]") {
  dda::cosim::CosimHarness h;
  const auto cs = consumers(h);
  for (const auto& c : cs) {
    INFO("consumer: " << c.name << " (regenerate text consumers with dda gen-params)");
    CHECK(c.follows(dda::hw::signal_table()));
  }
  const struct {
    const char* what;
    SignalTable table;
  } drifted[] = {
      {"cdir_x_q renamed", changed("cdir_x_q", "cdirx_q", 0)},
      {"u_cnt_x.cnt_q one bit wider", changed("u_cnt_x.cnt_q", "u_cnt_x.cnt_q", 1)},
  };
  for (const auto& d : drifted) {
    for (const auto& c : cs) {
      INFO("table with " << d.what << ", consumer: " << c.name);
      CHECK_FALSE(c.follows(d.table));
    }
  }
}
