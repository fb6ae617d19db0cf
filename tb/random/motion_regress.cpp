// SPDX-License-Identifier: Apache-2.0
// Regression of the motion block (scripts/regress.sh motion): its SystemC model and RTL
// co-simulated every cycle under random queued work (tb/random/motion_mix.hpp), classic
// and pipelined Wishbone cycles in halves. One co-simulation per process (SystemC
// elaborates once), so the two halves run one after the other in one elaboration.
//   usage: motion_regress [--arcs N] [--seed S]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <systemc>

#include "model/datapath/errors.hpp"
#include "tb/cosim/motion_cosim.hpp"
#include "tb/random/motion_mix.hpp"

int sc_main(int argc, char* argv[]) {
  CLI::App app{"motion block regression: SystemC model and RTL co-simulated under random queued work"};
  std::uint64_t arcs = 1000, seed = 1;
  app.add_option("--arcs", arcs, "arcs to queue (default 1000)");
  app.add_option("--seed", seed, "seed (default 1)");
  CLI11_PARSE(app, argc, argv);
  try {
    dda::motion::MotionCosim h;
    const auto a = dda::motion::run_motion_mix(h, seed, arcs / 2, false);
    const auto b = dda::motion::run_motion_mix(h, seed + 1000003, arcs - arcs / 2, true);
    std::printf(
        "motion regression: seed %llu: %llu arcs in %llu pieces (%llu ended on their end points; %llu batches: %llu "
        "position checks, %llu aborts, %llu resets, %llu partial commits, %llu overflows; %llu with step/dir timings, "
        "%llu of them large; %llu pieces at a feed increment; %llu paced by the pacer in %llu batches with %llu feed "
        "holds, %llu of the batches with its comparisons at their thresholds, the others with override changes; %llu "
        "hard stops, %llu soft stops, %llu watchdog timeouts), %llu step pulses "
        "checked by the timing monitor, %llu "
        "cycles co-simulated, 0 mismatches, 0 timing violations\n",
        (unsigned long long)seed, (unsigned long long)(a.arcs + b.arcs), (unsigned long long)(a.pieces + b.pieces),
        (unsigned long long)(a.piece_checks + b.piece_checks), (unsigned long long)(a.batches + b.batches),
        (unsigned long long)(a.position_checks + b.position_checks), (unsigned long long)(a.aborts + b.aborts),
        (unsigned long long)(a.resets + b.resets), (unsigned long long)(a.partial + b.partial),
        (unsigned long long)(a.overflow + b.overflow), (unsigned long long)(a.timed_batches + b.timed_batches),
        (unsigned long long)(a.large_timing_batches + b.large_timing_batches),
        (unsigned long long)(a.fed_pieces + b.fed_pieces), (unsigned long long)(a.paced_pieces + b.paced_pieces),
        (unsigned long long)(a.paced_batches + b.paced_batches), (unsigned long long)(a.holds + b.holds),
        (unsigned long long)(a.threshold_batches + b.threshold_batches),
        (unsigned long long)(a.hard_stops + b.hard_stops), (unsigned long long)(a.soft_stops + b.soft_stops),
        (unsigned long long)(a.watchdogs + b.watchdogs), (unsigned long long)(a.pulses + b.pulses),
        (unsigned long long)h.cycle());
    std::printf(
        "motion regression: the speed monitor at the pins on %llu paced batches (%llu windows): the fastest window "
        "%.4f of its batch's cruise speed, 0 speed or acceleration violations\n",
        (unsigned long long)(a.speed_watched + b.speed_watched),
        (unsigned long long)(a.speed_windows + b.speed_windows), std::max(a.peak_speed_share, b.peak_speed_share));
    std::printf(
        "motion regression: the machine's inputs: %llu glitches shorter than the filter ignored, %llu batches "
        "stopped by an input (an E-stop, a limit, a home switch, the probe)\n",
        (unsigned long long)(a.glitches + b.glitches), (unsigned long long)(a.input_trips + b.input_trips));
  } catch (const std::exception& e) {
    std::cerr << "motion regression: seed " << seed << ": " << e.what() << '\n';
    return 1;
  }
  return 0;
}
