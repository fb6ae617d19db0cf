// SPDX-License-Identifier: Apache-2.0
#include "tb/monitors/bus_monitors.hpp"

#include <string>

#include "model/datapath/errors.hpp"

namespace dda::motion {

void PieceMonitor::set_reset(bool rst_n) {
  reset_ = !rst_n;
  t_.set_reset(rst_n);
}

void PieceMonitor::tick(const BusIn& bus) {
  t_.tick(bus);
  const BlockRegs& r = t_.model().regs();
  const std::uint64_t done = r[breg("done_count_q")], err = r[breg("err_count_q")];
  if (reset_) {  // the counters restart from 0, the queue is empty
    ends_.clear();
    next_ = 0;
    done_ = done;
    err_ = err;
    return;
  }
  if (err != err_) throw GuardError("piece monitor: a queued piece stalled (ERR_COUNT " + std::to_string(err) + ")");
  if (done == done_) return;
  // Two pieces can finish on one edge (a piece whose last step leaves as a piece with no
  // step waiting ends): the position is then the later one's end.
  const std::uint64_t finished = (done - done_) & 0xFFFFFFFFu;
  done_ = done;
  if (next_ + finished > ends_.size()) throw GuardError("piece monitor: a piece finished that was not queued");
  next_ += std::size_t(finished);
  const Point want = ends_[next_ - 1];
  const auto x = std::int32_t(r[breg("pos_x_q")]), y = std::int32_t(r[breg("pos_y_q")]);
  const auto z = std::int32_t(r[breg("pos_z_q")]);
  if (x != want.x || y != want.y || z != want.z) {
    throw GuardError("piece monitor: piece " + std::to_string(next_) + " finished at (" + std::to_string(x) + ", " +
                     std::to_string(y) + ", " + std::to_string(z) + "), its end point is (" + std::to_string(want.x) +
                     ", " + std::to_string(want.y) + ", " + std::to_string(want.z) + ")");
  }
  ++checked_;
}

void SpeedWatch::tick(const BusIn& bus) {
  t_.tick(bus);
  if (!mon_) return;
  const BlockOutputs& o = t_.outputs();
  const std::uint64_t pol = t_.model().regs()[DDA_BREG("polarity_q")];
  // (POLARITY's bits found once: this runs on every edge.)
  static const std::array<int, 6> bit{field_of("POLARITY", "step_x").lsb, field_of("POLARITY", "step_y").lsb,
                                      field_of("POLARITY", "step_z").lsb, field_of("POLARITY", "dir_x").lsb,
                                      field_of("POLARITY", "dir_y").lsb,  field_of("POLARITY", "dir_z").lsb};
  const auto pin = [&](bool v, std::size_t k) { return v != (((pol >> bit[k]) & 1u) != 0); };
  mon_->edge({pin(o.step_x, 0), pin(o.step_y, 1), pin(o.step_z, 2)},
             {pin(o.dir_x, 3), pin(o.dir_y, 4), pin(o.dir_z, 5)});
}

}  // namespace dda::motion
