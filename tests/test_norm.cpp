// SPDX-License-Identifier: Apache-2.0
// The pacer's norm unit in RTL (rtl/dda_norm.v) against its reference
// (motion::iteration_distance): the same d, bit for bit, exactly kNormLatency edges after
// the edge that starts it (its operands changed after kNormOperandEdges), on random
// integrands and capacities of every size, the extremes (an integrand equal to its
// capacity, 0, inactive axes) and the iterations of planned arcs; a start while busy
// starts again.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <memory>
#include <random>

#include "Vdda_norm.h"
#include "host/accuracy/golden.hpp"
#include "model/motion/pacer.hpp"

using namespace dda;
using namespace dda::motion;

namespace {

class Norm {
 public:
  Norm() : top_(std::make_unique<Vdda_norm>()) {
    top_->rst_ni = 0;
    edge();
    top_->rst_ni = 1;
  }
  void edge() {
    top_->clk_i = 0;
    top_->eval();
    top_->clk_i = 1;
    top_->eval();
  }
  // The operands as the block gives them: an inactive axis' integrand as 0.
  void operands(const Command& c, const RegState& r) {
    const NormOperands o = norm_operands(c, r);
    top_->v_x_i = o.v_x;
    top_->v_y_i = o.v_y;
    top_->v_z_i = o.v_z;
    top_->cap_i = o.cap;
    top_->cap_z_i = o.cap_z;
  }
  // Starts on one edge with other operands (the command loads on it), then holds these
  // through edge kNormOperandEdges and changes them after (the unit has read them); returns
  // d after kNormLatency edges, checking busy_o and that d_o held until then.
  std::uint64_t run(const Command& c, const RegState& r) {
    const std::uint64_t before = top_->d_o;
    top_->start_i = 1;
    top_->v_x_i = top_->v_y_i = top_->v_z_i = 12345;  // not the operands: the start edge does not read them
    edge();
    top_->start_i = 0;
    operands(c, r);
    for (int i = 1; i < kNormLatency; ++i) {
      if (i == kNormOperandEdges + 1) {
        top_->v_x_i = top_->v_y_i = top_->v_z_i = 0;
        top_->cap_i = top_->cap_z_i = 7;
      }
      edge();
      CHECK(top_->busy_o);
      CHECK(top_->d_o == before);
    }
    edge();
    CHECK_FALSE(top_->busy_o);
    return top_->d_o;
  }
  Vdda_norm& top() { return *top_; }

 private:
  std::unique_ptr<Vdda_norm> top_;
};

}  // namespace

TEST_CASE("norm unit: the RTL's d equals the reference on random and extreme operands", "[pacer][rtl]") {
  Norm n;
  std::mt19937_64 rng(17);
  const std::int64_t max_cap = (std::int64_t{1} << hw::kAccWidth) - 1;
  for (int i = 0; i < 2000; ++i) {
    Command c;
    const int bits = 1 + int(rng() % std::uint64_t(hw::kAccWidth));
    c.cap = std::max<std::int64_t>(1, std::int64_t(rng() & std::uint64_t(max_cap >> (hw::kAccWidth - bits))));
    c.cap_z = std::max<std::int64_t>(1, std::int64_t(rng() & std::uint64_t(max_cap)));
    RegState r;
    const auto pick = [&](std::int64_t cap) {
      switch (rng() % 5) {
        case 0:
          return std::int64_t{0};
        case 1:
          return cap;
        case 2:
          return -std::int64_t(rng() % 1000);
        default:
          return std::int64_t(rng() % std::uint64_t(cap + 1));
      }
    };
    r.jv_x = pick(c.cap);
    r.jv_y = pick(c.cap);
    c.jv_z = std::max<std::int64_t>(0, pick(c.cap_z));
    r.cnt_x = std::int64_t(rng() % 3);
    r.cnt_y = std::int64_t(rng() % 3);
    r.cnt_z = std::int64_t(rng() % 3);
    INFO("cap " << c.cap << " jv " << r.jv_x << ", " << r.jv_y << ", " << c.jv_z << " cap_z " << c.cap_z);
    REQUIRE(n.run(c, r) == iteration_distance(c, r));
  }
}

TEST_CASE("norm unit: along planned arcs, every stepping iteration's d as the reference", "[pacer][rtl]") {
  Norm n;
  ArcSpec s;
  s.a = 3000;
  s.b = 700;
  s.angle = 25000000;
  s.preload = Preload::Half;
  s.from_theta = 10000000;
  s.to_theta = 200000000;
  const Plan p = plan_arc(s);
  int checked = 0;
  for (const auto& piece : p.pieces) {
    Datapath d(piece.cmd, Point{});
    for (int k = 0; !d.done() && k < 4000; ++k) {
      if (k % 7 == 0) {
        REQUIRE(n.run(piece.cmd, d.regs()) == iteration_distance(piece.cmd, d.regs()));
        ++checked;
      }
      d.iterate();
    }
  }
  CHECK(checked > 500);
}

TEST_CASE("norm unit: a start while busy starts again", "[pacer][rtl]") {
  Norm n;
  Command c;
  c.cap = 1000;
  RegState r;
  r.jv_x = 1000;
  r.jv_y = 0;
  r.cnt_x = r.cnt_y = 1;
  n.operands(c, r);
  n.top().start_i = 1;
  n.edge();
  n.top().start_i = 0;
  for (int i = 0; i < 30; ++i) n.edge();
  CHECK(n.run(c, r) == iteration_distance(c, r));       // kNormLatency edges from the second start
  CHECK(n.top().d_o == std::uint64_t{1} << kNormFrac);  // one step per iteration
}
