// SPDX-License-Identifier: Apache-2.0
#include "tb/random/bus_work.hpp"

#include <random>
#include <string>

#include "host/driver/motion_driver.hpp"
#include "host/planner/planner.hpp"
#include "tb/monitors/bus_monitors.hpp"
#include "tb/monitors/stepdir_monitor.hpp"
#include "tb/random/dda_random.hpp"

namespace dda::motion {

namespace {

// Records what the block does: a tap that notes the core's steps on every edge it
// iterated, and each pulse that leaves a step pin.
class Recorder : public BusTap {
 public:
  Recorder(BusTarget& inner, BusWork& w) : BusTap(inner), w_(w) {}
  void tick(const BusIn& bus) override {
    t_.tick(bus);
    ++w_.cycles;
    if (t_.model().iterated()) {
      // The iteration's steps and directions (the core's step_*_q, dir_*_q: the rest of
      // its registers may already hold the next command when one was waiting).
      const Signals& c = t_.model().core();
      std::uint8_t v = 0;
      for (const char* n : {"step_x_q", "step_y_q", "step_z_q", "dir_x_q", "dir_y_q", "dir_z_q"}) {
        v = std::uint8_t(v << 1 | (c[hw::sig(n)] & 1u));
      }
      w_.iterations.push_back(v);
    }
    const BlockOutputs& o = t_.outputs();
    const bool step[3] = {o.step_x, o.step_y, o.step_z}, dir[3] = {o.dir_x, o.dir_y, o.dir_z};
    for (int a = 0; a < 3; ++a) {
      if (step[a] && !last_[a]) w_.pulses[std::size_t(a)].push_back(dir[a] ? 1 : 0);
      last_[a] = step[a];
    }
  }

 private:
  BusWork& w_;
  bool last_[3] = {false, false, false};
};

// Glitches shorter than the input filter on random inputs, edge by edge (the block
// ignores them): every input pin of the bridged tops toggles too.
class Glitches : public BusTap {
 public:
  static constexpr std::uint32_t kFilter = 8;  // IN_FILTER's clocks, both fields
  Glitches(BusTarget& inner, std::uint64_t seed) : BusTap(inner), rng_(seed) {}
  void tick(const BusIn& bus) override {
    if (on && left_ == 0 && rest_ == 0 && rng_() % 40 == 0) {
      pin_ = 1u << (rng_() % kNumInputs);
      left_ = 1 + int(rng_() % (kFilter - 1));
      rest_ = left_ + int(kFilter) + 2;  // apart: two glitches never make one pulse as long as the filter
    }
    rest_ -= rest_ > 0;
    t_.set_pins(MachinePins::from_bits(MachinePins{}.bits() ^ (left_ > 0 ? pin_ : 0u)));
    left_ -= left_ > 0;
    t_.tick(bus);
  }
  bool on = false;  // from when IN_FILTER holds kFilter

 private:
  std::mt19937_64 rng_;
  std::uint32_t pin_ = 0;
  int left_ = 0, rest_ = 0;
};

}  // namespace

BusWork run_bus_work(BusTarget& t, Bus bus, std::uint64_t seed, int arcs) {
  BusWork w;
  Glitches glitches(t, seed + 9);
  StepDirMonitor timing(glitches);
  PieceMonitor mon(timing);
  Recorder rec(mon, w);
  std::mt19937_64 rng(seed), ce_rng(seed + 7);
  RandomArcs plane(seed + 1, 120, 4, ArcKind::Program), spatial(seed + 2, 120, 4, ArcKind::Spatial);
  const std::unique_ptr<BusMaster> m = make_master(bus, rec, seed + 3, rng() % 2 == 0, 20);
  MotionDriver d(*m, seed + 4);
  m->each_cycle = [&] { rec.set_ce(ce_rng() % 10 != 0); };
  rec.set_reset(false);
  m->idle(2);
  rec.set_reset(true);
  d.set_inputs(0, Glitches::kFilter, Glitches::kFilter, 0);
  d.read("IN_FILTER");  // (over SPI a write lands after its frame: the next one waits for it)
  glitches.on = true;
  // The done interrupt: irq_o rises on the first piece's end, falls when it is cleared.
  d.write("IRQ_ENABLE", field_bit("IRQ_ENABLE", "done"));
  for (const char axis : kAxes) {
    const auto draw = [&] { return std::uint32_t(rng() % 6); };
    d.set_timings(axis, StageTimings{draw(), draw(), draw(), draw()});
  }
  // On a block of two axes (CONFIG.axes), planar arcs only: its Z is not built.
  const bool spatial_ok = get_field("CONFIG", "axes", d.read("CONFIG")) == 3;
  std::vector<Plan> plans;
  while (int(plans.size()) < arcs) {
    const bool turned = rng() % 3 == 0 && spatial_ok;
    if (auto p = (turned ? spatial : plane).next()) {
      if (turned) turn_axes(*p, int(rng() % 3));
      plans.push_back(std::move(*p));
    }
  }
  d.preset(plans.front().from);
  Point at = plans.front().from;
  for (const auto& p : plans) {
    for (const auto& piece : p.pieces) {
      at = at + Point{piece.to.x - piece.from.x, piece.to.y - piece.from.y, piece.to.z - piece.from.z};
      mon.expect(at);
      const std::uint32_t feed = rng() % 2 == 0 ? 0 : 0x40000000u + std::uint32_t(rng() % 0xC0000000u);
      // Over SPI now and then a frame of the wrong length: an abort it must not make.
      if (auto* spi = dynamic_cast<SpiMaster*>(m.get()); spi && rng() % 4 == 0)
        spi->stray_write(reg_offset("CTRL"), field_bit("CTRL", "abort"));
      d.queue(piece.cmd, feed, piece.rot);
      ++w.pieces;
    }
  }
  d.drain();
  w.snap = d.snapshot().pos;  // (SNAP_* lie above 0x80, ENTRY above 0x100: every address bit)
  w.entry_read = d.read("ENTRY");
  d.write("SNAP_X", ~std::uint32_t(w.snap.x));  // read-only: the write changes nothing
  w.snap_after_write = d.positions("SNAP");
  w.irq_seen = rec.outputs().irq;
  d.write("IRQ_STATUS", ~0u);
  w.irq_cleared = !rec.outputs().irq;
  w.want = at;
  w.end = d.position();
  if (const auto* axil = dynamic_cast<const AxilMaster*>(m.get())) w.reads_past_response = axil->reads_past_response();
  if (const auto* spi = dynamic_cast<const SpiMaster*>(m.get())) w.stray_frames = spi->strays();
  return w;
}

std::string compare_work(const BusWork& a, const BusWork& b) {
  for (std::size_t i = 0; i < std::min(a.iterations.size(), b.iterations.size()); ++i) {
    if (a.iterations[i] != b.iterations[i]) return "iteration " + std::to_string(i) + ": the core's steps differ";
  }
  if (a.iterations.size() != b.iterations.size()) {
    return std::to_string(a.iterations.size()) + " iterations against " + std::to_string(b.iterations.size());
  }
  for (std::size_t k = 0; k < kAxes.size(); ++k) {
    const auto &p = a.pulses[k], &q = b.pulses[k];
    const std::string axis(1, kAxes[k]);
    for (std::size_t i = 0; i < std::min(p.size(), q.size()); ++i) {
      if (p[i] != q[i]) return axis + " pulse " + std::to_string(i) + ": the direction differs";
    }
    if (p.size() != q.size()) {
      return std::to_string(p.size()) + " " + axis + " pulses against " + std::to_string(q.size());
    }
  }
  if (!(a.end == b.end)) return "the positions at the end differ";
  return "";
}

}  // namespace dda::motion
