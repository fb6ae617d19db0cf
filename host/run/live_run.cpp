// SPDX-License-Identifier: Apache-2.0
#include "host/run/live_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>

#include "host/speed/segments.hpp"
#include "model/datapath/errors.hpp"
#include "model/motion/motion_map.hpp"

namespace dda::live {

namespace {

using motion::field_bit;
using motion::get_field;
using motion::reg_offset;

// Clocks of a time in ns, rounded up, in a field of `width` bits (InputError naming it).
std::uint32_t clocks_of(double ns, double clock_hz, int width, const std::string& what) {
  const double c = std::ceil(ns * 1e-9 * clock_hz - 1e-9);
  if (c >= std::ldexp(1.0, width))
    throw InputError(fmt::format("machine config: {} = {} ns is {} clocks at {} Hz: the field holds at most {}", what,
                                 ns, c, clock_hz, (1u << width) - 1));
  return std::uint32_t(std::max(0.0, c));
}

// A sent entry the block has not finished yet.
struct Sent {
  std::size_t block = 0, line = 0;
  double time = 0;  // the plan's, s
  Point to;
};

class Run {
 public:
  Run(const ProgramRun& run, const speed::MachineLimits& lim, Port& port, Controls& controls, std::ostream& status,
      const LiveOptions& opt)
      : run_(run), lim_(lim), port_(port), controls_(controls), status_(status), opt_(opt), d_(port.bus(), 1, false) {}
  LiveResult go(std::istream& in);

 private:
  struct Stop {
    int exit;
    std::string message;
  };
  void setup(const speed::PaceSetup& s);
  void configure_axes(int plane);
  void send(const speed::StreamEntry& e);
  // A program stop: at rest, the watchdog written, until the operator resumes.
  void program_stop(std::size_t line);
  // Reads STATUS and DONE_COUNT, writes the watchdog, applies the operator's requests
  // and prints the status when due; throws Stop when the block stopped.
  void service();
  void check_status(std::uint32_t st);
  void apply(const ControlRequest& r);
  void wait_rest(bool for_dwell);
  // Until the block is at rest after a stop (busy and stopping low).
  void settle();
  // WATCHDOG written now; or if a quarter of its timeout passed since the last write.
  void kick();
  void kick_if_due();
  // A soft stop to rest, on the way out of an error (which is the one said).
  void stop_softly() noexcept;
  void status_line(bool final);
  double seconds() const { return double(port_.clocks()) / clock_hz_; }
  [[noreturn]] void stop(int exit, std::string message) { throw Stop{exit, std::move(message)}; }
  std::string where() const;
  std::string mm(const Point& p) const;

  const ProgramRun& run_;
  const speed::MachineLimits& lim_;
  Port& port_;
  Controls& controls_;
  std::ostream& status_;
  LiveOptions opt_;
  motion::MotionDriver d_;
  double clock_hz_ = 0, step_mm_ = 0;
  std::uint32_t depth_ = 0, level_ = 0, watchdog_ = 0, override_ = motion::kOverrideOne;
  std::uint32_t last_done_ = 0;
  std::uint64_t last_kick_ = 0;  // the port's clocks at the last WATCHDOG write
  std::uint64_t done_ = 0, sent_count_ = 0;
  std::deque<Sent> sent_;
  std::size_t line_ = 0, block_ = 0;
  double done_time_ = 0;
  bool configured_ = false, held_ = false, stopping_ = false;
  int plane_ = 170;
  std::array<std::size_t, 3> machine_{0, 1, 2};  // the machine axis each block axis drives
  Point end_;                                    // the last sent entry's end
  double next_status_ = 0, last_status_s_ = -1;
  Point last_pos_;
  double feed_ = 0;  // mm/min measured between status lines
};

std::string Run::mm(const Point& p) const { return position_mm(p, plane_, step_mm_, run_.read.machine, d_.axes()); }

std::string Run::where() const { return line_ ? fmt::format("line {} (block {})", line_, block_ + 1) : "the start"; }

void Run::setup(const speed::PaceSetup& s) {
  clock_hz_ = s.clock_hz;
  step_mm_ = s.step_mm;
  if (d_.read("ID") != motion::kId)
    stop(kLink, fmt::format("the block's ID reads 0x{:08X}, not 0x{:08X}: no motion block answers on the link",
                            d_.read("ID"), motion::kId));
  d_.read_build();
  if (!d_.pacer()) throw InputError("the block is built without its pacer (CONFIG.pacer): dda run paces every entry");
  depth_ = 1u << get_field("CONFIG", "depth_log2", d_.read("CONFIG"));
  // (A block used before: its queue flushed, a feed hold ended, its errors cleared, its
  // count of finished entries taken as the start.)
  d_.write("CTRL", field_bit("CTRL", "abort"));
  d_.resume();
  d_.clear();
  last_done_ = d_.read("DONE_COUNT");
  const speed::LiveSettings& L = lim_.live;
  watchdog_ = std::uint32_t(std::min(4294967295.0, std::ceil(L.watchdog_ms * 1e-3 * clock_hz_)));
  if (d_.inputs()) {
    // The switches' filter: the shortest tick whose count holds the time.
    std::uint32_t tick = 0, count = 0;
    const double clocks = L.switch_filter_us * 1e-6 * clock_hz_;
    for (tick = 0; tick < (1u << motion::kFilterTickWidth); ++tick) {
      count = std::uint32_t(std::ceil(clocks / std::ldexp(1.0, int(tick)) - 1e-9));
      if (count < (1u << motion::kSwitchFilterWidth)) break;
    }
    if (tick == (1u << motion::kFilterTickWidth))
      throw InputError(fmt::format("machine config: inputs.switch_filter_us = {} is beyond the filter at {} Hz",
                                   L.switch_filter_us, clock_hz_));
    const double probe = std::ceil(L.probe_filter_us * 1e-6 * clock_hz_ - 1e-9);
    if (probe >= std::ldexp(1.0, motion::kFilterWidth))
      throw InputError(fmt::format("machine config: inputs.probe_filter_us = {} is {} clocks at {} Hz: at most {}",
                                   L.probe_filter_us, probe, clock_hz_, (1u << motion::kFilterWidth) - 1));
    d_.set_inputs(L.invert_inputs, count, std::uint32_t(std::max(0.0, probe)), L.limit_decel ? 1u : 0u, tick);
  } else if (L.invert_inputs || L.switch_filter_us > 0 || L.probe_filter_us > 0) {
    throw InputError("machine config: inputs are given, and the block is built without its inputs (CONFIG.inputs)");
  }
  d_.set_pacing(std::uint32_t(s.accel), s.vmin);
  d_.set_override(override_);
  d_.write("IRQ_LEVEL", std::max<std::uint32_t>(1, depth_ / 2));
  d_.write("IRQ_ENABLE", field_bit("IRQ_ENABLE", "low") | field_bit("IRQ_ENABLE", "err"));
  kick();
  const std::uint32_t st = d_.read("STATUS");
  if (d_.inputs() && (d_.read("INPUTS") >> motion::input_bit("estop") & 1u))
    stop(kEstop, "E-stop is active before the start: release it (the block refuses every entry while it is)");
  check_status(st);
}

void Run::configure_axes(int plane) {
  plane_ = plane;
  machine_ = speed::machine_axes(plane);
  std::uint32_t polarity = 0;
  for (std::size_t a = 0; a < std::size_t(d_.axes()); ++a) {
    const speed::AxisDrive& dr = lim_.live.axes[machine_[a]];
    const std::string name = std::string("axes.") + char('x' + machine_[a]) + ".";
    motion::StageTimings t;
    t.steplen = clocks_of(dr.step_len_ns, clock_hz_, 12, name + "step_len_ns");
    t.stepspace = clocks_of(dr.step_space_ns, clock_hz_, 12, name + "step_space_ns");
    t.dirsetup = clocks_of(dr.dir_setup_ns, clock_hz_, 12, name + "dir_setup_ns");
    t.dirhold = clocks_of(dr.dir_hold_ns, clock_hz_, 12, name + "dir_hold_ns");
    d_.set_timings(char('x' + a), t);
    polarity |= (dr.invert_step ? 1u : 0u) << (2 * a) | (dr.invert_dir ? 1u : 0u) << (2 * a + 1);
  }
  d_.set_polarity(polarity);
  configured_ = true;
}

void Run::check_status(std::uint32_t st) {
  level_ = get_field("STATUS", "level", st);
  held_ = get_field("STATUS", "held", st) != 0;
  if (!get_field("STATUS", "err", st)) return;
  const auto has = [&](const char* f) { return get_field("STATUS", f, st) != 0; };
  const Point pos = d_.position();
  if (has("err_estop")) stop(kEstop, fmt::format("E-stop at {} ({})", where(), mm(pos)));
  if (has("err_limit")) {
    const std::uint32_t trip = d_.read("TRIP");
    std::string which;
    for (const motion::Input& i : motion::kInputs)
      if (i.bit != 0 && i.bit < motion::kTripBits + 1 && (trip >> i.bit & 1u))
        which += (which.empty() ? "" : ", ") + std::string(i.meaning);
    stop(kLimit, fmt::format("limit switch: {} at {}, latched at {}", which.empty() ? "a limit" : which, where(),
                             mm(d_.positions("LATCH"))));
  }
  if (has("err_watchdog"))
    stop(kWatchdog, fmt::format("the block's watchdog ran out ({} ms without a write from the host) at {}",
                                lim_.live.watchdog_ms, where()));
  if (has("err_hard_stop")) stop(kOperator, fmt::format("hard stop at {}", where()));
  std::string causes;
  for (const char* f : {"err_overflow", "err_partial", "err_stall", "err_lanes"})
    if (has(f)) causes += std::string(causes.empty() ? "" : ", ") + f;
  stop(kFailure, fmt::format("the block reports an error ({}) at {}", causes, where()));
}

void Run::service() {
  if (!configured_) return;
  // (IRQ_STATUS.low cleared first: a dequeue after the STATUS read raises it again.)
  if (get_field("IRQ_STATUS", "low", d_.read("IRQ_STATUS"))) d_.write("IRQ_STATUS", field_bit("IRQ_STATUS", "low"));
  const std::uint32_t st = d_.read("STATUS");
  const std::uint32_t done = d_.read("DONE_COUNT");
  done_ += std::uint32_t(done - last_done_);
  last_done_ = done;
  while (!sent_.empty() && sent_count_ - sent_.size() < done_) {
    done_time_ += sent_.front().time;
    sent_.pop_front();
  }
  if (!sent_.empty()) {
    line_ = sent_.front().line;
    block_ = sent_.front().block;
  }
  check_status(st);
  kick();
  while (const std::optional<ControlRequest> r = controls_.poll(seconds())) apply(*r);
  if (opt_.status_every > 0 && seconds() >= next_status_) {
    status_line(false);
    next_status_ = seconds() + opt_.status_every;
  }
}

void Run::apply(const ControlRequest& r) {
  switch (r.what) {
    case Control::Hold:
      d_.hold();
      status_ << fmt::format("dda run: feed hold at {:.3f} s\n", seconds());
      break;
    case Control::Resume:
      d_.resume();
      status_ << fmt::format("dda run: resume at {:.3f} s\n", seconds());
      break;
    case Control::OverrideUp:
    case Control::OverrideDown:
    case Control::Override: {
      // (In percent: up and down go to the next multiple of 10%.)
      const double one = motion::kOverrideOne, now = std::round(override_ * 100.0 / one);
      double percent = r.percent;
      if (r.what == Control::OverrideUp) percent = (std::floor(now / 10) + 1) * 10;
      if (r.what == Control::OverrideDown) percent = (std::ceil(now / 10) - 1) * 10;
      const int v = int(std::lround(std::clamp(percent, 0.0, 200.0) / 100 * one));
      override_ = std::uint32_t(v);
      d_.set_override(override_);
      status_ << fmt::format("dda run: override {:.0f}% at {:.3f} s\n", 100.0 * override_ / motion::kOverrideOne,
                             seconds());
      break;
    }
    case Control::SoftStop: {
      d_.write("CTRL", field_bit("CTRL", "soft_stop"));
      stopping_ = true;
      wait_rest(false);
      stop(kOperator, fmt::format("soft stop by the operator at {}", where()));
    }
    case Control::HardStop:
      d_.write("CTRL", field_bit("CTRL", "hard_stop"));
      stop(kOperator, fmt::format("hard stop by the operator at {}", where()));
  }
}

void Run::kick() {
  d_.write("WATCHDOG", watchdog_);
  last_kick_ = port_.clocks();
}

void Run::kick_if_due() {
  // (A quarter of the timeout at most between writes, whatever the host does meanwhile.)
  if (port_.clocks() - last_kick_ >= watchdog_ / 4) kick();
}

void Run::stop_softly() noexcept {
  try {
    d_.write("CTRL", field_bit("CTRL", "soft_stop"));
    stopping_ = true;
    wait_rest(false);
  } catch (...) {  // (the error that brought it here is the one said)
  }
}

void Run::settle() {
  const std::uint64_t poll = std::max<std::uint64_t>(1, std::uint64_t(opt_.poll_ms * 1e-3 * clock_hz_));
  // (At most a minute of the machine's time: a ramp from any speed is shorter.)
  for (std::uint64_t t = 0; t < std::uint64_t(60 * clock_hz_); t += poll) {
    const std::uint32_t st = d_.read("STATUS");
    if (!get_field("STATUS", "busy", st) && !get_field("STATUS", "stopping", st)) return;
    kick();
    port_.wait(poll);
  }
  throw GuardError("the block did not come to rest within a minute after the stop");
}

void Run::wait_rest(bool for_dwell) {
  const std::uint64_t poll = std::max<std::uint64_t>(1, std::uint64_t(opt_.poll_ms * 1e-3 * clock_hz_));
  const std::uint64_t start = port_.clocks();
  for (;;) {
    const std::uint32_t st = d_.read("STATUS");
    if (get_field("STATUS", "empty", st) && !get_field("STATUS", "busy", st) && !get_field("STATUS", "stopping", st))
      break;
    if (stopping_) {
      // (A soft stop ramps down: an E-stop or the operator's second stop ends it at once.)
      kick();
      if (get_field("STATUS", "err", st) && get_field("STATUS", "err_estop", st)) check_status(st);
      if (const std::optional<ControlRequest> r = controls_.poll(seconds()))
        if (r->what == Control::HardStop || r->what == Control::SoftStop) {
          d_.write("CTRL", field_bit("CTRL", "hard_stop"));
          stop(kOperator, fmt::format("hard stop by the operator at {}", where()));
        }
      if (port_.clocks() - start > std::uint64_t(60 * clock_hz_))
        throw GuardError("the block did not come to rest within a minute of the machine's time after a soft stop");
    } else {
      service();
    }
    port_.wait(poll);
  }
  if (for_dwell) service();
}

void Run::program_stop(std::size_t line) {
  wait_rest(true);
  status_ << fmt::format("dda run: program stop (M00/M01) before line {} at {:.3f} s: waiting for a resume\n", line,
                         seconds());
  status_.flush();
  const std::uint64_t poll = std::max<std::uint64_t>(1, std::uint64_t(opt_.poll_ms * 1e-3 * clock_hz_));
  for (;;) {
    kick();
    check_status(d_.read("STATUS"));
    if (const std::optional<ControlRequest> r = controls_.poll(seconds())) {
      apply(*r);  // (a resume also ends a hold; a stop ends the run; an override stays)
      if (r->what == Control::Resume) break;
    }
    if (opt_.status_every > 0 && seconds() >= next_status_) {
      status_line(false);
      next_status_ = seconds() + opt_.status_every;
    }
    port_.wait(poll);
  }
}

void Run::send(const speed::StreamEntry& e) {
  if (!configured_) {
    configure_axes(e.plane);
    d_.preset(e.piece.from);
    last_pos_ = e.piece.from;
  }
  if (e.stop_before) program_stop(e.line);
  if (e.dwell > 0) {
    wait_rest(true);
    const double until = seconds() + e.dwell;
    const std::uint64_t poll = std::max<std::uint64_t>(1, std::uint64_t(opt_.poll_ms * 1e-3 * clock_hz_));
    while (seconds() < until) {
      port_.wait(std::min<std::uint64_t>(poll, std::uint64_t(std::ceil((until - seconds()) * clock_hz_)) + 1));
      service();
    }
  }
  const std::uint64_t poll = std::max<std::uint64_t>(1, std::uint64_t(opt_.poll_ms * 1e-3 * clock_hz_));
  service();
  // (The queue holds depth_ entries; the one the core runs is not counted in the level.)
  while (level_ >= depth_) {
    // With the interrupt on the link, the host waits for it (the queue below
    // IRQ_LEVEL) and only writes the watchdog meanwhile.
    if (port_.has_irq()) {
      for (int k = 0; k < 1000 && !port_.irq(); ++k) {
        port_.wait(poll);
        kick();
        while (const std::optional<ControlRequest> r = controls_.poll(seconds())) apply(*r);
        if (opt_.status_every > 0 && seconds() >= next_status_) break;
      }
    } else {
      port_.wait(poll);
    }
    service();
  }
  d_.each_word = [this] { kick_if_due(); };
  d_.queue(e.piece.cmd, 0, e.piece.rot, e.pace);
  ++level_;
  sent_.push_back(Sent{e.block, e.line, e.time, e.piece.to});
  ++sent_count_;
  end_ = e.piece.to;
  if (sent_.size() == 1) {
    line_ = e.line;
    block_ = e.block;
  }
}

void Run::status_line(bool final) {
  const Point pos = d_.position();
  const double t = seconds();
  if (last_status_s_ >= 0 && t > last_status_s_) {
    const double dx = double(pos.x - last_pos_.x), dy = double(pos.y - last_pos_.y), dz = double(pos.z - last_pos_.z);
    feed_ = std::sqrt(dx * dx + dy * dy + dz * dz) * step_mm_ / (t - last_status_s_) * 60;
  }
  last_pos_ = pos;
  last_status_s_ = t;
  std::string progress;
  if (opt_.totals && opt_.totals->time > 0) {
    const double share = std::clamp(done_time_ / opt_.totals->time, 0.0, 1.0);
    const int bar = int(std::lround(share * 20));
    progress = fmt::format(" [{}{}] {:3.0f}% left {:.1f} s", std::string(std::size_t(bar), '#'),
                           std::string(std::size_t(20 - bar), '.'), share * 100,
                           std::max(0.0, opt_.totals->time - done_time_));
  }
  const std::string text =
      fmt::format("{} | {} | F {:.0f} mm/min | override {:.0f}% | queue {}/{}{} | {:.2f} s{}", where(), mm(pos), feed_,
                  100.0 * override_ / motion::kOverrideOne, level_, depth_, held_ ? " | held" : "", t, progress);
  if (opt_.status_line)
    status_ << '\r' << text << "\x1b[K" << (final ? "\n" : "") << std::flush;
  else
    status_ << text << '\n';
}

LiveResult Run::go(std::istream& in) {
  LiveResult res;
  const program::Machine m = run_.read.machine;
  const speed::PlannerLimits plim = speed::planner_limits(lim_, m);
  const speed::PaceSetup pace = speed::pace_setup(plim, lim_, run_.lattice.step, lim_.live.clock_hz);
  try {
    setup(pace);
    speed::stream_program_entries(in, run_.file, run_.read, run_.lattice, run_.window, lim_, pace,
                                  [&](const speed::StreamEntry& e) { send(e); });
    wait_rest(false);
    service();
    if (opt_.status_every > 0) status_line(true);
    res.position = d_.position();
    res.position_known = true;
    if (res.position != end_) {
      res.exit = kFailure;
      res.message = fmt::format("the block ends at {}, the program at {}: steps were lost", mm(res.position), mm(end_));
    }
  } catch (const Stop& s) {
    res.exit = s.exit;
    res.message = s.message;
  } catch (const PortGone& e) {
    res.exit = kFailure;
    res.message = e.what();
    res.seconds = seconds();
    res.entries = sent_count_;
    res.plane = plane_;
    res.axes = d_.axes();
    return res;
  } catch (const motion::LinkError& e) {
    res.exit = kLink;
    res.message = std::string("the link failed: ") + e.what();
  } catch (const program::ProgramError&) {
    // (A block refused after the machine moved: it stops softly, and the error is said.)
    if (configured_) stop_softly();
    throw;
  } catch (const InputError&) {
    if (configured_) stop_softly();
    throw;
  } catch (const GuardError& e) {
    // (A guard on the host's side: the block stops softly and the run says why.)
    if (configured_) stop_softly();
    res.exit = kFailure;
    res.message = e.what();
  }
  if (opt_.status_line && res.exit != kDone) status_ << '\n';  // (past the line rewritten in place)
  if (res.exit != kDone && res.exit != kLink) {
    // (A soft stop, of a limit, the watchdog or the operator, ramps down first.)
    try {
      settle();
      res.position = d_.position();
      res.position_known = true;
    } catch (const std::exception& e) {
      res.message += std::string("; the position could not be read back: ") + e.what();
    }
  }
  res.seconds = seconds();
  res.entries = sent_count_;
  res.plane = plane_;
  res.axes = d_.axes();
  return res;
}

}  // namespace

LiveResult run_live(std::istream& in, const ProgramRun& run, const speed::MachineLimits& lim, Port& port,
                    Controls& controls, std::ostream& status, const LiveOptions& opt) {
  Run r(run, lim, port, controls, status, opt);
  return r.go(in);
}

}  // namespace dda::live
