#include "core_driver.hpp"

#include <sstream>

#include "dda/hw_command.hpp"

namespace dda {

void reset_core(CoreHarness& h, int cycles) {
  h.set_command(false, {});
  h.set_ce(false);
  h.set_reset(false);
  for (int i = 0; i < cycles; ++i) h.tick();
  h.set_reset(true);
}

DriveResult drive_arc(CoreHarness& h, const Plan& plan, const DriveOptions& opt) {
  DriveResult res;
  const std::uint64_t start = h.cycle();
  const auto ce_at = [&](std::uint64_t c) { return opt.ce ? opt.ce(c) : true; };
  // Watchdog: edges with ce_i high beyond the golden run's own iterations (plus the loads
  // and a margin) mean the core is not finishing.
  const std::uint64_t limit = run(plan).iterations + 4 * plan.segs.size() + 64;
  std::uint64_t ce_edges = 0;
  const std::size_t nseg = plan.segs.size();

  // The pieces' commands are presented back to back: the next one as soon as the
  // previous one was taken (valid/ready: held until a rising edge where ready was high).
  std::size_t presented = 0, running = 0;
  h.set_command(true, hw::pack_command(plan.segs[0].cmd));
  Scoreboard sb(plan, h.name());
  RecordBuilder rb(plan.from);
  bool started = false;  // the first command was taken
  for (;;) {
    if (opt.reset_at_cycle != 0 && h.cycle() - start + 1 >= opt.reset_at_cycle) {
      reset_core(h, 1);
      res.cycles = h.cycle() - start;
      res.end = rb.pos();
      res.was_reset = true;
      return res;
    }
    const bool ce = ce_at(h.cycle());
    ce_edges += ce;
    h.set_ce(ce);
    const bool offering = presented < nseg;
    const bool ready = offering && h.cmd_ready();
    const CoreSample pre = h.sample();
    h.tick();
    const CoreSample post = h.sample();
    if (ready) {
      if (!started) {
        res.initial.jv_x = std::int64_t(post.jv_x);
        res.initial.jv_y = std::int64_t(post.jv_y);
        res.initial.jr_x = std::int64_t(post.jr_x);
        res.initial.jr_y = std::int64_t(post.jr_y);
        res.initial.cnt_x = std::int64_t(post.cnt_x);
        res.initial.cnt_y = std::int64_t(post.cnt_y);
      }
      started = true;
      ++presented;
      if (presented < nseg) {
        h.set_command(true, hw::pack_command(plan.segs[presented].cmd));
      } else {
        h.set_command(false, {});
      }
    }
    if (!started) {
      if (h.cycle() - start > 1000) throw GuardError("watchdog: command not accepted in 1000 cycles");
      continue;
    }
    Iteration rec;
    if (rb.on_edge(pre, post, static_cast<std::uint32_t>(running), rec)) {
      ++res.iterations;
      if (opt.check && sb.on_iteration(pre, post, h.cycle(), ready) && offering && !ready) {
        // The spec: a command waiting loads on the edge that ends the running one.
        throw MismatchError(std::string(h.name()) + " mismatch: cmd_ready_o was low in the cycle of the last iteration of piece " +
                            std::to_string(running) + " (cycle " + std::to_string(h.cycle()) +
                            "): the next command did not load back to back");
      }
      if (opt.keep_records) res.records.push_back(rec);
      if (opt.reset_after != 0 && res.iterations == opt.reset_after) {
        reset_core(h, 1);
        res.cycles = h.cycle() - start;
        res.end = rb.pos();
        res.was_reset = true;
        return res;
      }
    }
    if (post.err) {
      std::ostringstream m;
      m << "core raised err_o (stall) at cycle " << h.cycle() << " after " << res.iterations
        << " iterations at (" << rb.pos().x << ',' << rb.pos().y << ')';
      throw GuardError(m.str());
    }
    if (post.done) {
      if (opt.check) sb.on_done(h.cycle());
      if (++running == nseg) break;
    }
    if (ce_edges > limit) {
      std::ostringstream m;
      m << h.name() << ": watchdog: no done_o after " << ce_edges << " edges with ce_i high ("
        << res.iterations << " iterations, piece " << running << " of " << nseg << ", at ("
        << rb.pos().x << ',' << rb.pos().y << "), cycle " << h.cycle() << ")";
      throw GuardError(m.str());
    }
  }
  res.cycles = h.cycle() - start;
  res.end = rb.pos();
  if (opt.check && res.end != plan.to) {
    throw MismatchError(std::string(h.name()) + " ended at (" + std::to_string(res.end.x) + "," +
                        std::to_string(res.end.y) + ") instead of the end point");
  }
  return res;
}

}  // namespace dda
