#include "scoreboard.hpp"

#include <sstream>

#include "dda/hw_params.hpp"

namespace dda {

namespace {

std::uint64_t hw_value(std::int64_t v) { return static_cast<std::uint64_t>(v) & hw::kAccMask; }

// An integrand register (AccWidth-bit two's complement) as the golden model's value.
std::int64_t integrand_value(std::uint64_t v) {
  const std::uint64_t neg = std::uint64_t{1} << (hw::kAccWidth - 1);
  return static_cast<std::int64_t>(v & hw::kAccMask) - static_cast<std::int64_t>((v & neg) << 1);
}

}  // namespace

bool RecordBuilder::on_edge(const CoreSample& pre, const CoreSample& post, std::uint32_t seg,
                            Iteration& rec) {
  if (!post.iter) return false;
  rec = Iteration{};
  rec.iter = ++n_;
  rec.seg = seg;
  rec.dir_x_neg = pre.cdir_x;  // the command running in this iteration
  rec.dir_y_neg = pre.cdir_y;
  rec.active_x = pre.cnt_x != 0;
  rec.active_y = pre.cnt_y != 0;
  rec.jv_x = integrand_value(pre.jv_x);
  rec.jv_y = integrand_value(pre.jv_y);
  // The adder's output counts where the axis adds: active, integrand not negative.
  const std::uint64_t neg = std::uint64_t{1} << (hw::kAccWidth - 1);
  rec.sum_x = static_cast<std::int64_t>(rec.active_x && !(pre.jv_x & neg) ? pre.sum_x : pre.jr_x);
  rec.sum_y = static_cast<std::int64_t>(rec.active_y && !(pre.jv_y & neg) ? pre.sum_y : pre.jr_y);
  rec.step_x = post.step_x;
  rec.step_y = post.step_y;
  rec.after.jv_x = integrand_value(post.jv_x);
  rec.after.jv_y = integrand_value(post.jv_y);
  rec.after.jr_x = static_cast<std::int64_t>(post.jr_x);
  rec.after.jr_y = static_cast<std::int64_t>(post.jr_y);
  rec.after.cnt_x = static_cast<std::int64_t>(post.cnt_x);
  rec.after.cnt_y = static_cast<std::int64_t>(post.cnt_y);
  if (post.step_x) pos_.x += post.dir_x ? -1 : 1;
  if (post.step_y) pos_.y += post.dir_y ? -1 : 1;
  rec.pos = pos_;
  return true;
}

Scoreboard::Scoreboard(const Plan& plan, std::string engine)
    : plan_(plan), engine_(std::move(engine)), dp_(plan.segs.front().cmd, plan.segs.front().from) {}

bool Scoreboard::on_iteration(const CoreSample& pre, const CoreSample& post, std::uint64_t cycle,
                              bool loaded) {
  if (dp_.done()) {
    std::ostringstream m;
    m << engine_ << " mismatch: iteration at cycle " << cycle << " after the golden run of piece "
      << seg_ << " ended (" << dp_.iterations() << " iterations)";
    throw MismatchError(m.str());
  }
  Iteration g = dp_.iterate();
  g.iter = ++iters_;
  const Command& cmd = plan_.segs[seg_].cmd;
  // Back to back, the edge of a piece's last iteration also loads the next command.
  const bool ended = dp_.done();
  const bool next_loaded = ended && loaded && seg_ + 1 < plan_.segs.size();
  const Command& held = next_loaded ? plan_.segs[seg_ + 1].cmd : cmd;
  const RegState r = next_loaded ? initial_regs(held) : dp_.regs();
  // dir_*_q changes only with a step; before the first step it holds what it had.
  const bool dir_x = g.step_x ? cmd.dir_x_neg : (have_dir_ ? prev_dir_x_ : pre.dir_x);
  const bool dir_y = g.step_y ? cmd.dir_y_neg : (have_dir_ ? prev_dir_y_ : pre.dir_y);
  struct Cmp {
    const char* name;
    std::uint64_t expect, got;
  };
  const Cmp regs[] = {
      {"u_int_x.jr_q", hw_value(r.jr_x), post.jr_x},
      {"u_int_y.jr_q", hw_value(r.jr_y), post.jr_y},
      {"step_x_q", g.step_x, post.step_x},
      {"step_y_q", g.step_y, post.step_y},
      {"u_cnt_x.cnt_q", hw_value(r.cnt_x), post.cnt_x},
      {"u_cnt_y.cnt_q", hw_value(r.cnt_y), post.cnt_y},
      {"u_int_x.jv_q", hw_value(r.jv_x), post.jv_x},
      {"u_int_y.jv_q", hw_value(r.jv_y), post.jv_y},
      {"dir_x_q", dir_x, post.dir_x},
      {"dir_y_q", dir_y, post.dir_y},
      {"cdir_x_q", held.dir_x_neg, post.cdir_x},
      {"cdir_y_q", held.dir_y_neg, post.cdir_y},
      {"cap_q", hw_value(held.cap), post.cap},
      {"u_int_x.inc_on_x_q", hw_value(held.inc_x_on_x), post.inc_x_on_x},
      {"u_int_x.inc_on_y_q", hw_value(held.inc_x_on_y), post.inc_x_on_y},
      {"u_int_y.inc_on_x_q", hw_value(held.inc_y_on_x), post.inc_y_on_x},
      {"u_int_y.inc_on_y_q", hw_value(held.inc_y_on_y), post.inc_y_on_y},
      {"u_ctrl.done_q", ended, post.done},
      {"u_ctrl.err_q", 0, post.err},
      {"u_ctrl.iter_q", 1, post.iter},
      // Running unless this iteration ended the command and none followed on the edge.
      {"u_ctrl.state_q", (ended && !next_loaded) ? unsigned(hw::State::Idle) : unsigned(hw::State::Run),
       post.state},
  };
  for (const auto& r : regs) {
    if (r.expect != r.got) {
      std::ostringstream m;
      m << engine_ << " mismatch: register " << r.name << " at iteration " << g.iter << " (cycle "
        << cycle << "): golden " << r.expect << ", " << engine_ << ' ' << r.got;
      throw MismatchError(m.str());
    }
  }
  have_dir_ = true;
  prev_dir_x_ = post.dir_x;
  prev_dir_y_ = post.dir_y;
  return ended;
}

void Scoreboard::on_done(std::uint64_t cycle) {
  if (!dp_.done()) {
    std::ostringstream m;
    m << engine_ << " mismatch: done at cycle " << cycle << " after " << dp_.iterations()
      << " iterations of piece " << seg_ << ", but the golden run owes (" << dp_.regs().cnt_x
      << ", " << dp_.regs().cnt_y << ") steps";
    throw MismatchError(m.str());
  }
  if (++seg_ < plan_.segs.size()) dp_ = Datapath(plan_.segs[seg_].cmd, plan_.segs[seg_].from);
}

std::string compare_samples(const CoreSample& a, const CoreSample& b) {
  struct Cmp {
    const char* name;
    std::uint64_t x, y;
  };
  const Cmp regs[] = {
      {"u_int_x.jv_q", a.jv_x, b.jv_x},   {"u_int_x.jr_q", a.jr_x, b.jr_x},
      {"u_int_y.jv_q", a.jv_y, b.jv_y},   {"u_int_y.jr_q", a.jr_y, b.jr_y},
      {"u_int_x.sum", a.sum_x, b.sum_x},  {"u_int_y.sum", a.sum_y, b.sum_y},
      {"u_cnt_x.cnt_q", a.cnt_x, b.cnt_x}, {"u_cnt_y.cnt_q", a.cnt_y, b.cnt_y},
      {"cap_q", a.cap, b.cap},            {"step_x_q", a.step_x, b.step_x},
      {"u_int_x.inc_on_x_q", a.inc_x_on_x, b.inc_x_on_x},
      {"u_int_x.inc_on_y_q", a.inc_x_on_y, b.inc_x_on_y},
      {"u_int_y.inc_on_x_q", a.inc_y_on_x, b.inc_y_on_x},
      {"u_int_y.inc_on_y_q", a.inc_y_on_y, b.inc_y_on_y},
      {"step_y_q", a.step_y, b.step_y},   {"dir_x_q", a.dir_x, b.dir_x},
      {"dir_y_q", a.dir_y, b.dir_y},      {"cdir_x_q", a.cdir_x, b.cdir_x},
      {"cdir_y_q", a.cdir_y, b.cdir_y},      {"u_ctrl.state_q", a.state, b.state},
      {"u_ctrl.done_q", a.done, b.done},  {"u_ctrl.err_q", a.err, b.err},
      {"u_ctrl.iter_q", a.iter, b.iter},
  };
  for (const auto& r : regs) {
    if (r.x != r.y) {
      std::ostringstream m;
      m << "register " << r.name << ": " << r.x << " vs " << r.y;
      return m.str();
    }
  }
  return "";
}

}  // namespace dda
