// SPDX-License-Identifier: Apache-2.0
#include "bench/bench_main.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace dda {

int bench_main(CoreHarness* h, int argc, char** argv) {
  std::int64_t radius = 20000;
  int reps = 5;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--radius"))
      radius = std::atoll(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--reps"))
      reps = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr, "usage: %s [--radius R] [--reps N]\n", argv[0]);
      return 2;
    }
  }
  ArcSpec s;
  s.a = s.b = radius;
  s.preload = Preload::Half;
  s.from_theta = s.to_theta = 0;  // one full turn
  const Plan plan = plan_arc(s);
  for (int k = 1; k <= reps; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    std::uint64_t n = 0;
    if (!h) {
      // The datapath's bare rate: every iteration through next_state() (Datapath::step),
      // no record, no guard, none skipped (run() without a record skips the iterations
      // without a step: not what this measures).
      for (const Piece& pc : plan.pieces) {
        Datapath dp(pc.cmd, pc.from);
        while (!dp.done()) dp.step();
        n += dp.iterations();
      }
    } else {
      h->disable_checking();  // the engine alone: no reference model beside it
      reset_core(*h);
      DriveOptions o;
      o.check = false;
      o.keep_records = false;
      n = drive_arc(*h, plan, o).cycles;
    }
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("rep %d: %llu %s in %.6f s\n", k, static_cast<unsigned long long>(n), h ? "cycles" : "iterations", sec);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace dda
