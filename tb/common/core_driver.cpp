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
  // Watchdog: the golden iteration bound, generously stretched for ce_i stalls.
  const std::uint64_t limit = 64 + 64 * (plan.iteration_bound + 16);

  // Command handshake: valid until a rising edge where ready was high.
  h.set_command(true, hw::pack_command(plan.cmd));
  for (;;) {
    h.set_ce(ce_at(h.cycle()));
    const bool ready = h.cmd_ready();
    h.tick();
    if (ready) break;
    if (h.cycle() - start > 1000) throw GuardError("watchdog: command not accepted in 1000 cycles");
  }
  h.set_command(false, {});

  Scoreboard sb(plan, h.name());
  RecordBuilder rb(plan.from);
  for (;;) {
    h.set_ce(ce_at(h.cycle()));
    const CoreSample pre = h.sample();
    h.tick();
    const CoreSample post = h.sample();
    Iteration rec;
    if (rb.on_edge(pre, post, rec)) {
      ++res.iterations;
      if (opt.check) sb.on_iteration(post, h.cycle());
      if (opt.keep_records) res.records.push_back(rec);
      if (opt.reset_after != 0 && res.iterations == opt.reset_after) {
        reset_core(h, 1);
        res.cycles = h.cycle() - start;
        res.end = rb.pos();
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
      break;
    }
    if (h.cycle() - start > limit) {
      throw GuardError("watchdog: no done_o within " + std::to_string(limit) + " cycles");
    }
  }
  res.cycles = h.cycle() - start;
  res.end = rb.pos();
  if (opt.check && res.end != plan.to) {
    throw MismatchError("engine ended at (" + std::to_string(res.end.x) + "," +
                        std::to_string(res.end.y) + ") instead of the end point");
  }
  return res;
}

}  // namespace dda
