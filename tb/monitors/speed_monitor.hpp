// SPDX-License-Identifier: Apache-2.0
// The speed monitor: the path speed and tangential acceleration a machine would feel,
// measured from the step and direction pins alone (which edge rose, on which clock),
// independent of the model or the hardware that drove them. Beside the timing monitor
// (stepdir_monitor.hpp), which checks each edge against the drive's timings, this one
// checks the motion: it fails a run whose speed or acceleration exceeds the limits.
//
// Method. The monitor counts each axis' rising step edges in the direction the pin shows
// (the position a drive would count) and samples the positions every `sub` clocks. The
// path length over a window of `subs` samples (window = subs * sub clocks, T seconds) is
// the length of the polyline through them; the speed v is that length over T, the
// acceleration the change of v from one window to the next (windows T apart) over T.
// Counting whole steps puts each sampled position within one step of the motion per
// axis, so a window's length is off by at most kQuantSteps steps (its two ends: inner
// samples move their two segments the opposite way) and the acceleration by at most
// 2 * kQuantSteps / T^2: window_for() picks the shortest window that keeps both within a
// share of their limits. Windows slide by one sample. The machine is at rest
// when the monitor starts (a run that leaves rest at speed fails). The polyline follows a
// curve whose radius is large against a sample's length (a chord of s steps on a radius
// r is short by about (s / r)^2 / 24 of it); on a curve as short as that the figures are
// not meaningful. More samples per window follow a tighter curve.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace dda::motion {

struct MotionLimits {
  double clock_hz = 0;   // the block's clock
  double max_speed = 0;  // steps/s along the path; 0: not checked
  double max_accel = 0;  // steps/s^2 along the path; 0: not checked
  // The share over each limit a measured figure may reach before it fails.
  double speed_tolerance = 0.01, accel_tolerance = 0.05;
  int subs = 4;  // samples per window
  // Each axis' own speed and acceleration (steps/s, steps/s^2; 0: not checked): its
  // position's change over a window, and that change's change between windows.
  std::array<double, 3> axis_speed{}, axis_accel{};
};

class SpeedMonitor {
 public:
  static constexpr double kQuantSteps = 2.0;  // a window length's error from whole steps, at most
  // The sampling period (clocks) whose window keeps the quantization's share of the
  // acceleration at most `share` of max_accel and of the speed at most half that of
  // max_speed (at least 1 clock): the slower the limits, the longer the window.
  static std::uint64_t window_for(const MotionLimits& l, double share = 0.02);

  // sub_clocks: the sampling period; 0 takes window_for(limits).
  explicit SpeedMonitor(const MotionLimits& limits, std::uint64_t sub_clocks = 0);

  // One clock edge: the pins after it, as the drive sees them (active-high step, dir 1 =
  // negative; undo POLARITY first). A step counts on its rising edge, in the direction
  // the dir pin shows on that edge. Throws GuardError at the first window over a limit,
  // naming the figure, the time and the limit.
  void edge(const std::array<bool, 3>& step, const std::array<bool, 3>& dir);
  // `clocks` edges with every step output low.
  void idle(std::uint64_t clocks);

  struct Sample {
    double t = 0;  // seconds, the window's end
    double speed = 0, accel = 0;
  };
  const std::vector<Sample>& samples() const { return samples_; }
  double peak_speed() const { return peak_speed_; }
  double peak_accel() const { return peak_accel_; }  // the largest |acceleration|
  // Each axis' largest |speed| and |acceleration|.
  const std::array<double, 3>& peak_axis_speed() const { return peak_axis_speed_; }
  const std::array<double, 3>& peak_axis_accel() const { return peak_axis_accel_; }
  const MotionLimits& limits() const { return lim_; }
  std::uint64_t sub_clocks() const { return sub_; }
  std::array<std::int64_t, 3> position() const { return pos_; }
  // A one-line summary of the figures against the limits.
  std::string summary() const;

 private:
  void sample();
  void sample_axes(double t_win, double t);

  MotionLimits lim_;
  std::uint64_t sub_ = 1, cycle_ = 0;
  std::array<bool, 3> step_{};
  std::array<std::int64_t, 3> pos_{};
  std::deque<std::array<std::int64_t, 3>> at_;  // the last subs + 1 sampled positions
  std::deque<double> speeds_;                   // the last subs + 1 windows' speeds
  std::deque<std::array<double, 3>> axis_v_;    // and each axis' velocity
  std::vector<Sample> samples_;
  double peak_speed_ = 0, peak_accel_ = 0;
  std::array<double, 3> peak_axis_speed_{}, peak_axis_accel_{};
};

}  // namespace dda::motion
