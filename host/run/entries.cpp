// SPDX-License-Identifier: Apache-2.0
#include "host/run/entries.hpp"

#include "host/speed/entry_stream.hpp"
#include "model/motion/motion_model.hpp"

namespace dda::live {

std::vector<PieceEntry> plan_entries(const Plan& plan) {
  std::vector<PieceEntry> out;
  for (std::size_t k = 0; k < plan.pieces.size(); ++k) {
    const Piece& pc = plan.pieces[k];
    out.push_back(PieceEntry{k, 0, pc.from, pc.to, motion::entry_words(pc.cmd, 0, pc.rot)});
  }
  return out;
}

speed::PaceSetup program_setup(const ProgramRun& run, const speed::MachineLimits& lim, double clock_hz) {
  return speed::pace_setup(speed::planner_limits(lim, run.read.machine), lim, run.lattice.step, clock_hz);
}

void program_entries(std::istream& in, const ProgramRun& run, const speed::MachineLimits& lim,
                     const speed::PaceSetup& setup, const std::function<void(const PieceEntry&)>& out) {
  std::size_t k = 0;
  speed::stream_program_entries(in, run.file, run.read, run.lattice, run.window, lim, setup,
                                [&](const speed::StreamEntry& e) {
                                  out(PieceEntry{k++, e.line, e.piece.from, e.piece.to,
                                                 motion::entry_words(e.piece.cmd, 0, e.piece.rot, e.pace)});
                                });
}

}  // namespace dda::live
