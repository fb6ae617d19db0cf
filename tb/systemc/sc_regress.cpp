// Regression: random arcs through the SystemC model in lockstep with the golden model,
// back to back in one elaboration, some with random ce_i stalls, some reset halfway.
//   usage: sc_regress [--arcs N] [--seed S]
// Prints the numbers of arcs, iterations and cycles compared; exit status 1 on the
// first mismatch, with the register, iteration, cycle and the arc's reproducer.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <systemc>

#include "core_driver.hpp"
#include "dda_random.hpp"
#include "sc_harness.hpp"

using namespace dda;

int main(int argc, char* argv[]) {
  int arcs = 2000;
  std::uint64_t seed = 1;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--arcs")) arcs = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--seed")) seed = std::strtoull(argv[i + 1], nullptr, 0);
    else { std::fprintf(stderr, "sc_regress: unknown option %s\n", argv[i]); return 2; }
  }
  RandomArcs gen(seed, 4096);
  std::mt19937_64 rng(seed ^ 0x5eed);
  sc::ScHarness h;
  reset_core(h);
  std::uint64_t iters = 0, cycles = 0, stalled = 0, resets = 0;
  int done = 0;
  std::string current;
  try {
    while (done < arcs) {
      const auto plan = gen.next();
      if (!plan) continue;
      current = describe(*plan);
      DriveOptions opt;
      opt.keep_records = false;
      const unsigned kind = unsigned(rng() % 8);
      if (kind == 0) {  // random ce stalls
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
    std::fprintf(stderr, "sc_regress: FAIL (seed %llu, arc %d: dda trace %s --engine systemc): %s\n",
                 static_cast<unsigned long long>(seed), done, current.c_str(), e.what());
    return 1;
  }
  std::printf("sc_regress: seed %llu: %d arcs (%llu with ce stalls, %llu reset halfway), "
              "%llu iterations and %llu cycles compared, 0 mismatches\n",
              static_cast<unsigned long long>(seed), done, static_cast<unsigned long long>(stalled),
              static_cast<unsigned long long>(resets), static_cast<unsigned long long>(iters),
              static_cast<unsigned long long>(cycles));
  return 0;
}

int sc_main(int argc, char* argv[]) { return main(argc, argv); }
