// Engine-independent checking and recording of a running core (SystemC model or RTL).
//
// A harness samples the core's architectural registers (and the integrators' adder
// outputs) before and after every clock edge; RecordBuilder turns the samples of an
// edge with an iteration into the golden model's Iteration record, and Scoreboard
// compares the registers after every iteration with the golden model's.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "dda/golden.hpp"

namespace dda {

// What a harness reads from a core, by the register names of docs/design.md.
struct CoreSample {
  std::uint64_t jv_x = 0, jr_x = 0, jv_y = 0, jr_y = 0;  // u_int_*.jv_q, jr_q
  std::uint64_t sum_x = 0, sum_y = 0;                    // u_int_*.sum (adder, combinational)
  std::uint64_t cnt_x = 0, cnt_y = 0;                    // u_cnt_*.cnt_q
  std::uint64_t cap = 0;                                 // cap_q
  std::uint64_t inc_x_on_x = 0, inc_x_on_y = 0;          // u_int_x.inc_on_x_q, inc_on_y_q
  std::uint64_t inc_y_on_x = 0, inc_y_on_y = 0;          // u_int_y.inc_on_x_q, inc_on_y_q
  bool step_x = false, step_y = false, dir_x = false, dir_y = false;  // *_q
  bool cdir_x = false, cdir_y = false;                                // cdir_*_q
  unsigned state = 0;                                   // u_ctrl.state_q
  bool done = false, err = false, iter = false;          // u_ctrl.*_q
};

// A register differs between an engine and the golden model (or another engine).
class MismatchError : public GuardError {
 public:
  using GuardError::GuardError;
};

// Builds Iteration records from samples: call on_edge() for every clock edge.
class RecordBuilder {
 public:
  explicit RecordBuilder(Point start) : pos_(start) {}
  // pre: sampled before the edge, post: after it. Returns true (and fills rec) if an
  // iteration happened on this edge (post.iter).
  bool on_edge(const CoreSample& pre, const CoreSample& post, std::uint32_t seg, Iteration& rec);
  Point pos() const { return pos_; }

 private:
  Point pos_;
  std::uint64_t n_ = 0;
};

// Compares every iteration of an engine with the golden model's, in lockstep.
class Scoreboard {
 public:
  Scoreboard(const Plan& plan, std::string engine);
  // After an edge with an iteration (pre and post: the samples around the edge; loaded:
  // the driver handed a command over on this edge): throws MismatchError naming the
  // first register that differs, the iteration, the cycle and both values. Returns
  // whether the golden piece ended with this iteration.
  bool on_iteration(const CoreSample& pre, const CoreSample& post, std::uint64_t cycle, bool loaded);
  // After an edge that raised done (the end of a command): the golden run of that
  // piece must be complete too; the next iteration belongs to the next piece.
  void on_done(std::uint64_t cycle);
  std::uint64_t iterations() const { return iters_; }
  std::size_t segment() const { return seg_; }

 private:
  Plan plan_;
  std::string engine_;
  std::size_t seg_ = 0;
  Datapath dp_;
  std::uint64_t iters_ = 0;
  bool have_dir_ = false, prev_dir_x_ = false, prev_dir_y_ = false;  // dir_*_q last seen
};

// Compares two samples register by register (e.g. SystemC against RTL, every cycle).
// Returns "" or a description of the first difference.
std::string compare_samples(const CoreSample& a, const CoreSample& b);

}  // namespace dda
