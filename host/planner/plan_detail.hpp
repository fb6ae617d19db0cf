// SPDX-License-Identifier: Apache-2.0
// Helpers shared by the planner's sources (not part of the library's interface).
#pragma once

#include <algorithm>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "host/planner/planner.hpp"
#include "model/datapath/rounding.hpp"

namespace dda::detail {

inline std::string pt(Point p) {
  std::ostringstream s;
  s << '(' << p.x << ',' << p.y;
  if (p.z != 0) s << ',' << p.z;  // (a point of a run that never moves the third axis: two coordinates)
  s << ')';
  return s.str();
}

// Ceil(num / den) for positive operands.
inline std::int64_t ceil_div(std::int64_t num, std::int64_t den) { return (num + den - 1) / den; }

// a * b, or nullopt if it does not fit in int64.
inline std::optional<std::int64_t> checked_mul(std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  if (__builtin_mul_overflow(a, b, &r)) return std::nullopt;
  return r;
}

inline int sign(i128 v) { return (v > 0) - (v < 0); }

// Quadrant signs (su, sv) of the four quadrants about the centre.
inline constexpr int kSu[5] = {0, +1, -1, -1, +1};
inline constexpr int kSv[5] = {0, +1, +1, -1, -1};

// Step directions in quadrant q: counter-clockwise, du has the sign of -v and dv of u.
inline int step_sx(int q, Direction dir) { return dir == Direction::Ccw ? -kSv[q] : kSv[q]; }
inline int step_sy(int q, Direction dir) { return dir == Direction::Ccw ? kSu[q] : -kSu[q]; }

// The quadrant (about the centre) whose steps, for direction dir, have signs (sx, sy).
inline int quadrant_of_steps(int sx, int sy, Direction dir) {
  for (int q = 1; q <= 4; ++q) {
    if (step_sx(q, dir) == sx && step_sy(q, dir) == sy) return q;
  }
  return 1;
}

// Iteration guard of a rotated ellipse's piece: a piece has at most 4 max(a, b) + 8
// steps, and between two steps at most 2^(n+2) / min(a, b) + 4 iterations (the larger
// integrand is at least about half the tangent's length, which is at least
// a b min(a, b) times the scale).
inline std::uint64_t rotated_piece_guard(const ArcSpec& spec) {
  const std::int64_t mn = std::min(spec.a, spec.b), mx = std::max(spec.a, spec.b);  // sub-step units
  return std::uint64_t(4 * steps_ceil(spec, mx) + 8) *
         (std::uint64_t(ceil_div(std::int64_t{1} << (spec.bits + 2 + spec.sub), mn)) + 4);
}

// The centre's fraction in Q(kPosFrac) (sub-step geometry; (0, 0) otherwise).
inline FixedPoint center_offset(const ArcSpec& s) {
  return FixedPoint{s.center_frac.x << (kPosFrac - s.sub), s.center_frac.y << (kPosFrac - s.sub)};
}

// Lattice point q relative to the ellipse's centre in sub-step units (Q(sub)).
inline std::pair<i128, i128> sub_rel(const ArcSpec& s, Point q) {
  return {(i128(q.x - s.center.x) << s.sub) - s.center_frac.x, (i128(q.y - s.center.y) << s.sub) - s.center_frac.y};
}

// The fixed-point datapath's tangent at lattice point q, times D (1 counter-clockwise, -1
// clockwise): (p x - qx y, qy x - p y) with (x, y) = q relative to the centre; for
// sub-step geometry computed in Q(sub) and rounded once to an integer (the integrands a
// command starts from; its corrections are the coefficients themselves).
inline std::pair<i128, i128> fixed_tangent(const ArcSpec& s, const Coefficients& k, int D, Point q) {
  const auto [x, y] = sub_rel(s, q);
  i128 tx = D * (i128(k.p) * x - i128(k.qx) * y), ty = D * (i128(k.qy) * x - i128(k.p) * y);
  if (s.sub != 0) tx = round_shift(tx, s.sub), ty = round_shift(ty, s.sub);
  return {tx, ty};
}

// A resolved start or end point: lattice point and the fraction of the ideal point.
struct EndPoint {
  Point lattice;
  std::int64_t fx = 0, fy = 0;  // Q(kPosFrac); non-zero only for half preload and theta
};

// Preload of an axis so that the represented position, lattice + s (jr / cap - 1/2),
// is lattice + frac / 2^kPosFrac (half preload; |frac| <= 1/2).
inline std::int64_t fraction_preload(std::int64_t cap, bool dir_neg, std::int64_t frac) {
  const __int128 s_frac = dir_neg ? -__int128(frac) : __int128(frac);
  const __int128 jr = (__int128(cap) * ((__int128(1) << (kPosFrac - 1)) + s_frac)) >> kPosFrac;
  return std::int64_t(std::clamp<__int128>(jr, 0, cap - 1));
}

// An end given as a parametric angle: the arc ends where the path first crosses the
// ray from the centre through that angle's ideal point `e` (relative, Q(kPosFrac)),
// moving in direction D; a full turn must pass the far side (the half-plane behind the
// centre) first. Whether the ray is still ahead at the start is decided from the
// represented start (the ideal point of a parametric start, which the lattice point can
// lie on the other side of). crossed() is called with every position after the start.
struct RayEnd {
  FixedPoint e;
  int D = 1;
  bool far_seen = true;
  bool armed = false;
  Point last;  // the position last looked at (relative); starts at the lattice start
  // Points are relative to the lattice centre; `off` is the true centre's offset from it
  // (sub-step geometry), so the ray is drawn from the true centre.
  FixedPoint off;
  RayEnd(FixedPoint end, Direction dir, bool full, FixedPoint start, Point lattice_start, FixedPoint centre_off = {})
      : e(FixedPoint{end.x - centre_off.x, end.y - centre_off.y}),
        D(dir == Direction::Ccw ? 1 : -1),
        last(lattice_start),
        off(centre_off) {
    // side < 0: the end lies less than half a turn ahead, so the path may end as soon as
    // it crosses the ray; otherwise (and for a full turn) it must pass the far side first.
    armed = far_seen = !full && side(start.x - off.x, start.y - off.y) < 0;
  }
  __int128 side(__int128 x, __int128 y) const { return D * (e.x * y - e.y * x); }
  // A lattice point relative to the true centre: exact integers, or Q(kPosFrac) when the
  // centre lies between lattice points.
  std::pair<__int128, __int128> from_centre(Point q) const {
    if (off.x == 0 && off.y == 0) return {q.x, q.y};
    return {(__int128(q.x) << kPosFrac) - off.x, (__int128(q.y) << kPosFrac) - off.y};
  }
  bool ahead(Point q) const {
    const auto [x, y] = from_centre(q);
    return e.x * x + e.y * y > 0;
  }
  // Only a step can cross the ray: an iteration without one leaves the verdict as it was.
  bool crossed(Point q) {
    if (q == last) return false;
    last = q;
    const auto [x, y] = from_centre(q);
    if (armed && side(x, y) >= 0 && ahead(q)) return true;
    far_seen = far_seen || !ahead(q);
    armed = far_seen && side(x, y) < 0;
    return false;
  }
};

// The coefficients of a turned ellipse for width n (see Coefficients), exact for
// quarter turns; the capacity goes with them.
struct Scaled {
  Coefficients k;
  std::int64_t cap = 0;
  i128 level = 0;  // quad_form on the nominal curve: a^2 b^2 (exact) or a b 2^(K-n)
};

// A start or end given as a lattice point or a parametric angle (planner.cpp): a lattice
// point as given (or the default when neither is given), an angle as the lattice point
// of theta_point() with, for half preload, the ideal point's fraction.
EndPoint resolve_point(const ArcSpec& spec, const std::optional<Point>& pnt, const std::optional<std::int64_t>& theta,
                       std::int64_t default_theta, const std::optional<Point>& default_pnt);

// The piece planners by the DDA's own path: each adds the arc's pieces to p, or says why
// it cannot (the caller reports that or plans another way).
// Quarter turns: pieces meet at the vertices (plan_quadrant.cpp).
[[nodiscard]] std::optional<Refusal> plan_quadrant_pieces(Plan& p, std::int64_t cap, const EndPoint& from,
                                                          std::optional<RayEnd> ray);
// Other angles: pieces found by running the datapath to each turn (plan_rotated.cpp).
[[nodiscard]] std::optional<Refusal> plan_rotated_pieces(Plan& p, const Scaled& sc, const EndPoint& from,
                                                         std::optional<RayEnd> ray);
// Rotated ellipses anchored on the ideal curve at every turn (plan_anchored.cpp): the arc
// from parametric angle theta_from (its first piece starting at `from`) to theta_to, or
// a full turn.
void plan_anchored_pieces(Plan& p, const Scaled& sc, const EndPoint& from, std::int64_t theta_from,
                          std::int64_t theta_to);

// The tangent of the ideal curve at parametric angle theta, counter-clockwise, in the
// ellipse's own scale: d/dtheta of R(angle) (a cos theta, b sin theta), Q(2 kTrigFrac).
std::pair<i128, i128> ideal_tangent(const ArcSpec& spec, std::int64_t theta);

// A turn of the ideal curve: where its tangent is parallel to an axis.
struct Turn {
  std::int64_t theta;  // micro-degrees in [0, 360 degrees)
  char axis;           // 'X': the X component of the tangent changes sign there; 'Y'
};

// The four turns of a rotated ellipse (plan_turns.cpp), kept for the next arc of the
// same shape.
std::vector<Turn> turns_of(const ArcSpec& spec);

// Refuses semi-axes or a centre beyond the planner's limits (InputError).
void check_axes_and_center(const ArcSpec& spec);

// The parametric angle (micro-degrees) of the curve point nearest to lattice point q
// (plan_curve.cpp).
std::int64_t nearest_theta(const ArcSpec& spec, Point q);

}  // namespace dda::detail
