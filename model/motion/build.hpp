// SPDX-License-Identifier: Apache-2.0
// The motion block's build-time choices (docs/design.md, "Builds"): the one definition
// the three engines take them from. Each is a parameter of rtl/dda_motion.v and of its
// bridged tops (rtl/dda_motion_axil.v, rtl/dda_motion_spi.v) under the name kBuildParams
// gives, a constructor argument of the SystemC model (sc::dda_motion) and of the
// reference model (MotionModel), and a field of the CONFIG register the host reads it
// back from. The bus is the choice of top (Wishbone: dda_motion). `dda build SPEC`
// prints a build's RTL parameters, which scripts/synth and scripts/netlist-sim.sh set for
// the same spec (`--build inputs=0,depth_log2=5`); the "build: ..." tests check the RTL's
// parameters against this table.
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "model/datapath/core_model.hpp"
#include "model/motion/motion_map.hpp"

namespace dda::motion {

struct Build {
  // The queue holds 2^depth_log2 entries (1 .. kMaxDepthLog2).
  int depth_log2 = kMaxDepthLog2;
  // The machine inputs with what they stop, the trip, probe and snapshot latches and the
  // cycle counter (rtl/dda_motion_io.v, u_io). Without them u_io is held in reset (its
  // registers keep their reset values, so every engine has the same registers in every
  // build, and synthesis keeps none of them): the pins are not read, the registers IN_*,
  // INPUTS, TRIP, LATCH_*, PROBE_*, SNAP_* read 0 and take no write, CTRL.snapshot and
  // CTRL.probe_arm do nothing and STATUS' input bits stay 0.
  bool inputs = true;
  // The block's axes: 3 (X, Y, Z), or 2 (X and Y: a lathe's two axes or a plotter's).
  // With 2, the core's linear axis, the Z stage, POS_Z, STEP_Z and DIR_Z, the Z bits of
  // POLARITY and the Z limit and home inputs are not built: each is held at its reset
  // value (the same registers in every engine and build; synthesis keeps none of them).
  // The core reads an entry's linear-axis fields as an idle axis's
  // (idle_linear_axis), the block reads its axes field as 0 (the core's plane on X and
  // Y), STEP_Z, DIR_Z and POS_Z read 0 and take no write, step_z_o and dir_z_o stay low.
  // A host must not queue an entry with Z motion or an axes field on such a block.
  int axes = 3;
  // The pacer (rtl/dda_pace.v, u_pace) with its norm unit. Without it u_pace is held in
  // reset and every entry runs at its feed increment, as an entry without a cruise speed
  // does on a block with it: no ramps (a feed hold or a soft stop stops at once), the
  // cruise speed ignored; ACCEL, VMIN and OVERRIDE keep their reset values and take no
  // write. A host must not queue an entry with a cruise speed on such a block.
  bool pacer = true;
};

// A choice: its key in a spec and in CONFIG's fields, the RTL parameter, its range.
struct BuildParam {
  std::string_view key;  // the spec's key and the CONFIG field
  std::string_view rtl;  // the parameter of dda_motion
  int min, max;
  std::string_view meaning;
};
inline constexpr std::array<BuildParam, 4> kBuildParams{{
    {"depth_log2", "DepthLog2", 1, kMaxDepthLog2, "log2 of the queue depth (entries)"},
    {"inputs", "Inputs", 0, 1, "1: the machine inputs, their latches and the snapshot are built in"},
    {"axes", "Axes", 2, 3, "the block's axes: 3 (X, Y, Z) or 2 (X, Y; no linear axis in the core)"},
    {"pacer", "Pacer", 0, 1, "1: the pacer is built in; 0: every entry runs at its feed increment"},
}};

// The value of each kBuildParams entry for a build, in kBuildParams' order.
std::vector<int> build_values(const Build& b);
// A spec: comma-separated key=value pairs of kBuildParams' keys, each at most once (an
// empty spec is the default build). InputError naming the key or value at fault.
Build parse_build(std::string_view spec);
// The spec of a build: every key with its value ("depth_log2=7,inputs=1").
std::string build_spec(const Build& b);
// The core's command as a block of 2 axes hands it: the linear axis' fields (those named
// *_z, the last of hw::kCmdFields) as an idle axis's, every one 0 but cap_z, 1 (a
// capacity is never 0: the norm unit divides by it).
CmdFields idle_linear_axis(CmdFields c);
// Whether machine input `in` (kInputs) is built: with the inputs, and of an axis built
// (with 2 axes, the Z limits and home are not).
bool input_built(const Input& in, const Build& b);
// The RTL parameters of a build, as `name value` pairs (for chparam and -G).
std::vector<std::pair<std::string, int>> rtl_params(const Build& b);

}  // namespace dda::motion
