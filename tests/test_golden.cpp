// SPDX-License-Identifier: Apache-2.0
// The paper's worked example (Table 1) through the golden model, row by row.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <fstream>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "host/accuracy/golden.hpp"
#include "host/report/report.hpp"

using namespace dda;

namespace {

std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  REQUIRE(f.good());
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

Plan paper_plan(Preload p = Preload::Zero) {
  ArcSpec s;
  s.a = 10;
  s.b = 6;
  s.bits = 4;
  s.preload = p;
  return plan_arc(s);
}

// A small exact fraction, independent of the model's scaled-integer arithmetic.
struct Frac {
  long long n = 0, d = 1;
  Frac(long long num = 0, long long den = 1) : n(num), d(den) { norm(); }
  void norm() {
    if (d < 0) {
      n = -n;
      d = -d;
    }
    const long long g = std::gcd(n < 0 ? -n : n, d);
    if (g > 1) {
      n /= g;
      d /= g;
    }
  }
  friend Frac operator+(Frac p, Frac q) { return Frac(p.n * q.d + q.n * p.d, p.d * q.d); }
  friend Frac operator-(Frac p, Frac q) { return Frac(p.n * q.d - q.n * p.d, p.d * q.d); }
  friend Frac operator*(Frac p, Frac q) { return Frac(p.n * q.n, p.d * q.d); }
  friend bool operator>=(Frac p, Frac q) { return p.n * q.d >= q.n * p.d; }
  friend bool operator==(Frac p, Frac q) { return p.n == q.n && p.d == q.d; }
};

}  // namespace

// The paper's Table 1, recomputed here in exact fractions as the paper describes it
// (JVX = (a/b) y, JVY = (b/a) x, capacity 2^n = 16), independently of the model's
// scaled integers, and compared with the model in every column of every iteration.
//
// The printed table in the paper is damaged at its end: it shows a row "26" with
// JRX 14.3 and an X pulse (14.3 < 16 cannot overflow: iteration 26 has no pulse) and a
// row "28" saying X stopped. Computed exactly, the last X step is at iteration 27
// (JRX 24.3) and the arc ends after 27 iterations; this test holds the exact values.
TEST_CASE("table1: every register of every iteration matches exact fractions", "[golden][table1]") {
  const Plan plan = paper_plan();
  const auto iters = run_records(plan);
  REQUIRE(iters.size() == 27);

  const Frac ab(10 * 6);
  const Frac a_over_b(10, 6), b_over_a(6, 10), cap(16);
  long long x = 10, y = 0, rem_x = 10, rem_y = 6;
  Frac jrx(0), jry(0);
  for (const auto& it : iters) {
    const Frac jvx = a_over_b * Frac(y), jvy = b_over_a * Frac(x);
    CHECK(Frac(it.jv_x) == jvx * ab);
    CHECK(Frac(it.jv_y) == jvy * ab);
    const bool ax = rem_x != 0, ay = rem_y != 0;
    CHECK(it.active_x == ax);
    CHECK(it.active_y == ay);
    const Frac sx = ax ? jrx + jvx : jrx, sy = ay ? jry + jvy : jry;
    CHECK(Frac(it.sum_x) == sx * ab);
    CHECK(Frac(it.sum_y) == sy * ab);
    const bool dx = ax && sx >= cap, dy = ay && sy >= cap;
    CHECK(it.step_x == dx);
    CHECK(it.step_y == dy);
    jrx = dx ? sx - cap : sx;
    jry = dy ? sy - cap : sy;
    rem_x -= dx;
    rem_y -= dy;
    x -= dx;
    y += dy;
    CHECK(Frac(it.after.jr_x) == jrx * ab);
    CHECK(Frac(it.after.jr_y) == jry * ab);
    CHECK(it.after.cnt_x == rem_x);
    CHECK(it.after.cnt_y == rem_y);
    CHECK(it.pos == Point{x, y});
  }
  CHECK(rem_x == 0);
  CHECK(rem_y == 0);
}

TEST_CASE("table1: CSV output is byte-identical to the spec's exact trace", "[golden][table1]") {
  const Plan plan = paper_plan();
  std::ostringstream os;
  write_trace(os, plan, run_records(plan), TraceFormat::Csv);
  CHECK(os.str() == read_file(std::string(DDA_TEST_DATA) + "/table1-exact-trace.csv"));
}

TEST_CASE("table1: rows the paper prints (the ones with a pulse)", "[golden][table1]") {
  // The paper's printed rows, by iteration number: which axes pulse.
  const std::vector<std::tuple<int, int, int>> printed = {
      {3, 0, 1},  {6, 0, 1},  {8, 0, 1},  {9, 1, 0},  {11, 0, 1}, {12, 1, 0}, {15, 1, 1}, {17, 1, 0},
      {18, 0, 1}, {19, 1, 0}, {20, 1, 0}, {22, 1, 0}, {23, 1, 0}, {25, 1, 0}, {27, 1, 0}};  // 27, not the misprinted 26
  const auto iters = run_records(paper_plan());
  std::vector<std::tuple<int, int, int>> got;
  for (const auto& it : iters) {
    if (it.step_x || it.step_y) got.emplace_back(int(it.iter), int(it.step_x), int(it.step_y));
  }
  CHECK(got == printed);
}

TEST_CASE("table1: path and statistics of the example", "[golden][table1]") {
  const Plan plan = paper_plan();
  const auto iters = run_records(plan);
  const std::vector<Point> expect = {{10, 0}, {10, 1}, {10, 2}, {10, 3}, {9, 3}, {9, 4}, {8, 4}, {7, 5},
                                     {6, 5},  {6, 6},  {5, 6},  {4, 6},  {3, 6}, {2, 6}, {1, 6}, {0, 6}};
  CHECK(path_points(plan, iters) == expect);
  const Stats s = compute_stats(plan, iters);
  CHECK(s.iterations == 27);
  CHECK(s.moves == 15);
  CHECK(s.points == 16);
  CHECK(s.pulses_x == 10);
  CHECK(s.pulses_y == 6);
  CHECK(s.max_dev_at == Point{6, 6});
  CHECK(s.max_dev == Approx(1.104).margin(0.0005));
  CHECK(ellipse_distance(10, 6, 10, 3) == Approx(1.028).margin(0.0005));
  CHECK(ellipse_distance(10, 6, 9, 4) == Approx(0.954).margin(0.0005));
}

TEST_CASE("paper units are rounded exactly, half away from zero", "[golden][format]") {
  CHECK(paper_units(100, 60) == "1.6667");
  CHECK(paper_units(-100, 60) == "-1.6667");
  CHECK(paper_units(0, 60) == "0.0000");
  CHECK(paper_units(1, 20000) == "0.0001");  // exactly 0.00005 rounds up
  CHECK(paper_units(-1, 20000) == "-0.0001");
  CHECK(paper_units(1, 20001) == "0.0000");
  CHECK(paper_units(-1, 20001) == "0.0000");  // no negative zero
  CHECK(paper_units(1460, 60) == "24.3333");
}

TEST_CASE("half preload starts both accumulators at half capacity", "[golden]") {
  const Plan plan = paper_plan(Preload::Half);
  CHECK(plan.cmd().jr_x == plan.cmd().cap / 2);
  CHECK(plan.cmd().jr_y == plan.cmd().cap / 2);
  const auto r = run(plan);
  CHECK(r.end == Point{0, 6});
  CHECK(r.iterations <= plan.iteration_bound);
}
