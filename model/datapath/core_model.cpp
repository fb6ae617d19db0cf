// SPDX-License-Identifier: Apache-2.0
// The cycle-level reference model: the next-state code of every register of the table.
#include "model/datapath/core_model.hpp"

#include <array>
#include <iterator>

namespace dda {

namespace {

using hw::sig;

// Register indices (a name missing from hw::kSignals does not compile).
constexpr std::size_t kJvX = sig("u_int_x.jv_q"), kJrX = sig("u_int_x.jr_q");
constexpr std::size_t kIncXX = sig("u_int_x.inc_on_x_q"), kIncXY = sig("u_int_x.inc_on_y_q");
constexpr std::size_t kJvY = sig("u_int_y.jv_q"), kJrY = sig("u_int_y.jr_q");
constexpr std::size_t kIncYX = sig("u_int_y.inc_on_x_q"), kIncYY = sig("u_int_y.inc_on_y_q");
constexpr std::size_t kCntX = sig("u_cnt_x.cnt_q"), kCntY = sig("u_cnt_y.cnt_q");
constexpr std::size_t kCap = sig("cap_q");
constexpr std::size_t kCdirX = sig("cdir_x_q"), kCdirY = sig("cdir_y_q");
constexpr std::size_t kDirX = sig("dir_x_q"), kDirY = sig("dir_y_q");
constexpr std::size_t kStepX = sig("step_x_q"), kStepY = sig("step_y_q");
constexpr std::size_t kState = sig("u_ctrl.state_q"), kDone = sig("u_ctrl.done_q");
constexpr std::size_t kErr = sig("u_ctrl.err_q"), kIter = sig("u_ctrl.iter_q");
constexpr std::size_t kSumX = sig("u_int_x.sum"), kSumY = sig("u_int_y.sum");
constexpr std::size_t kJvZ = sig("u_lin_z.jv_q"), kJrZ = sig("u_lin_z.jr_q"), kCapZ = sig("u_lin_z.cap_q");
constexpr std::size_t kCntZ = sig("u_cnt_z.cnt_q"), kCdirZ = sig("cdir_z_q"), kDirZ = sig("dir_z_q");
constexpr std::size_t kStepZ = sig("step_z_q"), kSumZ = sig("u_lin_z.sum");

// What a load takes from the command word: register <- field.
struct Load {
  std::size_t reg, field;
};
constexpr Load kLoads[] = {
    {kJvX, hw::field("jv_x")},         {kJvY, hw::field("jv_y")},         {kJrX, hw::field("jr_x")},
    {kJrY, hw::field("jr_y")},         {kCap, hw::field("cap")},          {kCntX, hw::field("cnt_x")},
    {kCntY, hw::field("cnt_y")},       {kCdirX, hw::field("dir_x")},      {kCdirY, hw::field("dir_y")},
    {kIncXX, hw::field("inc_x_on_x")}, {kIncXY, hw::field("inc_x_on_y")}, {kIncYX, hw::field("inc_y_on_x")},
    {kIncYY, hw::field("inc_y_on_y")}, {kJvZ, hw::field("jv_z")},         {kJrZ, hw::field("jr_z")},
    {kCapZ, hw::field("cap_z")},       {kCntZ, hw::field("cnt_z")},       {kCdirZ, hw::field("dir_z")},
};
static_assert(std::size(kLoads) == hw::kCmdFields.size(), "core_model.cpp: a command field is not loaded");

constexpr std::size_t kWritten[] = {kJvX,   kJrX,   kIncXX, kIncXY, kJvY,   kJrY,   kIncYX, kIncYY, kCntX, kCntY, kCap,
                                    kCdirX, kCdirY, kDirX,  kDirY,  kStepX, kStepY, kState, kDone,  kErr,  kIter, kSumX,
                                    kSumY,  kJvZ,   kJrZ,   kCapZ,  kCntZ,  kCdirZ, kDirZ,  kStepZ, kSumZ};
// Every signal of the table has its next-state code here.
constexpr bool covers_table() {
  for (std::size_t i = 0; i < hw::kNumSignals; ++i) {
    bool found = false;
    for (const std::size_t w : kWritten) found = found || w == i;
    if (!found) return false;
  }
  return true;
}
static_assert(covers_table(), "core_model.cpp: a signal of hw::kSignals has no next-state code");

std::uint64_t mask(std::int64_t v, int width) {
  return width >= 64 ? std::uint64_t(v) : std::uint64_t(v) & ((std::uint64_t{1} << width) - 1);
}
std::uint64_t put(std::size_t i, std::int64_t v) { return mask(v, hw::kSignals[i].width); }
// A two's complement register as a signed value.
std::int64_t sext(std::uint64_t v, int width) {
  const std::uint64_t neg = std::uint64_t{1} << (width - 1);
  return std::int64_t(v & ((neg << 1) - 1)) - std::int64_t((v & neg) << 1);
}
std::int64_t sval(const Signals& s, std::size_t i) { return sext(s[i], hw::kSignals[i].width); }
std::int64_t uval(const Signals& s, std::size_t i) { return std::int64_t(s[i]); }

constexpr std::uint64_t kRun = unsigned(hw::State::Run), kIdle = unsigned(hw::State::Idle);

// The command the registers hold (for the datapath's next-state function).
Command held_command(const Signals& s) {
  Command c;
  c.cap = uval(s, kCap);
  c.inc_x_on_x = sval(s, kIncXX);
  c.inc_x_on_y = sval(s, kIncXY);
  c.inc_y_on_x = sval(s, kIncYX);
  c.inc_y_on_y = sval(s, kIncYY);
  c.dir_x_neg = s[kCdirX] != 0;
  c.dir_y_neg = s[kCdirY] != 0;
  c.jv_z = uval(s, kJvZ);
  c.cap_z = uval(s, kCapZ);
  c.dir_z_neg = s[kCdirZ] != 0;
  return c;
}

struct Decision {
  bool run_ce, finished, stalled, iterate;
};
Decision decide(const Signals& s, bool ce) {
  Decision d{};
  d.run_ce = s[kState] == kRun && ce;
  const RegState r = CoreModel::datapath_regs(s);
  d.finished = d.run_ce && dda::finished(r);
  d.stalled = d.run_ce && !d.finished && dda::stalled(held_command(s), r);
  d.iterate = d.run_ce && !d.finished && !d.stalled;
  return d;
}

}  // namespace

RegState CoreModel::datapath_regs(const Signals& s) {
  RegState r;
  r.jv_x = sval(s, kJvX);
  r.jv_y = sval(s, kJvY);
  r.jr_x = uval(s, kJrX);
  r.jr_y = uval(s, kJrY);
  r.cnt_x = uval(s, kCntX);
  r.cnt_y = uval(s, kCntY);
  r.jr_z = uval(s, kJrZ);
  r.cnt_z = uval(s, kCntZ);
  return r;
}

void CoreModel::settle() {
  s_[kSumX] = s_[kJrX] + s_[kJvX];  // AccWidth + 1 bits: no wrap
  s_[kSumY] = s_[kJrY] + s_[kJvY];
  s_[kSumZ] = s_[kJrZ] + s_[kJvZ];
}

bool CoreModel::cmd_ready(bool ce) const {
  const Decision d = decide(s_, ce);
  bool last = false;
  if (d.iterate) {
    RegState r = datapath_regs(s_);
    next_state(held_command(s_), r);
    last = dda::finished(r);
  }
  return s_[kState] == kIdle || d.finished || last;
}

CoreEdge CoreModel::edge(const CoreInputs& in) {
  CoreEdge e;
  if (!in.rst_n) {
    s_.fill(0);
    s_[kState] = kIdle;
    settle();
    return e;
  }
  const Decision d = decide(s_, in.ce);
  Signals n = s_;
  StepOut o;
  if (d.iterate) {
    RegState r = datapath_regs(s_);
    o = next_state(held_command(s_), r);
    n[kJvX] = put(kJvX, r.jv_x);
    n[kJvY] = put(kJvY, r.jv_y);
    n[kJrX] = put(kJrX, r.jr_x);
    n[kJrY] = put(kJrY, r.jr_y);
    n[kCntX] = put(kCntX, r.cnt_x);
    n[kCntY] = put(kCntY, r.cnt_y);
    n[kJrZ] = put(kJrZ, r.jr_z);
    n[kCntZ] = put(kCntZ, r.cnt_z);
  }
  e.iterate = d.iterate;
  e.stalled = d.stalled;
  e.finishing = d.finished || (d.iterate && n[kCntX] == 0 && n[kCntY] == 0 && n[kCntZ] == 0);
  e.ready = s_[kState] == kIdle || e.finishing;
  e.load = e.ready && in.cmd_valid;
  n[kStepX] = d.iterate && o.step_x;
  n[kStepY] = d.iterate && o.step_y;
  n[kStepZ] = d.iterate && o.step_z;
  n[kDirX] = n[kStepX] ? s_[kCdirX] : s_[kDirX];  // a direction changes only with a step
  n[kDirY] = n[kStepY] ? s_[kCdirY] : s_[kDirY];
  n[kDirZ] = n[kStepZ] ? s_[kCdirZ] : s_[kDirZ];
  n[kDone] = e.finishing;
  n[kErr] = e.stalled;
  n[kIter] = e.iterate;
  n[kState] = e.load ? kRun : (e.finishing || e.stalled) ? kIdle : s_[kState];
  if (e.load) {  // the load wins over the last iteration's register updates
    for (const auto& l : kLoads) n[l.reg] = in.cmd[l.field];
  }
  s_ = n;
  settle();
  return e;
}

namespace {
// A port's index among the outputs.
std::size_t out_index(std::string_view name) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < hw::port(name); ++i) k += hw::kPorts[i].dir == hw::PortDir::Out;
  return k;
}
}  // namespace

PortValues CoreModel::outputs(const Signals& s, bool ready) {
  // (Each output's index found once: this runs on every edge.)
  static const std::size_t ready_o = out_index("cmd_ready_o"), step_x = out_index("step_x_o"),
                           step_y = out_index("step_y_o"), dir_x = out_index("dir_x_o"), dir_y = out_index("dir_y_o"),
                           step_z = out_index("step_z_o"), dir_z = out_index("dir_z_o"), busy_o = out_index("busy_o"),
                           done = out_index("done_o"), err = out_index("err_o"), iter = out_index("iter_o");
  PortValues p{};
  p[ready_o] = ready;
  p[step_x] = s[kStepX];
  p[step_y] = s[kStepY];
  p[dir_x] = s[kDirX];
  p[dir_y] = s[kDirY];
  p[step_z] = s[kStepZ];
  p[dir_z] = s[kDirZ];
  p[busy_o] = s[kState] == kRun;
  p[done] = s[kDone];
  p[err] = s[kErr];
  p[iter] = s[kIter];
  return p;
}

Iteration CoreModel::iteration_record(const Signals& pre, const Signals& post) {
  Iteration rec;
  rec.dir_x_neg = pre[kCdirX] != 0;  // the command running in this iteration
  rec.dir_y_neg = pre[kCdirY] != 0;
  rec.dir_z_neg = pre[kCdirZ] != 0;
  rec.active_x = pre[kCntX] != 0;
  rec.active_y = pre[kCntY] != 0;
  rec.active_z = pre[kCntZ] != 0;
  rec.jv_z = uval(pre, kJvZ);
  rec.sum_z = rec.active_z ? std::int64_t(pre[kSumZ]) : uval(pre, kJrZ);
  rec.jv_x = sval(pre, kJvX);
  rec.jv_y = sval(pre, kJvY);
  // The adder's output counts where the axis adds: active, integrand not negative.
  rec.sum_x = rec.active_x && rec.jv_x >= 0 ? std::int64_t(pre[kSumX]) : uval(pre, kJrX);
  rec.sum_y = rec.active_y && rec.jv_y >= 0 ? std::int64_t(pre[kSumY]) : uval(pre, kJrY);
  rec.step_x = post[kStepX] != 0;
  rec.step_y = post[kStepY] != 0;
  rec.step_z = post[kStepZ] != 0;
  rec.after = datapath_regs(post);
  return rec;
}

bool CoreModel::iterated(const Signals& post) { return post[kIter] != 0; }
bool CoreModel::done(const Signals& post) { return post[kDone] != 0; }
bool CoreModel::err(const Signals& post) { return post[kErr] != 0; }
bool CoreModel::busy(const Signals& s) { return s[kState] == kRun; }

Point CoreModel::step_of(const Signals& post) {
  Point d;
  if (post[kStepX]) d.x = post[kDirX] ? -1 : 1;
  if (post[kStepY]) d.y = post[kDirY] ? -1 : 1;
  if (post[kStepZ]) d.z = post[kDirZ] ? -1 : 1;
  return d;
}

CmdValues command_values(const Command& c) {
  CmdValues f{};
  const auto set = [&](std::string_view name, std::int64_t v) { f[hw::field(name)] = v; };
  set("jv_x", c.jv_x);
  set("jv_y", c.jv_y);
  set("jr_x", c.jr_x);
  set("jr_y", c.jr_y);
  set("cap", c.cap);
  set("cnt_x", c.cnt_x);
  set("cnt_y", c.cnt_y);
  set("dir_x", c.dir_x_neg ? hw::kDirNeg : hw::kDirPos);
  set("dir_y", c.dir_y_neg ? hw::kDirNeg : hw::kDirPos);
  set("inc_x_on_x", c.inc_x_on_x);
  set("inc_x_on_y", c.inc_x_on_y);
  set("inc_y_on_x", c.inc_y_on_x);
  set("inc_y_on_y", c.inc_y_on_y);
  set("jv_z", c.jv_z);
  set("jr_z", c.jr_z);
  set("cap_z", c.cap_z);
  set("cnt_z", c.cnt_z);
  set("dir_z", c.dir_z_neg ? hw::kDirNeg : hw::kDirPos);
  return f;
}

CmdFields command_fields_unchecked(const Command& c) {
  const CmdValues v = command_values(c);
  CmdFields f{};
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = mask(v[i], hw::kCmdFields[i].width);
  return f;
}

}  // namespace dda
