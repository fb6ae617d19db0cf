// SPDX-License-Identifier: Apache-2.0
// The planner for part programs (docs/programs.md, "From blocks to commands").
#include "host/program_plan/program_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "host/accuracy/accuracy.hpp"
#include "host/geometry/fixed_trig.hpp"
#include "host/geometry/geometry.hpp"
#include "host/planner/planner.hpp"
#include "model/datapath/hw_command.hpp"
#include "model/datapath/rounding.hpp"

namespace dda::program {

std::string block_name(const Move& mv) {
  return mv.block_number ? fmt::format("block N{} ({})", *mv.block_number, kind_name(mv.kind))
                         : fmt::format("block at line {} ({})", mv.pos.line, kind_name(mv.kind));
}

void block_error(const std::string& file, const Move& mv, const std::string& why) {
  throw ProgramError(file, mv.pos.line, mv.pos.column, block_name(mv) + ": " + why);
}

namespace {

std::int64_t floor_div(std::int64_t v, std::int64_t d) { return v >= 0 ? v / d : -((-v + d - 1) / d); }

[[noreturn]] void fail(const std::string& file, const Move& mv, const std::string& why) { block_error(file, mv, why); }

bool is_arc(MoveKind k) { return k == MoveKind::ArcCw || k == MoveKind::ArcCcw; }

// The arc or ellipse block as the planner's sub-step ArcSpec, from `from` to `to`.
ArcSpec arc_spec(const Move& mv, Length step, Preload preload, Point from, Point to) {
  ArcSpec s;
  s.sub = kSubBits;
  const std::int64_t one = std::int64_t{1} << kSubBits;
  const std::int64_t cu = to_sub_steps(mv.center.u, step), cv = to_sub_steps(mv.center.v, step);
  s.center = Point{floor_div(cu, one), floor_div(cv, one)};
  s.center_frac = Point{cu - s.center.x * one, cv - s.center.y * one};
  if (is_arc(mv.kind)) {
    s.a = s.b = to_sub_steps(mv.radius, step);
  } else {
    s.a = to_sub_steps(mv.a, step);
    s.b = to_sub_steps(mv.b, step);
    s.angle = normalize_udeg(mv.q_millideg * 1000);
  }
  s.dir = mv.kind == MoveKind::ArcCw || mv.kind == MoveKind::EllipseCw ? Direction::Cw : Direction::Ccw;
  s.preload = preload;
  s.from = from;
  s.to = to;
  // The ends may lie off the curve by the reader's tolerance (or as far as the reader
  // found this block's end, within its dialect's tolerance) plus the rounding to the
  // lattice (at most half a step on each axis) and one step of margin.
  s.tolerance = 1.0 + double(std::max(kEndTolerance, mv.end_off)) / double(step);
  // The width: 4 bits above the smallest valid (where the targets were measured; the
  // fixed-point capacity is 2^kRotCapBits whatever the size, so the exact datapath's
  // capacity limit of default_bits() does not apply), fewer if the coefficients'
  // rounding could move a thin ellipse's curve by more than kMaxCoefficientDrift
  // (planner.hpp); a program cannot choose it.
  const double mx = std::max(a_steps(s), b_steps(s)), mn = std::min(a_steps(s), b_steps(s));
  const int nmin = smallest_valid_bits(steps_ceil(s, s.a), steps_ceil(s, s.b));
  s.bits = std::min(nmin + 4, kRotCapBits);
  const auto drift = [&](int n) { return std::ldexp(mx * mx / mn, n - kRotCapBits); };
  while (s.bits > nmin && drift(s.bits) > kMaxCoefficientDrift) --s.bits;
  if (drift(s.bits) > kMaxCoefficientDrift) {
    throw InputError(fmt::format(
        "the ellipse is too thin for the datapath at --step {} mm: semi-axes {:.6g} mm and {:.6g} mm ({:.6g} "
        "and {:.6g} steps); the rounding of its fixed-point coefficients could move the curve by {:.3g} "
        "steps (at most {}); a coarser --step lowers it",
        double(step) / double(kNmPerMm), mx * double(step) / double(kNmPerMm), mn * double(step) / double(kNmPerMm), mx,
        mn, drift(s.bits), kMaxCoefficientDrift));
  }
  return s;
}

// The block as a full turn from its start (the extra turns of an arc with P).
Move full_turn(const Move& mv) {
  Move m = mv;
  m.to = m.from;
  m.full = true;
  return m;
}

// A block holds at most this many pieces (an arc of many turns beyond the datapath's
// radius runs as chords, tens of thousands a turn): its plan's memory stays bounded.
constexpr std::size_t kMaxBlockPieces = std::size_t{1} << 20;

// Puts `turns` copies of `turn`'s pieces before `plan`'s (an arc's extra turns run first,
// from its start; each the same full turn).
void prepend_turns(Plan& plan, const Plan& turn, int turns, const std::string& file, const Move& mv, Length step) {
  const std::size_t total = turn.pieces.size() * std::size_t(turns) + plan.pieces.size();
  if (total > kMaxBlockPieces) {
    fail(file, mv,
         fmt::format("{} turns of this arc take {} pieces at --step {} mm, more than the {} a block may hold: "
                     "fewer turns (P), or a coarser --step",
                     turns + 1, total, double(step) / double(kNmPerMm), kMaxBlockPieces));
  }
  std::vector<Piece> pieces;
  pieces.reserve(total);
  for (int k = 0; k < turns; ++k) pieces.insert(pieces.end(), turn.pieces.begin(), turn.pieces.end());
  pieces.insert(pieces.end(), plan.pieces.begin(), plan.pieces.end());
  plan.pieces = std::move(pieces);
  plan.iteration_bound += turn.iteration_bound * std::uint64_t(turns);
}

// Whether a block turns half a turn or more about its centre from its start to its end,
// in its direction: exactly, from the sign of the cross product of the two radii (an
// ellipse's parametric sweep passes half a turn where its polar one does).
bool half_turn_or_more(const Move& mv) {
  const __int128 ax = mv.from.u - mv.center.u, ay = mv.from.v - mv.center.v;
  const __int128 bx = mv.to.u - mv.center.u, by = mv.to.v - mv.center.v;
  const __int128 cross = ax * by - ay * bx, dot = ax * bx + ay * by;
  const bool cw = mv.kind == MoveKind::ArcCw || mv.kind == MoveKind::EllipseCw;
  const __int128 turn = cw ? -cross : cross;  // > 0: less than half a turn ahead
  return turn < 0 || (turn == 0 && dot < 0);
}

}  // namespace

std::optional<Length> parse_mm(const std::string& text) {
  std::string t = text;
  const bool neg = !t.empty() && t[0] == '-';
  if (!t.empty() && (t[0] == '-' || t[0] == '+')) t = t.substr(1);
  const auto dot = t.find('.');
  const std::string whole = t.substr(0, dot), frac = dot == std::string::npos ? "" : t.substr(dot + 1);
  const auto digits = [](const std::string& d) { return d.find_first_not_of("0123456789") == std::string::npos; };
  if ((whole.empty() && frac.empty()) || !digits(whole) || !digits(frac) || whole.size() > 7 || frac.size() > 6) {
    return std::nullopt;
  }
  Length f = frac.empty() ? 0 : std::stoll(frac);
  for (std::size_t d = frac.size(); d < 6; ++d) f *= 10;
  const Length v = (whole.empty() ? 0 : std::stoll(whole)) * kNmPerMm + f;
  return neg ? -v : v;
}

Length parse_step(const std::string& mm) {
  const std::optional<Length> nm = parse_mm(mm);
  if (!nm || *nm < 1 || *nm > kNmPerMm) {
    throw InputError("step = " + mm + " is invalid: the lattice unit is in millimetres, from 0.000001 (1 nm) to 1");
  }
  return *nm;
}

Point2 start_point(Machine m, Length first, Length second) {
  return m == Machine::Lathe ? Point2{second, first / 2} : Point2{first, second};
}

std::int64_t to_steps(Length v, Length step) { return std::int64_t(round_div(v, step)); }
std::int64_t to_sub_steps(Length v, Length step) { return std::int64_t(round_div(i128(v) << kSubBits, step)); }

Point on_lattice(Point2 p, Length step) { return Point{to_steps(p.u, step), to_steps(p.v, step)}; }

double rounding(Point q, Point2 p, Length step) {
  return std::hypot(double(q.x) - double(p.u) / double(step), double(q.y) - double(p.v) / double(step));
}

BlockPlanner::BlockPlanner(const LatticeOptions& opt, Point2 start, std::string file, std::size_t window,
                           std::function<void(BlockPlan&&)> on_block)
    : opt_(opt), file_(std::move(file)), window_(std::max<std::size_t>(window, 1)), on_block_(std::move(on_block)) {
  start_ = at_ = on_lattice(start, opt.step);
  start_rounding_ = rounding(start_, start, opt.step);
}

void BlockPlanner::move(const Move& mv) {
  last_ = mv.pos;
  held_.push_back(mv);
  if (held_.size() > window_) plan_front();
}

// The turn from a plane's axes onto the run plane's (to_run_axes): G17's axes are
// (X, Y, Z), G18's (Z, X, Y), G19's (Y, Z, X), each a cyclic turn of X, Y, Z.
static int turn_of(int plane, int run_plane) {
  const auto first = [](int p) { return p == 180 ? 2 : p == 190 ? 1 : 0; };  // the index of its u in X, Y, Z
  return (first(plane) - first(run_plane) + 3) % 3;
}

void BlockPlanner::plan_front() {
  const Move& mv = held_.front();
  const Length step = opt_.step;
  if (run_plane_ == 0) run_plane_ = mv.plane;  // (the reader gives the first move in the run's plane)
  // The block is planned in its own plane's axes (u, v and the normal w), then turned
  // onto the run's: an arc in another plane runs on the core's ellipse integrators,
  // which drive that plane's axes.
  const int rot = turn_of(mv.plane, run_plane_);
  const Point from = to_plane_axes(at_, rot);
  Point to = on_lattice(mv.to, step);
  to.z = to_steps(mv.w_to, step);  // the axis normal to the plane
  BlockPlan b;
  b.move = mv;
  b.from = at_;
  b.to = to_run_axes(to, rot);
  b.rot = rot;
  b.rounding = rounding(to, mv.to, step);
  b.plan.geometry = LineGeometry{opt_.preload};  // no piece unless the move is a step or longer
  b.plan.from = b.plan.to = from;
  try {
    if (mv.kind == MoveKind::Rapid || mv.kind == MoveKind::Line) {
      if (from != to) b.plan = plan_line(from, to, opt_.preload);
    } else if (const Point from2{from.x, from.y}, to2{to.x, to.y};  // in the plane
               from2 != to2 || mv.full || half_turn_or_more(mv) || mv.turns > 1) {
      // (A block whose rounded ends coincide in the plane and that sweeps less than half
      // a turn is shorter than a step there: at most a move of the normal axis, below.
      // One that sweeps more runs as a full turn.)
      b.plan = plan_curve(mv, from2, to2);
      // An arc of several turns (P): its full turns first, from its start.
      if (mv.turns > 1) prepend_turns(b.plan, plan_curve(full_turn(mv), from2, from2), mv.turns - 1, file_, mv, step);
      lift(b.plan, from.z, to.z, opt_.preload);  // a helix, or the arc at its height
    } else if (from != to) {
      b.plan = plan_line(from, to, opt_.preload);
    }
  } catch (const ProgramError&) {
    throw;
  } catch (const InputError& e) {
    fail(file_, mv, e.what());
  }
  turn_axes(b.plan, rot);
  b.first_piece = pieces_;
  pieces_ += b.plan.pieces.size();
  ++blocks_;
  at_ = b.to;
  held_.pop_front();
  on_block_(std::move(b));
}

Plan BlockPlanner::plan_curve(const Move& mv, Point from, Point to) const {
  if (beyond_datapath(mv, opt_.step)) return plan_chords(mv, opt_.step, opt_.preload, from, to);
  return plan_arc(arc_spec(mv, opt_.step, opt_.preload, from, to));
}

void BlockPlanner::finish() {
  while (!held_.empty()) plan_front();
  if (pieces_ == 0) {
    throw ProgramError(file_, last_.line, last_.column,
                       blocks_ == 0 ? "the program has no motion block: nothing to run"
                                    : "the program's moves are all shorter than a step: nothing to run");
  }
}

ProgramPlan plan_program(const Program& prog, const LatticeOptions& opt, const std::string& file) {
  ProgramPlan pp;
  pp.lattice = opt;
  BlockPlanner planner(opt, prog.start, file, kDefaultWindow, [&](BlockPlan&& b) {
    for (const Piece& pc : b.plan.pieces) pp.plan.pieces.push_back(pc);
    pp.plan.iteration_bound += b.plan.iteration_bound;
    pp.blocks.push_back(std::move(b));
  });
  pp.start = planner.start();
  pp.start_rounding = planner.start_rounding();
  for (const Move& mv : prog.moves) planner.move(mv);
  planner.finish();
  pp.plan.geometry = ProgramGeometry{opt.preload};
  pp.plan.from = pp.start;
  pp.plan.to = planner.end();
  return pp;
}

void check_hardware(const BlockPlan& b, const std::string& file) {
  for (const Piece& pc : b.plan.pieces) {
    try {
      hw::pack_command(pc.cmd);
    } catch (const InputError& e) {
      fail(file, b.move, std::string("beyond the hardware's widths: ") + e.what());
    }
  }
}

void check_hardware(const ProgramPlan& pp, const std::string& file) {
  for (const BlockPlan& b : pp.blocks) check_hardware(b, file);
}

BlockDistance::BlockDistance(const BlockPlan& b, Length step) {
  const Move& mv = b.move;
  const double s = double(step);
  if (mv.kind == MoveKind::Rapid || mv.kind == MoveKind::Line) {
    kind_ = Kind::Segment;
    x0_ = double(mv.from.u) / s, y0_ = double(mv.from.v) / s;
    ux_ = double(mv.to.u) / s - x0_, uy_ = double(mv.to.v) / s - y0_;
    len2_ = ux_ * ux_ + uy_ * uy_;
    return;
  }
  cx_ = double(mv.center.u) / s, cy_ = double(mv.center.v) / s;
  if (is_arc(mv.kind)) {
    kind_ = Kind::Circle;
    r_ = double(mv.radius) / s;
    return;
  }
  kind_ = Kind::Ellipse;
  a_ = double(mv.a) / s, b_ = double(mv.b) / s;
  angle_udeg_ = normalize_udeg(mv.q_millideg * 1000);
}

double BlockDistance::operator()(double x, double y) const {
  if (kind_ == Kind::Segment) {
    const double t = len2_ > 0 ? std::clamp(((x - x0_) * ux_ + (y - y0_) * uy_) / len2_, 0.0, 1.0) : 0.0;
    const double dx = x - (x0_ + t * ux_), dy = y - (y0_ + t * uy_);
    return std::sqrt(dx * dx + dy * dy);  // (coordinates within 2^40: no overflow to guard)
  }
  const double rx = x - cx_, ry = y - cy_;
  if (kind_ == Kind::Circle) return std::fabs(std::sqrt(rx * rx + ry * ry) - r_);
  const auto [u, v] = to_frame(angle_udeg_, rx, ry);
  return ellipse_distance(a_, b_, u, v);
}

void BlockDistance::operator()(const Point* pts, std::size_t n, double* out) const {
  if (kind_ == Kind::Segment && len2_ > 0) {
    for (std::size_t k = 0; k < n; ++k) {
      const double x = double(pts[k].x), y = double(pts[k].y);
      double t = ((x - x0_) * ux_ + (y - y0_) * uy_) / len2_;
      t = t < 0.0 ? 0.0 : t;  // std::clamp(t, 0, 1), as operator() takes it
      t = 1.0 < t ? 1.0 : t;
      const double dx = x - (x0_ + t * ux_), dy = y - (y0_ + t * uy_);
      out[k] = std::sqrt(dx * dx + dy * dy);
    }
  } else if (kind_ == Kind::Circle) {
    for (std::size_t k = 0; k < n; ++k) {
      const double rx = double(pts[k].x) - cx_, ry = double(pts[k].y) - cy_;
      out[k] = std::fabs(std::sqrt(rx * rx + ry * ry) - r_);
    }
  } else {
    for (std::size_t k = 0; k < n; ++k) out[k] = (*this)(double(pts[k].x), double(pts[k].y));
  }
}

double block_distance(const BlockPlan& b, Length step, double x, double y) { return BlockDistance(b, step)(x, y); }

double block_target(const BlockPlan& b, double from_rounding, Preload preload) {
  if (preload != Preload::Half) return std::numeric_limits<double>::infinity();
  const Move& m = b.move;
  double t = kTargetOther;
  if (m.kind == MoveKind::Line || m.kind == MoveKind::Rapid) {
    t = kTargetLine;
  } else if (is_arc(m.kind) ||
             (m.q_millideg % 90000 == 0 && double(std::max(m.a, m.b)) <= kTargetAspect * double(std::min(m.a, m.b)))) {
    t = kTargetAligned;
  }
  return t + std::max(from_rounding, b.rounding);
}

std::size_t block_of_piece(const ProgramPlan& pp, std::size_t piece) {
  const auto it = std::upper_bound(pp.blocks.begin(), pp.blocks.end(), piece,
                                   [](std::size_t k, const BlockPlan& b) { return k < b.first_piece; });
  return std::size_t(it - pp.blocks.begin()) - 1;
}

}  // namespace dda::program
