// SPDX-License-Identifier: Apache-2.0
// The motion block's reference model, its machine side (rtl/dda_motion_io.v, u_io): the
// E-stop, limit, home and probe inputs through their synchronizers and filters
// (rtl/dda_input.v), the stops they make, the trip, probe and snapshot latches.
#include "model/datapath/hw_params.hpp"
#include "model/motion/motion_model.hpp"
#include "model/motion/motion_wires.hpp"

namespace dda::motion {

namespace {

const std::string kIo = "u_io.";
// u_io's registers the model reads or writes on every edge, by their index in BlockRegs.
constexpr std::size_t kCycle = breg("u_io.cycle_q");
constexpr std::size_t kErrEstop = breg("u_io.err_estop_q");
constexpr std::size_t kErrLimit = breg("u_io.err_limit_q");
constexpr std::size_t kFiltProbe = breg("u_io.filt_probe_q");
constexpr std::size_t kFiltSw = breg("u_io.filt_sw_q");
constexpr std::size_t kFiltTick = breg("u_io.filt_tick_q");
constexpr std::size_t kMode = breg("u_io.mode_q");
constexpr std::size_t kPol = breg("u_io.pol_q");
constexpr std::size_t kProbeArmed = breg("u_io.probe_armed_q");
constexpr std::size_t kProbed = breg("u_io.probed_q");
constexpr std::size_t kTrip = breg("u_io.trip_q");

// The indices in BlockRegs of each input's registers (s1_q, s2_q, lvl_q, cnt_q): found
// once, as the model reads them on every edge.
const std::array<std::array<std::size_t, 4>, kInputs.size()>& input_regs() {
  static const auto idx = [] {
    std::array<std::array<std::size_t, 4>, kInputs.size()> a{};
    for (std::size_t i = 0; i < kInputs.size(); ++i) {
      const std::string p = kIo + std::string(kInputs[i].inst) + ".";
      a[i] = {breg(p + "s1_q"), breg(p + "s2_q"), breg(p + "lvl_q"), breg(p + "cnt_q")};
    }
    return a;
  }();
  return idx;
}

std::uint32_t mode_bit(std::string_view f) { return 1u << field_of("IN_MODE", f).lsb; }

// Whether the switches' filters count on this edge: the cycle count's low `tick` bits
// (IN_FILTER.tick) all 1.
bool filter_tick(std::uint64_t cycle, std::uint32_t tick) {
  const std::uint64_t mask = (std::uint64_t{1} << tick) - 1;
  return (cycle & mask) == mask;
}

}  // namespace

InputEdge input_edge(const InputRegs& r, bool pin, bool invert, bool tick, std::uint32_t filter) {
  // The level flips once the synchronized one has differed from it on `filter` ticks
  // (0 as 1) without a break; the count holds between ticks and is 0 while they agree.
  const bool differ = r.s2 != r.lvl;
  const std::uint32_t inc = r.cnt + 1;
  const bool flip = differ && tick && inc >= filter;
  InputEdge e;
  e.rise = flip && r.s2;
  e.next.s1 = pin != invert;
  e.next.s2 = r.s1;
  e.next.lvl = r.lvl != flip;
  e.next.cnt = !differ || flip ? 0 : tick ? inc : r.cnt;
  return e;
}

InputRegs MotionModel::input(std::size_t i) const {
  const auto& k = input_regs()[i];
  return InputRegs{r_[k[0]] != 0, r_[k[1]] != 0, r_[k[2]] != 0, std::uint32_t(r_[k[3]])};
}

std::array<std::pair<bool, bool>, 3> MotionModel::routed_steps() const {
  // The core's step outputs (registered) to the stages: stage j takes the core's axis
  // (j - route) mod 3 (route 3 as 0).
  const PortValues po = CoreModel::outputs(core_.state(), false);
  static const std::array<std::size_t, 6> at{core_out("step_x_o"), core_out("step_y_o"), core_out("step_z_o"),
                                             core_out("dir_x_o"),  core_out("dir_y_o"),  core_out("dir_z_o")};
  const std::array<bool, 3> step{po[at[0]] != 0, po[at[1]] != 0, po[at[2]] != 0};
  const std::array<bool, 3> dir{po[at[3]] != 0, po[at[4]] != 0, po[at[5]] != 0};
  const std::size_t route = r_[DDA_BREG("route_q")] == 3 ? 0 : std::size_t(r_[DDA_BREG("route_q")]);
  std::array<std::pair<bool, bool>, 3> r{};
  for (std::size_t j = 0; j < 3; ++j) r[j] = {step[(j + 3 - route) % 3], dir[(j + 3 - route) % 3]};
  return r;
}

void MotionModel::io_wires(const MachinePins& pins, Wires& w) const {
  if (!build_.inputs) return;  // no stop, no latch: the wires stay at their defaults
  const std::uint32_t pol = std::uint32_t(r_[kPol]), mode = std::uint32_t(r_[kMode]);
  const std::uint32_t bits = pins.bits();
  std::uint32_t lvl = 0, rise = 0;
  const bool sw_tick = filter_tick(r_[kCycle], std::uint32_t(r_[kFiltTick]));
  for (std::size_t i = 0; i < kInputs.size(); ++i) {
    const int b = kInputs[i].bit;
    // estop_ni is active low unless IN_POLARITY inverts it; the others active high.
    const bool invert = (((pol >> b) & 1u) != 0) != (b == input_bit("estop"));
    const bool probe = b == kProbeBit;
    const std::uint64_t filter = r_[probe ? kFiltProbe : kFiltSw];
    w.in[i] = input_built(kInputs[i], build_)
                  ? input_edge(input(i), ((bits >> b) & 1u) != 0, invert, probe || sw_tick, std::uint32_t(filter))
                  : InputEdge{};  // not built: held in reset
    lvl |= std::uint32_t(input(i).lvl) << b;
    rise |= std::uint32_t(w.in[i].rise) << b;
  }
  // A step toward an active limit: entering stage j or waiting in it (negative: dir 1).
  const auto steps = routed_steps();
  std::uint32_t hits = 0;
  for (std::size_t j = 0; j < 3; ++j) {
    const StageRegs s = stage(kAxes[j]);
    const bool neg = ((lvl >> (kLimitBit + 2 * j)) & 1u) != 0, pos = ((lvl >> (kLimitBit + 2 * j + 1)) & 1u) != 0;
    const bool hit_neg = ((steps[j].first && steps[j].second) || (s.pend && s.pdir)) && neg;
    const bool hit_pos = ((steps[j].first && !steps[j].second) || (s.pend && !s.pdir)) && pos;
    hits |= std::uint32_t(hit_neg) << (2 * j) | std::uint32_t(hit_pos) << (2 * j + 1);
  }
  const bool estop = (lvl & 1u) != 0;
  const std::uint32_t home_ev = (rise >> kHomeBit) & (mode >> DDA_FIELD_LSB("IN_MODE", "home_x")) & 7u;
  const bool probe_ev = ((rise >> kProbeBit) & 1u) != 0 && r_[kProbeArmed] != 0;
  const bool decel = (mode & mode_bit("limit_decel")) != 0;
  w.limit_hit = hits != 0;
  w.trip_now = std::uint32_t(estop) | hits << kLimitBit | home_ev << kHomeBit;
  w.io_hard = estop || r_[kErrEstop] != 0 || (w.limit_hit && !decel);
  w.io_soft = (w.limit_hit && decel) || home_ev != 0 || (probe_ev && (mode & mode_bit("probe_stop")) != 0);
  w.io_err = estop || w.limit_hit;
  w.io_probe = probe_ev;
  w.io_home = home_ev != 0;
}

void MotionModel::load_io(const Wires& w) {
  if (!build_.inputs) return;  // u_io's registers are not built
  const auto set = [&](const char* r, std::uint64_t v) { reg(kIo + r) = v; };
  const auto at = [&](const char* r) { return w.wr && w.adr == reg_offset(r); };
  if (at("IN_POLARITY")) r_[kPol] = w.wdat & ((1u << kNumInputs) - 1);
  if (at("IN_FILTER")) {
    const auto fld = [&](std::string_view f) {
      const auto& d = field_of("IN_FILTER", f);
      return (w.wdat >> d.lsb) & ((1u << d.width) - 1);
    };
    r_[kFiltSw] = fld("switches");
    r_[kFiltTick] = fld("tick");
    r_[kFiltProbe] = fld("probe");
  }
  if (at("IN_MODE")) r_[kMode] = w.wdat & 0x1Fu;
  // Sticky causes: a cause on the edge of a clear stays set.
  const std::uint64_t trip = r_[kTrip];
  r_[kErrEstop] = (r_[kErrEstop] != 0 && !w.clear) || (w.trip_now & 1u) != 0;
  r_[kErrLimit] = (r_[kErrLimit] != 0 && !w.clear) || w.limit_hit;
  r_[kTrip] = (w.clear ? 0 : trip) | w.trip_now;
  const auto latch = [&](const char* prefix) {
    for (const char axis : kAxes) reg(kIo + prefix + axis + "_q") = get(std::string("pos_") + axis + "_q");
  };
  if (trip == 0 && w.trip_now != 0) latch("latch_");
  // An arm written on the edge of a probe event re-arms (and clears probed).
  r_[kProbeArmed] = w.probe_arm || (r_[kProbeArmed] != 0 && !w.io_probe);
  r_[kProbed] = !w.probe_arm && (r_[kProbed] != 0 || w.io_probe);
  if (w.io_probe) latch("probe_");
  if (w.snapshot) {
    latch("snap_");
    set("snap_cycle_q", r_[kCycle]);
    set("snap_level_q", r_[DDA_BREG("level_q")]);
    set("snap_done_q", r_[DDA_BREG("done_count_q")]);
  }
  r_[kCycle] = (r_[kCycle] + 1) & 0xFFFFFFFFu;
  for (std::size_t i = 0; i < kInputs.size(); ++i) {
    const InputRegs& n = w.in[i].next;
    const auto& k = input_regs()[i];
    r_[k[0]] = n.s1;
    r_[k[1]] = n.s2;
    r_[k[2]] = n.lvl;
    r_[k[3]] = n.cnt;
  }
}

std::uint32_t MotionModel::read_io(std::uint32_t adr) const {
  if (!build_.inputs) return 0;
  if (adr == DDA_REG_OFFSET("STATUS")) {
    const auto bit = [&](std::string_view f, const char* r) {
      return std::uint32_t(get(kIo + r) != 0) << field_of("STATUS", f).lsb;
    };
    return bit("err_estop", "err_estop_q") | bit("err_limit", "err_limit_q") | bit("probe_armed", "probe_armed_q") |
           bit("probed", "probed_q");
  }
  if (adr == DDA_REG_OFFSET("INPUTS")) {
    std::uint32_t lvl = 0;
    for (std::size_t i = 0; i < kInputs.size(); ++i) lvl |= std::uint32_t(input(i).lvl) << kInputs[i].bit;
    return lvl;
  }
  if (adr == DDA_REG_OFFSET("IN_FILTER")) {
    return std::uint32_t(r_[kFiltSw]) << DDA_FIELD_LSB("IN_FILTER", "switches") |
           std::uint32_t(r_[kFiltTick]) << DDA_FIELD_LSB("IN_FILTER", "tick") |
           std::uint32_t(r_[kFiltProbe]) << DDA_FIELD_LSB("IN_FILTER", "probe");
  }
  static const std::array<std::pair<const char*, const char*>, 15> kPlain{{
      {"IN_POLARITY", "pol_q"},
      {"IN_MODE", "mode_q"},
      {"TRIP", "trip_q"},
      {"LATCH_X", "latch_x_q"},
      {"LATCH_Y", "latch_y_q"},
      {"LATCH_Z", "latch_z_q"},
      {"PROBE_X", "probe_x_q"},
      {"PROBE_Y", "probe_y_q"},
      {"PROBE_Z", "probe_z_q"},
      {"SNAP_X", "snap_x_q"},
      {"SNAP_Y", "snap_y_q"},
      {"SNAP_Z", "snap_z_q"},
      {"SNAP_CYCLE", "snap_cycle_q"},
      {"SNAP_LEVEL", "snap_level_q"},
      {"SNAP_DONE", "snap_done_q"},
  }};
  for (const auto& [r, q] : kPlain) {
    if (adr == reg_offset(r)) return std::uint32_t(get(kIo + q));
  }
  return 0;
}

}  // namespace dda::motion
