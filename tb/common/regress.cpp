#include "regress.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "dda_random.hpp"

namespace dda {

MixedStats run_mixed(CoreHarness& h, std::uint64_t seed, long arcs) {
  RandomArcs gen(seed, 4096);
  std::mt19937_64 rng(seed ^ 0x5eedULL);
  reset_core(h);
  MixedStats st;
  while (st.arcs < arcs) {
    const auto plan = gen.next();
    if (!plan) continue;
    DriveOptions opt;
    opt.keep_records = false;
    const unsigned kind = unsigned(rng() % 8);
    if (kind == 0) {  // random ce_i stalls
      opt.ce = [&](std::uint64_t) { return rng() % 4 != 0; };
      ++st.ce_stalled;
    } else if (kind == 1 && plan->cmd.cnt_x + plan->cmd.cnt_y > 4) {  // reset halfway
      opt.reset_after = 1 + rng() % 8;
      ++st.reset_halfway;
    }
    try {
      const DriveResult r = drive_arc(h, *plan, opt);
      st.iterations += r.iterations;
      st.cycles += r.cycles;
    } catch (const GuardError& e) {
      const std::string where = "arc " + std::to_string(st.arcs) + " (dda trace " + describe(*plan) +
                                " --engine " + h.name() + "): " + e.what();
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
    if (i + 1 < argc && !std::strcmp(argv[i], "--arcs")) {
      arcs = std::atol(argv[i + 1]);
    } else if (i + 1 < argc && !std::strcmp(argv[i], "--seed")) {
      seed = std::strtoull(argv[i + 1], nullptr, 0);
    } else {
      std::fprintf(stderr, "usage: %s [--arcs N] [--seed S]\n", argv[0]);
      return 2;
    }
  }
  try {
    const MixedStats st = run_mixed(h, seed, arcs);
    std::printf("%s regression: seed %llu: %ld arcs (%llu with ce stalls, %llu reset halfway), "
                "%llu iterations and %llu cycles compared, 0 mismatches\n",
                h.name(), static_cast<unsigned long long>(seed), st.arcs,
                static_cast<unsigned long long>(st.ce_stalled),
                static_cast<unsigned long long>(st.reset_halfway),
                static_cast<unsigned long long>(st.iterations), static_cast<unsigned long long>(st.cycles));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s regression: FAIL (seed %llu): %s\n", h.name(),
                 static_cast<unsigned long long>(seed), e.what());
    return 1;
  }
  return 0;
}

}  // namespace dda
