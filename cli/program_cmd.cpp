// SPDX-License-Identifier: Apache-2.0
// `--program FILE`: reading, planning and the per-block reports of a part program.
#include "program_cmd.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "dda/fixed_trig.hpp"
#include "dda/geometry.hpp"
#include "dda/report.hpp"

namespace dda::cli {

using program::BlockPlan;
using program::Length;
using program::MoveKind;
using program::ProgramPlan;

namespace {

// "X,Y" in millimetres (decimal, up to 6 decimals) to nanometres.
std::pair<Length, Length> parse_mm_pair(const std::string& name, const std::string& s) {
  const auto comma = s.find(',');
  const std::optional<Length> p = comma == std::string::npos ? std::nullopt : program::parse_mm(s.substr(0, comma));
  const std::optional<Length> q = comma == std::string::npos ? std::nullopt : program::parse_mm(s.substr(comma + 1));
  if (!p || !q) {
    throw InputError(name + " = '" + s + "' is invalid: give X,Y in millimetres (e.g. 10,-2.5; up to 6 decimals)");
  }
  return {*p, *q};
}

std::string mm(Length v) {
  // Exact decimal millimetres, trailing zeros dropped.
  const Length a = v < 0 ? -v : v;
  std::string s = fmt::format("{}{}.{:06d}", v < 0 ? "-" : "", a / program::kNmPerMm, a % program::kNmPerMm);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

struct BlockStats {
  std::uint64_t iterations = 0, steps = 0, points = 0;
  double max_dev = 0, sum_dev = 0;
  Point max_at, end;
};

std::vector<BlockStats> block_stats(const ProgramPlan& pp, const std::vector<Iteration>& iters) {
  std::vector<BlockStats> v(pp.blocks.size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i].end = pp.blocks[i].from;
  for (const Iteration& it : iters) {
    const std::size_t k = program::block_of_piece(pp, it.piece);
    BlockStats& s = v[k];
    ++s.iterations;
    s.end = it.pos;
    if (!it.step_x && !it.step_y) continue;
    ++s.steps;
    ++s.points;
    const double d = program::block_distance(pp.blocks[k], pp.lattice.step, double(it.pos.x), double(it.pos.y));
    s.sum_dev += d;
    if (d > s.max_dev || s.points == 1) s.max_dev = d, s.max_at = it.pos;
  }
  return v;
}

// Samples (steps) of a block's programmed geometry from its start to its end.
std::vector<std::pair<double, double>> block_geometry(const BlockPlan& b, Length step) {
  const program::Move& mv = b.move;
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
  const auto param = [&](program::Point2 p) {  // parametric angle of a point of the curve
    const double x = double(p.u - mv.center.u), y = double(p.v - mv.center.v);
    return std::atan2((-sn * x + c * y) / B, (c * x + sn * y) / A);
  };
  const double t0 = param(mv.from);
  double span = cw ? t0 - param(mv.to) : param(mv.to) - t0;
  while (span <= 0) span += 2 * M_PI;
  if (mv.full) span = 2 * M_PI;
  const int n = std::clamp(int(span / (2 * M_PI) * 2048), 16, 2048);
  for (int k = 0; k <= n; ++k) {
    const double t = t0 + (cw ? -1 : 1) * span * k / n, u = A * std::cos(t), v = B * std::sin(t);
    pts.emplace_back((double(mv.center.u) + u * c - v * sn) / s, (double(mv.center.v) + u * sn + v * c) / s);
  }
  return pts;
}

}  // namespace

void add_program_options(CLI::App* sub, ProgramCli& o) {
  sub->add_option("--program", o.file,
                  "run a part program (G-code, docs/programs.md; - for standard input) instead of one arc");
  sub->add_option("--machine", o.machine,
                  "with --program: mill (default; G17, X and Y as given) or lathe (G18: Z along the spindle as "
                  "x, X as a diameter, its radius as y)");
  sub->add_option("--start", o.start,
                  "with --program: the tool's start in millimetres, mill X,Y or lathe X,Z (X a diameter; "
                  "default 0,0)");
  sub->add_option("--step", o.step, "with --program: the lattice unit in millimetres (default 0.001)");
}

std::string program_name(const ProgramCli& o) { return o.file == "-" ? "<stdin>" : o.file; }

ProgramPlan load_program(const ProgramCli& o, Preload preload, bool hardware) {
  program::ReadOptions ro;
  if (o.machine == "lathe") {
    ro.machine = program::Machine::Lathe;
  } else if (o.machine != "mill") {
    throw InputError("machine = '" + o.machine + "' is invalid: use mill or lathe");
  }
  if (!o.start.empty()) {
    const auto [p, q] = parse_mm_pair("start", o.start);
    ro.start = program::start_point(ro.machine, p, q);
  }
  program::LatticeOptions lo;
  lo.step = program::parse_step(o.step);
  lo.preload = preload;
  std::string text;
  if (o.file == "-") {
    text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
  } else {
    std::ifstream in(o.file, std::ios::binary);
    if (!in) throw InputError("program = '" + o.file + "' is invalid: cannot read it");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string name = program_name(o);
  ProgramPlan pp = program::plan_program(program::read(text, name, ro), lo, name);
  if (hardware) program::check_hardware(pp, name);
  return pp;
}

void write_program_stats(std::ostream& os, const ProgramPlan& pp, const std::vector<Iteration>& iters,
                         BlockStatsFormat fmt) {
  const std::vector<BlockStats> st = block_stats(pp, iters);
  std::uint64_t it_sum = 0, steps = 0, points = 0;
  double worst = 0, round_worst = 0, dev_sum = 0;
  std::size_t worst_block = 0;
  for (std::size_t k = 0; k < st.size(); ++k) {
    it_sum += st[k].iterations;
    steps += st[k].steps;
    points += st[k].points;
    dev_sum += st[k].sum_dev;
    round_worst = std::max(round_worst, pp.blocks[k].rounding);
    if (st[k].max_dev > worst) worst = st[k].max_dev, worst_block = k;
  }
  const auto block_no = [](const BlockPlan& b) {
    return b.move.block_number ? fmt::format("N{}", *b.move.block_number) : std::string("-");
  };
  const auto ends_ok = [&](std::size_t k) { return st[k].end == pp.blocks[k].to; };
  bool all_ok = true;
  for (std::size_t k = 0; k < st.size(); ++k) all_ok = all_ok && ends_ok(k);
  // Each block's target (docs/programs.md, "Accuracy"); none with zero preload.
  std::vector<double> target(st.size());
  std::size_t over = 0;
  for (std::size_t k = 0; k < st.size(); ++k) {
    target[k] =
        program::block_target(pp.blocks[k], k ? pp.blocks[k - 1].rounding : pp.start_rounding, pp.lattice.preload);
    over += st[k].max_dev > target[k];
  }
  const bool targeted = pp.lattice.preload == Preload::Half;
  const auto within = [&](std::size_t k) {
    return !targeted ? std::string("-") : st[k].max_dev <= target[k] ? std::string("yes") : std::string("NO");
  };
  const std::string verdict = !targeted   ? "not targeted (zero preload: reported only)"
                              : over == 0 ? "every block within its target"
                                          : fmt::format("{} block{} over the target", over, over == 1 ? "" : "s");
  if (fmt == BlockStatsFormat::Json) {
    nlohmann::ordered_json j;
    j["step_mm"] = mm(pp.lattice.step);
    j["preload"] = to_string(pp.lattice.preload);
    j["start"] = {pp.start.x, pp.start.y};
    auto& rows = j["blocks"] = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < st.size(); ++k) {
      const BlockPlan& b = pp.blocks[k];
      nlohmann::ordered_json r;
      r["line"] = b.move.pos.line;
      r["block"] = block_no(b);
      r["kind"] = std::string(program::kind_name(b.move.kind));
      r["end_mm"] = {mm(b.move.to.u), mm(b.move.to.v)};
      r["end"] = {b.to.x, b.to.y};
      r["rounding"] = b.rounding;
      r["commands"] = b.plan.pieces.size();
      r["steps"] = st[k].steps;
      r["iterations"] = st[k].iterations;
      r["max_dev"] = st[k].max_dev;
      r["mean_dev"] = st[k].points ? st[k].sum_dev / double(st[k].points) : 0.0;
      r["on_end"] = ends_ok(k);
      if (targeted) {
        r["target"] = target[k];
        r["within_target"] = st[k].max_dev <= target[k];
      }
      rows.push_back(std::move(r));
    }
    nlohmann::ordered_json t;
    t["blocks"] = st.size();
    t["commands"] = pp.plan.pieces.size();
    t["steps"] = steps;
    t["iterations"] = it_sum;
    t["max_dev"] = worst;
    t["mean_dev"] = points ? dev_sum / double(points) : 0.0;
    t["max_rounding"] = round_worst;
    t["on_ends"] = all_ok;
    if (targeted) t["over_target"] = over;
    j["totals"] = std::move(t);
    os << j.dump(1) << '\n';
    return;
  }
  if (fmt == BlockStatsFormat::Csv) {
    os << "line,block,kind,end_u_mm,end_v_mm,end_x,end_y,rounding,commands,steps,iterations,max_dev,mean_dev,on_end,"
          "target,within_target\n";
    for (std::size_t k = 0; k < st.size(); ++k) {
      const BlockPlan& b = pp.blocks[k];
      fmt::print(os, "{},{},{},{},{},{},{},{:.6f},{},{},{},{:.6f},{:.6f},{},{},{}\n", b.move.pos.line, block_no(b),
                 program::kind_name(b.move.kind), mm(b.move.to.u), mm(b.move.to.v), b.to.x, b.to.y, b.rounding,
                 b.plan.pieces.size(), st[k].steps, st[k].iterations, st[k].max_dev,
                 st[k].points ? st[k].sum_dev / double(st[k].points) : 0.0, ends_ok(k) ? "yes" : "no",
                 targeted ? fmt::format("{:.6f}", target[k]) : "-", within(k) == "NO" ? "no" : within(k));
    }
    return;
  }
  fmt::print(os, "step {} mm, preload {}, start ({},{}); deviation: steps from the programmed geometry\n",
             mm(pp.lattice.step), to_string(pp.lattice.preload), pp.start.x, pp.start.y);
  fmt::print(os,
             "| {:>5} | {:>6} | {:<11} | {:>21} | {:>17} | {:>8} | {:>4} | {:>7} | {:>9} | {:>7} | {:>6} | {:>3} | "
             "{:>3} |\n",
             "line", "block", "kind", "end (mm)", "end (steps)", "rounding", "cmds", "steps", "iters", "max dev",
             "target", "ok", "end");
  fmt::print(os,
             "|-------|--------|-------------|-----------------------|-------------------|----------|------|---------|"
             "-----------|---------|--------|-----|-----|\n");
  for (std::size_t k = 0; k < st.size(); ++k) {
    const BlockPlan& b = pp.blocks[k];
    fmt::print(
        os,
        "| {:>5} | {:>6} | {:<11} | {:>21} | {:>17} | {:>8.3f} | {:>4} | {:>7} | {:>9} | {:>7.3f} | {:>6} | {:>3} | "
        "{:>3} |\n",
        b.move.pos.line, block_no(b), program::kind_name(b.move.kind),
        fmt::format("{},{}", mm(b.move.to.u), mm(b.move.to.v)), fmt::format("{},{}", b.to.x, b.to.y), b.rounding,
        b.plan.pieces.size(), st[k].steps, st[k].iterations, st[k].max_dev,
        targeted ? fmt::format("{:.3f}", target[k]) : "-", within(k), ends_ok(k) ? "yes" : "NO");
  }
  fmt::print(os, "blocks: {}\ncommands: {}\nsteps: {}\niterations: {}\n", st.size(), pp.plan.pieces.size(), steps,
             it_sum);
  fmt::print(os, "max_dev: {:.6f} (line {})\nmean_dev: {:.6f}\nmax_rounding: {:.6f}\nends: {}\n", worst,
             st.empty() ? 0 : pp.blocks[worst_block].move.pos.line, points ? dev_sum / double(points) : 0.0,
             round_worst, all_ok ? "every block on its rounded end" : "NOT every block on its rounded end");
  fmt::print(os, "targets: {}\n", verdict);
}

void write_program_svg(std::ostream& os, const ProgramPlan& pp, const std::vector<Iteration>& iters,
                       const std::string& title) {
  SvgPicture pic;
  pic.title = title;
  pic.curve = "the program";
  pic.pts.push_back(pp.start);
  pic.dist.push_back(pp.blocks.empty() ? 0.0
                                       : program::block_distance(pp.blocks.front(), pp.lattice.step, double(pp.start.x),
                                                                 double(pp.start.y)));
  for (const Iteration& it : iters) {
    if (!it.step_x && !it.step_y) continue;
    const std::size_t k = program::block_of_piece(pp, it.piece);
    pic.pts.push_back(it.pos);
    pic.dist.push_back(program::block_distance(pp.blocks[k], pp.lattice.step, double(it.pos.x), double(it.pos.y)));
  }
  for (const BlockPlan& b : pp.blocks) pic.ideal.push_back(block_geometry(b, pp.lattice.step));
  write_svg(os, pic);
}

}  // namespace dda::cli
