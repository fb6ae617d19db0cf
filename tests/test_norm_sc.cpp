// SPDX-License-Identifier: Apache-2.0
// The norm unit's SystemC model (model/systemc/dda_norm.hpp) and its RTL
// (rtl/dda_norm.v, Verilator) on the same inputs, every register compared after every
// edge, named with the cycle where they differ; both against the reference's d.
#define CATCH_CONFIG_RUNNER
// The verilated model first: verilated.h takes SystemC's time if <systemc> came before it.
#include "Vdda_norm.h"
#include "Vdda_norm___024root.h"
// (then SystemC)
#include <systemc>

#include <catch2/catch.hpp>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "model/datapath/hw_params.hpp"
#include "model/motion/pacer.hpp"
#include "model/systemc/dda_norm.hpp"

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
int sc_main(int argc, char* argv[]) { return main(argc, argv); }

using namespace dda;

TEST_CASE("norm unit: SystemC model and RTL equal in every register on every edge", "[pacer][rtl][systemc]") {
  sc_core::sc_signal<bool> clk{"clk"}, rst_n{"rst_n"}, start{"start"}, busy{"busy"};
  sc_core::sc_signal<std::uint64_t> vx{"vx"}, vy{"vy"}, vz{"vz"}, cap{"cap"}, cap_z{"cap_z"}, d{"d"};
  sc::dda_norm m("norm", hw::kAccWidth, motion::kNormFrac);
  m.clk_i(clk);
  m.rst_ni(rst_n);
  m.start_i(start);
  m.v_x_i(vx);
  m.v_y_i(vy);
  m.v_z_i(vz);
  m.cap_i(cap);
  m.cap_z_i(cap_z);
  m.busy_o(busy);
  m.d_o(d);
  auto rtl = std::make_unique<Vdda_norm>();
  Vdda_norm___024root& r = *rtl->rootp;
  struct Reg {
    const char* name;
    std::function<std::uint64_t()> rtl, sc;
  };
  const std::vector<Reg> regs = {
      {"cyc_q", [&] { return std::uint64_t(r.dda_norm__DOT__cyc_q); }, [&] { return std::uint64_t(m.cyc_q.read()); }},
      {"r_q", [&] { return std::uint64_t(r.dda_norm__DOT__r_q); }, [&] { return m.r_q.read(); }},
      {"c_q", [&] { return std::uint64_t(r.dda_norm__DOT__c_q); }, [&] { return m.c_q.read(); }},
      {"q_q", [&] { return std::uint64_t(r.dda_norm__DOT__q_q); }, [&] { return m.q_q.read(); }},
      {"sq_q", [&] { return std::uint64_t(r.dda_norm__DOT__sq_q); }, [&] { return m.sq_q.read(); }},
      {"mc_q", [&] { return std::uint64_t(r.dda_norm__DOT__mc_q); }, [&] { return m.mc_q.read(); }},
      {"a_q", [&] { return std::uint64_t(r.dda_norm__DOT__a_q); }, [&] { return m.a_q.read(); }},
      {"s_q", [&] { return std::uint64_t(r.dda_norm__DOT__s_q); }, [&] { return m.s_q.read(); }},
      {"rem_q", [&] { return std::uint64_t(r.dda_norm__DOT__rem_q); }, [&] { return m.rem_q.read(); }},
      {"root_q", [&] { return std::uint64_t(r.dda_norm__DOT__root_q); }, [&] { return m.root_q.read(); }},
      {"d_q", [&] { return std::uint64_t(r.dda_norm__DOT__d_q); }, [&] { return m.d_q.read(); }},
  };
  sc_core::sc_start(sc_core::SC_ZERO_TIME);
  std::uint64_t cycle = 0;
  bool started = false;  // registers without reset are compared once a run has set them
  const auto edge = [&](bool rst, bool st, std::uint64_t x, std::uint64_t y, std::uint64_t z, std::uint64_t c,
                        std::uint64_t cz) {
    rst_n.write(rst);
    start.write(st);
    vx.write(x);
    vy.write(y);
    vz.write(z);
    cap.write(c);
    cap_z.write(cz);
    rtl->rst_ni = rst;
    rtl->start_i = st;
    rtl->v_x_i = x;
    rtl->v_y_i = y;
    rtl->v_z_i = z;
    rtl->cap_i = c;
    rtl->cap_z_i = cz;
    rtl->clk_i = 0;
    rtl->eval();
    clk.write(false);
    sc_core::sc_start(1, sc_core::SC_NS);
    REQUIRE(bool(rtl->busy_o) == busy.read());
    rtl->clk_i = 1;
    rtl->eval();
    clk.write(true);
    sc_core::sc_start(1, sc_core::SC_NS);
    ++cycle;
    for (const auto& g : regs) {
      if (!started && std::string(g.name) != "cyc_q" && std::string(g.name) != "d_q") continue;
      INFO("cycle " << cycle << ", register " << g.name);
      REQUIRE(g.rtl() == g.sc());
    }
    REQUIRE(std::uint64_t(rtl->d_o) == d.read());
  };
  edge(false, false, 0, 0, 0, 1, 1);
  std::mt19937_64 rng(23);
  const std::uint64_t max_cap = (std::uint64_t{1} << hw::kAccWidth) - 1;
  for (int run = 0; run < 300; ++run) {
    const std::uint64_t c = std::max<std::uint64_t>(1, rng() & (max_cap >> (rng() % std::uint64_t(hw::kAccWidth))));
    const std::uint64_t cz = std::max<std::uint64_t>(1, rng() & max_cap);
    const std::uint64_t x = run % 7 == 0 ? c : rng() % (c + 1), y = run % 5 == 0 ? 0 : rng() % (c + 1);
    const std::uint64_t z = run % 3 == 0 ? 0 : rng() % (cz + 1);
    // A start while busy now and then: the unit starts again.
    const int len = run % 11 == 0 ? 20 : motion::kNormLatency;
    edge(true, true, 0, 0, 0, 1, 1);
    for (int k = 0; k < len; ++k) edge(true, false, x, y, z, c, cz);
    if (len == motion::kNormLatency) {
      started = true;
      Command cmd;
      cmd.cap = std::int64_t(c);
      cmd.cap_z = std::int64_t(cz);
      cmd.jv_z = std::int64_t(z);
      RegState rs;
      rs.jv_x = std::int64_t(x);
      rs.jv_y = std::int64_t(y);
      rs.cnt_x = rs.cnt_y = rs.cnt_z = 1;
      REQUIRE(d.read() == motion::iteration_distance(cmd, rs));
    }
  }
  CHECK(cycle > 15000);
}
