// SPDX-License-Identifier: Apache-2.0
#include "host/pipeline/pipeline.hpp"

#include <condition_variable>
#include <deque>
#include <exception>
#include <istream>
#include <mutex>
#include <thread>
#include <utility>

#include "host/program/program.hpp"
#include "model/datapath/errors.hpp"

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

namespace {

// The planned blocks on their way from the planner's thread to the engine's: at most
// `capacity` wait (the planner stops until the engine takes one), so memory stays
// bounded. The planner's end, or its failure, follows its last block.
class BlockQueue {
 public:
  explicit BlockQueue(std::size_t capacity) : capacity_(capacity) {}

  // The planner's side: false once the engine has stopped taking blocks.
  bool push(program::BlockPlan&& b) {
    std::unique_lock<std::mutex> lock(m_);
    if (q_.size() == capacity_) room_.wait(lock, [&] { return q_.size() <= capacity_ / 2 || cancelled_; });
    if (cancelled_) return false;
    q_.push_back(std::move(b));
    if (q_.size() == 1) ready_.notify_one();
    return true;
  }
  // No block follows; `error` (if any) is what stopped the planner.
  void close(std::exception_ptr error) {
    const std::lock_guard<std::mutex> lock(m_);
    closed_ = true;
    error_ = std::move(error);
    ready_.notify_one();
  }

  // The engine's side: the next block, or false at the end (rethrowing the planner's
  // failure after every block planned before it).
  bool pop(program::BlockPlan& b) {
    std::unique_lock<std::mutex> lock(m_);
    ready_.wait(lock, [&] { return !q_.empty() || closed_; });
    if (q_.empty()) {
      if (error_) std::rethrow_exception(error_);
      return false;
    }
    b = std::move(q_.front());
    q_.pop_front();
    // The planner, when it waits for room, is woken with half the queue free: a wake-up
    // per half queue, not per block.
    if (q_.size() == capacity_ / 2) room_.notify_one();
    return true;
  }
  // The engine stops (it failed): the planner's next push() returns false.
  void cancel() {
    const std::lock_guard<std::mutex> lock(m_);
    cancelled_ = true;
    room_.notify_one();
  }

 private:
  std::mutex m_;
  std::condition_variable ready_, room_;
  std::deque<program::BlockPlan> q_;
  const std::size_t capacity_;
  bool closed_ = false, cancelled_ = false;
  std::exception_ptr error_;
};

// Blocks planned ahead of the engine: enough to keep the planner's thread busy while
// the engine runs a long block, few enough to keep memory flat.
constexpr std::size_t kQueuedBlocks = 64;

// The reader and the planner, in their own thread: every block planned goes to the
// queue, then the end or the failure.
void plan_into(std::istream& in, const ProgramRun& run, BlockQueue& queue) {
  struct Cancelled {};
  try {
    const program::Point2 start = run.read.start.value_or(program::Point2{});
    program::BlockPlanner planner(run.lattice, start, run.file, run.window, [&](program::BlockPlan&& b) {
      if (!queue.push(std::move(b))) throw Cancelled{};
    });
    program::read_stream(in, run.file, run.read, [&](const program::Move& mv) { planner.move(mv); });
    planner.finish();
    queue.close(nullptr);
  } catch (const Cancelled&) {
    queue.close(nullptr);
  } catch (...) {
    queue.close(std::current_exception());
  }
}

}  // namespace

void run_program(std::istream& in, const ProgramRun& run, Engine& engine, RunSink& sink) {
  // Reading and planning (a third of a run's time on CAM programs) overlap the engine and
  // the reports on a second core; the engine takes the blocks in program order, so what
  // it runs and reports, and where a failure stops it, are the same as in one thread.
  BlockQueue queue(kQueuedBlocks);
  std::thread planner([&] { plan_into(in, run, queue); });
  struct Join {
    BlockQueue& q;
    std::thread& t;
    ~Join() {
      q.cancel();
      t.join();
    }
  } join{queue, planner};
  program::BlockPlan b;
  while (queue.pop(b)) {
    if (run.hardware) program::check_hardware(b, run.file);
    sink.block(b);
    for (const Piece& pc : b.plan.pieces) {
      sink.piece(pc);
      engine.piece(pc);
    }
  }
  engine.finish();
  sink.finish();
}

bool moves_third_axis(const std::string& path, const ProgramRun& run) {
  if (run.read.machine == program::Machine::Lathe) return false;  // two axes: the reader refuses Y
  if (path == "-") return true;
  struct Found {};  // the first such move ends the reading
  try {
    const auto in = program::open_program(path);
    int run_plane = 0;  // (a move in another plane than the first's moves the run's third axis)
    program::read_stream(*in, run.file, run.read, [&](const program::Move& mv) {
      if (run_plane == 0) run_plane = mv.plane;
      if (program::to_steps(mv.w, run.lattice.step) != 0 || program::to_steps(mv.w_to, run.lattice.step) != 0 ||
          mv.plane != run_plane) {
        throw Found{};
      }
    });
  } catch (const Found&) {
    return true;
  } catch (const InputError&) {
    return false;
  }
  return false;
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
