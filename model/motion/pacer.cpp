// SPDX-License-Identifier: Apache-2.0
#include "model/motion/pacer.hpp"

#include <algorithm>
#include <cmath>

#include "model/datapath/hw_params.hpp"

namespace dda::motion {

namespace {

using u128 = unsigned __int128;

// floor(sqrt(n)), exactly.
std::uint64_t isqrt(u128 n) {
  u128 r = 0;
  for (int b = 63; b >= 0; --b) {
    const u128 t = r | (u128(1) << b);
    if (t * t <= n) r = t;
  }
  return std::uint64_t(r);
}

// A ramp speed of an entry speed.
std::uint64_t ramp(std::uint32_t v) { return std::uint64_t(v) << (kRampFrac - kSpeedFrac); }

// Distances inside: the speed per clock (kRampFrac) and an entry's length at kDistFrac bits.
std::uint64_t dist_of_speed(std::uint64_t v) { return v >> (kRampFrac - kDistFrac); }
std::uint64_t dist_of_len(std::uint32_t l) { return std::uint64_t(l) << (kDistFrac - kLenFrac); }

}  // namespace

NormOperands norm_operands(const Command& c, const RegState& r) {
  const auto v = [](std::int64_t cnt, std::int64_t jv) { return cnt != 0 && jv > 0 ? std::uint64_t(jv) : 0; };
  return NormOperands{v(r.cnt_x, r.jv_x), v(r.cnt_y, r.jv_y), v(r.cnt_z, c.jv_z), std::uint64_t(c.cap),
                      std::uint64_t(c.cap_z)};
}

std::uint64_t iteration_distance(const Command& c, const RegState& r) {
  return iteration_distance(norm_operands(c, r));
}

namespace {
// The norm unit's divider bit for bit (rtl/dda_norm.v): 2 kNormClocks restoring steps of
// the AW-bit remainder, the quotient's top kNormFrac + 1 bits. floor(v 2^kNormFrac / cap)
// for the operands the core gives (0 < cap, v <= cap).
std::uint64_t unit_quotient(std::uint64_t v, std::uint64_t cap) {
  const std::uint64_t amask = (std::uint64_t{1} << hw::kAccWidth) - 1;
  std::uint64_t n = v & amask, q = 0;
  for (int i = 0; i < 2 * kNormClocks; ++i) {
    const bool b = n >= cap;
    n = ((b ? n - cap : n) & amask) << 1;
    q = (q << 1) | std::uint64_t(b);
  }
  return q >> (2 * kNormClocks - (kNormFrac + 1));
}
}  // namespace

std::uint64_t Pacer::unit_d() const {
  // The sum of the squares in the unit's 2 (kNormFrac + 1) bits.
  const u128 sum = (u128(qx_) * qx_ + u128(qy_) * qy_ + u128(qz_) * qz_) & ((u128(1) << (2 * (kNormFrac + 1))) - 1);
  return isqrt(sum);
}

std::uint64_t iteration_distance(const NormOperands& o) {
  const auto q = [](std::uint64_t v, std::uint64_t cap) {
    return cap > 0 ? (u128(v) << kNormFrac) / u128(cap) : u128(0);
  };
  const u128 qx = q(o.v_x, o.cap), qy = q(o.v_y, o.cap), qz = q(o.v_z, o.cap_z);
  return isqrt(qx * qx + qy * qy + qz * qz);
}

namespace {
// brake_distance, not bounded by the entry's field.
u128 brake_length(std::uint32_t v, std::uint32_t vmin, std::uint64_t accel) {
  if (accel == 0 || v <= vmin) return 0;
  // Speeds v - a, v - 2a, ... while above vmin, one per clock: n v - a n (n + 1) / 2.
  const u128 V = ramp(v);
  const u128 n = (V - ramp(vmin) - 1) / accel;
  const u128 b = n * V - u128(accel) * n * (n + 1) / 2;  // x 2^kRampFrac steps
  const u128 unit = u128(1) << (kRampFrac - kLenFrac);
  return (b + unit - 1) / unit;
}
}  // namespace

std::uint32_t brake_distance(std::uint32_t v, std::uint32_t vmin, std::uint64_t accel) {
  const u128 l = brake_length(v, vmin, accel);
  if (l > 0xFFFFFFFFu) throw GuardError("pacer: a braking distance longer than an entry holds");
  return std::uint32_t(l);
}

namespace {
// Calls f(d) with iteration_distance of each of the piece's iterations, in order (once
// per run: only a step changes it).
template <typename F>
void each_iteration_distance(const Command& c, F f) {
  Datapath dp(c, Point{});
  const std::uint64_t bound = std::uint64_t{1} << 40;
  std::uint64_t run = iteration_distance(c, dp.regs());
  while (!dp.done()) {
    if (dp.stalled() || dp.iterations() > bound) throw GuardError("pacer: a piece that does not end");
    f(run);
    const Iteration it = dp.iterate();
    if (it.step_x || it.step_y || it.step_z) run = iteration_distance(c, dp.regs());
  }
}
}  // namespace

std::uint32_t pace_length(const Command& c) {
  u128 sum = 0;
  each_iteration_distance(c, [&](std::uint64_t x) { sum += x; });
  const u128 unit = u128(1) << (kNormFrac - kLenFrac);
  const u128 l = (sum + unit - 1) / unit;
  if (l > 0xFFFFFFFFu) throw GuardError("pacer: a piece longer than an entry's length field holds");
  return std::uint32_t(l);
}

std::uint64_t min_iteration_distance(const Command& c) {
  std::uint64_t least = 0;
  each_iteration_distance(c, [&](std::uint64_t x) {
    if (x > 0 && (least == 0 || x < least)) least = x;
  });
  return least;
}

std::uint32_t fastest_within(std::uint32_t cap, std::uint64_t budget, std::uint32_t vmin, std::uint64_t accel) {
  // brake_length does not fall as the speed rises: bisect for the highest speed.
  if (brake_length(cap, vmin, accel) <= budget) return cap;
  std::uint32_t lo = std::min(vmin, cap), hi = cap;
  while (hi - lo > 1) {
    const std::uint32_t mid = lo + (hi - lo) / 2;
    (brake_length(mid, vmin, accel) <= budget ? lo : hi) = mid;
  }
  return lo;
}

void limit_exits(std::vector<PaceEntry>& entries, std::uint32_t vmin, std::uint64_t accel) {
  const std::uint64_t margin = std::uint64_t{1} << (kLenFrac - kMarginShift);
  for (std::size_t k = entries.size(); k-- > 0;) {
    PaceEntry& e = entries[k];
    if (k + 1 < entries.size() && accel != 0) {  // (without a ramp the speed jumps)
      // The pacer enters the next piece at this exit (its phase 0: it takes an entry
      // only when none runs) and ramps down once its braking distance and the margin
      // reach what is left of that piece and the braking from its own exit (none for
      // the last: it ends at VMIN).
      const PaceEntry& next = entries[k + 1];
      const std::uint64_t room = std::uint64_t(next.length) + (k + 2 < entries.size() ? next.brake_exit : 0);
      e.exit = room >= margin ? fastest_within(e.exit, room - margin, vmin, accel) : std::min(e.exit, vmin);
    }
    e.brake_exit = brake_distance(e.exit, vmin, accel);
  }
}

std::vector<PaceEntry> pace_entries(const std::vector<Command>& pieces, std::uint32_t cruise, std::uint32_t vmin,
                                    std::uint64_t accel) {
  std::vector<PaceEntry> entries(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    PaceEntry& e = entries[i];
    e.cruise = e.limit = cruise;
    e.length = pace_length(pieces[i]);
    e.exit = i + 1 < pieces.size() ? cruise : 0;
  }
  limit_exits(entries, vmin, accel);
  return entries;
}

std::uint64_t Pacer::phase() const { return std::uint64_t(ph_) & ((std::uint64_t{1} << kPhaseWidth) - 1); }

bool Pacer::decelerate(const In& in) const {
  const std::int64_t exit_brake = in.next_queued ? std::int64_t(dist_of_len(e_.brake_exit)) : 0;
  const std::int64_t margin = std::int64_t{1} << (kDistFrac - kMarginShift);
  // (the phase as a distance: floor, also below 0)
  return std::int64_t(s_) + (ph_ >> (kRampFrac - kDistFrac)) + margin >= std::int64_t(rem_) + exit_brake;
}

std::uint64_t Pacer::target(const In& in) const {
  if (in.set.hold) return 0;
  std::uint64_t t = eff_;
  // (Without a ramp the speed jumps: no piece slows down before its end.)
  if (in.set.accel != 0 && decelerate(in)) t = std::min(t, in.next_queued ? ramp(e_.exit) : 0);
  return std::max(t, ramp(in.set.vmin));
}

bool Pacer::blocked(const In& in) const {
  // (A step seen on this clock, or due: the norm unit starts on the run it begins, and
  // while it reads the operands the registers must hold; a correction on this clock.)
  return first_ || due_ || (pending_ && in.stepped) || (busy_ == 0 && !fresh_) ||
         busy_ > kNormLatency - kNormOperandEdges + 1;
}

bool Pacer::iterate(const In& in) const {
  if (!in.advance || !in.running || blocked(in)) return false;
  return ph_ + std::int64_t(v_) >= std::int64_t(d_ << (kRampFrac - kNormFrac));
}

std::uint64_t Pacer::idle_clocks(const In& in) const {
  if (!in.advance || !in.running || in.take || busy_ != 0 || pending_ || first_ || due_ || !fresh_ || cm_ != 0 ||
      v_ == 0 || v_ != target(in) || mul_ != 0 || in.set.override_ != ovr_)
    return 0;
  // Clock j (from 0) adds v to ph + j v: no iteration while ph + (j + 1) v < D.
  const std::int64_t D = std::int64_t(d_ << (kRampFrac - kNormFrac)), v = std::int64_t(v_);
  if (ph_ + v >= D) return 0;
  std::int64_t n = (D - ph_ - 1) / v;
  if (!decelerate(in)) {  // once true it stays true while the phase grows
    // The decision reads floor(ph / 2^(kRampFrac - kDistFrac)) + j v against rem + brake - s - margin.
    const std::int64_t exit_brake = in.next_queued ? std::int64_t(dist_of_len(e_.brake_exit)) : 0;
    const std::int64_t margin = std::int64_t{1} << (kDistFrac - kMarginShift);
    using i128 = __int128;  // (the threshold at the phase's scale passes 2^63)
    const i128 thr = i128(std::int64_t(rem_) + exit_brake - std::int64_t(s_) - margin) *
                     (std::int64_t{1} << (kRampFrac - kDistFrac));
    const i128 k = thr > ph_ ? (thr - 1 - ph_) / v + 1 : 0;
    n = std::int64_t(std::min<i128>(n, k));
  }
  return std::uint64_t(n);
}

void Pacer::skip(const In& in, std::uint64_t clocks) {
  ph_ += std::int64_t(clocks * v_);
  down_ = decelerate(in);
}

std::int64_t Pacer::correction_part() const {
  if ((cm_ & 1) == 0) return 0;
  const std::uint64_t sign = std::uint64_t{1} << (kCorrectionWidth - 1);
  return std::int64_t(cd_ ^ sign) - std::int64_t(sign);
}

void Pacer::norm_edge(const In& in, bool it) {
  // A step on the last edge (or one due) starts the norm unit on the new run, whose
  // iterations the pacer paces with the d it has (provisionally, counted in m) until the
  // unit has the run's own: then it takes it and corrects by m times the difference, a
  // bit of m per clock (cm_, cd_). A take starts it on the new piece's first run, whose
  // d the pacer waits for.
  const bool seen = pending_ && in.stepped, free = busy_ == 0;
  const bool load = free && !fresh_;
  const bool start = in.take || (free && (seen || due_));
  const std::uint64_t cmask = (std::uint64_t{1} << kCorrectionWidth) - 1;
  if (cm_ != 0) {
    cm_ >>= 1;
    cd_ = (cd_ << 1) & cmask;
  }
  // The unit reads each axis' operands on the first edge of its division (x's on the
  // edge after the start); a start on its last edge starts it again.
  if (busy_ == kNormLatency) qx_ = unit_quotient(in.norm.v_x, in.norm.cap);
  if (busy_ == kNormLatency - kNormClocks) qy_ = unit_quotient(in.norm.v_y, in.norm.cap);
  if (busy_ == kNormLatency - 2 * kNormClocks) qz_ = unit_quotient(in.norm.v_z, in.norm.cap_z);
  if (busy_ > 0 && --busy_ == 0 && !start) nd_ = unit_d();
  if (it && !fresh_) ++m_;
  if (load) {
    cm_ = m_;
    cd_ = std::uint64_t(std::int64_t(nd_) - std::int64_t(d_)) & cmask;
    d_ = nd_;
    fresh_ = true;
    first_ = false;
  }
  if (start) {
    busy_ = kNormLatency;
    fresh_ = due_ = false;
    m_ = 0;
  } else if (seen) {
    due_ = true;
  }
  pending_ = it;
}

void Pacer::ramp_edge(const In& in, std::uint64_t t) {
  const std::uint64_t a = in.set.accel, vmin = ramp(in.set.vmin);
  std::uint64_t v = v_;
  if (a == 0) {
    v = t;
    s_ = 0;
  } else if (v_ < t) {
    v = t - v_ > a ? v_ + a : t;
    if (v_ > vmin) s_ += dist_of_speed(v_);
  } else if (v_ > t) {
    v = v_ - t > a ? v_ - a : t;
    if (v > vmin) s_ -= std::min(s_, dist_of_speed(v));
  }
  v_ = v;
  if (v_ == 0) s_ = 0;
}

void Pacer::edge(const In& in) {
  // Every decision from the state before the edge (as the hardware's wires).
  const bool it = iterate(in);
  const std::uint64_t t = target(in);
  const std::uint64_t d_it = d_;
  const bool correcting = cm_ != 0;
  const std::int64_t corr = correction_part();
  norm_edge(in, it);
  // The distance to go and the phase: d off on an iteration and a part of the
  // correction on each of its clocks (x 2^-kNormFrac steps); v per clock while a piece
  // runs.
  const std::int64_t amt = (it ? std::int64_t(d_it) : 0) + corr;
  if (it || correcting) {
    const std::int64_t r = std::int64_t(rem_) - amt * (std::int64_t{1} << (kDistFrac - kNormFrac));
    rem_ = r > 0 ? std::uint64_t(r) : 0;
  }
  if (!in.running) {
    ph_ = 0;
  } else if (in.advance || correcting) {
    const std::int64_t sub = amt * (std::int64_t{1} << (kRampFrac - kNormFrac));
    ph_ = std::min(ph_ + (in.advance ? std::int64_t(v_) : 0) - sub, (std::int64_t{1} << kPhaseBits) - 1);
  }
  if (in.advance && in.running) ramp_edge(in, t);
  if (!in.running && !in.take) v_ = s_ = 0;  // no piece: at rest
  // The cruise speed times the override: kOverrideClocks after a take or a change of
  // the override (either starts it again), from the entry then in force.
  if (mul_ > 0 && --mul_ == 0) {
    eff_ = std::min(ramp(e_.cruise) / kOverrideOne * ovr_, ramp(e_.limit));  // (ramp(c) is a multiple of kOverrideOne)
  }
  if (in.take || in.set.override_ != ovr_) {
    ovr_ = in.set.override_;
    mul_ = kOverrideClocks;
  }
  if (in.take) {
    e_ = in.entry;
    eff_ = std::min(eff_, ramp(e_.limit));  // the product in force, within the new limit at once
    rem_ = dist_of_len(e_.length);
    pending_ = due_ = fresh_ = false;
    first_ = true;
    m_ = cm_ = 0;  // (a correction left of the piece before is dropped with it)
  }
  down_ = decelerate(in);
}

}  // namespace dda::motion
