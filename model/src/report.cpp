// SPDX-License-Identifier: Apache-2.0
#include "dda/report.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>

namespace dda {

std::string paper_units(std::int64_t v, std::int64_t scale) {
  const __int128 num = static_cast<__int128>(v) * 10000;
  const bool neg = (num < 0) != (scale < 0);
  __int128 n = num < 0 ? -num : num;
  const __int128 d = scale < 0 ? -static_cast<__int128>(scale) : scale;
  __int128 q = n / d;
  const __int128 r = n % d;
  if (2 * r >= d) ++q;  // half away from zero
  const auto whole = static_cast<std::uint64_t>(q / 10000);
  const auto frac = static_cast<unsigned>(q % 10000);
  return fmt::format("{}{}.{:04d}", (neg && q != 0) ? "-" : "", whole, frac);
}

namespace {

struct Row {
  std::uint64_t iter;
  std::uint32_t piece;
  std::int64_t jvx, jrx, jvy, jry;
  bool ax, ay;  // axis active (accumulator added) in this row
  bool dx, dy;
  std::int64_t remx, remy;
  bool negx, negy;
  Point pos;
};

// The scale of a row's values: the plan's (a b, or a line's capacity), or, for a line
// piece inside an arc (lead-in, lead-out, closing), that line's capacity: its values are
// in steps.
std::int64_t row_scale(const Plan& plan, std::uint32_t piece) {
  const Piece& pc = plan.pieces[std::min<std::size_t>(piece, plan.pieces.size() - 1)];
  return pc.kind == PieceKind::Line || plan.program ? pc.cmd.cap : plan.scale;
}

std::vector<Row> rows(const Plan& plan, const RegState& init, const std::vector<Iteration>& iters) {
  std::vector<Row> v;
  v.reserve(iters.size() + 1);
  const Command& c = plan.cmd();
  v.push_back({0, 0, init.jv_x, init.jr_x, init.jv_y, init.jr_y, init.cnt_x != 0, init.cnt_y != 0, false, false,
               init.cnt_x, init.cnt_y, c.dir_x_neg, c.dir_y_neg, plan.from});
  for (const auto& it : iters) {
    v.push_back({it.iter, it.piece, it.jv_x, it.sum_x, it.jv_y, it.sum_y, it.active_x, it.active_y, it.step_x,
                 it.step_y, it.after.cnt_x, it.after.cnt_y, it.dir_x_neg, it.dir_y_neg, it.pos});
  }
  return v;
}

std::string acc_cell(bool active, std::int64_t v, std::int64_t scale) {
  return active ? paper_units(v, scale) : std::string("stopped");
}

const char* sign(bool neg) { return neg ? "-" : "+"; }

}  // namespace

bool paper_columns(const Plan& plan) {
  return !plan.line && !plan.program && plan.pieces.size() == 1 && plan.spec.center == Point{0, 0} &&
         plan.cmd().dir_x_neg && !plan.cmd().dir_y_neg;
}

void write_trace(std::ostream& os, const Plan& plan, const std::vector<Iteration>& iters, TraceFormat fmt) {
  write_trace(os, plan, initial_regs(plan.cmd()), iters, fmt);
}

void write_trace(std::ostream& os, const Plan& plan, const RegState& initial, const std::vector<Iteration>& iters,
                 TraceFormat fmt) {
  const std::int64_t s = plan.scale;
  const bool paper = paper_columns(plan);
  if (fmt == TraceFormat::Csv) {
    os << (paper ? "iter,jvx,jrx,dx,rem_x,jvy,jry,dy,rem_y\n"
                 : "iter,seg,jvx,jrx,dx,rem_x,jvy,jry,dy,rem_y,dir_x,dir_y,x,y\n");
    for (const Row& r : rows(plan, initial, iters)) {
      if (paper) {
        fmt::print(os, "{},{},{},{:d},{},{},{},{:d},{}\n", r.iter, paper_units(r.jvx, s), acc_cell(r.ax, r.jrx, s),
                   r.dx, r.remx, paper_units(r.jvy, s), acc_cell(r.ay, r.jry, s), r.dy, r.remy);
      } else {
        const std::int64_t rs = row_scale(plan, r.piece);
        fmt::print(os, "{},{},{},{},{:d},{},{},{},{:d},{},{},{},{},{}\n", r.iter, r.piece, paper_units(r.jvx, rs),
                   acc_cell(r.ax, r.jrx, rs), r.dx, r.remx, paper_units(r.jvy, rs), acc_cell(r.ay, r.jry, rs), r.dy,
                   r.remy, sign(r.negx), sign(r.negy), r.pos.x, r.pos.y);
      }
    }
    return;
  }
  if (fmt == TraceFormat::Table) {
    // The paper's Table 1 layout: row 0 and every row with a pulse, in paper units.
    if (plan.program) {
      fmt::print(os,
                 "program: {} commands from ({},{}) to ({},{}), units: steps (scaled values / each piece's capacity)\n",
                 plan.pieces.size(), plan.from.x, plan.from.y, plan.to.x, plan.to.y);
    } else if (plan.line) {
      fmt::print(os, "line preload={} from ({},{}) to ({},{}), units: steps (scaled values / the capacity {})\n",
                 to_string(plan.spec.preload), plan.from.x, plan.from.y, plan.to.x, plan.to.y, s);
    } else {
      bool lines = false;
      for (const Piece& pc : plan.pieces) lines = lines || pc.kind == PieceKind::Line;
      fmt::print(os, "a={} b={} n={} preload={} {} from ({},{}) to ({},{}), paper units (scaled values / {}{})\n",
                 plan.spec.a, plan.spec.b, plan.spec.bits, to_string(plan.spec.preload), to_string(plan.spec.dir),
                 plan.from.x, plan.from.y, plan.to.x, plan.to.y, s,
                 lines ? "; rows of line pieces: steps, values / their capacity" : "");
    }
    const auto line = [&](auto... c) {
      fmt::print(os, "| {:>5} | {:>10} | {:>10} | {:>2} | {:>5} | {:>10} | {:>10} | {:>2} | {:>5} |", c...);
    };
    line("iter", "JVX", "JRX", "dX", "remX", "JVY", "JRY", "dY", "remY");
    os << (paper ? "\n" : " seg | dirs |      x |      y |\n");
    os << "|-------|------------|------------|----|-------|------------|------------|----|-------|"
       << (paper ? "\n" : "-----|------|--------|--------|\n");
    for (const Row& r : rows(plan, initial, iters)) {
      if (r.iter != 0 && !r.dx && !r.dy) continue;
      const std::int64_t rs = row_scale(plan, r.piece);
      line(r.iter, paper_units(r.jvx, rs), acc_cell(r.ax, r.jrx, rs), int(r.dx), r.remx, paper_units(r.jvy, rs),
           acc_cell(r.ay, r.jry, rs), int(r.dy), r.remy);
      if (paper) {
        os << '\n';
      } else {
        fmt::print(os, " {:>3} | {}{}   | {:>6} | {:>6} |\n", r.piece, sign(r.negx), sign(r.negy), r.pos.x, r.pos.y);
      }
    }
    return;
  }
  // JSON: the full records, exact scaled integers.
  nlohmann::ordered_json j;
  if (plan.line) j["line"] = true;
  if (plan.program) j["program"] = true;
  j["a"] = plan.spec.a;
  j["b"] = plan.spec.b;
  j["bits"] = plan.spec.bits;
  j["preload"] = to_string(plan.spec.preload);
  j["dir"] = to_string(plan.spec.dir);
  j["center"] = {plan.spec.center.x, plan.spec.center.y};
  j["from"] = {plan.from.x, plan.from.y};
  j["to"] = {plan.to.x, plan.to.y};
  j["scale"] = s;
  j["cap"] = plan.cmd().cap;
  j["iteration_bound"] = plan.iteration_bound;
  auto& pieces = j["segments"] = nlohmann::ordered_json::array();
  for (const auto& sg : plan.pieces) {
    const Command& c = sg.cmd;
    nlohmann::ordered_json g;
    g["from"] = {sg.from.x, sg.from.y};
    g["to"] = {sg.to.x, sg.to.y};
    g["quadrant"] = sg.quadrant;
    g["jv_x"] = c.jv_x;
    g["jv_y"] = c.jv_y;
    g["jr_x"] = c.jr_x;
    g["jr_y"] = c.jr_y;
    g["cap"] = c.cap;
    g["cnt_x"] = c.cnt_x;
    g["cnt_y"] = c.cnt_y;
    g["dir_x"] = sign(c.dir_x_neg);
    g["dir_y"] = sign(c.dir_y_neg);
    g["inc_x_on_x"] = c.inc_x_on_x;
    g["inc_x_on_y"] = c.inc_x_on_y;
    g["inc_y_on_x"] = c.inc_y_on_x;
    g["inc_y_on_y"] = c.inc_y_on_y;
    g["iteration_bound"] = sg.iteration_bound;
    pieces.push_back(std::move(g));
  }
  nlohmann::ordered_json in;
  in["jv_x"] = initial.jv_x;
  in["jv_y"] = initial.jv_y;
  in["jr_x"] = initial.jr_x;
  in["jr_y"] = initial.jr_y;
  in["cnt_x"] = initial.cnt_x;
  in["cnt_y"] = initial.cnt_y;
  j["initial"] = std::move(in);
  auto& recs = j["iterations"] = nlohmann::ordered_json::array();
  for (const auto& it : iters) {
    nlohmann::ordered_json r;
    r["iter"] = it.iter;
    r["seg"] = it.piece;
    r["active_x"] = it.active_x;
    r["active_y"] = it.active_y;
    r["jv_x"] = it.jv_x;
    r["jv_y"] = it.jv_y;
    r["sum_x"] = it.sum_x;
    r["sum_y"] = it.sum_y;
    r["step_x"] = it.step_x;
    r["step_y"] = it.step_y;
    r["dir_x"] = sign(it.dir_x_neg);
    r["dir_y"] = sign(it.dir_y_neg);
    r["jr_x"] = it.after.jr_x;
    r["jr_y"] = it.after.jr_y;
    r["cnt_x"] = it.after.cnt_x;
    r["cnt_y"] = it.after.cnt_y;
    r["jv_x_next"] = it.after.jv_x;
    r["jv_y_next"] = it.after.jv_y;
    r["x"] = it.pos.x;
    r["y"] = it.pos.y;
    recs.push_back(std::move(r));
  }
  os << j.dump(1) << '\n';
}

std::vector<Point> path_points(const Plan& plan, const std::vector<Iteration>& iters) {
  std::vector<Point> pts{plan.from};
  for (const auto& it : iters) {
    if (it.step_x || it.step_y) pts.push_back(it.pos);
  }
  return pts;
}

void write_path(std::ostream& os, const std::vector<Point>& points, PathFormat fmt) {
  if (fmt == PathFormat::Csv) {
    os << "point,x,y\n";
    for (std::size_t i = 0; i < points.size(); ++i) {
      fmt::print(os, "{},{},{}\n", i, points[i].x, points[i].y);
    }
    return;
  }
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const auto& p : points) j.push_back({p.x, p.y});
  os << j.dump() << '\n';
}

Stats compute_stats(const Plan& plan, const std::vector<Iteration>& iters) {
  Stats s;
  s.iterations = iters.size();
  for (const auto& it : iters) {
    s.pulses_x += it.step_x;
    s.pulses_y += it.step_y;
    s.moves += (it.step_x || it.step_y);
  }
  const auto pts = path_points(plan, iters);
  s.points = pts.size();
  double sum = 0;
  for (const auto& p : pts) {
    const double d = plan_distance(plan, double(p.x), double(p.y));
    sum += d;
    if (d > s.max_dev) {
      s.max_dev = d;
      s.max_dev_at = p;
    }
  }
  s.mean_dev = sum / double(pts.size());
  return s;
}

void write_stats(std::ostream& os, const Plan& plan, const Stats& s, StatsFormat fmt) {
  if (fmt == StatsFormat::Text) {
    fmt::print(os, "iterations: {}\nmoves: {}\npulses_x: {}\npulses_y: {}\npoints: {}\n", s.iterations, s.moves,
               s.pulses_x, s.pulses_y, s.points);
    fmt::print(os, "max_dev: {:.6f} at ({},{})\nmean_dev: {:.6f}\n", s.max_dev, s.max_dev_at.x, s.max_dev_at.y,
               s.mean_dev);
    fmt::print(os, "bits: {}\npreload: {}\n", plan.spec.bits, to_string(plan.spec.preload));
    fmt::print(os, "from: ({},{})\nto: ({},{})\npieces: {}\n", plan.from.x, plan.from.y, plan.to.x, plan.to.y,
               plan.pieces.size());
    return;
  }
  nlohmann::ordered_json j;
  j["iterations"] = s.iterations;
  j["moves"] = s.moves;
  j["pulses_x"] = s.pulses_x;
  j["pulses_y"] = s.pulses_y;
  j["points"] = s.points;
  j["max_dev"] = s.max_dev;
  j["max_dev_at"] = {s.max_dev_at.x, s.max_dev_at.y};
  j["mean_dev"] = s.mean_dev;
  j["bits"] = plan.spec.bits;
  j["preload"] = to_string(plan.spec.preload);
  j["from"] = {plan.from.x, plan.from.y};
  j["to"] = {plan.to.x, plan.to.y};
  j["pieces"] = plan.pieces.size();
  os << j.dump(1) << '\n';
}

std::string describe(const Plan& plan) {
  std::ostringstream s;
  if (plan.program) {  // a part program's blocks: the program file rebuilds them
    s << "--program (" << plan.pieces.size() << " commands from (" << plan.from.x << ',' << plan.from.y << ") to ("
      << plan.to.x << ',' << plan.to.y << "))";
    return s.str();
  }
  if (plan.line) {
    s << "--line --from " << plan.from.x << ',' << plan.from.y << " --to " << plan.to.x << ',' << plan.to.y
      << " --preload " << to_string(plan.spec.preload);
    return s.str();
  }
  s << "--a " << plan.spec.a << " --b " << plan.spec.b << " --bits " << plan.spec.bits << " --preload "
    << to_string(plan.spec.preload);
  if (plan.spec.center != Point{0, 0}) s << " --center " << plan.spec.center.x << ',' << plan.spec.center.y;
  if (plan.spec.angle != 0) s << " --angle " << format_degrees(plan.spec.angle);
  if (plan.spec.dir != Direction::Ccw) s << " --dir cw";
  if (plan.spec.from_theta) {
    s << " --from-theta " << format_degrees(*plan.spec.from_theta);
  } else {
    s << " --from " << plan.from.x << ',' << plan.from.y;
  }
  if (plan.spec.to_theta) {
    s << " --to-theta " << format_degrees(*plan.spec.to_theta);
  } else {
    s << " --to " << plan.to.x << ',' << plan.to.y;
  }
  return s.str();
}

}  // namespace dda
