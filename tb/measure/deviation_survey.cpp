// SPDX-License-Identifier: Apache-2.0
// Measures the golden model's drift: for random arcs (the property tests' distribution),
// the largest distance of a path point from the ellipse minus the start-offset term
// |r - 1| * max(a, b), binned by the larger semi-axis, per preload, next to the
// documented deviation_bound() drift term E. Prints a table; asserts nothing.
//   usage: deviation_survey [seed] [arcs]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "host/accuracy/golden.hpp"
#include "tb/random/dda_random.hpp"

using namespace dda;

int main(int argc, char** argv) {
  const std::uint64_t seed = argc > 1 ? std::strtoull(argv[1], nullptr, 0) : 1;
  const int arcs = argc > 2 ? std::atoi(argv[2]) : 20000;
  RandomArcs gen(seed, 4096);
  struct Bin {
    double worst[2] = {0, 0};
    double bound[2] = {1e9, 1e9};
    int n = 0;
  };
  std::map<int, Bin> bins;
  for (int i = 0; i < arcs;) {
    const auto plan = gen.next();
    if (!plan) continue;
    ++i;
    const ArcSpec& spec = plan->arc().spec;
    const double a = double(spec.a), b = double(spec.b);
    double worst = 0;
    run(*plan, [&](const Iteration& it) {
      if (it.step_x || it.step_y) worst = std::max(worst, plan_distance(*plan, double(it.pos.x), double(it.pos.y)));
    });
    const double offset = start_offset(*plan);
    const int k = spec.preload == Preload::Half;
    Bin& bin = bins[int(std::floor(std::log2(std::max(a, b))))];
    bin.worst[k] = std::max(bin.worst[k], worst - offset);
    bin.bound[k] = std::min(bin.bound[k], deviation_bound(*plan) - offset);
    ++bin.n;
  }
  std::printf("seed %llu, %d arcs (a, b log-uniform in [1, 4096], n = smallest..+8, random sub-arcs)\n",
              static_cast<unsigned long long>(seed), arcs);
  std::printf("| max(a,b) in | arcs | zero: worst drift | zero: E | half: worst drift | half: E |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const auto& [k, bin] : bins) {
    std::printf("| [%d, %d) | %d | %.3f | %.3f | %.3f | %.3f |\n", 1 << k, 2 << k, bin.n, bin.worst[0], bin.bound[0],
                bin.worst[1], bin.bound[1]);
  }

  // Rotated ellipses (whole-ellipse draws turned by a uniform angle): the worst drift
  // (distance minus the start offset and the coefficient bound) by bits above the
  // smallest valid width, half preload, aspect ratio <= 4 and above.
  RandomArcs whole(seed, 4096, 8, ArcKind::Whole);
  double rot[2][9] = {};
  int rot_n[2][9] = {};
  for (int i = 0; i < arcs;) {
    const auto plan = whole.next();
    if (!plan) continue;
    ++i;
    const ArcSpec& spec = plan->arc().spec;
    if (!plan->arc().rotated || spec.preload != Preload::Half || start_offset(*plan) > 1.0) continue;
    double worst = 0;
    run(*plan, [&](const Iteration& it) {
      if (it.step_x || it.step_y) worst = std::max(worst, plan_distance(*plan, double(it.pos.x), double(it.pos.y)));
    });
    const int e = spec.bits - smallest_valid_bits(spec.a, spec.b);
    const int thin = std::max(spec.a, spec.b) > 4 * std::min(spec.a, spec.b);
    rot[thin][e] = std::max(rot[thin][e], worst - start_offset(*plan) - coefficient_drift_bound(*plan));
    ++rot_n[thin][e];
  }
  std::printf("\nrotated ellipses, half preload, %d whole-ellipse draws (the property tests' distribution):\n", arcs);
  std::printf("| bits above the smallest | aspect <= 4: arcs | worst drift | aspect > 4: arcs | worst drift |\n");
  std::printf("|---|---|---|---|---|\n");
  for (int e = 0; e <= 8; ++e) {
    std::printf("| +%d | %d | %.3f | %d | %.3f |\n", e, rot_n[0][e], rot[0][e], rot_n[1][e], rot[1][e]);
  }
  return 0;
}
