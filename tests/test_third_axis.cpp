// SPDX-License-Identifier: Apache-2.0
// The third, linear, axis on the golden model: 3-D lines, moves of the third axis alone
// and helices, each axis against its ideal progress along the iterations.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <random>

#include "host/accuracy/golden.hpp"
#include "model/datapath/hw_command.hpp"
#include "tb/random/dda_random.hpp"

using namespace dda;

namespace {

// Largest distance (steps) of an axis from its ideal linear progress d * i / n over a
// run's iterations i = 1..n, the axis read by `coord`.
template <typename Coord>
double worst_lag(const std::vector<Iteration>& recs, std::int64_t from, std::int64_t d, Coord coord) {
  const double n = double(recs.size());
  double worst = 0;
  for (std::size_t i = 0; i < recs.size(); ++i) {
    const double ideal = double(from) + double(d) * double(i + 1) / n;
    worst = std::max(worst, std::abs(double(coord(recs[i].pos)) - ideal));
  }
  return worst;
}

}  // namespace

TEST_CASE("third axis: a 3-D line keeps every axis within half a step of its ideal progress", "[golden][random]") {
  const std::uint64_t seed = test_seed(20261202);
  std::mt19937_64 rng(seed);
  const auto in = [&](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  };
  for (int k = 0; k < 200; ++k) {
    // Each axis in turn the longest; one in twenty beyond the counters (several pieces).
    const std::int64_t m = k % 20 == 0 ? in(140000, 300000) : in(1, 3000);
    const Point from{in(-500, 500), in(-500, 500), in(-500, 500)};
    Point to{from.x + in(-m, m), from.y + in(-m, m), from.z + in(-m, m)};
    if (to == from) to.z += 1;
    const Plan plan = plan_line(from, to, Preload::Half);
    const std::vector<Iteration> recs = run_records(plan);
    INFO("seed " << seed << ": " << describe(plan));
    const std::int64_t n = std::max({std::llabs(to.x - from.x), std::llabs(to.y - from.y), std::llabs(to.z - from.z)});
    REQUIRE(std::int64_t(recs.size()) == n);  // the longest axis steps on every iteration
    CHECK(recs.back().pos == to);
    CHECK(worst_lag(recs, from.x, to.x - from.x, [](Point p) { return p.x; }) <= 0.5);
    CHECK(worst_lag(recs, from.y, to.y - from.y, [](Point p) { return p.y; }) <= 0.5);
    CHECK(worst_lag(recs, from.z, to.z - from.z, [](Point p) { return p.z; }) <= 0.5);
    for (const Piece& pc : plan.pieces) REQUIRE_NOTHROW(hw::pack_command(pc.cmd));
  }
}

TEST_CASE("third axis: a move of the third axis alone steps it on every iteration and nothing else", "[golden]") {
  const Plan plan = plan_line(Point{7, -3, 10}, Point{7, -3, -200000}, Preload::Half);
  REQUIRE(plan.pieces.size() == 2);  // beyond the 17-bit counters: cut, the phase carried
  const std::vector<Iteration> recs = run_records(plan);
  REQUIRE(recs.size() == 200010);
  std::size_t z_only = 0;
  for (const Iteration& it : recs) z_only += it.step_z && !it.step_x && !it.step_y;
  CHECK(z_only == recs.size());
  CHECK(recs.back().pos == Point{7, -3, -200000});
}

TEST_CASE("third axis: a helix rises within half a step of the ideal at every iteration", "[golden][random]") {
  const std::uint64_t seed = test_seed(20261203);
  RandomArcs gen(seed, 1024, 6, ArcKind::Program);
  std::mt19937_64 rng(seed);
  int helices = 0, several_pieces = 0;
  for (int k = 0; k < 150; ++k) {
    std::optional<Plan> drawn = gen.next();
    if (!drawn || drawn->is_line()) continue;
    const std::vector<Iteration> flat = run_records(*drawn);
    const std::int64_t n = std::int64_t(flat.size());
    const std::int64_t rise = std::uniform_int_distribution<std::int64_t>(-n, n)(rng), z0 = 40 - k;
    Plan helix = *drawn;
    lift(helix, z0, z0 + rise, Preload::Half);
    INFO("seed " << seed << ": " << describe(*drawn) << " rising " << rise);
    const std::vector<Iteration> recs = run_records(helix);
    REQUIRE(recs.size() == flat.size());
    // The plane's path is the flat arc's, iteration for iteration.
    std::size_t same = 0;
    for (std::size_t i = 0; i < recs.size(); ++i)
      same += recs[i].pos.x == flat[i].pos.x && recs[i].pos.y == flat[i].pos.y;
    REQUIRE(same == recs.size());
    CHECK(recs.back().pos.z == z0 + rise);
    CHECK(worst_lag(recs, z0, rise, [](Point p) { return p.z; }) <= 0.5);
    for (const Piece& pc : helix.pieces) REQUIRE_NOTHROW(hw::pack_command(pc.cmd));
    ++helices;
    several_pieces += helix.pieces.size() > 1;
  }
  CHECK(helices > 80);
  CHECK(several_pieces > 50);  // the phase is carried from piece to piece
}

TEST_CASE("third axis: a zero-preload helix lags the ideal by less than a step", "[golden]") {
  ArcSpec s;
  s.a = s.b = 500;
  s.preload = Preload::Zero;
  s.from = Point{500, 0};
  s.to = Point{500, 0};  // a full circle
  Plan helix = plan_arc(s);
  const std::int64_t n = std::int64_t(run_records(helix).size());
  lift(helix, 0, -n / 3, Preload::Zero);
  const std::vector<Iteration> recs = run_records(helix);
  double least = 1, most = 0;  // z - ideal: behind, never ahead, by less than a step
  for (std::size_t i = 0; i < recs.size(); ++i) {
    const double lag = double(recs[i].pos.z) + double(n / 3) * double(i + 1) / double(n);
    least = std::min(least, lag), most = std::max(most, lag);
  }
  CHECK(least >= 0.0);
  CHECK(most < 1.0);
}

TEST_CASE("third axis: what the hardware and the planner refuse", "[golden]") {
  ArcSpec s;
  s.a = s.b = 100;
  s.preload = Preload::Half;
  Plan quarter = plan_arc(s);
  const std::int64_t n = std::int64_t(run_records(quarter).size());
  // Steeper than one step per iteration.
  Plan steep = quarter;
  CHECK_THROWS_WITH(lift(steep, 0, n + 1, Preload::Half), Catch::Contains("at most once per iteration"));
  Plan ok = quarter;
  CHECK_NOTHROW(lift(ok, 0, n, Preload::Half));  // a step on every iteration
  // The packer refuses a third axis that could step twice in an iteration.
  Command c = quarter.cmd();
  c.cnt_z = 3, c.cap_z = 10, c.jv_z = 11;
  CHECK_THROWS_WITH(hw::pack_command(c), Catch::Contains("jv_z <= cap_z"));
  c.jv_z = 4, c.jr_z = 10;
  CHECK_THROWS_WITH(hw::pack_command(c), Catch::Contains("jr_z < cap_z"));
  c.jr_z = 0, c.cap_z = 0;
  CHECK_THROWS_WITH(hw::pack_command(c), Catch::Contains("cap_z"));
}
