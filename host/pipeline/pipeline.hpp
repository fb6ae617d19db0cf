// SPDX-License-Identifier: Apache-2.0
// The run as one stream: reader -> motion blocks -> planner (a bounded window of blocks)
// -> pieces (one core command each) -> engine -> iteration records -> reports. Each stage
// takes one unit at a time, so memory is bounded by the planner's window and the
// engine's few pieces in flight, never by the program's length or an arc's size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <iosfwd>
#include <memory>
#include <string>

#include "host/planner/plan.hpp"
#include "host/program_plan/program_plan.hpp"
#include "host/runner/runner.hpp"

namespace dda {

// What a run tells a report, in this order: the registers after the first command's
// load (once, before any record), each program block before its pieces, each piece
// before its records, the records, and the end. A report that needs a record's piece
// keeps the few pieces announced and not yet passed (PieceWindow).
class RunSink {
 public:
  virtual ~RunSink() = default;
  virtual void initial(const RegState&) {}
  virtual void block(const program::BlockPlan&) {}
  virtual void piece(const Piece&) {}
  virtual void record(const Iteration& it) = 0;
  virtual void finish() {}
  // A report that reads only the records with a step, and counts iterations by the
  // records' `iter` numbers: the golden engine then skips the iterations without a step
  // in closed form (Datapath::skip_quiet). The hardware engines give every record.
  virtual bool steps_only() const { return false; }
};

// An engine of the stream: pieces in, in path order; records out to the sink it was
// made with (the golden model, or a harness around the SystemC model or the RTL).
class Engine {
 public:
  virtual ~Engine() = default;
  virtual void piece(const Piece& pc) = 0;
  virtual void finish() = 0;
};

// The golden model as an engine (runner.hpp's GoldenRun).
class GoldenEngine : public Engine {
 public:
  explicit GoldenEngine(RunSink& sink);
  void piece(const Piece& pc) override;
  void finish() override;

 private:
  RunSink& sink_;
  GoldenRun run_;
};

// Runs a plan (an arc or a line): its pieces into the engine, and the sink told.
void run_plan(const Plan& plan, Engine& engine, RunSink& sink);

// A part program through the stream.
struct ProgramRun {
  std::string file;  // the name in messages
  program::ReadOptions read;
  program::LatticeOptions lattice;
  std::size_t window = program::kDefaultWindow;
  // Refuse a block whose commands the hardware's widths cannot hold (engines systemc
  // and rtl), before it runs.
  bool hardware = false;
  // The program may move the third axis (the axis normal to its plane): the reports add
  // its columns (moves_third_axis()).
  bool third_axis = false;
};
// Does the program at `path` move the axis normal to its plane (or leave it off 0)? A
// first reading of the program up to its first such move, its moves dropped (memory
// bounded as the run's; a program of the plane alone is read twice); false on a lathe
// (two axes), true for a mill's program from standard input, which cannot be read
// twice, and false when the reader refuses the program before such a move (the run then
// reports the refusal where it occurs).
bool moves_third_axis(const std::string& path, const ProgramRun& run);
// Reads `in` (program::open_program), plans each block as it leaves the planner's
// window and runs its pieces. Throws ProgramError naming the block at fault; the
// blocks before it have run and been reported by then.
void run_program(std::istream& in, const ProgramRun& run, Engine& engine, RunSink& sink);

// The pieces a report has been told of and whose records have not all passed: the
// piece of a record is at most a few pieces behind the last announced.
class PieceWindow {
 public:
  void push(const Piece& pc);
  // The piece with this index (0-based, in stream order); older ones are dropped.
  const Piece& at(std::uint32_t index);
  bool empty() const { return pieces_.empty(); }

 private:
  std::deque<Piece> pieces_;
  std::uint64_t first_ = 0;  // index of pieces_.front()
};

}  // namespace dda
