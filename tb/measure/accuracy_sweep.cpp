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

#include "host/accuracy/golden.hpp"
#include "tb/random/dda_random.hpp"

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

struct Options {
  long arcs = 2000;
  std::uint64_t seed = 2026;
  std::int64_t max_axis = 32768;
};

// Reads the options; false (after the usage line) on a bad one.
bool parse_options(int argc, char** argv, Options& o) {
  for (int i = 1; i + 1 < argc; i += 2) {
    char* end = nullptr;
    if (!std::strcmp(argv[i], "--arcs"))
      o.arcs = std::strtol(argv[i + 1], &end, 10);
    else if (!std::strcmp(argv[i], "--seed"))
      o.seed = std::strtoull(argv[i + 1], &end, 0);
    else if (!std::strcmp(argv[i], "--max-axis"))
      o.max_axis = std::strtoll(argv[i + 1], &end, 10);
    if (!end || *end != '\0') {
      std::fprintf(stderr, "usage: accuracy_sweep [--arcs N] [--seed S] [--max-axis M]\n");
      return false;
    }
  }
  return true;
}

// One arc as drawn, before its preload is chosen.
struct DrawnArc {
  ArcSpec s;  // the semi-axes
  double aspect = 1;
  std::int64_t t0 = 0, t1 = 0, angle = 0;
  bool cw = false, turned = false;
  Point c;
};

// Draws an arc (every draw in the same order whether or not it is kept).
DrawnArc draw_arc(std::mt19937_64& rng, std::int64_t max_axis) {
  const auto unit = [&] { return double(rng() % (1u << 30)) / double(1u << 30); };
  DrawnArc d;
  d.s.a = std::max<std::int64_t>(1, std::llround(std::exp(unit() * std::log(double(max_axis)))));
  d.s.b = std::max<std::int64_t>(1, std::llround(std::exp(unit() * std::log(double(max_axis)))));
  d.aspect = double(std::max(d.s.a, d.s.b)) / double(std::min(d.s.a, d.s.b));
  d.t0 = std::int64_t(rng() % std::uint64_t(kFullTurn));
  d.t1 = std::int64_t(rng() % std::uint64_t(kFullTurn));
  d.cw = rng() % 2;
  d.c = Point{std::int64_t(rng() % 2001) - 1000, std::int64_t(rng() % 2001) - 1000};
  d.turned = rng() % 2;
  d.angle = std::int64_t(rng() % std::uint64_t(kFullTurn));
  return d;
}

// Plans the arc with zero (plans[0]) and half (plans[1]) preload; false if the planner
// refuses either (e.g. an unreachable end point: the same arc is skipped in both modes).
bool plan_both(const DrawnArc& d, Plan (&plans)[2]) {
  for (int m = 0; m < 2; ++m) {
    ArcSpec sm = d.s;
    sm.preload = m == 0 ? Preload::Zero : Preload::Half;
    sm.dir = d.cw ? Direction::Cw : Direction::Ccw;
    sm.center = d.c;
    sm.angle = d.turned ? d.angle : 0;
    sm.from_theta = d.t0;
    sm.to_theta = d.t1;
    try {
      plans[m] = plan_arc(sm);
    } catch (const InputError& e) {
      if (std::getenv("DDA_SWEEP_VERBOSE"))
        std::fprintf(stderr, "refused (%s, %s): %s\n", to_string(sm.preload), d.turned ? "turned" : "axis-aligned",
                     e.what());
      return false;
    }
  }
  return true;
}

// [row][aspect class]; rows: zero, half (axis-aligned), rotated zero, rotated half,
// rotated half without the smallest ellipses (max(a, b) < 16).
struct Sweep {
  Acc acc[5][2];
  long drawn = 0, rejected = 0;
};

// Adds both plans of an arc to their rows.
void add_arc(Sweep& sw, const DrawnArc& d, const Plan (&plans)[2]) {
  const int k = d.aspect <= 4 ? 0 : 1;
  for (int m = 0; m < 2; ++m) {
    double worst = 0, sum = 0;
    long pts = 0;
    measure(plans[m], worst, sum, pts);
    const int row = (plans[m].arc().rotated ? 2 : 0) + m;
    for (const int r : {row, row == 3 && std::max(d.s.a, d.s.b) >= 16 ? 4 : -1}) {
      if (r < 0) continue;
      Acc& a = sw.acc[r][k];
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

Sweep run_sweep(const Options& o) {
  std::mt19937_64 rng(o.seed);
  Sweep sw;
  while (sw.drawn - sw.rejected < o.arcs) {
    const DrawnArc d = draw_arc(rng, o.max_axis);
    if (d.aspect > 1000) continue;
    ++sw.drawn;
    Plan plans[2];
    if (!plan_both(d, plans)) {
      ++sw.rejected;
      continue;
    }
    add_arc(sw, d, plans);
  }
  return sw;
}

void print_table(const Options& o, const Sweep& sw) {
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
      o.arcs, (unsigned long long)o.seed, (long long)o.max_axis, sw.rejected, sw.drawn);
  std::printf("| mode | aspect ratio | arcs | worst distance (steps) | mean distance (steps) | worst arc |\n");
  std::printf("|---|---|---|---|---|---|\n");
  const char* names[5] = {"zero preload (the paper), axis-aligned", "half preload (default mode), axis-aligned",
                          "rotated, zero preload", "rotated, half preload", "rotated, half preload, max(a, b) >= 16"};
  for (int m = 0; m < 5; ++m) {
    for (int k = 0; k < 2; ++k) {
      const Acc& a = sw.acc[m][k];
      std::printf("| %s | %s | %ld | %.3f | %.3f | `%s` |\n", names[m], k == 0 ? "<= 4" : "4 to 1000", a.arcs, a.worst,
                  a.points ? a.sum / double(a.points) : 0.0, a.worst_arc.c_str());
    }
  }
  std::printf(
      "| the paper's example (a = 10, b = 6, n = 4, zero preload) | 1.67 | 1 | %.3f | %.3f | "
      "`--a 10 --b 6 --bits 4 --preload zero` |\n",
      pw, ps / double(pp));
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse_options(argc, argv, o)) return 2;
  print_table(o, run_sweep(o));
  return 0;
}
