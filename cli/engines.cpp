// SPDX-License-Identifier: Apache-2.0
#include "cli/engines.hpp"

#include <iterator>
#include <utility>

#include "model/datapath/hw_command.hpp"
#include "tb/engines/core_driver.hpp"
#include "tb/engines/rtl_harness.hpp"
#include "tb/engines/sc_harness.hpp"

namespace dda::cli {

namespace {

// The SystemC model or the RTL under Verilator (--cc), driven over its ports with ce_i
// high; rows are built from its registers sampled after every edge, and a scoreboard
// checks every edge against the golden model as it comes (a mismatch is a run-time
// failure, exit status 1).
template <typename Harness>
class HardwareEngine : public Engine {
 public:
  HardwareEngine(const EngineOptions& opt, RunSink& sink)
      : h_(opt.vcd),
        drive_(
            reset(h_), no_records(), [&sink](const Iteration& it) { sink.record(it); },
            [&sink](const RegState& r) { sink.initial(r); }) {}
  void piece(const Piece& pc) override {
    hw::pack_command(pc.cmd);  // InputError if too wide for the hardware
    drive_.piece(pc);
  }
  void finish() override {
    drive_.finish();
    h_.close_trace();
  }

 private:
  static Harness& reset(Harness& h) {
    reset_core(h);
    return h;
  }
  static DriveOptions no_records() {
    DriveOptions o;
    o.keep_records = false;
    return o;
  }
  Harness h_;
  CoreDrive drive_;
};

using Factory = std::unique_ptr<Engine> (*)(const EngineOptions&, RunSink&);

template <typename E>
std::unique_ptr<Engine> make(const EngineOptions& opt, RunSink& sink) {
  return std::make_unique<E>(opt, sink);
}

std::unique_ptr<Engine> make_golden(const EngineOptions&, RunSink& sink) {
  return std::make_unique<GoldenEngine>(sink);
}

// In the order of kEngineNames.
constexpr Factory kFactories[] = {
    &make_golden,
    &make<HardwareEngine<sc::ScHarness>>,
    &make<HardwareEngine<rtl::RtlHarness>>,
};
static_assert(std::size(kFactories) == std::size(kEngineNames), "an engine without a factory, or the reverse");

}  // namespace

std::unique_ptr<Engine> make_engine(const std::string& name, const EngineOptions& opt, RunSink& sink) {
  for (std::size_t i = 0; i < std::size(kEngineNames); ++i) {
    if (name == kEngineNames[i]) return kFactories[i](opt, sink);
  }
  return nullptr;
}

}  // namespace dda::cli
