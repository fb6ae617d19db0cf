// SPDX-License-Identifier: Apache-2.0
#include "model/motion/motion_model.hpp"
#include "model/motion/motion_wires.hpp"

#include "model/datapath/errors.hpp"
#include "model/datapath/hw_command.hpp"

#include <unordered_map>

namespace dda::motion {

namespace {

std::uint64_t mask_of(int bits) { return bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1; }

}  // namespace

std::string BlockOutputs::diff(const BlockOutputs& o) const {
  std::string d;
  const auto one = [&](const char* n, std::uint64_t a, std::uint64_t b) {
    if (a != b) d += (d.empty() ? "" : ", ") + std::string(n) + " " + std::to_string(a) + "/" + std::to_string(b);
  };
  one("wb_ack_o", ack, o.ack);
  one("wb_stall_o", stall, o.stall);
  one("wb_dat_o", dat, o.dat);
  one("step_x_o", step_x, o.step_x);
  one("step_y_o", step_y, o.step_y);
  one("dir_x_o", dir_x, o.dir_x);
  one("dir_y_o", dir_y, o.dir_y);
  one("step_z_o", step_z, o.step_z);
  one("dir_z_o", dir_z, o.dir_z);
  one("busy_o", busy, o.busy);
  one("irq_o", irq, o.irq);
  one("s_awready_o", axil.awready, o.axil.awready);
  one("s_wready_o", axil.wready, o.axil.wready);
  one("s_bvalid_o", axil.bvalid, o.axil.bvalid);
  one("s_bresp_o", axil.bresp, o.axil.bresp);
  one("s_arready_o", axil.arready, o.axil.arready);
  one("s_rvalid_o", axil.rvalid, o.axil.rvalid);
  one("s_rdata_o", axil.rdata, o.axil.rdata);
  one("s_rresp_o", axil.rresp, o.axil.rresp);
  one("spi_miso_o", spi.miso, o.spi.miso);
  one("spi_miso_oe_o", spi.miso_oe, o.spi.miso_oe);
  return d;
}

int width_bits(Width w, int depth_log2) {
  switch (w) {
    case Width::One:
      return 1;
    case Width::Two:
      return 2;
    case Width::Three:
      return 3;
    case Width::Six:
      return 6;
    case Width::Timing:
      return kTimingWidth;
    case Width::Feed:
      return kFeedWidth;
    case Width::Word:
      return 32;
    case Width::Level:
      return kLevelWidth;
    case Width::Index:
      return depth_log2;
    case Width::Entry:
      return kEntryWords;
    case Width::Override:
      return kOverrideBits;
    case Width::Speed:
      return kRampFrac;
    case Width::Phase:
      return kPhaseWidth;
    case Width::Distance:
      return kDistWidth;
    case Width::NormBusy:
      return kNormBusyWidth;
    case Width::NormD:
      return kNormFrac + 2;
    case Width::Provisional:
      return kProvisionalWidth;
    case Width::Correction:
      return kCorrectionWidth;
    case Width::OverrideCount:
      return kOverrideCountWidth;
    case Width::Five:
      return 5;
    case Width::Inputs:
      return kNumInputs;
    case Width::Trip:
      return kTripBits;
    case Width::Filter:
      return kFilterWidth;
    case Width::SwitchFilter:
      return kSwitchFilterWidth;
    case Width::FilterTick:
      return kFilterTickWidth;
  }
  return 0;
}

std::vector<std::uint32_t> entry_words(const Command& c, std::uint32_t feed, int axes, const PaceEntry& pace) {
  if (std::uint64_t{feed} >> kFeedWidth)
    throw GuardError("motion: a feed increment of more than " + std::to_string(kFeedWidth) + " bits");
  if (axes < 0 || axes > 2) throw GuardError("motion: axes " + std::to_string(axes) + " is not 0, 1 or 2");
  std::vector<std::uint32_t> w = hw::pack_command(c);
  w.resize(kEntryWords, 0);
  w[kAxesWord] |= std::uint32_t(axes) << kAxesLsb;
  w[kFeedWord] |= feed << kFeedLsb;
  const std::array<std::uint32_t, kPaceWords> p{pace.cruise, pace.limit, pace.exit, pace.length, pace.brake_exit};
  for (int i = 0; i < kPaceWords; ++i) w[std::size_t(kPaceWord + i)] = p[std::size_t(i)];
  return w;
}

PaceEntry entry_pace(const std::vector<std::uint32_t>& words) {
  const auto f = [&](int i) { return words[std::size_t(kPaceWord + i)]; };
  return PaceEntry{f(0), f(1), f(2), f(3), f(4)};
}

CmdFields entry_fields(const std::vector<std::uint32_t>& words) {
  CmdFields f{};
  int off = 0;
  for (std::size_t i = 0; i < hw::kCmdFields.size(); ++i) {
    const int width = hw::kCmdFields[i].width;
    std::uint64_t v = 0;
    // (A word's share of the field at a time: this runs on every edge an entry waits.)
    for (int got = 0; got < width;) {
      const int bit = off + got, b = bit % 32, take = std::min(32 - b, width - got);
      v |= (std::uint64_t(words[std::size_t(bit / 32)] >> b) & ((std::uint64_t{1} << take) - 1)) << got;
      got += take;
    }
    f[i] = v;
    off += width;
  }
  return f;
}

MotionModel::MotionModel(int depth_log2) : MotionModel(Build{depth_log2, true, 3}) {}

MotionModel::MotionModel(const Build& build)
    : build_(build),
      depth_log2_(build.depth_log2),
      mem_(std::size_t{1} << build.depth_log2, std::vector<std::uint32_t>(kEntryWords, 0)) {
  if (depth_log2_ < 1 || depth_log2_ > kMaxDepthLog2) throw GuardError("motion model: queue depth out of range");
  if (build.axes != 2 && build.axes != 3) throw GuardError("motion model: the axes are 2 or 3");
}

namespace {
// breg() at run time: the model reads its registers by name on every edge, and breg's
// search compares names one by one.
std::size_t reg_index(std::string_view name) {
  static const std::unordered_map<std::string_view, std::size_t> index = [] {
    std::unordered_map<std::string_view, std::size_t> m;
    for (std::size_t i = 0; i < kBlockRegs.size(); ++i) m.emplace(kBlockRegs[i].name, i);
    return m;
  }();
  const auto it = index.find(name);
  return it != index.end() ? it->second : breg(name);  // (breg throws for a name not there)
}
}  // namespace

std::uint64_t MotionModel::get(std::string_view name) const { return r_[reg_index(name)]; }

namespace {
// A stage's registers' indices (its instance u_sx, u_sy or u_sz), found once.
struct StageIndex {
  std::size_t step, dir, pend, pdir, tf, ts, tag;
};
const StageIndex& stage_index(char axis) {
  static const std::array<StageIndex, 3> index = [] {
    std::array<StageIndex, 3> a{};
    for (std::size_t k = 0; k < 3; ++k) {
      const std::string p = std::string("u_s") + char('x' + k) + ".";
      a[k] = {breg(p + "step_q"), breg(p + "dir_q"), breg(p + "pend_q"), breg(p + "pdir_q"),
              breg(p + "tf_q"),   breg(p + "ts_q"),  breg(p + "tag_q")};
    }
    return a;
  }();
  if (axis < 'x' || axis > 'z') throw GuardError("motion model: no stage for axis " + std::string(1, axis));
  return index[std::size_t(axis - 'x')];
}
}  // namespace

StageRegs MotionModel::stage(char axis) const {
  const StageIndex& i = stage_index(axis);
  StageRegs s;
  s.step = r_[i.step] != 0;
  s.dir = r_[i.dir] != 0;
  s.pend = r_[i.pend] != 0;
  s.pdir = r_[i.pdir] != 0;
  s.tf = std::uint32_t(r_[i.tf]);
  s.ts = std::uint32_t(r_[i.ts]);
  s.tag = r_[i.tag] != 0;
  return s;
}

void MotionModel::set_stage(char axis, const StageRegs& s) {
  const StageIndex& i = stage_index(axis);
  r_[i.step] = s.step;
  r_[i.dir] = s.dir;
  r_[i.pend] = s.pend;
  r_[i.pdir] = s.pdir;
  r_[i.tf] = s.tf;
  r_[i.ts] = s.ts;
  r_[i.tag] = s.tag;
}

StageTimings MotionModel::timings(char axis) const {
  // (Each axis' four registers found once.)
  static const std::array<std::array<std::size_t, 4>, 3> index = [] {
    std::array<std::array<std::size_t, 4>, 3> a{};
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t i = 0; i < 4; ++i)
        a[k][i] = breg(std::string(kTimingFields[i].name) + "_" + char('x' + k) + "_q");
    return a;
  }();
  if (axis < 'x' || axis > 'z') throw GuardError("motion model: no timings for axis " + std::string(1, axis));
  const auto& i = index[std::size_t(axis - 'x')];
  return StageTimings{std::uint32_t(r_[i[0]]), std::uint32_t(r_[i[1]]), std::uint32_t(r_[i[2]]),
                      std::uint32_t(r_[i[3]])};
}

bool MotionModel::busy() const {
  // The core runs, or a step is on its way to the pins: the core's step output (it enters
  // a stage on the next edge), a step waiting in a stage, a pulse out.
  const PortValues p = CoreModel::outputs(core_.state(), false);
  static const std::size_t sx = core_out("step_x_o"), sy = core_out("step_y_o"), sz = core_out("step_z_o");
  bool b = CoreModel::busy(core_.state()) || p[sx] != 0 || p[sy] != 0 || p[sz] != 0;
  for (const char axis : kAxes) b = b || stage(axis).pend || stage(axis).step;
  return b;
}
std::uint64_t& MotionModel::reg(std::string_view name) { return r_[reg_index(name)]; }

std::uint32_t MotionModel::read(std::uint32_t adr) const {
  const std::uint64_t level = r_[DDA_BREG("level_q")];
  const std::uint64_t depth = std::uint64_t{1} << depth_log2_;
  if (adr == DDA_REG_OFFSET("ID")) return kId;
  if (adr == DDA_REG_OFFSET("VERSION")) return std::uint32_t(kVersionMajor) << 16 | std::uint32_t(kVersionMinor);
  if (adr == DDA_REG_OFFSET("CONFIG")) {
    return std::uint32_t(kEntryWords) << std::uint32_t(DDA_FIELD_LSB("CONFIG", "entry_words")) |
           std::uint32_t(depth_log2_) << std::uint32_t(DDA_FIELD_LSB("CONFIG", "depth_log2")) |
           std::uint32_t(kEntryRows) << std::uint32_t(DDA_FIELD_LSB("CONFIG", "entry_rows")) |
           std::uint32_t(hw::kAccWidth) << std::uint32_t(DDA_FIELD_LSB("CONFIG", "acc_width")) |
           std::uint32_t(hw::kCntWidth) << std::uint32_t(DDA_FIELD_LSB("CONFIG", "cnt_width")) |
           std::uint32_t(build_.inputs) << std::uint32_t(DDA_FIELD_LSB("CONFIG", "inputs")) |
           std::uint32_t(build_.axes) << std::uint32_t(DDA_FIELD_LSB("CONFIG", "axes")) |
           std::uint32_t(build_.pacer) << std::uint32_t(DDA_FIELD_LSB("CONFIG", "pacer"));
  }
  if (adr == DDA_REG_OFFSET("STATUS")) {
    const auto bit = [&](std::string_view f, bool v) { return std::uint32_t(v) << field_of("STATUS", f).lsb; };
    return bit("busy", busy()) | bit("empty", level == 0) | bit("full", level == depth) |
           bit("err", r_[DDA_BREG("err_q")]) | bit("err_overflow", r_[DDA_BREG("err_overflow_q")]) |
           bit("err_partial", r_[DDA_BREG("err_partial_q")]) | bit("err_stall", r_[DDA_BREG("err_stall_q")]) |
           bit("aborted", r_[DDA_BREG("aborted_q")]) | bit("err_lanes", r_[DDA_BREG("err_lanes_q")]) | read_pace(adr) |
           read_io(adr) | std::uint32_t(level) << std::uint32_t(DDA_FIELD_LSB("STATUS", "level"));
  }
  if (adr == DDA_REG_OFFSET("IRQ_STATUS")) return std::uint32_t(r_[DDA_BREG("irq_status_q")]);
  if (adr == DDA_REG_OFFSET("IRQ_ENABLE")) return std::uint32_t(r_[DDA_BREG("irq_enable_q")]);
  if (adr == DDA_REG_OFFSET("IRQ_LEVEL")) return std::uint32_t(r_[DDA_BREG("irq_level_q")]);
  if (adr == DDA_REG_OFFSET("DONE_COUNT")) return std::uint32_t(r_[DDA_BREG("done_count_q")]);
  if (adr == DDA_REG_OFFSET("ERR_COUNT")) return std::uint32_t(r_[DDA_BREG("err_count_q")]);
  if (adr == DDA_REG_OFFSET("POS_X")) return std::uint32_t(r_[DDA_BREG("pos_x_q")]);
  if (adr == DDA_REG_OFFSET("POS_Y")) return std::uint32_t(r_[DDA_BREG("pos_y_q")]);
  if (adr == DDA_REG_OFFSET("POS_Z")) return std::uint32_t(r_[DDA_BREG("pos_z_q")]);
  if (adr == DDA_REG_OFFSET("ENTRY_MASK")) return std::uint32_t(r_[DDA_BREG("mask_q")]);
  if (adr == DDA_REG_OFFSET("POLARITY")) return std::uint32_t(r_[DDA_BREG("polarity_q")]);
  for (const char* r : {"ACCEL", "VMIN", "OVERRIDE", "WATCHDOG"})
    if (adr == reg_offset(r)) return read_pace(adr);
  std::uint32_t v = 0;
  for (const char axis : kAxes) {
    if (axis == 'z' && build_.axes == 2) continue;  // not built
    for (const auto& t : kTimingFields) {
      const std::string r = std::string(t.reg) + "_" + char(axis - 'a' + 'A');
      if (adr == reg_offset(r))
        v |= std::uint32_t(get(std::string(t.name) + "_" + axis + "_q")) << field_of(r, t.name).lsb;
    }
  }
  return v | read_io(adr);
}

BlockOutputs MotionModel::outputs() const {
  const std::uint64_t pol = r_[DDA_BREG("polarity_q")];
  // (POLARITY's bits as constants: this runs on every edge.)
  constexpr int sx = DDA_FIELD_LSB("POLARITY", "step_x"), sy = DDA_FIELD_LSB("POLARITY", "step_y"),
                sz = DDA_FIELD_LSB("POLARITY", "step_z"), dx = DDA_FIELD_LSB("POLARITY", "dir_x"),
                dy = DDA_FIELD_LSB("POLARITY", "dir_y"), dz = DDA_FIELD_LSB("POLARITY", "dir_z");
  const auto inv = [&](int bit) { return ((pol >> bit) & 1u) != 0; };
  BlockOutputs o;
  o.ack = o.stall = r_[DDA_BREG("ack_q")] != 0;
  o.dat = std::uint32_t(r_[DDA_BREG("dat_q")]);
  o.step_x = (r_[DDA_BREG("u_sx.step_q")] != 0) != inv(sx);
  o.step_y = (r_[DDA_BREG("u_sy.step_q")] != 0) != inv(sy);
  o.dir_x = (r_[DDA_BREG("u_sx.dir_q")] != 0) != inv(dx);
  o.dir_y = (r_[DDA_BREG("u_sy.dir_q")] != 0) != inv(dy);
  o.step_z = (r_[DDA_BREG("u_sz.step_q")] != 0) != inv(sz);
  o.dir_z = (r_[DDA_BREG("u_sz.dir_q")] != 0) != inv(dz);
  o.busy = busy();
  o.irq = (r_[DDA_BREG("irq_status_q")] & r_[DDA_BREG("irq_enable_q")]) != 0;
  return o;
}

MotionModel::Wires MotionModel::bus_wires(const BusIn& b, const MachinePins& pins) const {
  Wires w;
  io_wires(pins, w);
  const std::uint64_t depth = std::uint64_t{1} << depth_log2_;
  const std::uint64_t all_words = mask_of(kEntryWords);
  w.adr = b.adr & std::uint32_t(mask_of(kAddrWidth)) & ~3u;

  w.req = b.cyc && b.stb && !r_[DDA_BREG("ack_q")];
  w.wr = w.req && b.we;
  std::uint32_t lanes = 0;
  for (int k = 0; k < 4; ++k)
    if ((b.sel >> k) & 1u) lanes |= 0xFFu << (8 * k);
  w.wsel = b.dat & lanes;
  // The addressed register (read data; a write keeps it in the other lanes): on requests.
  if (w.req) w.rd = read(w.adr);
  w.wdat = (w.rd & ~lanes) | w.wsel;
  const bool wr_ctrl = w.wr && w.adr == DDA_REG_OFFSET("CTRL");
  w.commit = wr_ctrl && ((w.wsel >> std::uint32_t(DDA_FIELD_LSB("CTRL", "commit"))) & 1u);
  w.hard_stop = wr_ctrl && ((w.wsel >> std::uint32_t(DDA_FIELD_LSB("CTRL", "hard_stop"))) & 1u);
  w.soft_stop = wr_ctrl && ((w.wsel >> std::uint32_t(DDA_FIELD_LSB("CTRL", "soft_stop"))) & 1u);
  w.abort = (wr_ctrl && ((w.wsel >> std::uint32_t(DDA_FIELD_LSB("CTRL", "abort"))) & 1u)) || w.hard_stop ||
            soft_flush() || w.io_hard;
  w.snapshot = wr_ctrl && ((w.wsel >> std::uint32_t(DDA_FIELD_LSB("CTRL", "snapshot"))) & 1u);
  w.probe_arm = wr_ctrl && ((w.wsel >> std::uint32_t(DDA_FIELD_LSB("CTRL", "probe_arm"))) & 1u);
  w.bite = !(w.wr && w.adr == DDA_REG_OFFSET("WATCHDOG")) && r_[DDA_BREG("wd_cnt_q")] == 1;
  w.clear = wr_ctrl && ((w.wsel >> std::uint32_t(DDA_FIELD_LSB("CTRL", "clear"))) & 1u);
  const bool in_entry = w.adr >= kEntryBase && w.adr < kEntryBase + 4u * kEntryWords;
  w.word = (w.adr - kEntryBase) >> 2;

  w.level = r_[DDA_BREG("level_q")];
  const bool full = w.level == depth;
  w.empty = w.level == 0;
  const bool mask_all = r_[DDA_BREG("mask_q")] == all_words;
  const bool wr_entry = w.wr && in_entry && !w.abort;
  const bool all_lanes = (b.sel & 0xFu) == 0xFu;
  w.entry_ok = wr_entry && !full && all_lanes;
  w.err_lanes = wr_entry && !all_lanes;
  w.commit_ok = w.commit && !w.abort && !full && mask_all;
  w.err_overflow = (wr_entry || w.commit) && !w.abort && full;
  w.err_partial = w.commit && !w.abort && !full && !mask_all;
  return w;
}

void MotionModel::core_wires(bool ce, Wires& w) const {
  // The core's outputs during this cycle (registered): what the stages and counters see.
  const Signals& pre = core_.state();
  w.core_done = CoreModel::done(pre);
  w.core_err = CoreModel::err(pre);
  w.running = CoreModel::busy(pre);
  // The core's axes to the stages (routed).
  const auto rs = routed_steps();
  w.ex = stage_edge(stage('x'), timings('x'), rs[0].first, rs[0].second, w.core_done, w.abort);
  w.ey = stage_edge(stage('y'), timings('y'), rs[1].first, rs[1].second, w.core_done, w.abort);
  w.ez = stage_edge(stage('z'), timings('z'), rs[2].first, rs[2].second, w.core_done, w.abort);
  if (build_.axes == 2) {  // Z not built: its stage held in reset
    w.ez = StageEdge{};
    w.ez.next = stage_reset();
  }
  // The feed: the core may iterate when no stage holds it and the accumulator carries
  // (a timing written on this edge holds it once: the stages' look-ahead used the old).
  bool wr_timing = false;
  for (const char* r : {"STEP_X", "DIR_X", "STEP_Y", "DIR_Y", "STEP_Z", "DIR_Z"})
    wr_timing = wr_timing || (w.wr && w.adr == reg_offset(r));
  const bool hold = w.ex.hold || w.ey.hold || w.ez.hold || wr_timing;
  w.advance = ce && !hold;
  const std::uint64_t feed = r_[DDA_BREG("feed_q")];
  w.acc_sum = r_[DDA_BREG("acc_q")] + feed;
  w.stepped = rs[0].first || rs[1].first || rs[2].first;
  pace_wires(false, w);
  w.core_ce =
      w.pace.running ? w.pace_iterate : w.advance && !halt() && (feed == 0 || ((w.acc_sum >> kFeedWidth) & 1u) != 0);

  // The head entry is whole once both its rows are read (fetch_q 2); the RAM reads row 0
  // again after the head moves, while the queue is empty and after reset.
  w.cmd_valid = r_[DDA_BREG("fetch_q")] == 2 && !w.empty;
  w.take = w.cmd_valid && core_.cmd_ready(w.core_ce) && !w.abort;
  w.fetch_d = w.empty || w.take || w.abort || r_[DDA_BREG("fetch_q")] == 0 ? 1 : 2;
  w.level_d = w.level + w.commit_ok - w.take;
  w.head = r_[DDA_BREG("head_q")];
  w.tail = r_[DDA_BREG("tail_q")];
  w.entry_feed = (mem_[w.head][kFeedWord] >> kFeedLsb) & mask_of(kFeedWidth);
  w.entry_axes = build_.axes == 3 ? (mem_[w.head][kAxesWord] >> kAxesLsb) & mask_of(kAxesWidth) : 0;
  pace_wires(true, w);
}

void MotionModel::step_core(bool rst_n, const Wires& w) {
  CoreInputs ci;
  ci.rst_n = rst_n && !w.abort;
  ci.ce = w.core_ce;
  ci.cmd_valid = w.cmd_valid;
  if (w.cmd_valid) {
    ci.cmd = entry_fields(mem_[w.head]);
    if (build_.axes == 2) ci.cmd = idle_linear_axis(ci.cmd);
  }
  core_.edge(ci);
}

void MotionModel::note_edge(const Wires& w) {
  took_ = w.take;
  core_ce_ = w.core_ce;
  iterated_ = w.core_ce && !w.abort && w.running;
  rise_x_ = w.ex.rise ? (w.ex.rise_dir ? -1 : 1) : 0;
  rise_y_ = w.ey.rise ? (w.ey.rise_dir ? -1 : 1) : 0;
  rise_z_ = w.ez.rise ? (w.ez.rise_dir ? -1 : 1) : 0;
}

void MotionModel::load_bus(const BusIn& b, const Wires& w) {
  r_[DDA_BREG("ack_q")] = w.req;
  if (w.req && !b.we) r_[DDA_BREG("dat_q")] = w.rd;
}

void MotionModel::load_queue(const Wires& w) {
  r_[DDA_BREG("fetch_q")] = w.fetch_d;
  r_[DDA_BREG("head_q")] = w.abort ? w.tail : w.take ? (w.head + 1) & mask_of(depth_log2_) : w.head;
  if (w.abort) {
    r_[DDA_BREG("level_q")] = 0;
    r_[DDA_BREG("mask_q")] = 0;
  } else {
    r_[DDA_BREG("level_q")] = w.level_d;
    if (w.commit_ok) {
      r_[DDA_BREG("tail_q")] = (w.tail + 1) & mask_of(depth_log2_);
      r_[DDA_BREG("mask_q")] = 0;
    } else if (w.entry_ok) {
      r_[DDA_BREG("mask_q")] |= std::uint64_t{1} << w.word;
    }
  }
}

void MotionModel::load_status(const Wires& w) {
  const bool err_set =
      w.err_overflow || w.err_partial || w.err_lanes || w.core_err || w.hard_stop || w.bite || w.io_err;
  const bool low_set = w.take && w.level_d < r_[DDA_BREG("irq_level_q")];
  // A piece is done once its last steps (tagged on the core's done_o) have left.
  const bool tags_left = w.ex.tag_left || w.ey.tag_left || w.ez.tag_left;
  const bool old_done = r_[DDA_BREG("done_wait_q")] && !tags_left;
  const bool new_wait = w.core_done && (w.ex.wait || w.ey.wait || w.ez.wait);
  const bool new_done = w.core_done && !new_wait;
  r_[DDA_BREG("done_wait_q")] = !w.abort && (new_wait || (r_[DDA_BREG("done_wait_q")] && tags_left));
  const std::uint64_t irq_set = std::uint64_t(old_done || new_done) | std::uint64_t(err_set) << 1 |
                                std::uint64_t(low_set) << 2 | std::uint64_t(w.io_probe) << 3 |
                                std::uint64_t(w.io_home) << 4;
  // Sticky bits: a cause on the edge of a clear stays set.
  r_[DDA_BREG("err_q")] = (r_[DDA_BREG("err_q")] && !w.clear) || err_set;
  r_[DDA_BREG("err_overflow_q")] = (r_[DDA_BREG("err_overflow_q")] && !w.clear) || w.err_overflow;
  r_[DDA_BREG("err_partial_q")] = (r_[DDA_BREG("err_partial_q")] && !w.clear) || w.err_partial;
  r_[DDA_BREG("err_lanes_q")] = (r_[DDA_BREG("err_lanes_q")] && !w.clear) || w.err_lanes;
  r_[DDA_BREG("err_stall_q")] = (r_[DDA_BREG("err_stall_q")] && !w.clear) || w.core_err;
  r_[DDA_BREG("aborted_q")] = (r_[DDA_BREG("aborted_q")] && !w.clear) || w.abort;
  r_[DDA_BREG("err_hard_q")] = (r_[DDA_BREG("err_hard_q")] && !w.clear) || w.hard_stop;
  r_[DDA_BREG("err_watchdog_q")] = (r_[DDA_BREG("err_watchdog_q")] && !w.clear) || w.bite;
  const std::uint64_t w1c = w.wr && w.adr == DDA_REG_OFFSET("IRQ_STATUS") ? (w.wsel & 0x1Fu) : 0;
  r_[DDA_BREG("irq_status_q")] = (r_[DDA_BREG("irq_status_q")] & ~w1c & 0x1Fu) | irq_set;
  if (w.wr && w.adr == DDA_REG_OFFSET("IRQ_ENABLE")) r_[DDA_BREG("irq_enable_q")] = w.wdat & 0x1Fu;
  if (w.wr && w.adr == DDA_REG_OFFSET("IRQ_LEVEL")) r_[DDA_BREG("irq_level_q")] = w.wdat & mask_of(kLevelWidth);
  r_[DDA_BREG("done_count_q")] = (r_[DDA_BREG("done_count_q")] + old_done + new_done) & 0xFFFFFFFFu;
  r_[DDA_BREG("err_count_q")] = (r_[DDA_BREG("err_count_q")] + w.core_err) & 0xFFFFFFFFu;
  load_positions(w);
}

void MotionModel::load_positions(const Wires& w) {
  // A preset is the position before the steps of the same edge: a pulse that starts on
  // the edge of a preset counts from the preset value, so none is lost.
  const auto load = [&](std::uint32_t r, std::size_t q, const StageEdge& e) {
    const std::uint64_t d = e.rise ? (e.rise_dir ? 0xFFFFFFFFu : 1u) : 0u;
    const std::uint64_t p = w.wr && w.adr == r ? w.wdat : r_[q];
    r_[q] = (p + d) & 0xFFFFFFFFu;
  };
  load(DDA_REG_OFFSET("POS_X"), DDA_BREG("pos_x_q"), w.ex);
  load(DDA_REG_OFFSET("POS_Y"), DDA_BREG("pos_y_q"), w.ey);
  if (build_.axes == 3) load(DDA_REG_OFFSET("POS_Z"), DDA_BREG("pos_z_q"), w.ez);
}

void MotionModel::load_feed(const Wires& w) {
  if (w.abort) {
    r_[DDA_BREG("feed_q")] = 0;
    r_[DDA_BREG("acc_q")] = 0;
    r_[DDA_BREG("paced_q")] = 0;
    r_[DDA_BREG("axes_q")] = 0;
    r_[DDA_BREG("route_q")] = 0;
  } else {
    if (w.take) r_[DDA_BREG("feed_q")] = w.entry_feed;
    if (w.advance && !halt()) r_[DDA_BREG("acc_q")] = w.acc_sum & mask_of(kFeedWidth);
    if (w.take) r_[DDA_BREG("paced_q")] = build_.pacer && w.pace.entry.cruise != 0;  // (no pacer: the feed paces)
    r_[DDA_BREG("route_q")] = r_[DDA_BREG("axes_q")];
    if (w.take) r_[DDA_BREG("axes_q")] = w.entry_axes;
  }
}

void MotionModel::load_settings(const Wires& w) {
  for (const char axis : kAxes) {
    if (axis == 'z' && build_.axes == 2) continue;  // not built
    for (const auto& t : kTimingFields) {
      const std::string r = std::string(t.reg) + "_" + char(axis - 'a' + 'A');
      if (w.wr && w.adr == reg_offset(r)) {
        reg(std::string(t.name) + "_" + axis + "_q") = (w.wdat >> field_of(r, t.name).lsb) & mask_of(kTimingWidth);
      }
    }
  }
  if (w.wr && w.adr == DDA_REG_OFFSET("POLARITY"))
    r_[DDA_BREG("polarity_q")] = w.wdat & (build_.axes == 3 ? 0x3Fu : 0x0Fu);
}

void MotionModel::edge(const BlockInputs& in) {
  // Every wire first, from the registers before the edge; then the core's edge, the
  // RAM's write and the block's registers, in that order.
  Wires w = bus_wires(in.bus, in.pins);
  core_wires(in.ce, w);
  step_core(in.rst_n, w);

  if (w.entry_ok) mem_[w.tail][w.word] = in.bus.dat;  // the RAM has no reset
  took_ = false;
  core_ce_ = iterated_ = false;
  rise_x_ = rise_y_ = rise_z_ = 0;
  if (!in.rst_n) {
    r_ = BlockRegs{};
    r_[DDA_BREG("override_q")] = kOverrideOne;
    pacer_ = Pacer{};
    for (const char axis : kAxes) set_stage(axis, stage_reset());
    return;
  }
  note_edge(w);
  load_io(w);  // (first: its latches take the positions, level and count before the edge)
  load_bus(in.bus, w);
  load_queue(w);
  load_status(w);
  load_pace(w);
  load_feed(w);
  load_pace_settings(w);
  set_stage('x', w.ex.next);
  set_stage('y', w.ey.next);
  set_stage('z', w.ez.next);
  load_settings(w);
  load_watchdog(w);
}

}  // namespace dda::motion
