// SPDX-License-Identifier: Apache-2.0
// The runner: pieces through the golden datapath, one after another, with the run-time
// guards. Depends on the datapath and the plan's types, not on the planner.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "host/planner/plan.hpp"

namespace dda {

struct RunSummary {
  std::uint64_t iterations = 0;
  Point end;
  RegState final_regs;
};

using RecordFn = std::function<void(const Iteration&)>;

// The golden engine as a stream: pieces go in one at a time, in path order, and each
// piece's iterations come out (to on_iter) as soon as the piece after it is known (the
// last iteration of a piece also loads the next piece's command: its `after` registers
// are that command's) or the stream is finished. Memory: one piece. Throws GuardError
// if a piece passes its iteration bound, stalls, or ends anywhere but its end point.
class GoldenRun {
 public:
  // steps_only: records only for the iterations with a step (their `iter` numbers count
  // the others, which are skipped in closed form: Datapath::skip_quiet).
  explicit GoldenRun(RecordFn on_iter = {}, bool steps_only = false)
      : on_iter_(std::move(on_iter)), every_(!steps_only) {}
  void piece(const Piece& pc);
  RunSummary finish();
  std::uint64_t pieces() const { return pieces_; }

 private:
  void run_pending(const Command* next);
  RecordFn on_iter_;
  bool every_;
  std::optional<Piece> pending_;
  std::uint64_t pieces_ = 0;
  RunSummary total_;
};

// Run a plan to the end, piece after piece. Calls on_iter for each iteration if given.
RunSummary run(const Plan& plan, const RecordFn& on_iter = {});
std::vector<Iteration> run_records(const Plan& plan);

// The planner's reachability check: the same run, but a stall, an integrand beyond the
// capacity or a piece past its bound is the input's fault (a Refusal naming the point)
// rather than a guard. nullopt: every piece reaches its end.
std::optional<Refusal> unreachable(const Plan& plan);
// The same, the refusal thrown as an InputError.
void check_reachable(const Plan& plan);

}  // namespace dda
