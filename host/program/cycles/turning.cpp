// SPDX-License-Identifier: Apache-2.0
// LinuxCNC's lathe turning cycles (host/program/cycles/turning.hpp): the contour's geometry and the
// passes. The profile is brought to one orientation (turned a quarter for facing,
// mirrored so that X and Z fall along it), its corners finished, worked there, and every
// pass mapped back.
// Where LinuxCNC's cycle would loop for ever or read outside its list, this one stops
// with a CycleError.
#include "host/program/cycles/turning.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <iterator>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace dda::program::detail::turning {

namespace {

// Bounds on the work of a cycle: rounds of the offsetting, and depths of cut.
constexpr int kMaxRounds = 100000;
constexpr double kMaxLevels = 1e5;

using Segments = std::list<Segment>;
using It = Segments::iterator;

// ---- the profile ----

class Profile {
 public:
  explicit Profile(Segments s) : segs_(std::move(s)) {
    if (segs_.size() < 2) throw CycleError("the contour needs at least two moves");
  }
  void finish(const CycleWords& w, const Sink& sink);
  void rough(const CycleWords& w, int variant, bool face, const Sink& sink);

 private:
  // A quarter turn (facing works as turning); flips_ bit 2.
  void rotate() {
    for (Segment& g : segs_) map_points(g, [](Pt p) { return -p * kI; });
    flips_ ^= 4;
  }
  // Mirrors so that X and Z fall from the contour's first end to its last (bits 1, 0).
  void orient();
  void mirror(bool along_z);
  void finish_corners();
  void check_monotonic();
  void add_distance(double distance);
  void offset_round(double step, double distance);
  void pocket(int variant, Pt at, It p, const Out& out);
  void cut(It& p, Pt& at, double& x, const Out& out);

  Segments segs_;
  int flips_ = 0;
  double delta_ = 0.5;
  Pt escape_{0.3, 0.3};
  std::vector<Pt> starts_;          // where the pockets' depths count from
  long steps_ = 0, max_steps_ = 0;  // the roughing's steps: LinuxCNC's can loop for ever
};

void Profile::mirror(bool along_z) {
  for (Segment& g : segs_) {
    map_points(g, [along_z](Pt p) { return along_z ? -std::conj(p) : std::conj(p); });
    g.ccw = !g.ccw;
  }
  flips_ ^= along_z ? 1 : 2;
}

void Profile::orient() {
  const double dir_x = std::imag(segs_.front().e - segs_.back().e), dir_z = std::real(segs_.front().e - segs_.back().e);
  if (dir_x > 0) mirror(false);
  if (dir_z < 0) mirror(true);
}

// The corners between two segments (a corner last in the contour has no next: it goes).
void Profile::finish_corners() {
  for (auto h = std::next(segs_.begin()); h != std::prev(segs_.end());) {
    const auto n = std::next(h);
    if (h->finish != 0) finish_corner(*h, *std::prev(h), *n);
    h = n;
  }
  for (auto p = segs_.begin(); p != segs_.end();) p = radius(*p) < 1e-3 ? segs_.erase(p) : std::next(p);
  if (segs_.empty()) throw CycleError("the contour vanishes");
}

// The approach may not lead away from the contour along Z; every segment must be monotonic.
void Profile::check_monotonic() {
  if (std::real(segs_.front().e - segs_.front().s) > 0) segs_.front().s.real(segs_.front().e.real());
  for (const Segment& g : segs_) {
    if (!monotonic(g)) throw CycleError("the contour is not monotonic (X must not rise as Z falls, or the reverse)");
  }
}

// The contour (but its first segment, the approach) moved by `distance` towards the
// material's outside, in rounds of at most half the shortest segment: segments that
// shrink away are dropped, gaps get an arc, segments that turn back are dropped and the
// neighbours joined again.
void Profile::add_distance(double distance) {
  const Pt v1 = segs_.front().e - segs_.front().s, v2 = segs_.back().s - segs_.front().s;
  if (std::imag(v1 / v2) < 0) distance = -distance;
  Segment approach = segs_.front();
  segs_.pop_front();
  double done = 0;
  for (int round = 0; done != distance; ++round) {
    if (round == kMaxRounds) throw CycleError("the contour's offset does not converge");
    double step = 1e9;
    for (const Segment& g : segs_) step = std::min(step, radius(g) / 2);
    step = std::min(step, std::abs(distance - done));
    if (distance < 0) step = -step;
    offset_round(step, distance);
    done += step;
  }
  for (auto p = segs_.begin(); std::next(p) != segs_.end(); ++p) {
    const Pt mid = (p->e + std::next(p)->s) / 2.0;
    p->e = std::next(p)->s = mid;
  }
  approach.e = segs_.front().s;
  segs_.push_front(approach);
}

void Profile::offset_round(double step, double distance) {
  for (auto p = segs_.begin(); p != segs_.end();) {
    offset(*p, step);
    p = radius(*p) < 1e-3 ? segs_.erase(p) : std::next(p);
  }
  // (Two segments at least where a join follows; LinuxCNC reads past its list there.)
  const auto few = [&](std::size_t n) {
    if (segs_.size() < n) throw CycleError("the allowance leaves too little of the contour");
  };
  few(1);
  for (auto p = segs_.begin(); p != std::prev(segs_.end()); ++p) {
    const auto n = std::next(p);
    if (std::real(p->e - n->s) > 1e-2) {  // a gap: closed by an arc about the old corner
      Segment s = *p, e = *n;
      offset(s, -step);
      offset(e, -step);
      segs_.insert(n, Segment{true, distance > 0, p->e, n->s, (s.e + e.s) / 2.0});
      ++p;
    }
  }
  for (auto p = segs_.begin(); p != std::prev(segs_.end()); ++p) {
    if (!monotonic(*p)) {
      if (p == segs_.begin()) throw CycleError("the offset contour turns back at its start");
      const auto pp = std::prev(p);
      segs_.erase(radius(*p) < radius(*pp) ? p : pp);
      few(2);
      p = segs_.begin();
    }
    if (radius(*p) < 1e-3) {
      segs_.erase(p);
      few(2);
      p = segs_.begin();
    } else {
      join(*p, *std::next(p));
    }
  }
}

void Profile::finish(const CycleWords& w, const Sink& sink) {
  segs_.front().s = Pt(w.z, w.x);
  Profile rest = *this;  // whether facing: the contour after the approach, oriented
  rest.segs_.pop_front();
  rest.orient();
  if (std::any_of(rest.segs_.begin(), rest.segs_.end(), [](const Segment& g) { return !monotonic(g); })) {
    rest.rotate();
    rest.orient();
  }
  rest.check_monotonic();
  if (rest.flips_ & 4) rotate();
  orient();
  finish_corners();
  check_monotonic();
  const Out out(sink, flips_);
  for (int pass = int(w.p); pass > 0; --pass) {
    const double distance = (pass - 1) * (w.d - w.e) / w.p + w.e;
    Profile path = *this;
    path.add_distance(distance);
    out.line(path.segs_.front().s, true);
    out.line(path.segs_.front().e, true);
    for (auto p = std::next(path.segs_.begin()); p != path.segs_.end(); ++p) out.draw(*p);
  }
}

void Profile::rough(const CycleWords& w, int variant, bool face, const Sink& sink) {
  segs_.front().s = Pt(w.z, w.x);
  if (face) rotate();
  orient();
  finish_corners();
  check_monotonic();
  add_distance(w.d);
  const Out out(sink, flips_);
  delta_ = std::max(w.i, 2 * kTol);
  escape_ = w.r * Pt(1, 1);
  // Each depth of cut takes a few steps per segment, and each pocket starts over: a
  // roughing that takes many more has stopped advancing.
  double low = segs_.front().s.imag(), high = low;
  for (const Segment& g : segs_) {
    low = std::min({low, g.s.imag(), g.e.imag()});
    high = std::max({high, g.s.imag(), g.e.imag()});
  }
  const double levels = (high - low) / delta_;
  if (!(levels <= kMaxLevels)) throw CycleError("I (the depth of cut) is too small: more than 100000 depths");
  const double n = double(segs_.size()) + 2;
  max_steps_ = long(8 * n * (levels + n)) + 1000;
  out.line(segs_.front().s, true);
  if (segs_.back().e.imag() < segs_.front().s.imag()) {  // back up to the start's X at the end
    Segment up;
    up.s = segs_.back().e;
    up.e = Pt(up.s.real(), segs_.front().s.imag());
    segs_.push_back(up);
  }
  starts_.push_back(segs_.front().s);
  pocket(variant, segs_.front().s, segs_.begin(), out);
}

// The roughing cuts from segment p on: each cut goes down by the depth of cut, along Z to
// the contour, and back with the retract; where the contour climbs it is followed, and
// a pocket behind it is cut the same way. Variant 1 follows the contour after the first
// roughing; variant 2 (then 3) skips the first roughing and cuts the pockets.
void Profile::pocket(int variant, Pt at, It p, const Out& out) {
  double x = starts_.back().imag();
  if (variant == 2) {
    for (; p != segs_.end(); ++p) {
      if (dive(*p, at, -1e9, out, p == segs_.begin())) break;
    }
    variant = 3;
  }
  while (p != segs_.end()) {
    if (++steps_ > max_steps_) throw CycleError("the roughing passes do not end (LinuxCNC's would loop for ever)");
    while (x - kTol > at.imag()) x -= delta_;
    if (dive(*p, at, x, out, p == segs_.begin())) {
      if (variant == 1) {
        for (; p != segs_.end(); ++p) climb_only(*p, at, out);
        return;
      }
      for (; p != segs_.end(); ++p) {
        if (!climb(*p, at, out)) continue;
        if (variant == 3) {
          if (at.imag() > starts_.back().imag() && starts_.size() > 1) starts_.pop_back();
          if (starts_.size() == 1) starts_.push_back(at);
        }
        return pocket(variant, at, p, out);
      }
      return;
    }
    if (std::abs(at.imag() - x) > kTol) {  // below this segment: on to the next
      ++p;
      continue;
    }
    cut(p, at, x, out);
  }
}

// One cut along Z at the tool's X, from segment p to the first segment it meets, and the
// retract; or, where the tool already stands on the next segment, on to it.
void Profile::cut(It& p, Pt& at, double& x, const Out& out) {
  for (auto ip = p; ip != segs_.end(); ++ip) {
    Cuts is;
    crossings(*ip, at.imag(), is);
    if (is.empty()) continue;
    const double z = ip != p ? is.front() : is.back();
    const double length = std::abs(z - at.real());
    if (z - kTol > at.real()) continue;  // the diving segment met at the start only
    if (length < kTol) {
      if (ip == p) continue;
      if (std::abs(at - ip->s) < kTol) {
        p = ip;
      } else {
        x -= delta_;  // a segment of length 0: done
      }
      return;
    }
    Pt to = at;
    to.real(z);
    out.line(to, false);
    const double scale = std::min(1.0, length / 2 / std::real(escape_));  // a short cut retracts less
    to += scale * escape_;
    out.line(to, true);
    out.line(at - std::conj(scale * escape_), true);
    out.line(at, p == segs_.begin());
    x -= delta_;
    return;
  }
}

}  // namespace

void finish(std::list<Segment> contour, const CycleWords& words, const Sink& out) {
  Profile(std::move(contour)).finish(words, out);
}

void rough(std::list<Segment> contour, const CycleWords& words, int variant, bool face, const Sink& out) {
  Profile(std::move(contour)).rough(words, variant, face, out);
}

}  // namespace dda::program::detail::turning
