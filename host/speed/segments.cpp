// SPDX-License-Identifier: Apache-2.0
#include "host/speed/segments.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "model/datapath/datapath.hpp"

namespace dda::speed {

std::array<std::size_t, 3> machine_axes(int plane) {
  if (plane == 180) return {2, 0, 1};
  if (plane == 190) return {1, 2, 0};
  return {0, 1, 2};
}

namespace {

using program::Move;
using program::MoveKind;

constexpr double kPi = 3.14159265358979323846;
constexpr int kSamples = 16;  // intervals along a curved piece (Simpson's rule: even)

Vec3 unit(Vec3 v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (n == 0) return v;
  return {v[0] / n, v[1] / n, v[2] / n};
}

// A vector of the block's plane axes (u, v, w) in machine axes.
Vec3 to_machine(const Vec3& uvw, int plane) {
  const auto ax = machine_axes(plane);
  Vec3 m{};
  for (std::size_t i = 0; i < 3; ++i) m[ax[i]] = uvw[i];
  return m;
}

bool curved(MoveKind k) { return k != MoveKind::Rapid && k != MoveKind::Line; }

// The curve of a curved block in its plane, mm: the ellipse (a circle: a = b = r) of
// centre (cu, cv), semi-axes a, b, a turned by q from +u.
struct Curve {
  double cu, cv, a, b, q;
  double param(double u, double v) const {
    const double du = u - cu, dv = v - cv, c = std::cos(q), s = std::sin(q);
    return std::atan2((-s * du + c * dv) / b, (c * du + s * dv) / a);
  }
  // The derivative of the point at parameter t.
  std::pair<double, double> d(double t) const {
    const double x = -a * std::sin(t), y = b * std::cos(t), c = std::cos(q), s = std::sin(q);
    return {c * x - s * y, s * x + c * y};
  }
  double radius(double t) const {
    const double s = std::sin(t), c = std::cos(t);
    return std::pow(a * a * s * s + b * b * c * c, 1.5) / (a * b);
  }
};

Curve curve_of(const Move& mv) {
  const double k = 1.0 / double(program::kNmPerMm);
  if (mv.kind == MoveKind::EllipseCw || mv.kind == MoveKind::EllipseCcw) {
    return Curve{double(mv.center.u) * k, double(mv.center.v) * k, double(mv.a) * k, double(mv.b) * k,
                 double(mv.q_millideg) * 1e-3 * kPi / 180};
  }
  const double r = double(mv.radius) * k;
  return Curve{double(mv.center.u) * k, double(mv.center.v) * k, r, r, 0};
}

Segment line_segment(const Vec3& d, int plane) {
  Segment s;
  s.length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  s.t0 = s.t1 = to_machine(unit(d), plane);
  for (std::size_t i = 0; i < 3; ++i) s.share[i] = std::abs(s.t0[i]);
  return s;
}

// A curved piece between its ends' parameters (the shorter way: a piece is monotone,
// less than half a turn), the normal axis moving dw along it.
// The parameter at a piece's start and its signed sweep to its end (the shorter way).
std::pair<double, double> piece_sweep(const Curve& c, double u0, double v0, double u1, double v1) {
  const double t0 = c.param(u0, v0);
  double sweep = c.param(u1, v1) - t0;
  while (sweep > kPi) sweep -= 2 * kPi;
  while (sweep <= -kPi) sweep += 2 * kPi;
  return {t0, sweep};
}

Segment curve_segment(const Curve& c, double u0, double v0, double u1, double v1, double dw, int plane) {
  const auto [t0, sweep] = piece_sweep(c, u0, v0, u1, v1);
  Segment s;
  s.min_radius = kInfinity;
  double speeds[kSamples + 1];
  for (int k = 0; k <= kSamples; ++k) {
    const double t = t0 + sweep * k / kSamples;
    const auto [du, dv] = c.d(t);
    const Vec3 d{du * sweep, dv * sweep, dw};
    speeds[k] = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const Vec3 tm = to_machine(unit(d), plane);
    for (std::size_t i = 0; i < 3; ++i) s.share[i] = std::max(s.share[i], std::abs(tm[i]));
    if (k == 0) s.t0 = tm;
    if (k == kSamples) s.t1 = tm;
    s.min_radius = std::min(s.min_radius, c.radius(t));
  }
  // The smallest radius of an ellipse is at the ends of its major axis: there when the
  // piece passes one.
  const double vertex = c.a >= c.b ? 0 : kPi / 2;
  for (int n = -4; n <= 4; ++n) {
    const double t = vertex + n * kPi;
    if ((t - t0) / sweep > 0 && (t - t0) / sweep < 1) s.min_radius = std::min(s.min_radius, c.radius(t));
  }
  double sum = speeds[0] + speeds[kSamples];
  for (int k = 1; k < kSamples; ++k) sum += (k % 2 ? 4 : 2) * speeds[k];
  s.length = sum / (3.0 * kSamples);
  return s;
}

// A curved piece's speed limit varies with its curvature: the fractions of its sweep
// where it is cut so that, within each part, the limit min(cap, sqrt(A_n rho)) varies
// by at most kCutRatio (none when the curvature never holds it below cap).
constexpr double kCutRatio = 1.04;
constexpr int kCutSamples = 512;

std::vector<double> cut_fractions(const Curve& c, double t0, double sweep, double cap, double an) {
  std::vector<double> cuts;
  double lo = kInfinity, hi = 0;
  for (int k = 0; k <= kCutSamples; ++k) {
    const double v = std::min(cap, std::sqrt(an * c.radius(t0 + sweep * k / kCutSamples)));
    const double lo2 = std::min(lo, v), hi2 = std::max(hi, v);
    if (k > 0 && hi2 > lo2 * kCutRatio) {
      cuts.push_back(double(k) / kCutSamples);
      lo = hi = v;
    } else {
      lo = lo2, hi = hi2;
    }
  }
  return cuts;
}

// Runs the piece's command through the datapath and cuts it after the first step at or
// past each fraction of its sweep: the parts' commands are the registers there, so the
// parts step exactly as the whole did (a part's counters are the steps it makes).
std::vector<Piece> cut_piece(const Piece& pc, int rot, const Curve& c, double t0, double sweep,
                             const std::vector<double>& cuts, double mm) {
  std::vector<Piece> parts;
  RegState r = initial_regs(pc.cmd);
  Point at = to_plane_axes(pc.from, rot);
  Piece cur = pc;
  std::int64_t sx = 0, sy = 0, sz = 0;
  std::uint64_t it = 0, start_it = 0;
  std::size_t next = 0;
  while (r.cnt_x != 0 || r.cnt_y != 0 || r.cnt_z != 0) {
    if (++it > pc.iteration_bound) throw GuardError("a piece cut for its curvature ran past its iteration bound");
    const StepOut o = next_state(pc.cmd, r);
    if (!o.step_x && !o.step_y && !o.step_z) continue;
    at.x += o.step_x ? (pc.cmd.dir_x_neg ? -1 : 1) : 0;
    at.y += o.step_y ? (pc.cmd.dir_y_neg ? -1 : 1) : 0;
    at.z += o.step_z ? (pc.cmd.dir_z_neg ? -1 : 1) : 0;
    sx += o.step_x, sy += o.step_y, sz += o.step_z;
    if (next == cuts.size() || (r.cnt_x == 0 && r.cnt_y == 0 && r.cnt_z == 0)) continue;
    double d = c.param(double(at.x) * mm, double(at.y) * mm) - t0;
    while (d > kPi) d -= 2 * kPi;
    while (d <= -kPi) d += 2 * kPi;
    if (d / sweep < cuts[next]) continue;
    while (next < cuts.size() && d / sweep >= cuts[next]) ++next;
    Piece part = cur;
    part.cmd.cnt_x = sx, part.cmd.cnt_y = sy, part.cmd.cnt_z = sz;
    part.to = to_run_axes(at, rot);
    part.iteration_bound = it - start_it;
    parts.push_back(part);
    cur.cmd.jv_x = r.jv_x, cur.cmd.jv_y = r.jv_y, cur.cmd.jr_x = r.jr_x, cur.cmd.jr_y = r.jr_y;
    cur.cmd.cnt_x = r.cnt_x, cur.cmd.cnt_y = r.cnt_y, cur.cmd.jr_z = r.jr_z, cur.cmd.cnt_z = r.cnt_z;
    cur.from = part.to;
    cur.iteration_bound = pc.iteration_bound - it;
    start_it = it;
    sx = sy = sz = 0;
    if (next == cuts.size()) break;  // (the rest is the last part, as it stands)
  }
  parts.push_back(cur);
  return parts;
}

}  // namespace

namespace {

const char* mode_name(program::FeedMode m) {
  return m == program::FeedMode::PerMinute       ? "per minute (G94)"
         : m == program::FeedMode::PerRevolution ? "per revolution (G95, G99)"
                                                 : "in inverse time (G93)";
}

double asked_feed(const Move& mv, double length_mm, const MachineLimits& lim, const std::string& file) {
  if (mv.feed <= 0) {
    if (lim.default_feed > 0) return lim.default_feed / 60;
    program::block_error(file, mv,
                         "no feed rate: the program gives no F (give one, or a default feed: --default-feed "
                         "MM_PER_MIN or default_feed_mm_per_min in the machine config)");
  }
  if (mv.feed_stale) {
    program::block_error(file, mv,
                         std::string("the feed mode changed to ") + mode_name(mv.feed_mode) +
                             " since F was given: give F again in the new mode");
  }
  const double unit = mv.inch ? 25.4 : 1.0;
  switch (mv.feed_mode) {
    case program::FeedMode::PerMinute:
      return mv.feed * unit / 60;
    case program::FeedMode::InverseTime:
      return length_mm * mv.feed / 60;
    case program::FeedMode::PerRevolution:
      if (mv.css) {
        program::block_error(file, mv,
                             "a feed per revolution (G95, G99) under constant surface speed (G96): the feed would "
                             "change with the radius along the move, which the planner does not follow; program "
                             "G97 S (a constant spindle speed)");
      }
      if (mv.spindle <= 0) {
        program::block_error(file, mv, "a feed per revolution (G95, G99) with no spindle speed: give S (rpm, G97)");
      }
      return mv.feed * unit * mv.spindle / 60;
  }
  return 0;
}

}  // namespace

double block_feed(const Move& mv, double length_mm, const MachineLimits& lim, const std::string& file) {
  if (mv.kind == MoveKind::Rapid) return lim.rapid / 60;
  const double f = asked_feed(mv, length_mm, lim, file);
  // The block paces no piece below its minimum speed (VMIN): such a feed would run faster.
  if (f * 60 < lim.min_speed) {
    program::block_error(file, mv,
                         fmt::format("a feed of {:.6g} mm/min is below the machine's minimum speed {:.6g} mm/min "
                                     "(min_speed_mm_per_min), at which its drives start and stop",
                                     f * 60, lim.min_speed));
  }
  return f;
}

PlannerLimits planner_limits(const MachineLimits& lim, program::Machine m) {
  PlannerLimits p;
  p.accel = path_accel(lim, m);
  p.normal_accel = normal_accel(lim, m);
  for (std::size_t i = 0; i < 3; ++i) {
    const bool has = m == program::Machine::Mill || i != 1;
    p.vmax[i] = has ? lim.axes[i].vmax / 60 : 0;
    p.axis_accel[i] = has ? lim.axes[i].accel : 0;
  }
  p.window = lim.window;
  return p;
}

Segment piece_segment(const program::BlockPlan& b, const Piece& pc, program::Length step) {
  const double mm = double(step) / double(program::kNmPerMm);
  const Point f = to_plane_axes(pc.from, b.rot), t = to_plane_axes(pc.to, b.rot);
  const Vec3 d{double(t.x - f.x) * mm, double(t.y - f.y) * mm, double(t.z - f.z) * mm};
  if (!curved(b.move.kind) || pc.kind == PieceKind::Line) return line_segment(d, b.move.plane);
  return curve_segment(curve_of(b.move), double(f.x) * mm, double(f.y) * mm, double(t.x) * mm, double(t.y) * mm, d[2],
                       b.move.plane);
}

SegmentBuilder::SegmentBuilder(const MachineLimits& lim, const PlannerLimits& plim, program::Length step,
                               std::string file)
    : lim_(lim), plim_(plim), step_(step), file_(std::move(file)) {}

// A curved piece whose curvature holds it below the feed and the axes' limits, cut where
// that limit changes (cut_fractions), with the segments of its parts.
void SegmentBuilder::cut(const program::BlockPlan& b, const Piece& pc, const Segment& seg, double feed,
                         std::vector<Piece>& pieces, std::vector<Segment>& segs) const {
  double cap = feed;
  for (std::size_t i = 0; i < 3; ++i) {
    if (seg.share[i] > 1e-12 && plim_.vmax[i] > 0) cap = std::min(cap, plim_.vmax[i] / seg.share[i]);
  }
  const bool arc = curved(b.move.kind) && pc.kind != PieceKind::Line;
  if (!arc || std::sqrt(plim_.normal_accel * seg.min_radius) * kCutRatio >= cap) {
    pieces.push_back(pc);
    segs.push_back(seg);
    return;
  }
  const double mm = double(step_) / double(program::kNmPerMm);
  const Curve c = curve_of(b.move);
  const Point f = to_plane_axes(pc.from, b.rot), t = to_plane_axes(pc.to, b.rot);
  const auto [t0, sweep] = piece_sweep(c, double(f.x) * mm, double(f.y) * mm, double(t.x) * mm, double(t.y) * mm);
  const std::vector<double> cuts = cut_fractions(c, t0, sweep, cap, plim_.normal_accel);
  if (cuts.empty()) {  // (a circle: the same limit all along)
    pieces.push_back(pc);
    segs.push_back(seg);
    return;
  }
  for (const Piece& part : cut_piece(pc, b.rot, c, t0, sweep, cuts, mm)) {
    pieces.push_back(part);
    segs.push_back(piece_segment(b, part, step_));
  }
}

std::vector<Segment> SegmentBuilder::block(program::BlockPlan& b, std::size_t index) {
  const Move& mv = b.move;
  b.first_piece = pieces_;
  rest_ = rest_ || mv.stop || mv.dwell > 0;
  std::vector<Segment> whole;
  whole.reserve(b.plan.pieces.size());
  double length = 0;
  for (const Piece& pc : b.plan.pieces) {
    whole.push_back(piece_segment(b, pc, step_));
    length += whole.back().length;
  }
  if (whole.empty()) return whole;
  const double feed = block_feed(mv, length, lim_, file_);
  std::vector<Piece> pieces;
  std::vector<Segment> out;
  for (std::size_t k = 0; k < whole.size(); ++k) cut(b, b.plan.pieces[k], whole[k], feed, pieces, out);
  b.plan.pieces = std::move(pieces);
  pieces_ += b.plan.pieces.size();
  const double tol = double(mv.path_tolerance) / double(program::kNmPerMm);
  for (Segment& s : out) {
    s.feed = feed;
    s.rapid = mv.kind == MoveKind::Rapid;
    s.deviation = tol > 0 ? std::min(lim_.junction_deviation, tol) : lim_.junction_deviation;
    s.block = index;
  }
  out.front().rest_before = rest_;
  rest_ = mv.exact_stop;
  return out;
}

}  // namespace dda::speed
