// SPDX-License-Identifier: Apache-2.0
#include "host/report/program_report.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "host/geometry/fixed_trig.hpp"
#include "host/geometry/geometry.hpp"
#include "host/report/json_stream.hpp"

namespace dda::program {

namespace {

std::string block_no(const BlockPlan& b) {
  return b.move.block_number ? fmt::format("N{}", *b.move.block_number) : std::string("-");
}

double mean(const BlockStats& s) { return s.points ? s.sum_dev / double(s.points) : 0.0; }

// p read a word at a time. The engine has just written the record a word at a time, and
// a copy of the words at once (as the compiler would make it) cannot take them from
// the pending stores: it waits for them to reach the cache, on every record.
Point word_by_word(const Point& p) {
  std::int64_t x = p.x, y = p.y, z = p.z;
  asm("" : "+r"(x), "+r"(y), "+r"(z));  // (keeps the loads apart; no instruction)
  return Point{x, y, z};
}

// A point of a block's path at distance d from its geometry.
void add_point(BlockStats& s, Point p, double d) {
  ++s.points;
  s.sum_dev += d;
  if (d > s.max_dev || s.points == 1) s.max_dev = d, s.max_at = p;
}

// Samples (steps) of a block's programmed geometry from its start to its end.
std::vector<std::pair<double, double>> block_geometry(const BlockPlan& b, Length step) {
  const Move& mv = b.move;
  const double s = double(step);
  std::vector<std::pair<double, double>> pts;
  if (mv.kind == MoveKind::Rapid || mv.kind == MoveKind::Line) {
    pts.emplace_back(double(mv.from.u) / s, double(mv.from.v) / s);
    pts.emplace_back(double(mv.to.u) / s, double(mv.to.v) / s);
    return pts;
  }
  const bool ellipse = mv.kind == MoveKind::EllipseCw || mv.kind == MoveKind::EllipseCcw;
  const bool cw = mv.kind == MoveKind::ArcCw || mv.kind == MoveKind::EllipseCw;
  const double A = double(ellipse ? mv.a : mv.radius), B = double(ellipse ? mv.b : mv.radius);
  const SinCos q = sincos_udeg(ellipse ? mv.q_millideg * 1000 : 0);
  const double c = std::ldexp(double(q.c), -kTrigFrac), sn = std::ldexp(double(q.s), -kTrigFrac);
  const auto param = [&](Point2 p) {  // parametric angle of a point of the curve
    const double x = double(p.u - mv.center.u), y = double(p.v - mv.center.v);
    return std::atan2((-sn * x + c * y) / B, (c * x + sn * y) / A);
  };
  const double t0 = param(mv.from);
  double span = cw ? t0 - param(mv.to) : param(mv.to) - t0;
  while (span <= 0) span += 2 * M_PI;
  if (mv.full) span = 2 * M_PI;
  const int n = std::clamp(int(span / (2 * M_PI) * 2048), 16, 2048);
  const EllipseDrawing e{double(mv.center.u), double(mv.center.v), A, B, ellipse ? mv.q_millideg * 1000 : 0, s};
  return ellipse_points(e, t0, (cw ? -1 : 1) * span, n);
}

}  // namespace

std::string mm(Length v) {
  const Length a = v < 0 ? -v : v;
  std::string s = fmt::format("{}{}.{:06d}", v < 0 ? "-" : "", a / kNmPerMm, a % kNmPerMm);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

void BlockWindow::push(const BlockPlan& b) {
  held_.push_back(Entry{b, BlockDistance(b, step_), BlockStats{}, b.first_piece + b.plan.pieces.size()});
  held_.back().stats.end = b.from;
}

BlockWindow::Entry& BlockWindow::front() {
  if (held_.empty()) throw GuardError("a record after the program's last block");
  return held_.front();
}

BlockStatsSink::BlockStatsSink(std::ostream& os, const LatticeOptions& lattice, Point2 start, BlockStatsFormat fmt,
                               bool third_axis)
    : os_(os),
      lattice_(lattice),
      start_(on_lattice(start, lattice.step)),
      fmt_(fmt),
      z_(third_axis),
      window_(lattice.step),
      targeted_(lattice.preload == Preload::Half),
      prev_rounding_(rounding(start_, start, lattice.step)) {}

// The header, with the first block: a program the reader refuses prints nothing.
void BlockStatsSink::header() {
  if (started_) return;
  started_ = true;
  if (fmt_ == BlockStatsFormat::Json) {
    nlohmann::ordered_json j;
    j["step_mm"] = mm(lattice_.step);
    j["preload"] = to_string(lattice_.preload);
    j["start"] = {start_.x, start_.y};
    os_ << json_stream::open_object(j) << ",\n \"blocks\": [";
  } else if (fmt_ == BlockStatsFormat::Csv) {
    os_ << "line,block,kind,end_u_mm,end_v_mm,end_x,end_y,rounding,commands,steps,iterations,max_dev,mean_dev,on_end,"
           "target,within_target"
        << (z_ ? ",end_w_mm,end_z\n" : "\n");
  } else {
    fmt::print(os_, "step {} mm, preload {}, start ({},{}); deviation: steps from the programmed geometry\n",
               mm(lattice_.step), to_string(lattice_.preload), start_.x, start_.y);
    fmt::print(os_,
               "| {:>5} | {:>6} | {:<11} | {:>21} | {:>17} | {:>8} | {:>4} | {:>7} | {:>9} | {:>7} | {:>6} | {:>3} | "
               "{:>3} |\n",
               "line", "block", "kind", "end (mm)", "end (steps)", "rounding", "cmds", "steps", "iters", "max dev",
               "target", "ok", "end");
    fmt::print(os_,
               "|-------|--------|-------------|-----------------------|-------------------|----------|------|-------"
               "--|-----------|---------|--------|-----|-----|\n");
  }
}

void BlockStatsSink::block(const BlockPlan& b) {
  header();
  window_.push(b);
}

// A record's lattice point as part of its block (`iterations`: the record's and those
// without a record before it); a step adds a point of the path, measured with the
// block's next batch.
void BlockStatsSink::record(const Iteration& it) {
  BlockWindow::Entry& e = window_.of_piece(it.piece, [&](BlockWindow::Entry& done) { row(done); });
  BlockStats& s = e.stats;
  s.iterations += it.iter - last_iter_;
  last_iter_ = it.iter;
  const Point pos = word_by_word(it.pos);
  s.end = pos;
  if (!it.step_x && !it.step_y && !it.step_z) return;
  ++s.steps;
  if (!it.step_x && !it.step_y) return;  // (the third axis alone: the plane's point stays)
  pending_[pending_n_++] = pos;
  if (pending_n_ == kMeasureBatch) measure(e);
}

void BlockStatsSink::measure(BlockWindow::Entry& e) {
  double d[kMeasureBatch];
  if (e.block.rot == 0) {
    e.distance(pending_.data(), pending_n_, d);
  } else {  // the distance in the block's own plane
    std::array<Point, kMeasureBatch> q;
    for (std::size_t i = 0; i < pending_n_; ++i) q[i] = to_plane_axes(pending_[i], e.block.rot);
    e.distance(q.data(), pending_n_, d);
  }
  for (std::size_t i = 0; i < pending_n_; ++i) add_point(e.stats, pending_[i], d[i]);
  pending_n_ = 0;
}

void BlockStatsSink::finish() {
  header();
  window_.drain([&](BlockWindow::Entry& e) { row(e); });
  const double mean_all = points_ ? dev_sum_ / double(points_) : 0.0;
  const std::string verdict = !targeted_   ? "not targeted (zero preload: reported only)"
                              : over_ == 0 ? "every block within its target"
                                           : fmt::format("{} block{} over the target", over_, over_ == 1 ? "" : "s");
  if (fmt_ == BlockStatsFormat::Json) {
    nlohmann::ordered_json t;
    t["blocks"] = blocks_;
    t["commands"] = commands_;
    t["steps"] = steps_;
    t["iterations"] = it_sum_;
    t["max_dev"] = worst_;
    t["mean_dev"] = mean_all;
    t["max_rounding"] = round_worst_;
    t["on_ends"] = all_ok_;
    if (targeted_) t["over_target"] = over_;
    os_ << (blocks_ == 0 ? "]" : "\n ]") << ",\n \"totals\": " << json_stream::nested(t, 1) << "\n}\n";
  } else if (fmt_ == BlockStatsFormat::Text) {
    fmt::print(os_, "blocks: {}\ncommands: {}\nsteps: {}\niterations: {}\n", blocks_, commands_, steps_, it_sum_);
    fmt::print(os_, "max_dev: {:.6f} (line {})\nmean_dev: {:.6f}\nmax_rounding: {:.6f}\nends: {}\n", worst_,
               worst_line_, mean_all, round_worst_,
               all_ok_ ? "every block on its rounded end" : "NOT every block on its rounded end");
    fmt::print(os_, "targets: {}\n", verdict);
  }
}

// A block's end for the text table: in mm or in steps, with the third coordinate in a
// report that has it.
std::string BlockStatsSink::end_text(const BlockPlan& b, bool in_mm) const {
  if (in_mm) {
    const Point e = run_end_nm(b);
    return z_ ? fmt::format("{},{},{}", mm(e.x), mm(e.y), mm(e.z)) : fmt::format("{},{}", mm(e.x), mm(e.y));
  }
  return z_ ? fmt::format("{},{},{}", b.to.x, b.to.y, b.to.z) : fmt::format("{},{}", b.to.x, b.to.y);
}

// The row of a block whose records have all passed (its pending points measured first).
void BlockStatsSink::row(BlockWindow::Entry& e) {
  measure(e);
  const BlockPlan& b = e.block;
  const BlockStats& st = e.stats;
  const Point end_nm = run_end_nm(b);
  // Each block's target (docs/programs.md, "Accuracy"); none with zero preload.
  const double target = block_target(b, prev_rounding_, lattice_.preload);
  prev_rounding_ = b.rounding;
  const bool on_end = st.end == b.to, within = st.max_dev <= target;
  if (blocks_ == 0 || st.max_dev > worst_) {
    if (st.max_dev > worst_ || blocks_ == 0) worst_line_ = b.move.pos.line;
    worst_ = std::max(worst_, st.max_dev);
  }
  ++blocks_;
  commands_ += b.plan.pieces.size();
  it_sum_ += st.iterations;
  steps_ += st.steps;
  points_ += st.points;
  dev_sum_ += st.sum_dev;
  round_worst_ = std::max(round_worst_, b.rounding);
  all_ok_ = all_ok_ && on_end;
  over_ += st.max_dev > target;
  const std::string ok = !targeted_ ? "-" : within ? "yes" : "NO";
  if (fmt_ == BlockStatsFormat::Json) {
    nlohmann::ordered_json r;
    r["line"] = b.move.pos.line;
    r["block"] = block_no(b);
    r["kind"] = std::string(kind_name(b.move.kind));
    r["end_mm"] = {mm(end_nm.x), mm(end_nm.y)};
    r["end"] = {b.to.x, b.to.y};
    if (z_) r["end_mm"].push_back(mm(end_nm.z)), r["end"].push_back(b.to.z);
    r["rounding"] = b.rounding;
    r["commands"] = b.plan.pieces.size();
    r["steps"] = st.steps;
    r["iterations"] = st.iterations;
    r["max_dev"] = st.max_dev;
    r["mean_dev"] = mean(st);
    r["on_end"] = on_end;
    if (targeted_) {
      r["target"] = target;
      r["within_target"] = within;
    }
    os_ << (blocks_ == 1 ? "\n" : ",\n") << json_stream::element(r, 2);
  } else if (fmt_ == BlockStatsFormat::Csv) {
    fmt::print(os_, "{},{},{},{},{},{},{},{:.6f},{},{},{},{:.6f},{:.6f},{},{},{}", b.move.pos.line, block_no(b),
               kind_name(b.move.kind), mm(end_nm.x), mm(end_nm.y), b.to.x, b.to.y, b.rounding, b.plan.pieces.size(),
               st.steps, st.iterations, st.max_dev, mean(st), on_end ? "yes" : "no",
               targeted_ ? fmt::format("{:.6f}", target) : "-", ok == "NO" ? "no" : ok);
    os_ << (z_ ? fmt::format(",{},{}\n", mm(end_nm.z), b.to.z) : std::string("\n"));
  } else {
    fmt::print(
        os_,
        "| {:>5} | {:>6} | {:<11} | {:>21} | {:>17} | {:>8.3f} | {:>4} | {:>7} | {:>9} | {:>7.3f} | {:>6} | {:>3} | "
        "{:>3} |\n",
        b.move.pos.line, block_no(b), kind_name(b.move.kind), end_text(b, true), end_text(b, false), b.rounding,
        b.plan.pieces.size(), st.steps, st.iterations, st.max_dev, targeted_ ? fmt::format("{:.3f}", target) : "-", ok,
        on_end ? "yes" : "NO");
  }
}

ProgramSvgSink::ProgramSvgSink(std::ostream& os, const LatticeOptions& lattice, Point2 start, std::string title,
                               View view)
    : os_(os),
      lattice_(lattice),
      title_(std::move(title)),
      view_(view),
      window_(lattice.step),
      start_(on_lattice(start, lattice.step)) {}

void ProgramSvgSink::block(const BlockPlan& b) {
  if (first_) {
    const Point s = to_plane_axes(start_, b.rot);
    sample_.add(project(start_, view_), block_distance(b, lattice_.step, double(s.x), double(s.y)));
  }
  first_ = false;
  window_.push(b);
  geometry(b);
}

void ProgramSvgSink::record(const Iteration& it) {
  if (!it.step_x && !it.step_y && (view_ == View::XY || !it.step_z)) return;
  const BlockWindow::Entry& e = window_.of_piece(it.piece, [](const BlockWindow::Entry&) {});
  const bool end = it.pos == e.block.to;
  const Point q = to_plane_axes(it.pos, e.block.rot);  // the distance in the block's plane
  sample_.add(project(it.pos, view_), e.distance(double(q.x), double(q.y)), end);
}

// The block's programmed geometry, joined to the polyline before it where it goes on
// from that one's end. Beyond the budget every ideal_stride_-th vertex stays, and the
// last vertex so far (provisional: replaced by the next one that joins).
void ProgramSvgSink::geometry(const BlockPlan& b) {
  auto pts = block_geometry(b, lattice_.step);
  if (view_ != View::XY || b.rot != 0) {  // the normal axis along the block, from its start to its end
    const double w0 = double(b.move.w) / double(lattice_.step), w1 = double(b.move.w_to) / double(lattice_.step);
    const int first = view_ == View::YZ ? 1 : 0, second = view_ == View::XY ? 1 : 2;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      auto& [u, v] = pts[k];
      const double t = pts.size() > 1 ? double(k) / double(pts.size() - 1) : 1.0;
      // The block's axes (u, v, w) in the run's (to_run_axes), then the view's two.
      std::array<double, 3> p{}, run{};
      p = {u, v, w0 + (w1 - w0) * t};
      for (int i = 0; i < 3; ++i) run[std::size_t((i + b.rot) % 3)] = p[std::size_t(i)];
      u = run[std::size_t(first)];
      v = run[std::size_t(second)];
    }
  }
  if (ideal_.empty() || ideal_.back().back() != pts.front()) {
    ideal_.emplace_back(1, pts.front());
    ++ideal_vertices_;
    provisional_ = false;
  }
  auto& line = ideal_.back();
  for (std::size_t k = 1; k < pts.size(); ++k) {
    const bool on_stride = ++ideal_seq_ % ideal_stride_ == 0;
    if (!on_stride && k + 1 != pts.size()) continue;
    if (provisional_) line.pop_back(), --ideal_vertices_;
    line.push_back(pts[k]);
    ++ideal_vertices_;
    provisional_ = !on_stride;
  }
  if (ideal_vertices_ > ideal_budget_) thin_ideal();
}

void ProgramSvgSink::thin_ideal() {
  ideal_stride_ *= 2;
  ideal_vertices_ = 0;
  for (auto& line : ideal_) {
    std::size_t n = 0;
    for (std::size_t k = 0; k < line.size(); ++k) {
      if (k % 2 == 0 || k + 1 == line.size()) line[n++] = line[k];
    }
    line.resize(n);
    ideal_vertices_ += n;
  }
  provisional_ = true;
}

void ProgramSvgSink::finish() {
  SvgPicture pic;
  pic.title = title_;
  pic.curve = "the program";
  pic.projection = view_;
  if (sample_.stride() > 1) pic.sampled_from = sample_.seen(), pic.sample_stride = sample_.stride();
  sample_.take(pic.pts, pic.dist);
  pic.ideal = std::move(ideal_);
  write_svg(os_, pic);
}

}  // namespace dda::program
