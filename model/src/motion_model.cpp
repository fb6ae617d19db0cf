// SPDX-License-Identifier: Apache-2.0
#include "dda/motion_model.hpp"

#include "dda/errors.hpp"
#include "dda/hw_command.hpp"

namespace dda::motion {

namespace {

// The index of an output port in PortValues (the outputs of kPorts, in order).
constexpr std::size_t out(std::string_view name) {
  std::size_t i = 0;
  for (const auto& p : hw::kPorts) {
    if (p.name == name) return i;
    if (p.dir == hw::PortDir::Out) ++i;
  }
  throw "motion model: no such output";
}

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
  one("busy_o", busy, o.busy);
  one("irq_o", irq, o.irq);
  return d;
}

int width_bits(Width w, int depth_log2) {
  switch (w) {
    case Width::One:
      return 1;
    case Width::Three:
      return 3;
    case Width::Word:
      return 32;
    case Width::Level:
      return kLevelWidth;
    case Width::Index:
      return depth_log2;
    case Width::Entry:
      return kEntryWords;
  }
  return 0;
}

std::string gtkw(std::string_view file, std::string_view top, int depth_log2) {
  const auto reg = [&](std::string_view name, bool is_signed = false) {
    return hw::WaveSignal{std::string(name), width_bits(kBlockRegs[breg(name)].width, depth_log2), is_signed};
  };
  std::vector<hw::WaveGroup> g;
  g.push_back({"Bus",
               {{"wb_cyc_i", 1},
                {"wb_stb_i", 1},
                {"wb_we_i", 1},
                {"wb_adr_i", kAddrWidth},
                {"wb_dat_i", 32},
                {"wb_ack_o", 1},
                {"wb_stall_o", 1},
                {"wb_dat_o", 32}}});
  g.push_back({"Queue", {reg("head_q"), reg("tail_q"), reg("level_q"), reg("mask_q"), reg("primed_q")}});
  g.push_back({"Status",
               {reg("err_q"),
                reg("err_overflow_q"),
                reg("err_partial_q"),
                reg("err_stall_q"),
                reg("aborted_q"),
                reg("irq_status_q"),
                reg("irq_enable_q"),
                reg("irq_level_q"),
                {"irq_o", 1}}});
  g.push_back({"Axes",
               {{"step_x_o", 1},
                {"dir_x_o", 1},
                {"step_y_o", 1},
                {"dir_y_o", 1},
                {"busy_o", 1},
                reg("pos_x_q", true),
                reg("pos_y_q", true),
                reg("done_count_q"),
                reg("err_count_q")}});
  hw::WaveGroup core{"Core", {}};
  for (const auto& r : hw::kSignals) {
    if (r.kind == hw::SigKind::Reg && (r.group == "Control" || r.group == "Counters")) {
      core.signals.push_back({"u_core." + std::string(r.name), r.width, r.show_signed});
    }
  }
  g.push_back(std::move(core));
  return hw::gtkw_file(g, "the DDA motion block", file, top);
}

std::vector<std::uint32_t> entry_words(const Command& c) {
  std::vector<std::uint32_t> w = hw::pack_command(c);
  w.resize(kEntryWords, 0);
  return w;
}

CmdFields entry_fields(const std::vector<std::uint32_t>& words) {
  CmdFields f{};
  int off = 0;
  for (std::size_t i = 0; i < hw::kCmdFields.size(); ++i) {
    const int width = hw::kCmdFields[i].width;
    std::uint64_t v = 0;
    for (int k = 0; k < width; ++k) {
      const int bit = off + k;
      if ((words[std::size_t(bit / 32)] >> (bit % 32)) & 1u) v |= std::uint64_t{1} << k;
    }
    f[i] = v;
    off += width;
  }
  return f;
}

MotionModel::MotionModel(int depth_log2)
    : depth_log2_(depth_log2), mem_(std::size_t{1} << depth_log2, std::vector<std::uint32_t>(kEntryWords, 0)) {
  if (depth_log2 < 1 || depth_log2 > kMaxDepthLog2) throw GuardError("motion model: queue depth out of range");
}

std::uint64_t MotionModel::get(std::string_view name) const { return r_[breg(name)]; }
std::uint64_t& MotionModel::reg(std::string_view name) { return r_[breg(name)]; }

std::uint32_t MotionModel::read(std::uint32_t adr) const {
  const std::uint64_t level = get("level_q");
  const std::uint64_t depth = std::uint64_t{1} << depth_log2_;
  const Signals& s = core_.state();
  if (adr == reg_offset("ID")) return kId;
  if (adr == reg_offset("VERSION")) return std::uint32_t(kVersionMajor) << 16 | std::uint32_t(kVersionMinor);
  if (adr == reg_offset("CONFIG")) {
    return std::uint32_t(kEntryWords) << std::uint32_t(field_of("CONFIG", "entry_words").lsb) |
           std::uint32_t(depth_log2_) << std::uint32_t(field_of("CONFIG", "depth_log2").lsb) |
           std::uint32_t(hw::kAccWidth) << std::uint32_t(field_of("CONFIG", "acc_width").lsb) |
           std::uint32_t(hw::kCntWidth) << std::uint32_t(field_of("CONFIG", "cnt_width").lsb);
  }
  if (adr == reg_offset("STATUS")) {
    const auto bit = [&](std::string_view f, bool v) { return std::uint32_t(v) << field_of("STATUS", f).lsb; };
    return bit("busy", CoreModel::busy(s)) | bit("empty", level == 0) | bit("full", level == depth) |
           bit("err", get("err_q")) | bit("err_overflow", get("err_overflow_q")) |
           bit("err_partial", get("err_partial_q")) | bit("err_stall", get("err_stall_q")) |
           bit("aborted", get("aborted_q")) | std::uint32_t(level) << std::uint32_t(field_of("STATUS", "level").lsb);
  }
  if (adr == reg_offset("IRQ_STATUS")) return std::uint32_t(get("irq_status_q"));
  if (adr == reg_offset("IRQ_ENABLE")) return std::uint32_t(get("irq_enable_q"));
  if (adr == reg_offset("IRQ_LEVEL")) return std::uint32_t(get("irq_level_q"));
  if (adr == reg_offset("DONE_COUNT")) return std::uint32_t(get("done_count_q"));
  if (adr == reg_offset("ERR_COUNT")) return std::uint32_t(get("err_count_q"));
  if (adr == reg_offset("POS_X")) return std::uint32_t(get("pos_x_q"));
  if (adr == reg_offset("POS_Y")) return std::uint32_t(get("pos_y_q"));
  if (adr == reg_offset("ENTRY_MASK")) return std::uint32_t(get("mask_q"));
  return 0;
}

BlockOutputs MotionModel::outputs() const {
  const Signals& s = core_.state();
  const PortValues p = CoreModel::outputs(s, false);
  BlockOutputs o;
  o.ack = o.stall = get("ack_q") != 0;
  o.dat = std::uint32_t(get("dat_q"));
  o.step_x = p[out("step_x_o")] != 0;
  o.step_y = p[out("step_y_o")] != 0;
  o.dir_x = p[out("dir_x_o")] != 0;
  o.dir_y = p[out("dir_y_o")] != 0;
  o.busy = CoreModel::busy(s);
  o.irq = (get("irq_status_q") & get("irq_enable_q")) != 0;
  return o;
}

void MotionModel::edge(const BlockInputs& in) {
  const BusIn& b = in.bus;
  const std::uint64_t depth = std::uint64_t{1} << depth_log2_;
  const std::uint64_t all_words = mask_of(kEntryWords);
  const std::uint32_t adr = b.adr & std::uint32_t(mask_of(kAddrWidth)) & ~3u;

  const bool req = b.cyc && b.stb && !get("ack_q");
  const bool wr = req && b.we;
  const bool wr_ctrl = wr && adr == reg_offset("CTRL");
  const bool commit = wr_ctrl && ((b.dat >> std::uint32_t(field_of("CTRL", "commit").lsb)) & 1u);
  const bool abort = wr_ctrl && ((b.dat >> std::uint32_t(field_of("CTRL", "abort").lsb)) & 1u);
  const bool clear = wr_ctrl && ((b.dat >> std::uint32_t(field_of("CTRL", "clear").lsb)) & 1u);
  const bool in_entry = adr >= kEntryBase && adr < kEntryBase + 4u * kEntryWords;
  const std::uint32_t word = (adr - kEntryBase) >> 2;

  const std::uint64_t level = get("level_q");
  const bool full = level == depth, empty = level == 0;
  const bool mask_all = get("mask_q") == all_words;
  const bool wr_entry = wr && in_entry && !abort;
  const bool entry_ok = wr_entry && !full;
  const bool commit_ok = commit && !abort && !full && mask_all;
  const bool err_overflow = (wr_entry || commit) && !abort && full;
  const bool err_partial = commit && !abort && !full && !mask_all;

  const bool cmd_valid = get("primed_q") && !empty;
  const bool take = cmd_valid && core_.cmd_ready(in.ce) && !abort;
  const std::uint64_t level_d = level + commit_ok - take;

  // The core's outputs during this cycle (registered): what the counters see.
  const Signals& pre = core_.state();
  const PortValues po = CoreModel::outputs(pre, false);
  const bool core_done = CoreModel::done(pre), core_err = CoreModel::err(pre);
  const bool step_x = po[out("step_x_o")] != 0, step_y = po[out("step_y_o")] != 0;
  const bool dir_x = po[out("dir_x_o")] != 0, dir_y = po[out("dir_y_o")] != 0;
  const std::uint32_t rd = read(adr);
  const std::uint64_t head = get("head_q"), tail = get("tail_q");

  CoreInputs ci;
  ci.rst_n = in.rst_n && !abort;
  ci.ce = in.ce;
  ci.cmd_valid = cmd_valid;
  if (cmd_valid) ci.cmd = entry_fields(mem_[head]);
  core_.edge(ci);

  if (entry_ok) mem_[tail][word] = b.dat;  // the RAM has no reset
  took_ = false;
  if (!in.rst_n) {
    r_ = BlockRegs{};
    return;
  }
  took_ = take;
  reg("ack_q") = req;
  if (req && !b.we) reg("dat_q") = rd;
  reg("primed_q") = 1;
  reg("head_q") = abort ? tail : take ? (head + 1) & mask_of(depth_log2_) : head;
  if (abort) {
    reg("level_q") = 0;
    reg("mask_q") = 0;
  } else {
    reg("level_q") = level_d;
    if (commit_ok) {
      reg("tail_q") = (tail + 1) & mask_of(depth_log2_);
      reg("mask_q") = 0;
    } else if (entry_ok) {
      reg("mask_q") |= std::uint64_t{1} << word;
    }
  }
  const bool err_set = err_overflow || err_partial || core_err;
  const bool low_set = take && level_d < get("irq_level_q");
  const std::uint64_t irq_set = std::uint64_t(core_done) | std::uint64_t(err_set) << 1 | std::uint64_t(low_set) << 2;
  reg("err_q") = (get("err_q") && !clear) || err_set;
  reg("err_overflow_q") = (get("err_overflow_q") && !clear) || err_overflow;
  reg("err_partial_q") = (get("err_partial_q") && !clear) || err_partial;
  reg("err_stall_q") = (get("err_stall_q") && !clear) || core_err;
  reg("aborted_q") = (get("aborted_q") && !clear) || abort;
  const std::uint64_t w1c = wr && adr == reg_offset("IRQ_STATUS") ? (b.dat & 7u) : 0;
  reg("irq_status_q") = (get("irq_status_q") & ~w1c & 7u) | irq_set;
  if (wr && adr == reg_offset("IRQ_ENABLE")) reg("irq_enable_q") = b.dat & 7u;
  if (wr && adr == reg_offset("IRQ_LEVEL")) reg("irq_level_q") = b.dat & mask_of(kLevelWidth);
  reg("done_count_q") = (get("done_count_q") + core_done) & 0xFFFFFFFFu;
  reg("err_count_q") = (get("err_count_q") + core_err) & 0xFFFFFFFFu;
  const std::uint64_t dx = step_x ? (dir_x ? 0xFFFFFFFFu : 1u) : 0u;
  const std::uint64_t dy = step_y ? (dir_y ? 0xFFFFFFFFu : 1u) : 0u;
  const std::uint64_t px = wr && adr == reg_offset("POS_X") ? b.dat : get("pos_x_q");
  const std::uint64_t py = wr && adr == reg_offset("POS_Y") ? b.dat : get("pos_y_q");
  reg("pos_x_q") = (px + dx) & 0xFFFFFFFFu;
  reg("pos_y_q") = (py + dy) & 0xFFFFFFFFu;
}

}  // namespace dda::motion
