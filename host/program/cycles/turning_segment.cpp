// SPDX-License-Identifier: Apache-2.0
// One segment of a turning cycle's contour (host/program/cycles/turning.hpp): where it crosses a
// depth, how a pass follows it down or up, its offset, and the joins and corner
// finishes between neighbours, with LinuxCNC's tolerances.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "host/program/cycles/turning.hpp"

namespace dda::program::detail::turning {

namespace {

bool on_arc(const Segment& g, Pt p) {
  const double from = std::imag(std::conj(g.s - g.c) * (p - g.c)), to = std::imag(std::conj(g.e - g.c) * (p - g.c));
  if (g.ccw) return from >= -kTol && to <= kTol;
  return from <= kTol && to >= -kTol;
}

// A line's dive (dive()).
bool dive_line(const Segment& g, Pt& at, double x, const Out& out, bool fast) {
  if (g.s.imag() <= g.e.imag() + kTol) return true;
  if (x < g.e.imag()) {
    out.line(g.e, fast);
    at = g.e;
    return false;
  }
  Cuts is;
  crossings(g, x, is);
  if (is.empty()) throw CycleError("the depth of cut passed the contour");
  const Pt end(is.front(), x);
  out.line(end, fast);
  at = end;
  return false;
}

// Where the line through a and b meets the circle about c through `on`: of the two
// meetings, the one closer to `near`.
Pt line_meets_circle(Pt a, Pt b, Pt c, Pt on, Pt near) {
  const Pt rot = std::conj(a - b) / std::abs(a - b);
  const Pt pe = (on - b) * rot, pc = (c - b) * rot;
  double h = std::norm(pc - pe) - std::imag(pc) * std::imag(pc);
  h = h < 0 ? 0 : std::sqrt(h);
  const Pt s1 = (std::real(pc) + h) / rot + b, s2 = (std::real(pc) - h) / rot + b;
  return std::abs(near - s1) < std::abs(near - s2) ? s1 : s2;
}

// A counter-clockwise arc is followed up to its top at most.
Pt top_end(const Segment& g) {
  return g.e.real() < g.c.real() ? Pt(g.c.real(), g.c.imag() + std::abs(g.s - g.c)) : g.e;
}

}  // namespace

double radius(const Segment& g) {
  return g.arc ? std::min(std::abs(g.s - g.e), std::abs(g.s - g.c)) : std::abs(g.s - g.e);
}

bool monotonic(const Segment& g) {
  if (!g.arc) return std::real(g.e - g.s) <= 1e-3;
  if (g.finish != 0) return true;
  const double entry = std::imag(g.s - g.c), exit = std::imag(g.e - g.c), dz = std::real(g.e - g.s);
  if (g.ccw) return entry >= -1e-3 && exit >= -1e-3 && dz <= -1e-3;
  return entry <= 1e-3 && exit <= 1e-3 && dz <= -1e-3;
}

void crossings(const Segment& g, double x, Cuts& is) {
  if (!g.arc) {
    if (std::min(g.s.imag(), g.e.imag()) > x + kTol || std::max(g.s.imag(), g.e.imag()) < x - kTol) return;
    if (std::abs(std::imag(g.s - g.e)) < kTol) {
      is.push_back(g.s.real());
      is.push_back(g.e.real());
    } else {
      is.push_back((x - g.s.imag()) / (g.e.imag() - g.s.imag()) * (g.e.real() - g.s.real()) + g.s.real());
    }
    return;
  }
  const double r = std::abs(g.s - g.c);
  double h = -(x - r - g.c.imag()) * (x + r - g.c.imag());
  if (h < -kTol) return;
  h = std::sqrt(std::max(h, 0.0));
  const Pt p1(g.c.real() + h, x), p2(g.c.real() - h, x);
  if (on_arc(g, p1)) is.push_back(p1.real());
  if (on_arc(g, p2)) is.push_back(p2.real());
}

void offset(Segment& g, double d) {
  if (!g.arc) {
    const Pt shift = kI * d * (g.s - g.e) / std::abs(g.s - g.e);
    g.s += shift;
    g.e += shift;
    return;
  }
  const double factor = (std::abs(g.s - g.c) + (g.ccw ? 1 : -1) * d) / std::abs(g.s - g.c);
  g.s = factor * (g.s - g.c) + g.c;
  g.e = factor * (g.e - g.c) + g.c;
}

// Follows the segment up (X rising) from `at`; true where it does not climb (a pocket
// may start there).
bool climb(const Segment& g, Pt& at, const Out& out) {
  if (!g.arc) {
    if (g.e.imag() + kTol < g.s.imag()) return true;
    if (std::abs(at - g.s) > kTol) throw CycleError("the pass left the contour");
    out.line(g.e, false);
    at = g.e;
    return false;
  }
  if (!g.ccw) {
    if (at.real() > g.c.real()) return true;
    if (std::abs(at - g.e) > 1e-3) out.arc(false, g.c, g.e);
    at = g.e;
    return false;
  }
  if (at.real() < g.c.real()) return true;
  const Pt end = top_end(g);
  if (std::abs(at - end) > 1e-3) out.arc(true, g.c, end);
  at = end;
  return true;
}

// From where the segment crosses X = at's, up along it (the variant without pockets).
void climb_only(const Segment& g, Pt& at, const Out& out) {
  if (!g.arc && g.e.imag() < g.s.imag()) return;
  Cuts is;
  crossings(g, at.imag(), is);
  if (is.empty()) return;
  if (!g.arc) {
    at.real(is.front());
    out.line(at, false);
    out.line(g.e, false);
    at = g.e;
    return;
  }
  if (!g.ccw) {
    if (is.back() > g.c.real()) return;
    at.real(is.back());
    out.line(at, false);
    if (std::abs(at - g.e) > 1e-3) out.arc(false, g.c, g.e);
    at = g.e;
    return;
  }
  if (is.front() < g.c.real()) return;
  at.real(is.front());
  out.line(at, false);
  const Pt end = top_end(g);
  if (std::abs(at - end) > 1e-3) out.arc(true, g.c, end);
  at = end;
}

// Follows the segment down (X falling) from `at` to X = x at most; true where it does not
// dive. The first segment (the approach) goes at the rapid rate.
bool dive(const Segment& g, Pt& at, double x, const Out& out, bool fast) {
  if (!g.arc) return dive_line(g, at, x, out, fast);
  if (std::abs(at - g.e) < kTol || std::real(at - g.e) <= kTol) {
    at = g.e;
    return false;
  }
  Cuts is;
  crossings(g, x, is);
  if (is.empty()) crossings(g, x - kTol, is);
  if (g.ccw) {
    if (at.real() - kTol > g.c.real()) return true;
  } else if (at.real() <= g.c.real()) {
    return true;  // already climbing
  }
  if (is.empty() || (g.ccw && is.back() > g.c.real())) {  // the depth not reached: to the end
    out.arc(g.ccw, g.c, g.e);
    at = g.e;
    return false;
  }
  if (!g.ccw && is.front() < g.c.real()) return false;  // met on the far side only: deeper first
  const Pt end(g.ccw ? is.back() : is.front(), x);
  out.arc(g.ccw, g.c, end);
  at = end;
  return false;
}

// Moves the end of `prev` and the start of `next` to where the two meet after an offset.
void join(Segment& prev, Segment& next) {
  if (!prev.arc && !next.arc) {
    const Pt rot = std::conj(next.s - next.e) / std::abs(next.s - next.e);
    const Pt ps = (prev.s - next.e) * rot, pe = (prev.e - next.e) * rot;
    if (std::imag(ps - pe) == 0) throw CycleError("two parallel lines of the contour cannot be joined");
    const double f = std::imag(ps) / std::imag(ps - pe);
    next.s = prev.e = (ps + f * (pe - ps)) / rot + next.e;
  } else if (prev.arc && !next.arc) {
    if (std::abs(next.s - prev.e) < kTol) return;
    next.s = prev.e = line_meets_circle(next.s, next.e, prev.c, prev.e, next.s);
  } else if (!prev.arc) {
    if (std::abs(next.s - prev.e) < kTol) return;
    next.s = prev.e = line_meets_circle(prev.s, prev.e, next.c, next.e, next.s);
  } else {
    const double a = std::abs(next.s - next.c), b = std::abs(prev.s - prev.c), c = std::abs(next.c - prev.c);
    const double cos_b = (c * c + a * a - b * b) / 2.0 / a / c;
    const double cos_b2 = std::min(cos_b * cos_b, 1.0);
    const Pt rot(cos_b, std::sqrt(1 - cos_b2));
    next.s = prev.e = rot * (prev.c - next.c) / c * a + next.c;
  }
}

// A corner h between prev and next finished: the neighbours offset by the finish (to the
// side where they meet), joined, and brought back; h spans the two tangent points (a
// rounding: about the joined point).
void finish_corner(Segment& h, Segment& prev, Segment& next) {
  Segment p = prev, n = next;
  offset(p, h.finish);
  offset(n, h.finish);
  if (std::real(p.e - n.s) > 1e-2) {
    h.finish = -h.finish;
    p = prev;
    n = next;
    offset(p, h.finish);
    offset(n, h.finish);
  }
  if (std::real(p.e - n.s) > 1e-2) {
    throw CycleError(fmt::format("the corner finish at Z{:.4f} X{:.4f} does not fit", prev.e.real(), prev.e.imag()));
  }
  join(p, n);
  const Pt centre = (p.e + n.s) / 2.0;
  offset(p, -h.finish);
  offset(n, -h.finish);
  h.s = prev.e = p.e;
  h.e = next.s = n.s;
  if (!h.arc) return;
  h.c = centre;
  h.ccw = std::imag(h.s - h.c) > 0 || std::imag(h.e - h.c) > 0;
  h.finish = 0;
}

}  // namespace dda::program::detail::turning
