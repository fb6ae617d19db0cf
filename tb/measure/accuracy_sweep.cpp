// SPDX-License-Identifier: Apache-2.0
// Accuracy sweep: the largest and mean distance of the path points from the ideal
// ellipse over a fixed-seed set of arcs, per mode, split by aspect ratio. Prints a
// Markdown table (scripts/accuracy-sweep.sh writes it into docs/results.md).
//   usage: accuracy_sweep [--arcs N] [--seed S] [--max-axis M]
// Arcs: a, b log-uniform in [1, M] with aspect ratio at most 1000, random centre, start
// and end at random parametric angles, both directions, at the default width (smallest
// valid + 4); half of the ellipses are turned by a uniform angle in [0, 360) degrees
// (micro-degree resolution), the other half are axis-aligned. Every arc runs with both
// preloads. Rows: the paper's zero preload and half preload (the default mode) on the
// axis-aligned half, and both preloads on the rotated half.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "dda/golden.hpp"
#include "dda_random.hpp"

using namespace dda;

namespace {

struct Acc {
  double worst = 0, sum = 0;
  long points = 0, arcs = 0;
  std::string worst_arc;
  void add(double d) {
    sum += d;
    ++points;
  }
};

// Largest and summed distance of an arc's points (start included) from its ellipse.
void measure(const Plan& plan, double& worst, double& sum, long& points) {
  const auto dev = [&](Point p) { return plan_distance(plan, double(p.x), double(p.y)); };
  worst = dev(plan.from);
  sum = worst;
  points = 1;
  for (const Piece& sg : plan.pieces) {
    Datapath dp(sg.cmd, sg.from);
    Point last = sg.from;
    while (!dp.done()) {
      dp.step();
      if (dp.pos() != last) {
        last = dp.pos();
        const double d = dev(last);
        worst = std::max(worst, d);
        sum += d;
        ++points;
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  long arcs = 2000;
  std::uint64_t seed = 2026;
  std::int64_t max_axis = 32768;
  for (int i = 1; i + 1 < argc; i += 2) {
    char* end = nullptr;
    if (!std::strcmp(argv[i], "--arcs"))
      arcs = std::strtol(argv[i + 1], &end, 10);
    else if (!std::strcmp(argv[i], "--seed"))
      seed = std::strtoull(argv[i + 1], &end, 0);
    else if (!std::strcmp(argv[i], "--max-axis"))
      max_axis = std::strtoll(argv[i + 1], &end, 10);
    if (!end || *end != '\0') {
      std::fprintf(stderr, "usage: accuracy_sweep [--arcs N] [--seed S] [--max-axis M]\n");
      return 2;
    }
  }
  std::mt19937_64 rng(seed);
  const auto unit = [&] { return double(rng() % (1u << 30)) / double(1u << 30); };
  // [row][aspect class]; rows: zero, half (axis-aligned), rotated zero, rotated half,
  // rotated half without the smallest ellipses (max(a, b) < 16).
  Acc acc[5][2];
  long drawn = 0, rejected = 0;
  while (drawn - rejected < arcs) {
    ArcSpec s;
    s.a = std::max<std::int64_t>(1, std::llround(std::exp(unit() * std::log(double(max_axis)))));
    s.b = std::max<std::int64_t>(1, std::llround(std::exp(unit() * std::log(double(max_axis)))));
    const double aspect = double(std::max(s.a, s.b)) / double(std::min(s.a, s.b));
    const std::int64_t t0 = std::int64_t(rng() % std::uint64_t(kFullTurn));
    const std::int64_t t1 = std::int64_t(rng() % std::uint64_t(kFullTurn));
    const bool cw = rng() % 2;
    const Point c{std::int64_t(rng() % 2001) - 1000, std::int64_t(rng() % 2001) - 1000};
    const bool turned = rng() % 2;
    const std::int64_t angle = std::int64_t(rng() % std::uint64_t(kFullTurn));
    if (aspect > 1000) continue;
    ++drawn;
    Plan plans[2];
    bool ok = true;
    for (int m = 0; m < 2 && ok; ++m) {
      ArcSpec sm = s;
      sm.preload = m == 0 ? Preload::Zero : Preload::Half;
      sm.dir = cw ? Direction::Cw : Direction::Ccw;
      sm.center = c;
      sm.angle = turned ? angle : 0;
      sm.from_theta = t0;
      sm.to_theta = t1;
      try {
        plans[m] = plan_arc(sm);
      } catch (const InputError& e) {
        ok = false;  // e.g. an unreachable end point: the same arc is skipped in both modes
        if (std::getenv("DDA_SWEEP_VERBOSE"))
          std::fprintf(stderr, "refused (%s, %s): %s\n", to_string(sm.preload), turned ? "turned" : "axis-aligned",
                       e.what());
      }
    }
    if (!ok) {
      ++rejected;
      continue;
    }
    const int k = aspect <= 4 ? 0 : 1;
    for (int m = 0; m < 2; ++m) {
      double worst = 0, sum = 0;
      long pts = 0;
      measure(plans[m], worst, sum, pts);
      const int row = (plans[m].rotated ? 2 : 0) + m;
      for (const int r : {row, row == 3 && std::max(s.a, s.b) >= 16 ? 4 : -1}) {
        if (r < 0) continue;
        Acc& a = acc[r][k];
        ++a.arcs;
        a.sum += sum;
        a.points += pts;
        if (worst > a.worst) {
          a.worst = worst;
          a.worst_arc = describe(plans[m]);
        }
      }
    }
  }
  ArcSpec paper;
  paper.a = 10;
  paper.b = 6;
  paper.bits = 4;
  double pw = 0, ps = 0;
  long pp = 0;
  measure(plan_arc(paper), pw, ps, pp);

  std::printf(
      "Sweep: %ld arcs (seed %llu; a, b log-uniform in [1, %lld], aspect ratio <= 1000, random "
      "centre, start and end angles, both directions, half of them turned by a uniform angle, "
      "default width = smallest valid + 4; %ld of %ld drawn arcs were refused by the planner "
      "and skipped).\n\n",
      arcs, (unsigned long long)seed, (long long)max_axis, rejected, drawn);
  std::printf("| mode | aspect ratio | arcs | worst distance (steps) | mean distance (steps) | worst arc |\n");
  std::printf("|---|---|---|---|---|---|\n");
  const char* names[5] = {"zero preload (the paper), axis-aligned", "half preload (default mode), axis-aligned",
                          "rotated, zero preload", "rotated, half preload", "rotated, half preload, max(a, b) >= 16"};
  for (int m = 0; m < 5; ++m) {
    for (int k = 0; k < 2; ++k) {
      const Acc& a = acc[m][k];
      std::printf("| %s | %s | %ld | %.3f | %.3f | `%s` |\n", names[m], k == 0 ? "<= 4" : "4 to 1000", a.arcs, a.worst,
                  a.points ? a.sum / double(a.points) : 0.0, a.worst_arc.c_str());
    }
  }
  std::printf(
      "| the paper's example (a = 10, b = 6, n = 4, zero preload) | 1.67 | 1 | %.3f | %.3f | "
      "`--a 10 --b 6 --bits 4` |\n",
      pw, ps / double(pp));
  return 0;
}
