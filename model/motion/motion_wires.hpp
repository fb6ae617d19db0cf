// SPDX-License-Identifier: Apache-2.0
// The motion block's reference model inside: the wires of one edge (motion_model.cpp,
// motion_pace.cpp).
#pragma once

#include "model/datapath/hw_params.hpp"
#include "model/motion/motion_model.hpp"

namespace dda::motion {

// The index of one of the core's output ports in PortValues (the outputs of kPorts, in
// order).
constexpr std::size_t core_out(std::string_view name) {
  std::size_t i = 0;
  for (const auto& p : hw::kPorts) {
    if (p.name == name) return i;
    if (p.dir == hw::PortDir::Out) ++i;
  }
  throw "motion model: no such output";
}

// The combinational side of one edge (the RTL's wires): everything the registers load,
// decoded from the inputs and the registers before the edge, before anything is written.
struct MotionModel::Wires {
  // The bus request.
  std::uint32_t adr = 0, word = 0;
  // The write data in the byte lanes selected, and merged with the addressed register's
  // value in the others.
  std::uint32_t wsel = 0, wdat = 0;
  bool req = false, wr = false, commit = false, abort = false, clear = false, err_lanes = false;
  // A hard stop, a soft stop asked for, the watchdog running out on this edge.
  bool hard_stop = false, soft_stop = false, bite = false;
  // The queue.
  std::uint64_t level = 0, head = 0, tail = 0, level_d = 0, entry_feed = 0, entry_axes = 0, fetch_d = 0;
  bool empty = false, entry_ok = false, commit_ok = false, err_overflow = false, err_partial = false;
  bool cmd_valid = false, take = false;
  // The core's registered outputs, the stages and the feed.
  bool core_done = false, core_err = false, running = false, advance = false, core_ce = false;
  // The pacer's inputs and its decision, whether the core's last iteration stepped.
  Pacer::In pace;
  bool pace_iterate = false, stepped = false;
  StageEdge ex, ey, ez;
  std::uint64_t acc_sum = 0;
  // The read data of a bus read in this cycle.
  std::uint32_t rd = 0;
  // The machine's inputs (motion_io.cpp): each input's edge; the CTRL bits of u_io; the
  // stops, causes and events of this edge (rtl/dda_motion_io.v's outputs), the trips.
  std::array<InputEdge, kInputs.size()> in{};
  bool snapshot = false, probe_arm = false;
  bool io_hard = false, io_soft = false, io_err = false, io_probe = false, io_home = false, limit_hit = false;
  std::uint32_t trip_now = 0;
};

}  // namespace dda::motion
