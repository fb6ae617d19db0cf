// SPDX-License-Identifier: Apache-2.0
#include "host/speed/lookahead.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace dda::speed {

const char* to_string(Limit l) {
  switch (l) {
    case Limit::None:
      return "none";
    case Limit::VelocityX:
      return "vmax X";
    case Limit::VelocityY:
      return "vmax Y";
    case Limit::VelocityZ:
      return "vmax Z";
    case Limit::Curvature:
      return "curvature";
    case Limit::Length:
      return "length";
  }
  return "?";
}

double junction_speed(const Vec3& in, const Vec3& out, double deviation, const Vec3& axis_accel) {
  const double cos_theta = -(in[0] * out[0] + in[1] * out[1] + in[2] * out[2]);
  if (cos_theta > 0.999999) return 0;           // a reversal
  if (cos_theta < -0.999999) return kInfinity;  // straight on
  Vec3 j{out[0] - in[0], out[1] - in[1], out[2] - in[2]};
  const double n = std::sqrt(j[0] * j[0] + j[1] * j[1] + j[2] * j[2]);
  double a = kInfinity;
  for (std::size_t i = 0; i < 3; ++i) {
    const double c = std::abs(j[i] / n);
    if (c > 1e-12) a = std::min(a, axis_accel[i] > 0 ? axis_accel[i] / c : 0.0);
  }
  const double sin_half = std::sqrt(0.5 * (1 - cos_theta));
  return std::sqrt(a * deviation * sin_half / (1 - sin_half));
}

double ramp_time(double length, double v0, double v1, double vc, double a, double* peak) {
  // The peak of the triangle whose ramps at a from v0 and down to v1 cover the length.
  const double top = std::sqrt(std::max(0.0, (2 * a * length + v0 * v0 + v1 * v1) / 2));
  if (top <= vc) {
    if (peak) *peak = top;
    return (2 * top - v0 - v1) / a;
  }
  if (peak) *peak = vc;
  const double up = (vc * vc - v0 * v0) / (2 * a), down = (vc * vc - v1 * v1) / (2 * a);
  return (vc - v0) / a + (vc - v1) / a + (length - up - down) / vc;
}

Lookahead::Lookahead(const PlannerLimits& lim, std::function<void(const PlannedSegment&)> out)
    : lim_(lim), out_(std::move(out)) {}

double Lookahead::cap(const Segment& s, Limit* by) const {
  double v = s.feed;
  Limit why = Limit::None;
  constexpr Limit kAxis[3] = {Limit::VelocityX, Limit::VelocityY, Limit::VelocityZ};
  for (std::size_t i = 0; i < 3; ++i) {
    if (s.share[i] <= 1e-12) continue;
    const double vi = lim_.vmax[i] / s.share[i];
    if (vi < v) v = vi, why = kAxis[i];
  }
  if (std::isfinite(s.min_radius)) {
    const double vr = std::sqrt(lim_.normal_accel * s.min_radius);
    if (vr < v) v = vr, why = Limit::Curvature;
  }
  if (by) *by = why;
  return v;
}

void Lookahead::push(const Segment& s) {
  Item it;
  it.p.seg = s;
  it.p.cap = cap(s, &it.p.cap_by);
  if (!started_ || s.rest_before) {
    it.p.junction = 0;
  } else {
    const Vec3& in = q_.empty() ? last_t1_ : q_.back().p.seg.t1;
    const double prev_cap = q_.empty() ? last_cap_ : q_.back().p.cap;
    it.p.junction = std::min({junction_speed(in, s.t0, s.deviation, lim_.axis_accel), prev_cap, it.p.cap});
  }
  started_ = true;
  q_.push_back(std::move(it));
  if (q_.size() > lim_.window) emit_front();
}

void Lookahead::finish() {
  while (!q_.empty()) emit_front();
}

// The backward pass from rest after the last piece held, then the front's exit: the
// fastest it can reach from its entry, at most what the pieces after it can brake from.
void Lookahead::emit_front() {
  const double a = lim_.accel;
  double v = 0;
  for (std::size_t k = q_.size(); k-- > 1;) {
    Item& it = q_[k];
    it.entry_max = std::min(it.p.junction, std::sqrt(v * v + 2 * a * it.p.seg.length));
    v = it.entry_max;
  }
  PlannedSegment p = q_.front().p;
  p.entry = front_entry_;
  p.exit = std::min(v, std::sqrt(p.entry * p.entry + 2 * a * p.seg.length));
  p.time = ramp_time(p.seg.length, p.entry, p.exit, p.cap, a, &p.peak);
  last_t1_ = p.seg.t1;
  last_cap_ = p.cap;
  front_entry_ = p.exit;
  q_.pop_front();
  out_(p);
}

}  // namespace dda::speed
