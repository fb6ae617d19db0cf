// SPDX-License-Identifier: Apache-2.0
// The golden model as DPI-C functions (dda_dpi.h): the plan and its records from the
// golden model, the reference core (CoreModel) stepped by the bench, each output port
// and each iteration compared as the bench reports them.
#include "tb/dpi/dda_dpi.h"

#include <cstdint>
#include <cstdio>
#include <deque>
#include <exception>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/options/arc_options.hpp"
#include "host/runner/runner.hpp"
#include "model/datapath/core_model.hpp"
#include "model/datapath/hw_command.hpp"

namespace {

using namespace dda;

// What the bench compares of an iteration: its steps and their directions.
struct Record {
  std::uint64_t iter = 0;
  std::uint32_t piece = 0;
  bool step[3] = {}, dir_neg[3] = {};
};

// The golden run is pulled a piece at a time as the bench compares iterations, so the
// records held are one piece's, not the plan's.
struct Bench {
  Plan plan;
  std::unique_ptr<GoldenRun> run;
  std::size_t fed = 0;  // pieces given to the run
  bool run_done = false;
  std::deque<Record> pending;
  CoreModel core;
  PortValues seen{};                // the outputs the bench gave since the last edge
  std::uint64_t cycle = 0;          // edges since dda_plan
  std::uint64_t checked_ports = 0;  // bit i: output i checked since the last edge
  bool reset_seen = false;
  int result = -1;  // dda_finish()'s
  std::uint64_t ports_compared = 0, records_compared = 0, mismatches = 0;
};

Bench& bench() {
  static Bench b;
  return b;
}

std::vector<std::string> split(const char* args) {
  std::istringstream in(args ? args : "");
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// The index among the output ports (kPorts order, outputs only), or -1.
int output_index(const std::string& name) {
  int i = 0;
  for (const auto& p : hw::kPorts) {
    if (p.dir != hw::PortDir::Out) continue;
    if (p.name == name) return i;
    ++i;
  }
  return -1;
}

std::string output_name(std::size_t index) {
  std::size_t i = 0;
  for (const auto& p : hw::kPorts) {
    if (p.dir != hw::PortDir::Out) continue;
    if (i++ == index) return std::string(p.name);
  }
  return "?";
}

int fail(const std::string& what) {
  std::fprintf(stderr, "dda_dpi: %s\n", what.c_str());
  ++bench().mismatches;
  return 1;
}

// The golden run's next iteration, running the next piece when those held are used up;
// false after the last.
bool next_record(Bench& b, Record& out) {
  while (b.pending.empty()) {
    if (b.fed < b.plan.pieces.size()) {
      b.run->piece(b.plan.pieces[b.fed++]);
    } else if (!b.run_done) {
      b.run->finish();
      b.run_done = true;
    } else {
      return false;
    }
  }
  out = b.pending.front();
  b.pending.pop_front();
  return true;
}

}  // namespace

extern "C" int dda_plan(const char* args) {
  Bench& b = bench();
  try {
    b.plan = cli::plan_from_args(split(args));
    for (const Piece& pc : b.plan.pieces) hw::pack_command(pc.cmd);  // refuses what the widths cannot hold
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dda_dpi: %s\n", e.what());
    return -1;
  }
  b.pending.clear();
  b.fed = 0;
  b.run_done = false;
  b.run = std::make_unique<GoldenRun>([&b](const Iteration& it) {
    Record r;
    r.iter = it.iter;
    r.piece = it.piece;
    r.step[0] = it.step_x, r.step[1] = it.step_y, r.step[2] = it.step_z;
    r.dir_neg[0] = it.dir_x_neg, r.dir_neg[1] = it.dir_y_neg, r.dir_neg[2] = it.dir_z_neg;
    b.pending.push_back(r);
  });
  b.core = CoreModel();
  b.cycle = b.checked_ports = 0;
  b.reset_seen = false;
  return static_cast<int>(b.plan.pieces.size());
}

extern "C" void dda_piece_command(int index, svBitVecVal* cmd) {
  const Bench& b = bench();
  if (index < 0 || static_cast<std::size_t>(index) >= b.plan.pieces.size()) {
    fail("dda_piece_command: no piece " + std::to_string(index) + " (the plan has " +
         std::to_string(b.plan.pieces.size()) + ")");
    return;
  }
  const std::vector<std::uint32_t> words = hw::pack_command(b.plan.pieces[static_cast<std::size_t>(index)].cmd);
  for (std::size_t i = 0; i < words.size(); ++i) cmd[i] = words[i];
}

extern "C" int dda_ref_edge(svBit rst_n, svBit ce, svBit cmd_valid, const svBitVecVal* cmd) {
  Bench& b = bench();
  int bad = 0;
  // The outputs mean something from the first reset edge on; cmd_ready_o is the one
  // that depends on this cycle's inputs (ce_i).
  if (b.reset_seen) {
    if (b.checked_ports != (std::uint64_t{1} << hw::kNumOutputs) - 1) {
      bad += fail("cycle " + std::to_string(b.cycle) + ": the bench did not give every output port before the edge");
    }
    const PortValues want = CoreModel::outputs(b.core.state(), b.core.cmd_ready(ce != 0));
    for (std::size_t i = 0; i < hw::kNumOutputs; ++i) {
      ++b.ports_compared;
      if (want[i] == b.seen[i]) continue;
      bad += fail("cycle " + std::to_string(b.cycle) + ": output " + output_name(i) + ": golden " +
                  std::to_string(want[i]) + ", dut " + std::to_string(b.seen[i]));
    }
  }
  CoreInputs in;
  in.rst_n = rst_n != 0;
  in.ce = ce != 0;
  in.cmd_valid = cmd_valid != 0;
  if (in.cmd_valid) in.cmd = hw::unpack_fields(std::vector<std::uint32_t>(cmd, cmd + (hw::kCmdWidth + 31) / 32));
  b.core.edge(in);
  b.reset_seen = b.reset_seen || !in.rst_n;
  b.checked_ports = 0;
  ++b.cycle;
  return bad;
}

extern "C" int dda_ref_output(const char* port, svBit value) {
  Bench& b = bench();
  const int i = output_index(port ? port : "");
  if (i < 0) return fail(std::string("dda_ref_output: '") + (port ? port : "") + "' is not an output of dda_core");
  b.checked_ports |= std::uint64_t{1} << i;
  b.seen[static_cast<std::size_t>(i)] = value ? 1 : 0;
  return 0;
}

extern "C" int dda_check_record(svBit step_x, svBit step_y, svBit step_z, svBit dir_x, svBit dir_y, svBit dir_z) {
  Bench& b = bench();
  Record r;
  try {
    if (!next_record(b, r)) {
      return fail("cycle " + std::to_string(b.cycle) + ": an iteration past the golden run's " +
                  std::to_string(b.records_compared));
    }
  } catch (const std::exception& e) {  // a guard of the golden run
    return fail(e.what());
  }
  ++b.records_compared;
  const bool steps[3] = {step_x != 0, step_y != 0, step_z != 0};
  const bool dirs[3] = {dir_x != 0, dir_y != 0, dir_z != 0};
  for (int a = 0; a < 3; ++a) {
    // A direction output means something with a step (it changes only with one).
    if (steps[a] != r.step[a] || (steps[a] && dirs[a] != r.dir_neg[a])) {
      const char axis = "xyz"[a];
      return fail("iteration " + std::to_string(r.iter) + " (piece " + std::to_string(r.piece) + ", cycle " +
                  std::to_string(b.cycle) + "): step_" + axis + "/dir_" + axis + ": golden " +
                  std::to_string(r.step[a]) + "/" + std::to_string(r.dir_neg[a]) + ", dut " + std::to_string(steps[a]) +
                  "/" + std::to_string(dirs[a]));
    }
  }
  return 0;
}

extern "C" int dda_finish(void) {
  Bench& b = bench();
  Record r;
  try {
    if (b.run && next_record(b, r)) {
      fail("the run ended after " + std::to_string(b.records_compared) + " iterations; the golden run's next is " +
           std::to_string(r.iter));
    }
  } catch (const std::exception& e) {
    fail(e.what());
  }
  std::printf("dda_dpi: %zu pieces, %llu cycles, %llu port values and %llu iterations compared, %llu mismatches\n",
              b.plan.pieces.size(), static_cast<unsigned long long>(b.cycle),
              static_cast<unsigned long long>(b.ports_compared), static_cast<unsigned long long>(b.records_compared),
              static_cast<unsigned long long>(b.mismatches));
  b.result = b.mismatches == 0 ? 0 : 1;
  return b.result;
}

extern "C" int dda_dpi_result(void) { return bench().result; }
