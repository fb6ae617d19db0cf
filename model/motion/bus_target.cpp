// SPDX-License-Identifier: Apache-2.0
#include "model/motion/bus_target.hpp"

namespace dda::motion {

void ModelTarget::tick(const BusIn& bus) {
  const BlockInputs in = block_inputs(rst_n_, ce_, bridge_ ? bridge_->wishbone() : bus, pins_);
  const BlockOutputs before = model_.outputs();
  model_.edge(in);
  seen_ = in.bus;
  out_ = model_.outputs();
  if (bridge_) {
    bridge_->edge(rst_n_, bus, before);
    bridge_->outputs(out_);
  }
  if (on_edge) on_edge(bus, in, out_, model_);
}

}  // namespace dda::motion
