// SPDX-License-Identifier: Apache-2.0
// The block-entry words a host writes for each piece (docs/design.md, "The command
// queue": ENTRY + 4k, then CTRL.commit), of an arc's or a line's plan or of a part
// program's planned pieces: what `dda entries` prints and `dda.entry_words` returns.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <istream>
#include <vector>

#include "host/pipeline/pipeline.hpp"
#include "host/planner/plan.hpp"
#include "host/speed/machine_limits.hpp"
#include "host/speed/pace_plan.hpp"

namespace dda::live {

struct PieceEntry {
  std::size_t piece = 0;             // in path order, from 0
  std::size_t line = 0;              // the program block's source line (0 for an arc or a line)
  Point from, to;                    // the piece's ends, steps
  std::vector<std::uint32_t> words;  // motion::kEntryWords of them, word 0 first
};

// An arc's or a line's pieces, each run at the core's full rate (feed increment 0, no
// pacing: a cruise speed of 0).
std::vector<PieceEntry> plan_entries(const Plan& plan);
// The block's settings a program's entries are paced for at `clock_hz` (ACCEL and VMIN,
// which the host writes before the entries; speed::pace_setup).
speed::PaceSetup program_setup(const ProgramRun& run, const speed::MachineLimits& lim, double clock_hz);
// A part program's pieces at their planned speeds for that setup (the entries `dda run`
// writes: speed::stream_program_entries), each handed to `out` as it is planned. Throws
// as the planners do.
void program_entries(std::istream& in, const ProgramRun& run, const speed::MachineLimits& lim,
                     const speed::PaceSetup& setup, const std::function<void(const PieceEntry&)>& out);

}  // namespace dda::live
