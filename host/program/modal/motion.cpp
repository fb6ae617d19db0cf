// SPDX-License-Identifier: Apache-2.0
// The program reader's motion (docs/programs.md, "Machines and the plane" and "Arcs and
// ellipses"): a block's target in machine coordinates, on the plane of the two axes
// (the machine's: a lathe's G18, a mill's plane in force at its first move), its lines,
// arcs (by centre or radius, with the dialect's end tolerance) and ellipses.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "host/geometry/fixed_trig.hpp"
#include "host/program/reader.hpp"

namespace dda::program::detail {

namespace {

std::string plane_name(int plane) { return plane == 180 ? "G18: Z, X" : plane == 190 ? "G19: Y, Z" : "G17: X, Y"; }

// The centre of a circle of radius r through p and q (distinct), on the side that makes
// the turn from p to q in direction cw sweep at most half a turn (short) or at least (long).
std::pair<double, double> centre_through(double px, double py, double qx, double qy, double r, bool cw,
                                         bool short_arc) {
  const double mx = (px + qx) / 2, my = (py + qy) / 2;
  const double dx = qx - px, dy = qy - py;
  const double d = std::hypot(dx, dy);
  const double h = std::sqrt(std::max(0.0, r * r - d * d / 4));
  // Left of the chord (counter-clockwise side): a ccw short arc has its centre there.
  const double lx = -dy / d, ly = dx / d;
  const bool left = (!cw) == short_arc;
  const double s = left ? h : -h;
  return {mx + s * lx, my + s * ly};
}

}  // namespace

Reader::PlaneAxes Reader::plane_axes(int plane) {
  if (plane == 180) return {2, 0, 1, 'K', 'I'};
  if (plane == 190) return {1, 2, 0, 'J', 'K'};
  return {0, 1, 2, 'I', 'J'};
}

// The plane of the two axes is fixed by the first block that needs the position: the
// start (given on that plane) is placed there, the normal axis at 0.
void Reader::fix_lattice() {
  if (lattice_ != 0) return;
  lattice_ = opt_.machine == Machine::Lathe ? 180 : m_.plane;
  const PlaneAxes pa = plane_axes(lattice_);
  pos_[std::size_t(pa.u)] = sum_.start.u;
  pos_[std::size_t(pa.v)] = sum_.start.v;
  pos_[std::size_t(pa.w)] = 0;
}

// The letters a motion block may carry besides its axes, by mode and dialect.
void Reader::check_letters(const Block& b) const {
  const bool lcnc = dialect_ == Dialect::LinuxCnc, lathe = opt_.machine == Machine::Lathe;
  const bool ellipse_mode = m_.motion == 62 || m_.motion == 63, arc_mode = m_.motion == 20 || m_.motion == 30;
  const PlaneAxes pa = plane_axes(m_.plane);
  for (const auto& [c, w] : b.axes) {
    const std::string l(1, c);
    if (c == 'X' || c == 'Z' || (c == 'Y' && !lathe)) continue;
    if (c == 'Y') fail(w->pos, "Y is not an axis of the lathe (Z and X)");
    if ((c == 'U' || c == 'W') && lathe && !lcnc) continue;
    if ((c == pa.iu || c == pa.iv) && (arc_mode || ellipse_mode)) continue;
    if ((c == 'R' || (c == 'P' && lcnc)) && arc_mode) continue;
    if ((c == 'A' || c == 'B' || c == 'Q') && ellipse_mode) continue;
    if (c == 'U' || c == 'V' || c == 'W') {
      if (lcnc) fail(w->pos, l + ": secondary linear axes (U, V, W) are not supported");
      fail(w->pos, l + " is not an axis of the " +
                       (lathe ? std::string("lathe (Z and X)") : "plane in force (G17 X Y, G18 Z X, G19 Y Z)"));
    }
    if (c == 'C' || ((c == 'A' || c == 'B') && lcnc)) {
      fail(w->pos, l + ": rotary axes (A, B, C) are not supported: the interpolator drives linear axes");
    }
    if (c == 'I' || c == 'J' || c == 'K') fail(w->pos, l + " is not a centre word here");
    if (c == 'R') fail(w->pos, "R is read only with G02/G03");
    if (c == 'P') fail(w->pos, lcnc ? "P is read only with G04, G10, G64 and arcs" : "P is read only with G04 and M98");
    if (c == 'L') fail(w->pos, lcnc ? "L is read only with G10" : "L is read only with M98");
    if (c == 'H') fail(w->pos, "H is read only with G43");
    if (c == 'D')
      fail(w->pos, lcnc ? "D is read only with G41/G42 and the turning cycles G70-G72" : "D is read only with G41/G42");
    if (c == 'E') fail(w->pos, "E is read only with G70");
    fail(w->pos, l + " is read only with G6.2/G6.3");
  }
}

// The block's target in machine coordinates (the axis normal to the plane may move: a
// 3-D line, a helix; the planner decides what the interpolator runs).
Axes Reader::target(const Block& b, bool machine, const SourcePos& /*where*/) const {
  return word_axes(b, machine, pos_);
}

void Reader::motion(const Block& b, const SourcePos& where, bool machine) {
  if (m_.motion < 0) fail(where, "a move with no motion mode (G00, G01, G02, G03, G6.2, G6.3) in force");
  fix_lattice();
  check_letters(b);
  const bool arc_mode = m_.motion == 20 || m_.motion == 30, feed_mode = m_.motion != 0;
  if (machine && m_.motion != 0 && m_.motion != 10) fail(where, "G53 goes with G00 or G01 only");
  if (machine && m_.incremental) fail(where, "G53 moves to machine coordinates: not in G91 (LinuxCNC refuses it)");
  const bool ellipse_mode = m_.motion == 62 || m_.motion == 63;
  if (ellipse_mode && m_.plane != lattice_) {
    fail(where, fmt::format("G{}.{} in ", m_.motion / 10, m_.motion % 10) + plane_name(m_.plane) +
                    ": an ellipse outside the plane of the two axes (" + plane_name(lattice_) + ") is not supported");
  }
  // An arc lies in the plane in force (a helix along its normal); every other move is
  // given in the plane of the two axes.
  move_plane_ = arc_mode ? m_.plane : lattice_;
  if (arc_mode && move_plane_ != 170 && rotation_[std::size_t(m_.cs)] != 0) {
    fail(where, "G" + std::to_string(m_.motion / 10) + " in " + plane_name(m_.plane) +
                    " with the coordinate system turned (G10 L2 R): the arc's plane turns with X and Y, out of "
                    "the machine's planes, and the interpolator's axes cannot follow it (such arcs are not "
                    "supported)");
  }
  if (dialect_ != Dialect::Hnc && feed_mode) {  // (HNC's examples carry no F)
    if (m_.inverse_time && !b.feed) fail(where, "G93 (inverse time): every feed move needs its own F");
    if (!m_.inverse_time && m_.feed <= 0) {
      fail(where, "G" + std::to_string(m_.motion / 10) + " with no feed rate in force: give F (" +
                      (dialect_ == Dialect::LinuxCnc ? "LinuxCNC refuses" : "Fanuc's controls alarm at") +
                      " a feed move at zero feed)");
    }
  }
  const Axes to = target(b, machine, where);
  const PlaneAxes pa = plane_axes(move_plane_);
  Move mv;
  mv.pos = where;
  mv.block_number = b.n;
  mv.from = Point2{pos_[std::size_t(pa.u)], pos_[std::size_t(pa.v)]};
  mv.to = Point2{to[std::size_t(pa.u)], to[std::size_t(pa.v)]};
  mv.feed = m_.feed;
  if (m_.motion == 0 || m_.motion == 10) {
    mv.kind = m_.motion == 0 ? MoveKind::Rapid : MoveKind::Line;
  } else if (arc_mode) {
    mv.kind = m_.motion == 20 ? MoveKind::ArcCw : MoveKind::ArcCcw;
    arc(mv, b, where);
  } else {
    mv.kind = m_.motion == 62 ? MoveKind::EllipseCw : MoveKind::EllipseCcw;
    ellipse(mv, b, where);
  }
  emit(mv, to);
}

// A rapid from the tool to `to` (G28, G30).
void Reader::traverse(const Axes& to, const Block& b, const SourcePos& where) {
  move_plane_ = lattice_;
  const PlaneAxes pa = plane_axes(move_plane_);
  Move mv;
  mv.pos = where;
  mv.block_number = b.n;
  mv.kind = MoveKind::Rapid;
  mv.from = Point2{pos_[std::size_t(pa.u)], pos_[std::size_t(pa.v)]};
  mv.to = Point2{to[std::size_t(pa.u)], to[std::size_t(pa.v)]};
  mv.feed = m_.feed;
  emit(mv, to);
}

void Reader::emit(Move& mv, const Axes& to) {
  const std::size_t w = std::size_t(plane_axes(move_plane_).w);
  mv.w = pos_[w];
  mv.w_to = to[w];
  mv.plane = move_plane_;
  mv.feed_mode = m_.inverse_time ? FeedMode::InverseTime : m_.per_rev ? FeedMode::PerRevolution : FeedMode::PerMinute;
  mv.inch = m_.inch;
  mv.feed_stale = m_.feed_mode_of_f != (m_.inverse_time ? 2 : m_.per_rev ? 1 : 0);
  mv.spindle = m_.spindle;
  mv.css = m_.css;
  mv.exact_stop = m_.exact_stop;
  mv.path_tolerance = m_.path_tolerance;
  mv.dwell = dwell_;
  mv.stop = stop_;
  dwell_ = 0;
  stop_ = false;
  out_.on_move(mv);
  pos_ = to;
  sync_position();
}

void Reader::arc(Move& mv, const Block& b, const SourcePos& where) {
  const PlaneAxes pa = plane_axes(move_plane_);
  const auto iu = b.axes.find(pa.iu), iv = b.axes.find(pa.iv), r = b.axes.find('R');
  const bool has_centre = iu != b.axes.end() || iv != b.axes.end();
  if (r != b.axes.end() && has_centre) fail(r->second->pos, "an arc takes a centre or a radius R, not both");
  if (r == b.axes.end() && !has_centre) {
    fail(where, std::string("an arc needs a centre (") + pa.iu + ", " + pa.iv + ") or a radius R");
  }
  if (const auto p = b.axes.find('P'); p != b.axes.end()) {
    const std::int64_t t = integer(*p->second);
    if (t < 1 || t > 10000) fail(p->second->pos, "P (the arc's turns) must be from 1 to 10000");
    mv.turns = int(t);
  }
  if (has_centre) return arc_by_centre(mv, b, where);
  arc_by_radius(mv, *r->second, where);
}

// Centre words are offsets from the start (RS274; the lathe's I is a radius), or with
// G90.1 the centre itself in program coordinates. The end must lie on the circle within
// the dialect's tolerance.
void Reader::arc_by_centre(Move& mv, const Block& b, const SourcePos& where) {
  const PlaneAxes pa = plane_axes(move_plane_);
  const auto iu = b.axes.find(pa.iu), iv = b.axes.find(pa.iv);
  const Length du = iu != b.axes.end() ? length(*iu->second) : 0, dv = iv != b.axes.end() ? length(*iv->second) : 0;
  if (m_.ijk_absolute) {
    Axes c = to_program(pos_);
    c[std::size_t(pa.u)] = du;
    c[std::size_t(pa.v)] = dv;
    const Axes m = to_machine(c);
    mv.center = Point2{m[std::size_t(pa.u)], m[std::size_t(pa.v)]};
  } else if (rotation_[std::size_t(m_.cs)] != 0 && move_plane_ == 170) {
    const auto [x, y] = turn(double(du), double(dv), 1);  // offsets turn with the system
    mv.center = Point2{mv.from.u + std::llround(x), mv.from.v + std::llround(y)};
  } else {
    mv.center = Point2{mv.from.u + du, mv.from.v + dv};
  }
  const double r0 = std::hypot(double(mv.from.u - mv.center.u), double(mv.from.v - mv.center.v));
  const double r1 = std::hypot(double(mv.to.u - mv.center.u), double(mv.to.v - mv.center.v));
  if (r0 < 1) fail(where, "the arc's centre is its start point");
  const double off = std::fabs(r1 - r0);
  if (dialect_ == Dialect::LinuxCnc) {
    // LinuxCNC's rule (rs274 2.9): refused when off both its absolute tolerance and 0.1%.
    const double tol = double(m_.inch ? kLinuxCncEndToleranceInch : kLinuxCncEndTolerance);
    if (off > tol && off > 0.001 * std::max(r0, r1)) {
      fail(where, fmt::format("the end is {:.4f} mm off the arc's circle (radius {:.4f} mm; LinuxCNC's tolerance "
                              "{:.4f} mm or 0.1% of the radius)",
                              off / double(kNmPerMm), r0 / double(kNmPerMm), tol / double(kNmPerMm)));
    }
  } else if (off > double(kEndTolerance)) {
    fail(where, fmt::format("the end is {:.4f} mm off the arc's circle (radius {:.4f} mm; tolerance {:.3f} mm)",
                            length_mm(Length(std::llround(off))), r0 / double(kNmPerMm), length_mm(kEndTolerance)));
  }
  mv.end_off = Length(std::llround(off));
  mv.radius = Length(std::llround(r0));
  mv.full = mv.from == mv.to;
}

// R > 0: the arc of at most half a turn; R < 0 the longer one.
void Reader::arc_by_radius(Move& mv, const Word& r, const SourcePos& /*where*/) {
  const Length rr = length(r);
  if (rr == 0) fail(r.pos, "the radius R must not be 0");
  if (mv.from == mv.to) fail(r.pos, "a full circle needs a centre, not R");
  const double d = std::hypot(double(mv.to.u - mv.from.u), double(mv.to.v - mv.from.v));
  const double ar = std::fabs(double(rr));
  // (LinuxCNC lets the half chord pass the radius by 0.00005 in, 1.27 um.)
  const double reach = dialect_ == Dialect::LinuxCnc ? 2 * (ar + 1270) : 2 * ar + double(kEndTolerance);
  if (d > reach) {
    fail(r.pos, fmt::format("the end is out of reach: {:.4f} mm from the start, more than twice R {:.4f} mm",
                            d / double(kNmPerMm), ar / double(kNmPerMm)));
  }
  const bool cw = mv.kind == MoveKind::ArcCw;
  const auto [cx, cy] =
      centre_through(double(mv.from.u), double(mv.from.v), double(mv.to.u), double(mv.to.v), ar, cw, rr > 0);
  mv.center = Point2{Length(std::llround(cx)), Length(std::llround(cy))};
  mv.radius = Length(std::llround(ar));
  mv.end_off = Length(std::llround(std::max(0.0, d / 2 - ar)));
}

void Reader::ellipse(Move& mv, const Block& b, const SourcePos& where) {
  const PlaneAxes pl = plane_axes(lattice_);
  const auto& axes = b.axes;
  const auto a = axes.find('A'), bb = axes.find('B'), q = axes.find('Q');
  if (a == axes.end() || bb == axes.end()) fail(where, "an ellipse block needs its semi-axes A and B");
  mv.a = length(*a->second);
  mv.b = length(*bb->second);
  if (mv.a <= 0) fail(a->second->pos, "the semi-axis A must be positive");
  if (mv.b <= 0) fail(bb->second->pos, "the semi-axis B must be positive");
  mv.q_millideg = q == axes.end() ? 0 : integer(*q->second);
  const bool cw = mv.kind == MoveKind::EllipseCw;
  // The deterministic fixed-point sines (fixed_trig.hpp), so that every machine computes
  // the same centre to the nanometre.
  const SinCos qt = sincos_udeg(mv.q_millideg * 1000);
  const double c = std::ldexp(double(qt.c), -kTrigFrac), s = std::ldexp(double(qt.s), -kTrigFrac);
  const double A = double(mv.a), B = double(mv.b);
  // To the ellipse's frame, with the minor axis stretched to A: the ellipse is a circle.
  const auto to_frame = [&](double x, double y) {
    return std::pair<double, double>{c * x + s * y, (-s * x + c * y) * A / B};
  };
  const auto from_frame = [&](double x, double y) {
    const double yy = y * B / A;
    return std::pair<double, double>{c * x - s * yy, s * x + c * yy};
  };
  const auto iu = axes.find(pl.iu), iv = axes.find(pl.iv);
  if (iu != axes.end() || iv != axes.end()) {
    mv.center = mv.from;
    if (iu != axes.end()) mv.center.u += length(*iu->second);
    if (iv != axes.end()) mv.center.v += length(*iv->second);
  } else {
    if (mv.from == mv.to) fail(where, "a full ellipse needs its centre (I, K)");
    const auto [px, py] = to_frame(double(mv.from.u), double(mv.from.v));
    const auto [qx, qy] = to_frame(double(mv.to.u), double(mv.to.v));
    const double d = std::hypot(qx - px, qy - py);
    if (d > 2 * A + double(kEndTolerance)) fail(where, "the end is out of reach of an ellipse with these A, B and Q");
    // The circle's centre for the shorter arc; the frame keeps the turning sense.
    const auto [fx, fy] = centre_through(px, py, qx, qy, A, cw, true);
    const auto [cx, cy] = from_frame(fx, fy);
    if (!(std::fabs(cx) <= double(4 * kMaxLength) && std::fabs(cy) <= double(4 * kMaxLength))) {
      fail(where, "the ellipse's centre leaves the range the reader holds");
    }
    mv.center = Point2{Length(std::llround(cx)), Length(std::llround(cy))};
  }
  // Both ends on the ellipse, within the tolerance along the radius.
  const std::array<Point2, 2> ends{mv.from, mv.to};
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const double x = double(ends[i].u - mv.center.u), y = double(ends[i].v - mv.center.v);
    const double xe = c * x + s * y, ye = -s * x + c * y;
    const double rho = std::hypot(xe / A, ye / B);
    // (At the centre itself the distance to the curve is the smaller semi-axis.)
    const double off = rho < 1e-12 ? std::min(A, B) : std::fabs(rho - 1) * std::hypot(x, y) / rho;
    if (off > double(kEndTolerance)) {
      fail(where, fmt::format("the {} is {:.4f} mm off the ellipse (tolerance {:.3f} mm)", i == 0 ? "start" : "end",
                              off / double(kNmPerMm), length_mm(kEndTolerance)));
    }
  }
  mv.full = mv.from == mv.to;
}

}  // namespace dda::program::detail
