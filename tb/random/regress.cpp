// SPDX-License-Identifier: Apache-2.0
#include "regress.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "dda/hw_params.hpp"
#include "dda_random.hpp"

namespace dda {

int MixedStats::pairs_covered() const {
  int n = 0;
  for (const auto& s : quadrant_pairs) {
    for (const auto& e : s) n += (e[0] > 0) + (e[1] > 0);
  }
  return n;
}

MixedStats run_mixed(CoreHarness& h, std::uint64_t seed, long arcs) {
  RandomArcs quarter(seed, 4096), whole(seed + 1, 4096, 8, ArcKind::Whole);
  std::mt19937_64 rng(seed ^ 0x5eedULL);
  reset_core(h);
  MixedStats st;
  while (st.arcs < arcs) {
    const auto plan = (st.arcs % 2 ? whole : quarter).next();
    if (!plan) continue;
    DriveOptions opt;
    opt.keep_records = false;
    const unsigned kind = unsigned(rng() % 8);
    if (kind == 0 || (kind == 1 && rng() % 2)) {  // random ce_i stalls
      opt.ce = [&](std::uint64_t) { return rng() % 4 != 0; };
      ++st.ce_stalled;
    }
    if (kind == 1) {  // a reset on any edge the arc runs through (with ce high)
      const std::uint64_t span = run(*plan).iterations + 2 * plan->pieces.size() + 1;
      opt.reset_at_cycle = 1 + rng() % span;
    }
    try {
      const DriveResult r = drive_arc(h, *plan, opt);
      st.iterations += r.iterations;
      st.cycles += r.cycles;
      st.pieces += plan->pieces.size();
      if (!r.was_reset) {
        const Plan& p = *plan;
        ++st.quadrant_pairs[p.pieces.front().quadrant - 1][p.pieces.back().quadrant - 1][p.spec.dir == Direction::Cw];
        st.full += p.full;
        st.circles += p.spec.a == p.spec.b;
        st.turned += quarter_turns(p.spec) == 1 || quarter_turns(p.spec) == 3;
        st.rotated += p.rotated;
        st.thin += std::max(p.spec.a, p.spec.b) > 100 * std::min(p.spec.a, p.spec.b);
      }
      if (r.was_reset) {
        ++st.resets;
        // Idle, no pulse, ready for the next command.
        h.set_ce(true);
        h.tick();
        const Signals s = h.sample();
        if (CoreModel::busy(s) || CoreModel::step_of(s) != Point{} || CoreModel::iterated(s) || CoreModel::done(s) ||
            !h.cmd_ready()) {
          throw MismatchError(std::string(h.name()) + " not idle after a reset");
        }
      }
    } catch (const GuardError& e) {
      const std::string where = "arc " + std::to_string(st.arcs) + " (" + describe(*plan) + "): " + e.what();
      if (dynamic_cast<const MismatchError*>(&e)) throw MismatchError(where);
      throw GuardError(where);
    }
    ++st.arcs;
  }
  return st;
}

int regress_main(CoreHarness& h, int argc, char* argv[]) {
  long arcs = 2000;
  std::uint64_t seed = 1;
  for (int i = 1; i < argc; i += 2) {
    char* end = nullptr;
    if (i + 1 < argc && !std::strcmp(argv[i], "--arcs")) {
      arcs = std::strtol(argv[i + 1], &end, 10);
      if (*end != '\0' || arcs < 1) {
        std::fprintf(stderr, "%s: --arcs '%s' is invalid: a positive integer\n", argv[0], argv[i + 1]);
        return 2;
      }
    } else if (i + 1 < argc && !std::strcmp(argv[i], "--seed")) {
      seed = std::strtoull(argv[i + 1], &end, 0);
      if (*end != '\0' || argv[i + 1][0] == '-' || argv[i + 1][0] == '\0') {
        std::fprintf(stderr, "%s: --seed '%s' is invalid: a non-negative integer\n", argv[0], argv[i + 1]);
        return 2;
      }
    } else {
      std::fprintf(stderr, "usage: %s [--arcs N] [--seed S]\n", argv[0]);
      return 2;
    }
  }
  try {
    const MixedStats st = run_mixed(h, seed, arcs);
    std::printf(
        "%s regression: seed %llu: %ld arcs in %llu pieces (%llu with ce stalls, %llu reset "
        "mid-arc), %llu iterations and %llu cycles compared, 0 mismatches\n",
        h.name(), static_cast<unsigned long long>(seed), st.arcs, static_cast<unsigned long long>(st.pieces),
        static_cast<unsigned long long>(st.ce_stalled), static_cast<unsigned long long>(st.resets),
        static_cast<unsigned long long>(st.iterations), static_cast<unsigned long long>(st.cycles));
    std::printf(
        "coverage: %d of 32 (start quadrant, end quadrant, direction) combinations, %ld full "
        "ellipses, %ld circles, %ld turned by 90 or 270 degrees, %ld rotated by other angles, %ld "
        "with aspect ratio > 100\n",
        st.pairs_covered(), st.full, st.circles, st.turned, st.rotated, st.thin);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s regression: FAIL (rerun: %s --seed %llu --arcs %ld): %s\n", h.name(), argv[0],
                 static_cast<unsigned long long>(seed), arcs, e.what());
    return 1;
  }
  return 0;
}

}  // namespace dda
