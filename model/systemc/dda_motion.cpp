// SPDX-License-Identifier: Apache-2.0
#include "model/systemc/dda_motion.hpp"

#include <algorithm>

#include "model/datapath/errors.hpp"

namespace dda::sc {

namespace {

using motion::kEntryWords;

const std::uint32_t kCtrl = motion::reg_offset("CTRL"), kIrqStatus = motion::reg_offset("IRQ_STATUS"),
                    kIrqEnable = motion::reg_offset("IRQ_ENABLE"), kIrqLevel = motion::reg_offset("IRQ_LEVEL"),
                    kPosX = motion::reg_offset("POS_X"), kPosY = motion::reg_offset("POS_Y"),
                    kPosZ = motion::reg_offset("POS_Z");
const std::string kAxisSuffix[] = {"_X", "_Y", "_Z"};
constexpr std::uint32_t kAdrMask = ((1u << motion::kAddrWidth) - 1) & ~3u;  // the word address the block decodes

// The bytes of the lanes selected.
std::uint32_t lane_mask(std::uint32_t sel) {
  std::uint32_t m = 0;
  for (int k = 0; k < 4; ++k)
    if ((sel >> k) & 1u) m |= 0xFFu << (8 * k);
  return m;
}

cmd_t entry_bits(const std::vector<std::uint32_t>& w) {
  cmd_t c;
  for (int b = 0; b < hw::kCmdWidth; ++b) c[b] = bool((w[std::size_t(b / 32)] >> (b % 32)) & 1u);
  return c;
}

}  // namespace

dda_motion::dda_motion(sc_core::sc_module_name name, const motion::Build& build)
    : sc_core::sc_module(name),
      u_io("u_io", build),
      build_(build),
      depth_log2_(build.depth_log2),
      mem_(std::size_t{1} << build.depth_log2, std::vector<std::uint32_t>(kEntryWords, 0)),
      rd_row_q(motion::kRowWords, 0),
      row0_q(motion::kRowWords, 0) {
  if (build.depth_log2 < 1 || build.depth_log2 > motion::kMaxDepthLog2 || (build.axes != 2 && build.axes != 3))
    throw GuardError("dda_motion: a build out of range (" + motion::build_spec(build) + ")");
  u_core.clk_i(clk_i);
  u_core.rst_ni(core_rst_n);
  u_core.ce_i(core_ce);
  u_core.cmd_valid_i(cmd_valid);
  u_core.cmd_ready_o(core_ready);
  u_core.cmd_i(entry);
  u_core.step_x_o(c_step_x);
  u_core.step_y_o(c_step_y);
  u_core.dir_x_o(c_dir_x);
  u_core.dir_y_o(c_dir_y);
  u_core.step_z_o(c_step_z);
  u_core.dir_z_o(c_dir_z);
  u_core.busy_o(core_busy);
  u_core.done_o(core_done);
  u_core.err_o(core_err);
  u_core.iter_o(core_iter);
  u_core.norm_v_x_o(norm_v_x);
  u_core.norm_v_y_o(norm_v_y);
  u_core.norm_v_z_o(norm_v_z);
  u_core.norm_cap_o(norm_cap);
  u_core.norm_cap_z_o(norm_cap_z);
  bind_stages();
  bind_pace();
  bind_io();

  SC_METHOD(comb);
  sensitive << rst_ni << wb_cyc_i << wb_stb_i << wb_we_i << wb_adr_i << wb_dat_i << wb_sel_i << ack_q << dat_q
            << fetch_q << level_q << core_busy << irq_status_q << irq_enable_q << ce_i << feed_q << acc_q << polarity_q
            << stw.sx_step << stw.sx_dir << stw.sx_hold << stw.sx_busy << stw.sy_step << stw.sy_dir << stw.sy_hold
            << stw.sy_busy << stw.sz_step << stw.sz_dir << stw.sz_hold << stw.sz_busy << c_step_x << c_step_y
            << c_step_z << c_dir_x << c_dir_y << c_dir_z << route_q << core_ready << pace_iterate << paced_q
            << feed_hold_q << stopping_q << pace_speed << iow.io_hard << iow.io_rd << stw.sx_pend << stw.sy_pend
            << stw.sz_pend << stw.sx_pdir << stw.sy_pdir << stw.sz_pdir;
  SC_METHOD(seq);
  sensitive << clk_i.pos();
  dont_initialize();
}

void dda_motion::comb() {
  const bool req = wb_cyc_i.read() && wb_stb_i.read() && !ack_q.read();
  const std::uint32_t adr = wb_adr_i.read() & kAdrMask;
  const std::uint32_t wsel = wb_dat_i.read() & lane_mask(wb_sel_i.read());
  const auto ctrl = [&](std::string_view f) {
    return req && wb_we_i.read() && adr == kCtrl && ((wsel >> std::uint32_t(motion::field_of("CTRL", f).lsb)) & 1u);
  };
  // A soft stop at rest with no step on its way flushes as an abort does.
  const bool soft_flush =
      stopping_q.read() && pace_speed.read() == 0 && !(stw.sx_busy.read() || stw.sy_busy.read() || stw.sz_busy.read());
  const bool abort = ctrl("abort") || ctrl("hard_stop") || soft_flush || iow.io_hard.read();
  flush.write(abort);
  core_rst_n.write(rst_ni.read() && !abort);
  io_rst_n.write(rst_ni.read() && build_.inputs);             // u_io not built: held in reset
  pace_rst_n.write(rst_ni.read() && !abort && build_.pacer);  // u_pace's: the core's, or held
  cmd_valid.write(fetch_q.read() == 2 && level_q.read() != 0);
  // A timing written on this edge holds the core once (the stages' look-ahead used the old).
  const bool wr = req && wb_we_i.read();
  const bool wr_timing = wr && (adr == motion::reg_offset("STEP_X") || adr == motion::reg_offset("DIR_X") ||
                                adr == motion::reg_offset("STEP_Y") || adr == motion::reg_offset("DIR_Y") ||
                                adr == motion::reg_offset("STEP_Z") || adr == motion::reg_offset("DIR_Z"));
  const bool held = stw.sx_hold.read() || stw.sy_hold.read() || stw.sz_hold.read() || wr_timing;
  hold.write(held);
  const bool adv = ce_i.read() && !held;
  advance.write(adv);
  const std::uint64_t feed = feed_q.read(), sum = acc_q.read() + feed;
  const bool running_paced = core_busy.read() && paced_q.read();
  pace_running.write(running_paced);
  const bool halt = feed_hold_q.read() || stopping_q.read();  // the pace heads for rest
  pace_halt.write(halt);
  core_ce.write(running_paced ? pace_iterate.read()
                              : adv && !halt && (feed == 0 || ((sum >> motion::kFeedWidth) & 1u) != 0));
  const bool tk = fetch_q.read() == 2 && level_q.read() != 0 && core_ready.read() && !abort;
  take.write(tk);
  next_queued.write(level_q.read() > (tk ? 1u : 0u));
  stepped.write(c_step_x.read() || c_step_y.read() || c_step_z.read());
  wb_ack_o.write(ack_q.read());
  wb_stall_o.write(ack_q.read());
  wb_dat_o.write(dat_q.read());
  const std::uint32_t pol = polarity_q.read();
  const auto inv = [pol](std::string_view f) { return ((pol >> motion::field_of("POLARITY", f).lsb) & 1u) != 0; };
  step_x_o.write(stw.sx_step.read() != inv("step_x"));
  step_y_o.write(stw.sy_step.read() != inv("step_y"));
  dir_x_o.write(stw.sx_dir.read() != inv("dir_x"));
  dir_y_o.write(stw.sy_dir.read() != inv("dir_y"));
  step_z_o.write(stw.sz_step.read() != inv("step_z"));
  dir_z_o.write(stw.sz_dir.read() != inv("dir_z"));
  busy_o.write(core_busy.read() || stw.sx_busy.read() || stw.sy_busy.read() || stw.sz_busy.read());
  // Stage j takes the core's axis (j - route) mod 3 (route 3 as 0).
  const std::array<bool, 3> cs{c_step_x.read(), c_step_y.read(), c_step_z.read()};
  const std::array<bool, 3> cd{c_dir_x.read(), c_dir_y.read(), c_dir_z.read()};
  const std::size_t route = route_q.read() == 3 ? 0 : std::size_t(route_q.read());
  const std::array<sc_core::sc_signal<bool>*, 3> st{&step_x, &step_y, &step_z}, di{&dir_x, &dir_y, &dir_z};
  std::uint32_t r_step = 0, r_dir = 0;
  for (std::size_t j = 0; j < 3; ++j) {
    const bool built = j < 2 || build_.axes == 3;  // (2 axes: the Z stage takes nothing)
    st[j]->write(built && cs[(j + 3 - route) % 3]);
    di[j]->write(built && cd[(j + 3 - route) % 3]);
    r_step |= std::uint32_t(cs[(j + 3 - route) % 3]) << j;
    r_dir |= std::uint32_t(cd[(j + 3 - route) % 3]) << j;
  }
  comb_io(req && wb_we_i.read(), adr, wsel, lane_mask(wb_sel_i.read()), r_step, r_dir);
  irq_o.write((irq_status_q.read() & irq_enable_q.read()) != 0);
}

std::uint32_t dda_motion::read(std::uint32_t adr) const {
  const std::uint32_t level = level_q.read(), depth = 1u << depth_log2_;
  if (adr == motion::reg_offset("ID")) return motion::kId;
  if (adr == motion::reg_offset("VERSION")) return std::uint32_t(motion::kVersionMajor) << 16 | motion::kVersionMinor;
  if (adr == motion::reg_offset("CONFIG")) {
    return std::uint32_t(kEntryWords) << std::uint32_t(motion::field_of("CONFIG", "entry_words").lsb) |
           std::uint32_t(depth_log2_) << std::uint32_t(motion::field_of("CONFIG", "depth_log2").lsb) |
           std::uint32_t(motion::kEntryRows) << std::uint32_t(motion::field_of("CONFIG", "entry_rows").lsb) |
           std::uint32_t(hw::kAccWidth) << std::uint32_t(motion::field_of("CONFIG", "acc_width").lsb) |
           std::uint32_t(hw::kCntWidth) << std::uint32_t(motion::field_of("CONFIG", "cnt_width").lsb) |
           std::uint32_t(build_.inputs) << std::uint32_t(motion::field_of("CONFIG", "inputs").lsb) |
           std::uint32_t(build_.axes) << std::uint32_t(motion::field_of("CONFIG", "axes").lsb) |
           std::uint32_t(build_.pacer) << std::uint32_t(motion::field_of("CONFIG", "pacer").lsb);
  }
  if (adr == motion::reg_offset("STATUS")) {
    const auto bit = [](std::string_view f, bool v) { return std::uint32_t(v) << motion::field_of("STATUS", f).lsb; };
    return bit("busy", core_busy.read() || stw.sx_busy.read() || stw.sy_busy.read() || stw.sz_busy.read()) |
           bit("empty", level == 0) | bit("full", level == depth) | bit("err", err_q.read()) |
           bit("err_overflow", err_overflow_q.read()) | bit("err_partial", err_partial_q.read()) |
           bit("err_stall", err_stall_q.read()) | bit("aborted", aborted_q.read()) |
           bit("err_lanes", err_lanes_q.read()) | bit("holding", feed_hold_q.read() && pace_speed.read() != 0) |
           bit("held", feed_hold_q.read() && pace_speed.read() == 0) | bit("stopping", stopping_q.read()) |
           bit("err_hard_stop", err_hard_q.read()) | bit("err_watchdog", err_watchdog_q.read()) |
           bit("err_estop", iow.io_err_estop.read()) | bit("err_limit", iow.io_err_limit.read()) |
           bit("probe_armed", iow.io_probe_armed.read()) | bit("probed", iow.io_probed.read()) |
           level << std::uint32_t(motion::field_of("STATUS", "level").lsb);
  }
  if (adr == kIrqStatus) return irq_status_q.read();
  if (adr == kIrqEnable) return irq_enable_q.read();
  if (adr == kIrqLevel) return irq_level_q.read();
  if (adr == motion::reg_offset("DONE_COUNT")) return done_count_q.read();
  if (adr == motion::reg_offset("ERR_COUNT")) return err_count_q.read();
  if (adr == kPosX) return pos_x_q.read();
  if (adr == kPosY) return pos_y_q.read();
  if (adr == kPosZ) return pos_z_q.read();
  if (adr == motion::reg_offset("ENTRY_MASK")) return mask_q.read();
  if (adr == motion::reg_offset("POLARITY")) return polarity_q.read();
  if (adr == motion::reg_offset("ACCEL")) return accel_q.read();
  if (adr == motion::reg_offset("VMIN")) return vmin_q.read();
  if (adr == motion::reg_offset("OVERRIDE")) return override_q.read();
  if (adr == motion::reg_offset("WATCHDOG")) return wd_q.read();
  std::uint32_t v = 0;
  const auto regs = timing_regs();
  for (std::size_t i = 0; i < regs.size(); ++i) {
    const auto& t = motion::kTimingFields[i % motion::kTimingFields.size()];
    const std::string r = std::string(t.reg) + kAxisSuffix[i / motion::kTimingFields.size()];
    if (adr == motion::reg_offset(r)) v |= regs[i]->read() << motion::field_of(r, t.name).lsb;
  }
  return v | iow.io_rd.read();  // u_io's registers (0 at other addresses)
}

std::array<sc_core::sc_signal<std::uint32_t>*, 12> dda_motion::timing_regs() const {
  auto* m = const_cast<dda_motion*>(this);  // (the const reads of read() and the writes of seq_settings())
  return {&m->steplen_x_q,  &m->stepspace_x_q, &m->dirsetup_x_q, &m->dirhold_x_q,   &m->steplen_y_q,  &m->stepspace_y_q,
          &m->dirsetup_y_q, &m->dirhold_y_q,   &m->steplen_z_q,  &m->stepspace_z_q, &m->dirsetup_z_q, &m->dirhold_z_q};
}

// seq() in parts, in the order it runs them: the decode, the RAM lanes, then the reset or
// the registers group by group as rtl/dda_motion.v's always blocks hold them. First the
// decode of this edge's bus request and queue (the RTL's wires), read from the ports and
// registers before the edge.
struct dda_motion::Decode {
  // dat: the write data; wsel: in the byte lanes selected; wdat: merged with the addressed
  // register's value in the others.
  std::uint32_t adr = 0, dat = 0, wsel = 0, wdat = 0, word = 0, tail = 0, level_d = 0, head_d = 0, fetch_d = 0;
  bool req = false, wr = false, abort = false, clear = false, hard_stop = false, soft_stop = false, bite = false;
  bool entry_ok = false, commit_ok = false, err_overflow = false, err_partial = false, err_lanes = false, take = false;
};

dda_motion::Decode dda_motion::decode() const {
  const std::uint32_t depth = 1u << depth_log2_, imask = depth - 1;
  const std::uint32_t all_words = std::uint32_t((std::uint64_t{1} << kEntryWords) - 1);
  Decode d;
  d.req = wb_cyc_i.read() && wb_stb_i.read() && !ack_q.read();
  d.wr = d.req && wb_we_i.read();
  d.adr = wb_adr_i.read() & kAdrMask;
  d.dat = wb_dat_i.read();
  const std::uint32_t lanes = lane_mask(wb_sel_i.read());
  d.wsel = d.dat & lanes;
  if (d.wr) d.wdat = (read(d.adr) & ~lanes) | d.wsel;  // (it reads the whole map: only for a write)
  const bool wr_ctrl = d.wr && d.adr == kCtrl;
  const bool commit = wr_ctrl && ((d.wsel >> std::uint32_t(motion::field_of("CTRL", "commit").lsb)) & 1u);
  const auto bit = [&](std::string_view f) {
    return wr_ctrl && ((d.wsel >> std::uint32_t(motion::field_of("CTRL", f).lsb)) & 1u) != 0;
  };
  d.hard_stop = bit("hard_stop");
  d.soft_stop = bit("soft_stop");
  d.abort = bit("abort") || d.hard_stop || flush.read();  // flush: the abort wire, soft flush included
  d.bite = !(d.wr && d.adr == motion::reg_offset("WATCHDOG")) && wd_cnt_q.read() == 1;
  d.clear = wr_ctrl && ((d.wsel >> std::uint32_t(motion::field_of("CTRL", "clear").lsb)) & 1u);
  const bool in_entry = d.adr >= motion::kEntryBase && d.adr < motion::kEntryBase + 4u * kEntryWords;
  d.word = (d.adr - motion::kEntryBase) >> 2;
  const std::uint32_t level = level_q.read(), head = head_q.read();
  d.tail = tail_q.read();
  const bool full = level == depth;
  const bool mask_all = mask_q.read() == all_words;
  const bool wr_entry = d.wr && in_entry && !d.abort;
  const bool all_lanes = (wb_sel_i.read() & 0xFu) == 0xFu;
  d.entry_ok = wr_entry && !full && all_lanes;
  d.err_lanes = wr_entry && !all_lanes;
  d.commit_ok = commit && !d.abort && !full && mask_all;
  d.err_overflow = (wr_entry || commit) && !d.abort && full;
  d.err_partial = commit && !d.abort && !full && !mask_all;
  d.take = cmd_valid.read() && core_ready.read() && !d.abort;
  d.level_d = level + d.commit_ok - d.take;
  d.head_d = !rst_ni.read() ? 0 : d.abort ? d.tail : d.take ? (head + 1) & imask : head;
  // Row 0 of the head after it moves, while the queue is empty and after reset; else row 1.
  const bool refetch = !rst_ni.read() || level == 0 || d.take || d.abort || fetch_q.read() == 0;
  d.fetch_d = refetch ? 1 : 2;
  return d;
}

// The RAM lanes: row 0 kept when the output holds it, the row fetch_d of the next head
// read, then this edge's entry word written; the command of the two rows to the core.
void dda_motion::seq_ram(const Decode& d) {
  if (fetch_q.read() == 1) row0_q = rd_row_q;
  const std::size_t first = d.fetch_d == 2 ? motion::kRowWords : 0;
  const auto& slot = mem_[d.head_d];
  for (std::size_t k = 0; k < rd_row_q.size(); ++k)
    rd_row_q[k] = first + k < slot.size() ? slot[first + k] : 0;  // read before this edge's write
  if (d.entry_ok) mem_[d.tail][d.word] = d.dat;
  std::vector<std::uint32_t> words(row0_q);
  words.insert(words.end(), rd_row_q.begin(), rd_row_q.end());
  cmd_t bits = entry_bits(words);
  if (build_.axes == 2) {  // the core's linear axis not built: its fields as an idle axis's
    CmdFields f{};
    int off = 0;
    for (std::size_t i = 0; i < hw::kCmdFields.size(); off += hw::kCmdFields[i].width, ++i)
      for (int b = 0; b < hw::kCmdFields[i].width; ++b) f[i] |= std::uint64_t(bits[off + b].to_bool()) << b;
    f = motion::idle_linear_axis(f);
    off = 0;
    for (std::size_t i = 0; i < hw::kCmdFields.size(); off += hw::kCmdFields[i].width, ++i)
      for (int b = 0; b < hw::kCmdFields[i].width; ++b) bits[off + b] = bool((f[i] >> b) & 1u);
  }
  entry.write(bits);
  entry_feed.write(
      std::uint32_t((words[motion::kFeedWord] >> motion::kFeedLsb) & ((std::uint64_t{1} << motion::kFeedWidth) - 1)));
  entry_axes.write(build_.axes == 3 ? (words[motion::kAxesWord] >> motion::kAxesLsb) & ((1u << motion::kAxesWidth) - 1)
                                    : 0u);
  for (std::size_t i = 0; i < entry_pace.size(); ++i) entry_pace[i].write(words[std::size_t(motion::kPaceWord) + i]);
}

void dda_motion::seq_reset() {
  for (auto* s : {&ack_q, &done_wait_q, &err_q, &err_overflow_q, &err_partial_q, &err_stall_q, &aborted_q, &err_lanes_q,
                  &stopping_q, &err_hard_q, &err_watchdog_q})
    s->write(false);
  for (auto* s :
       {&dat_q,       &head_q,        &tail_q,       &level_q,     &mask_q,      &irq_status_q,  &irq_enable_q,
        &irq_level_q, &done_count_q,  &err_count_q,  &pos_x_q,     &pos_y_q,     &feed_q,        &acc_q,
        &steplen_x_q, &stepspace_x_q, &dirsetup_x_q, &dirhold_x_q, &steplen_y_q, &stepspace_y_q, &dirsetup_y_q,
        &dirhold_y_q, &polarity_q,    &pos_z_q,      &fetch_q,     &steplen_z_q, &stepspace_z_q, &dirsetup_z_q,
        &dirhold_z_q, &axes_q,        &route_q,      &accel_q,     &vmin_q,      &wd_q,          &wd_cnt_q})
    s->write(0);
  paced_q.write(false);
  feed_hold_q.write(false);
  override_q.write(motion::kOverrideOne);
}

// ack_q, dat_q.
void dda_motion::seq_bus(const Decode& d) {
  ack_q.write(d.req);
  if (d.req && !wb_we_i.read()) dat_q.write(read(d.adr));
}

// fetch_q, head_q, level_q, tail_q, mask_q.
void dda_motion::seq_queue(const Decode& d) {
  const std::uint32_t imask = (1u << depth_log2_) - 1;
  fetch_q.write(d.fetch_d);
  head_q.write(d.head_d);
  if (d.abort) {
    level_q.write(0);
    mask_q.write(0);
  } else {
    level_q.write(d.level_d);
    if (d.commit_ok) {
      tail_q.write((d.tail + 1) & imask);
      mask_q.write(0);
    } else if (d.entry_ok) {
      mask_q.write(mask_q.read() | (1u << d.word));
    }
  }
}

// done_wait_q, the sticky errors, the interrupt registers, the counters and positions.
void dda_motion::seq_status(const Decode& d) {
  // A piece is done once its last steps (tagged on the core's done_o) have left.
  const bool tags_left = stw.sx_tag_left.read() || stw.sy_tag_left.read() || stw.sz_tag_left.read();
  const bool old_done = done_wait_q.read() && !tags_left;
  const bool new_wait = core_done.read() && (stw.sx_wait.read() || stw.sy_wait.read() || stw.sz_wait.read());
  const bool new_done = core_done.read() && !new_wait;
  const bool cdone = old_done || new_done, cerr = core_err.read();
  done_wait_q.write(!d.abort && (new_wait || (done_wait_q.read() && tags_left)));
  const bool err_set =
      d.err_overflow || d.err_partial || d.err_lanes || cerr || d.hard_stop || d.bite || iow.io_err.read();
  const bool low_set = d.take && d.level_d < irq_level_q.read();
  const std::uint32_t irq_set = std::uint32_t(cdone) | std::uint32_t(err_set) << 1 | std::uint32_t(low_set) << 2 |
                                std::uint32_t(iow.io_probe.read()) << 3 | std::uint32_t(iow.io_home.read()) << 4;
  // Sticky bits: a cause on the edge of a clear stays set.
  err_q.write((err_q.read() && !d.clear) || err_set);
  err_overflow_q.write((err_overflow_q.read() && !d.clear) || d.err_overflow);
  err_partial_q.write((err_partial_q.read() && !d.clear) || d.err_partial);
  err_lanes_q.write((err_lanes_q.read() && !d.clear) || d.err_lanes);
  err_stall_q.write((err_stall_q.read() && !d.clear) || cerr);
  aborted_q.write((aborted_q.read() && !d.clear) || d.abort);
  err_hard_q.write((err_hard_q.read() && !d.clear) || d.hard_stop);
  err_watchdog_q.write((err_watchdog_q.read() && !d.clear) || d.bite);
  const std::uint32_t w1c = d.wr && d.adr == kIrqStatus ? (d.wsel & 0x1Fu) : 0u;
  irq_status_q.write((irq_status_q.read() & ~w1c & 0x1Fu) | irq_set);
  if (d.wr && d.adr == kIrqEnable) irq_enable_q.write(d.wdat & 0x1Fu);
  if (d.wr && d.adr == kIrqLevel) irq_level_q.write(d.wdat & ((1u << motion::kLevelWidth) - 1));
  done_count_q.write(done_count_q.read() + std::uint32_t(old_done) + std::uint32_t(new_done));
  err_count_q.write(err_count_q.read() + cerr);
  const std::uint32_t dx = stw.sx_rise.read() ? (stw.sx_rise_dir.read() ? 0xFFFFFFFFu : 1u) : 0u;
  const std::uint32_t dy = stw.sy_rise.read() ? (stw.sy_rise_dir.read() ? 0xFFFFFFFFu : 1u) : 0u;
  const std::uint32_t dz = stw.sz_rise.read() ? (stw.sz_rise_dir.read() ? 0xFFFFFFFFu : 1u) : 0u;
  // A preset is the position before the steps of the same edge: a pulse that starts on
  // the edge of a preset counts from the preset value, so none is lost.
  pos_x_q.write((d.wr && d.adr == kPosX ? d.wdat : pos_x_q.read()) + dx);
  pos_y_q.write((d.wr && d.adr == kPosY ? d.wdat : pos_y_q.read()) + dy);
  if (build_.axes == 3) pos_z_q.write((d.wr && d.adr == kPosZ ? d.wdat : pos_z_q.read()) + dz);
}

// feed_q, acc_q: the phase accumulator that paces the core; axes_q, route_q: which
// stage each of the core's axes drives (route_q: axes_q a clock later, as the core's
// step outputs show the iteration of the edge before).
void dda_motion::seq_feed(const Decode& d) {
  const std::uint64_t fmask = (std::uint64_t{1} << motion::kFeedWidth) - 1;
  if (d.abort) {
    feed_q.write(0);
    acc_q.write(0);
    paced_q.write(false);
    axes_q.write(0);
    route_q.write(0);
  } else {
    route_q.write(axes_q.read());
    if (d.take) axes_q.write(entry_axes.read());
    if (d.take) feed_q.write(entry_feed.read());
    if (d.take) paced_q.write(build_.pacer && entry_pace[0].read() != 0);  // (no pacer: the feed paces)
    if (ce_i.read() && !hold.read() && !pace_halt.read())                  // (a feed hold or a soft stop)
      acc_q.write(std::uint32_t((std::uint64_t{acc_q.read()} + feed_q.read()) & fmask));
  }
}

// The step/dir timings and polarity_q.
void dda_motion::seq_settings(const Decode& d) {
  const std::uint32_t tmask = (1u << motion::kTimingWidth) - 1;
  const auto regs = timing_regs();
  for (std::size_t i = 0; i < regs.size(); ++i) {
    const auto& t = motion::kTimingFields[i % motion::kTimingFields.size()];
    const std::string r = std::string(t.reg) + kAxisSuffix[i / motion::kTimingFields.size()];
    const bool built = i / motion::kTimingFields.size() < 2 || build_.axes == 3;  // (2 axes: Z's not built)
    if (built && d.wr && d.adr == motion::reg_offset(r))
      regs[i]->write((d.wdat >> motion::field_of(r, t.name).lsb) & tmask);
  }
  if (d.wr && d.adr == motion::reg_offset("POLARITY")) polarity_q.write(d.wdat & (build_.axes == 3 ? 0x3Fu : 0x0Fu));
}

// A feed hold outlasts an abort: a held machine stays held until CTRL.resume.
void dda_motion::seq_pace_settings(const Decode& d) {
  const bool ctrl = d.wr && d.adr == kCtrl;
  const auto bit = [&](std::string_view f) {
    return ctrl && ((d.wsel >> std::uint32_t(motion::field_of("CTRL", f).lsb)) & 1u) != 0;
  };
  feed_hold_q.write(bit("hold") || (feed_hold_q.read() && !bit("resume")));
  const bool pace_wr = d.wr && build_.pacer;  // (no pacer: ACCEL, VMIN, OVERRIDE keep their reset values)
  if (pace_wr && d.adr == motion::reg_offset("ACCEL")) accel_q.write(d.wdat);
  if (pace_wr && d.adr == motion::reg_offset("VMIN")) vmin_q.write(d.wdat);
  if (pace_wr && d.adr == motion::reg_offset("OVERRIDE")) override_q.write(std::min(d.wdat, 2 * motion::kOverrideOne));
  // The soft stop runs until its flush; the watchdog counts down from each write.
  stopping_q.write(!d.abort && (stopping_q.read() || d.soft_stop || d.bite || iow.io_soft.read()));
  if (d.wr && d.adr == motion::reg_offset("WATCHDOG")) {
    wd_q.write(d.wdat);
    wd_cnt_q.write(d.wdat);
  } else if (wd_cnt_q.read() != 0) {
    wd_cnt_q.write(wd_cnt_q.read() - 1);
  }
}

void dda_motion::seq() {
  const Decode d = decode();
  seq_ram(d);
  if (!rst_ni.read()) {
    seq_reset();
    return;
  }
  seq_bus(d);
  seq_queue(d);
  seq_status(d);
  seq_feed(d);
  seq_settings(d);
  seq_pace_settings(d);
}

}  // namespace dda::sc
