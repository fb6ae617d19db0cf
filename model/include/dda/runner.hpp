// SPDX-License-Identifier: Apache-2.0
// The runner: a plan's pieces through the golden datapath, one after another, with
// the run-time guards. Depends on the datapath and the plan's types, not on the planner.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "dda/plan.hpp"

namespace dda {

struct RunSummary {
  std::uint64_t iterations = 0;
  Point end;
  RegState final_regs;
};

// Run a plan to the end, piece after piece. Calls on_iter for each iteration if given.
// Throws GuardError if a piece passes its iteration bound, stalls, or ends anywhere but
// its end point.
RunSummary run(const Plan& plan, const std::function<void(const Iteration&)>& on_iter = {});
std::vector<Iteration> run_records(const Plan& plan);

// The planner's reachability check: the same run, but a stall or an integrand beyond
// the capacity is the input's fault (InputError naming the point) rather than a guard.
void check_reachable(const Plan& plan);

}  // namespace dda
