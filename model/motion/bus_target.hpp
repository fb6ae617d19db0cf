// SPDX-License-Identifier: Apache-2.0
// The motion block as a bus master sees it, one clock edge at a time: the target
// interface (reset, ce_i, the machine's input pins, the bus, the outputs after each
// edge), the taps that sit between a master and a target, and the reference model alone
// as a target (ModelTarget: `dda vectors --bus` records its cycles). The RTL beside the
// model is another target (tb/engines/motion_harness.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "model/motion/bridges.hpp"
#include "model/motion/motion_model.hpp"

namespace dda::motion {

class BusTarget {
 public:
  virtual ~BusTarget() = default;
  virtual void set_reset(bool rst_n) = 0;
  virtual void set_ce(bool ce) = 0;
  // The machine's input pins from the next edge on.
  virtual void set_pins(const MachinePins& pins) = 0;
  // The pins as last set.
  virtual const MachinePins& pins() const = 0;
  // One rising edge with these bus inputs (those of the target's bus).
  virtual void tick(const BusIn& bus) = 0;
  // The Wishbone inputs the block itself took on the last edge (behind a bridge, the
  // bridge's requests).
  virtual const BusIn& bus_seen() const = 0;
  // The outputs after the last edge.
  virtual const BlockOutputs& outputs() const = 0;
  // The reference model beside the target, after the last edge (equal to the target's
  // registers: every target checks that edge by edge).
  virtual const MotionModel& model() const = 0;
  // The bus the target takes (a bridged top's, or the block's own Wishbone).
  virtual Bus bus() const { return Bus::wishbone; }
};

// A target between the bus master and another target that passes everything through to
// it: the monitors and the simulated machine below override what they watch or drive.
class BusTap : public BusTarget {
 public:
  explicit BusTap(BusTarget& inner) : t_(inner) {}
  void set_reset(bool rst_n) override { t_.set_reset(rst_n); }
  void set_ce(bool ce) override { t_.set_ce(ce); }
  void set_pins(const MachinePins& pins) override { t_.set_pins(pins); }
  const MachinePins& pins() const override { return t_.pins(); }
  void tick(const BusIn& bus) override { t_.tick(bus); }
  const BusIn& bus_seen() const override { return t_.bus_seen(); }
  const BlockOutputs& outputs() const override { return t_.outputs(); }
  const MotionModel& model() const override { return t_.model(); }
  Bus bus() const override { return t_.bus(); }

 protected:
  BusTarget& t_;
};

// A target that keeps the next edge's reset, ce_i and pins until its tick (the models
// and the harnesses).
class HeldInputs : public BusTarget {
 public:
  void set_reset(bool rst_n) override { rst_n_ = rst_n; }
  void set_ce(bool ce) override { ce_ = ce; }
  void set_pins(const MachinePins& pins) override { pins_ = pins; }
  const MachinePins& pins() const override { return pins_; }

 protected:
  bool rst_n_ = true, ce_ = true;
  MachinePins pins_;
};

// The reference model alone, on its Wishbone bus or behind a bridge (the bridge's
// reference model, model/motion/bridges.hpp); `on_edge` sees every edge's bus inputs as the
// host drove them, the inputs as the block took them, and the outputs and state after it.
class ModelTarget : public HeldInputs {
 public:
  explicit ModelTarget(int depth_log2 = kMaxDepthLog2, Bus bus = Bus::wishbone)
      : model_(depth_log2), bridge_(make_bridge(bus)), bus_(bus) {}
  explicit ModelTarget(const Build& build, Bus bus = Bus::wishbone)
      : model_(build), bridge_(make_bridge(bus)), bus_(bus) {}
  Bus bus() const override { return bus_; }
  void tick(const BusIn& bus) override;
  const BusIn& bus_seen() const override { return seen_; }
  const BlockOutputs& outputs() const override { return out_; }
  const MotionModel& model() const override { return model_; }
  // The bridge's reference model (nullptr on Wishbone).
  const Bridge* bridge() const { return bridge_.get(); }
  std::function<void(const BusIn&, const BlockInputs&, const BlockOutputs&, const MotionModel&)> on_edge;

 private:
  MotionModel model_;
  std::unique_ptr<Bridge> bridge_;
  Bus bus_;
  BusIn seen_;
  BlockOutputs out_;
};

}  // namespace dda::motion
