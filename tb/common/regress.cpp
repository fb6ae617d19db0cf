#include "regress.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "dda_random.hpp"

namespace dda {

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
  RandomArcs gen(seed, 4096);
  std::mt19937_64 rng(seed ^ 0x5eedULL);
  reset_core(h);
  std::uint64_t iters = 0, cycles = 0, stalled = 0, resets = 0;
  long done = 0;
  std::string current;
  try {
    while (done < arcs) {
      const auto plan = gen.next();
      if (!plan) continue;
      current = describe(*plan);
      DriveOptions opt;
      opt.keep_records = false;
      const unsigned kind = unsigned(rng() % 8);
      if (kind == 0) {  // random ce_i stalls
        opt.ce = [&](std::uint64_t) { return rng() % 4 != 0; };
        ++stalled;
      } else if (kind == 1 && plan->cmd.cnt_x + plan->cmd.cnt_y > 4) {  // reset halfway
        opt.reset_after = 1 + rng() % 8;
        ++resets;
      }
      const DriveResult r = drive_arc(h, *plan, opt);
      iters += r.iterations;
      cycles += r.cycles;
      ++done;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s regression: FAIL (seed %llu, arc %ld: dda trace %s --engine %s): %s\n",
                 h.name(), static_cast<unsigned long long>(seed), done, current.c_str(), h.name(), e.what());
    return 1;
  }
  std::printf("%s regression: seed %llu: %ld arcs (%llu with ce stalls, %llu reset halfway), "
              "%llu iterations and %llu cycles compared, 0 mismatches\n",
              h.name(), static_cast<unsigned long long>(seed), done, static_cast<unsigned long long>(stalled),
              static_cast<unsigned long long>(resets), static_cast<unsigned long long>(iters),
              static_cast<unsigned long long>(cycles));
  return 0;
}

}  // namespace dda
