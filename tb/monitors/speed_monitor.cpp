// SPDX-License-Identifier: Apache-2.0
#include "tb/monitors/speed_monitor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/datapath/errors.hpp"

namespace dda::motion {

std::uint64_t SpeedMonitor::window_for(const MotionLimits& l, double share) {
  if (!(l.clock_hz > 0)) throw GuardError("speed monitor: the clock must be positive");
  if (l.subs < 1) throw GuardError("speed monitor: a window takes at least one sample");
  if (!(share > 0)) return 1;
  // 2 * kQuantSteps / T^2 <= share * max_accel and kQuantSteps / T <= share / 2 *
  // max_speed, T = subs * sub / clock.
  double t = 0;
  if (l.max_accel > 0) t = std::sqrt(2 * kQuantSteps / (share * l.max_accel));
  if (l.max_speed > 0) t = std::max(t, kQuantSteps / (share / 2 * l.max_speed));
  return std::max<std::uint64_t>(1, std::uint64_t(std::ceil(t * l.clock_hz / l.subs)));
}

SpeedMonitor::SpeedMonitor(const MotionLimits& limits, std::uint64_t sub_clocks)
    : lim_(limits), sub_(sub_clocks ? sub_clocks : window_for(limits)) {
  if (!(lim_.clock_hz > 0)) throw GuardError("speed monitor: the clock must be positive");
  if (lim_.subs < 1) throw GuardError("speed monitor: a window takes at least one sample");
  // The machine is at rest when the monitor starts: the windows before it are still.
  at_.assign(std::size_t(lim_.subs) + 1, pos_);
  speeds_.assign(std::size_t(lim_.subs) + 1, 0.0);
  axis_v_.assign(std::size_t(lim_.subs) + 1, std::array<double, 3>{});
}

void SpeedMonitor::edge(const std::array<bool, 3>& step, const std::array<bool, 3>& dir) {
  for (std::size_t a = 0; a < 3; ++a) {
    if (step[a] && !step_[a]) pos_[a] += dir[a] ? -1 : 1;
    step_[a] = step[a];
  }
  if (++cycle_ % sub_ == 0) sample();
}

void SpeedMonitor::idle(std::uint64_t clocks) {
  step_ = {};
  while (clocks > 0) {
    const std::uint64_t k = std::min(clocks, sub_ - cycle_ % sub_);
    cycle_ += k;
    clocks -= k;
    if (cycle_ % sub_ == 0) sample();
  }
}

void SpeedMonitor::sample() {
  at_.push_back(pos_);
  at_.pop_front();
  double len = 0;
  for (std::size_t j = 1; j < at_.size(); ++j) {
    double s = 0;
    for (std::size_t a = 0; a < 3; ++a) {
      const double d = double(at_[j][a] - at_[j - 1][a]);
      s += d * d;
    }
    len += std::sqrt(s);
  }
  const double t_win = double(std::uint64_t(lim_.subs) * sub_) / lim_.clock_hz;
  Sample s;
  s.t = double(cycle_) / lim_.clock_hz;
  s.speed = len / t_win;
  speeds_.push_back(s.speed);
  speeds_.pop_front();
  s.accel = (s.speed - speeds_.front()) / t_win;
  samples_.push_back(s);
  sample_axes(t_win, s.t);
  peak_speed_ = std::max(peak_speed_, s.speed);
  peak_accel_ = std::max(peak_accel_, std::fabs(s.accel));
  if (lim_.max_speed > 0 && s.speed > lim_.max_speed * (1 + lim_.speed_tolerance)) {
    throw GuardError(
        fmt::format("speed monitor: {:.1f} steps/s over the window ending at {:.6f} s, above the limit "
                    "{:.1f} steps/s (+{:.0f}%)",
                    s.speed, s.t, lim_.max_speed, 100 * lim_.speed_tolerance));
  }
  if (lim_.max_accel > 0 && std::fabs(s.accel) > lim_.max_accel * (1 + lim_.accel_tolerance)) {
    throw GuardError(
        fmt::format("speed monitor: {:.4g} steps/s^2 between the windows ending at {:.6f} s and {:.6f} s, "
                    "above the limit {:.4g} steps/s^2 (+{:.0f}%)",
                    s.accel, s.t - t_win, s.t, lim_.max_accel, 100 * lim_.accel_tolerance));
  }
}

// Each axis over the same windows: its velocity, and the change from the window before.
void SpeedMonitor::sample_axes(double t_win, double t) {
  std::array<double, 3> v{};
  for (std::size_t a = 0; a < 3; ++a) v[a] = double(at_.back()[a] - at_.front()[a]) / t_win;
  axis_v_.push_back(v);
  axis_v_.pop_front();
  constexpr char kName[] = "XYZ";
  for (std::size_t a = 0; a < 3; ++a) {
    const double acc = (v[a] - axis_v_.front()[a]) / t_win;
    peak_axis_speed_[a] = std::max(peak_axis_speed_[a], std::fabs(v[a]));
    peak_axis_accel_[a] = std::max(peak_axis_accel_[a], std::fabs(acc));
    if (lim_.axis_speed[a] > 0 && std::fabs(v[a]) > lim_.axis_speed[a] * (1 + lim_.speed_tolerance)) {
      throw GuardError(
          fmt::format("speed monitor: axis {} at {:.1f} steps/s over the window ending at {:.6f} s, above "
                      "its limit {:.1f} steps/s (+{:.0f}%)",
                      kName[a], v[a], t, lim_.axis_speed[a], 100 * lim_.speed_tolerance));
    }
    if (lim_.axis_accel[a] > 0 && std::fabs(acc) > lim_.axis_accel[a] * (1 + lim_.accel_tolerance)) {
      throw GuardError(
          fmt::format("speed monitor: axis {} at {:.4g} steps/s^2 between the windows ending at {:.6f} s "
                      "and {:.6f} s, above its limit {:.4g} steps/s^2 (+{:.0f}%)",
                      kName[a], acc, t - t_win, t, lim_.axis_accel[a], 100 * lim_.accel_tolerance));
    }
  }
}

std::string SpeedMonitor::summary() const {
  return fmt::format(
      "speed monitor: {} windows of {} clocks, peak speed {:.1f} steps/s (limit {}), peak acceleration "
      "{:.4g} steps/s^2 (limit {})",
      samples_.size(), std::uint64_t(lim_.subs) * sub_, peak_speed_,
      lim_.max_speed > 0 ? fmt::format("{:.1f}", lim_.max_speed) : "none", peak_accel_,
      lim_.max_accel > 0 ? fmt::format("{:.4g}", lim_.max_accel) : "none");
}

}  // namespace dda::motion
