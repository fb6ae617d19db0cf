// SPDX-License-Identifier: Apache-2.0
#include "pipeline/pipeline.hpp"

#include <istream>
#include <utility>

#include "datapath/errors.hpp"
#include "program/program.hpp"

namespace dda {

GoldenEngine::GoldenEngine(RunSink& sink)
    : sink_(sink), run_([this](const Iteration& it) { sink_.record(it); }, sink.steps_only()) {}

void GoldenEngine::piece(const Piece& pc) {
  if (run_.pieces() == 0) sink_.initial(initial_regs(pc.cmd));
  run_.piece(pc);
}

void GoldenEngine::finish() { run_.finish(); }

void run_plan(const Plan& plan, Engine& engine, RunSink& sink) {
  for (const Piece& pc : plan.pieces) {
    sink.piece(pc);
    engine.piece(pc);
  }
  engine.finish();
  sink.finish();
}

void run_program(std::istream& in, const ProgramRun& run, Engine& engine, RunSink& sink) {
  const program::Point2 start = run.read.start.value_or(program::Point2{});
  program::BlockPlanner planner(run.lattice, start, run.file, run.window, [&](program::BlockPlan&& b) {
    if (run.hardware) program::check_hardware(b, run.file);
    sink.block(b);
    for (const Piece& pc : b.plan.pieces) {
      sink.piece(pc);
      engine.piece(pc);
    }
  });
  program::read_stream(in, run.file, run.read, [&](const program::Move& mv) { planner.move(mv); });
  planner.finish();
  engine.finish();
  sink.finish();
}

void PieceWindow::push(const Piece& pc) { pieces_.push_back(pc); }

const Piece& PieceWindow::at(std::uint32_t index) {
  while (pieces_.size() > 1 && first_ < index) {
    pieces_.pop_front();
    ++first_;
  }
  if (pieces_.empty() || first_ != index)
    throw GuardError("a record names piece " + std::to_string(index) + ", which the run has not announced");
  return pieces_.front();
}

}  // namespace dda
