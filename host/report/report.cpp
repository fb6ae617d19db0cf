// SPDX-License-Identifier: Apache-2.0
#include "host/report/report.hpp"

#include "host/report/json_stream.hpp"
#include "model/datapath/core_model.hpp"

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

std::string acc_cell(bool active, std::int64_t v, std::int64_t scale) {
  return active ? paper_units(v, scale) : std::string("stopped");
}
// The third axis idles (its counter 0) in every piece that does not move it: "-".
std::string acc_cell_z(bool active, std::int64_t v, std::int64_t scale) {
  return active ? paper_units(v, scale) : std::string("-");
}

struct Row {
  std::uint64_t iter;
  std::uint32_t piece;
  std::int64_t jvx, jrx, jvy, jry;
  bool ax, ay;  // axis active (accumulator added) in this row
  bool dx, dy;
  std::int64_t remx, remy;
  bool negx, negy;
  Point pos;
  std::int64_t jvz, jrz;  // the third axis
  bool az, dz;
  std::int64_t remz;
  bool negz;
};

Row row_of(const Iteration& it) {
  return {it.iter,     it.piece,  it.jv_x,   it.sum_x,       it.jv_y,        it.sum_y,       it.active_x,
          it.active_y, it.step_x, it.step_y, it.after.cnt_x, it.after.cnt_y, it.dir_x_neg,   it.dir_y_neg,
          it.pos,      it.jv_z,   it.sum_z,  it.active_z,    it.step_z,      it.after.cnt_z, it.dir_z_neg};
}

// The third axis' columns of a row (CSV), its values in steps (divided by its capacity).
std::string z_cells(const Row& r, std::int64_t cap_z) {
  return fmt::format(",{},{},{:d},{},{},{}", paper_units(r.jvz, cap_z), acc_cell_z(r.az, r.jrz, cap_z), r.dz, r.remz,
                     r.negz ? "-" : "+", r.pos.z);
}

const char* sign(bool neg) { return neg ? "-" : "+"; }

// "(x,y)", or "(x,y,z)" in a report with the third axis' columns.
std::string point_text(Point p, bool z) {
  return z ? fmt::format("({},{},{})", p.x, p.y, p.z) : fmt::format("({},{})", p.x, p.y);
}

void table_line(std::ostream& os, const std::string& iter, const std::string& jvx, const std::string& jrx,
                const std::string& dx, const std::string& remx, const std::string& jvy, const std::string& jry,
                const std::string& dy, const std::string& remy) {
  fmt::print(os, "| {:>5} | {:>10} | {:>10} | {:>2} | {:>5} | {:>10} | {:>10} | {:>2} | {:>5} |", iter, jvx, jrx, dx,
             remx, jvy, jry, dy, remy);
}

nlohmann::ordered_json command_json(const Piece& sg, bool z) {
  const Command& c = sg.cmd;
  nlohmann::ordered_json g;
  g["from"] = {sg.from.x, sg.from.y};
  g["to"] = {sg.to.x, sg.to.y};
  if (z) g["from"].push_back(sg.from.z), g["to"].push_back(sg.to.z);
  g["quadrant"] = sg.quadrant;
  const CmdValues v = command_values(c);
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string name(hw::kCmdFields[i].name);
    if (!z && name.size() > 2 && name.compare(name.size() - 2, 2, "_z") == 0) continue;  // (a plane's command)
    if (name.rfind("dir_", 0) == 0) {
      g[name] = sign(v[i] == hw::kDirNeg);
    } else {
      g[name] = v[i];
    }
  }
  g["iteration_bound"] = sg.iteration_bound;
  return g;
}

// What register values are divided by in a plan's rows: a b for an arc, the capacity
// for a line (its values are then in steps).
std::int64_t value_scale(const Plan& plan) { return plan.is_arc() ? plan.arc().scale : plan.cmd().cap; }

}  // namespace

bool third_axis(const Plan& plan) {
  if (plan.from.z != 0 || plan.to.z != 0) return true;
  for (const Piece& pc : plan.pieces) {
    if (pc.cmd.cnt_z != 0 || pc.rot != 0) return true;
  }
  return false;
}

bool paper_columns(const Plan& plan) {
  return plan.is_arc() && plan.pieces.size() == 1 && plan.arc().spec.center == Point{0, 0} && plan.cmd().dir_x_neg &&
         !plan.cmd().dir_y_neg;
}

TraceSink::TraceSink(std::ostream& os, const Plan& plan, TraceFormat fmt)
    : os_(os),
      plan_(&plan),
      preload_(plan.preload()),
      from_(plan.from),
      at_(plan.from),
      fmt_(fmt),
      paper_(paper_columns(plan) && !third_axis(plan)),
      z_(third_axis(plan)) {}

TraceSink::TraceSink(std::ostream& os, Preload preload, Point from, TraceFormat fmt, bool third_axis)
    : os_(os), preload_(preload), from_(from), at_(from), fmt_(fmt), z_(third_axis) {}

void TraceSink::piece(const Piece& pc) {
  window_.push(pc);
  ++pieces_;
}

void TraceSink::initial(const RegState& r) { header(r); }

void TraceSink::header(const RegState& init) {
  const Command& c = window_.at(0).cmd;
  const Plan* p = plan_;
  Iteration row0;
  row0.jv_x = init.jv_x, row0.sum_x = init.jr_x, row0.jv_y = init.jv_y, row0.sum_y = init.jr_y;
  row0.active_x = init.cnt_x != 0, row0.active_y = init.cnt_y != 0;
  row0.after.cnt_x = init.cnt_x, row0.after.cnt_y = init.cnt_y;
  row0.dir_x_neg = c.dir_x_neg, row0.dir_y_neg = c.dir_y_neg;
  row0.pos = from_;
  row0.jv_z = c.jv_z, row0.sum_z = init.jr_z, row0.active_z = init.cnt_z != 0;
  row0.after.cnt_z = init.cnt_z, row0.dir_z_neg = c.dir_z_neg;
  if (fmt_ == TraceFormat::Csv) {
    os_ << (paper_ ? "iter,jvx,jrx,dx,rem_x,jvy,jry,dy,rem_y\n"
                   : "iter,seg,jvx,jrx,dx,rem_x,jvy,jry,dy,rem_y,dir_x,dir_y,x,y");
    if (!paper_) os_ << (z_ ? ",jvz,jrz,dz,rem_z,dir_z,z\n" : "\n");
  } else if (fmt_ == TraceFormat::Table) {
    // The paper's Table 1 layout: row 0 and every row with a pulse, in paper units.
    if (!p) {
      fmt::print(os_, "program from {}, units: steps (scaled values / each piece's capacity)\n", point_text(from_, z_));
    } else if (p->is_line()) {
      fmt::print(os_, "line preload={} from ({},{}) to ({},{}), units: steps (scaled values / the capacity {})\n",
                 to_string(p->preload()), p->from.x, p->from.y, p->to.x, p->to.y, value_scale(*p));
    } else {
      const ArcSpec& spec = p->arc().spec;
      bool lines = false;
      for (const Piece& pc : p->pieces) lines = lines || pc.kind == PieceKind::Line;
      fmt::print(os_, "a={} b={} n={} preload={} {} from ({},{}) to ({},{}), paper units (scaled values / {}{})\n",
                 spec.a, spec.b, spec.bits, to_string(spec.preload), to_string(spec.dir), p->from.x, p->from.y, p->to.x,
                 p->to.y, value_scale(*p), lines ? "; rows of line pieces: steps, values / their capacity" : "");
    }
    table_line(os_, "iter", "JVX", "JRX", "dX", "remX", "JVY", "JRY", "dY", "remY");
    os_ << (paper_ ? "\n"
            : z_   ? " seg | dirs |      x |      y | dZ |  remZ |      z |\n"
                   : " seg | dirs |      x |      y |\n");
    os_ << "|-------|------------|------------|----|-------|------------|------------|----|-------|"
        << (paper_ ? "\n"
            : z_   ? "-----|------|--------|--------|----|-------|--------|\n"
                   : "-----|------|--------|--------|\n");
  } else {
    json_header(init);  // JSON: the full records, exact scaled integers
    return;
  }
  record(row0);  // row 0: the registers as loaded
}

void TraceSink::json_header(const RegState& init) {
  const Plan* p = plan_;
  nlohmann::ordered_json j;
  if (p) {
    // A line has the arc's fields too (one shape): a = b = bits = 0, counter-clockwise,
    // centred on its start.
    const ArcSpec spec = p->is_arc() ? p->arc().spec : ArcSpec{};
    if (p->is_line()) j["line"] = true;
    j["a"] = spec.a;
    j["b"] = spec.b;
    j["bits"] = spec.bits;
    j["preload"] = to_string(p->preload());
    j["dir"] = to_string(spec.dir);
    const Point c = p->is_arc() ? spec.center : p->from;
    j["center"] = {c.x, c.y};
    j["from"] = {p->from.x, p->from.y};
    j["to"] = {p->to.x, p->to.y};
    if (z_) j["from"].push_back(p->from.z), j["to"].push_back(p->to.z);
    j["scale"] = value_scale(*p);
    j["cap"] = p->cmd().cap;
    j["iteration_bound"] = p->iteration_bound;
    auto& pieces = j["segments"] = nlohmann::ordered_json::array();
    for (const auto& sg : p->pieces) pieces.push_back(command_json(sg, z_));
  } else {
    j["program"] = true;
    j["preload"] = to_string(preload_);
    j["from"] = {from_.x, from_.y};
    if (z_) j["from"].push_back(from_.z);
  }
  nlohmann::ordered_json in;
  in["jv_x"] = init.jv_x;
  in["jv_y"] = init.jv_y;
  in["jr_x"] = init.jr_x;
  in["jr_y"] = init.jr_y;
  in["cnt_x"] = init.cnt_x;
  in["cnt_y"] = init.cnt_y;
  if (z_) in["jr_z"] = init.jr_z, in["cnt_z"] = init.cnt_z;
  j["initial"] = std::move(in);
  os_ << json_stream::open_object(j) << ",\n \"iterations\": [";
}

void TraceSink::json_record(const Iteration& it, const Piece& pc) {
  nlohmann::ordered_json r;
  r["iter"] = it.iter;
  r["seg"] = it.piece;
  if (!plan_ && std::int64_t(it.piece) != last_piece_) r["segment"] = command_json(pc, z_);
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
  if (z_) {
    r["active_z"] = it.active_z;
    r["jv_z"] = it.jv_z;
    r["sum_z"] = it.sum_z;
    r["step_z"] = it.step_z;
    r["dir_z"] = sign(it.dir_z_neg);
    r["jr_z"] = it.after.jr_z;
    r["cnt_z"] = it.after.cnt_z;
    r["z"] = it.pos.z;
  }
  os_ << (records_ == 0 ? "\n" : ",\n") << json_stream::element(r, 2);
}

void TraceSink::record(const Iteration& it) {
  const bool row0 = it.iter == 0;
  const Piece& pc = window_.at(it.piece);
  if (!row0) {
    at_ = it.pos;
    if (fmt_ == TraceFormat::Json) json_record(it, pc);
    last_piece_ = it.piece;
    ++records_;
    if (fmt_ == TraceFormat::Json) return;
  }
  const Row r = row_of(it);
  // A row's scale: the plan's (a b, or a line's capacity), or, for a line piece inside
  // an arc (lead-in, lead-out, closing) or any piece of a program, that piece's
  // capacity: its values are in steps.
  const std::int64_t rs = pc.kind == PieceKind::Line || !plan_ ? pc.cmd.cap : value_scale(*plan_);
  if (fmt_ == TraceFormat::Csv) {
    if (paper_) {
      fmt::print(os_, "{},{},{},{:d},{},{},{},{:d},{}\n", r.iter, paper_units(r.jvx, rs), acc_cell(r.ax, r.jrx, rs),
                 r.dx, r.remx, paper_units(r.jvy, rs), acc_cell(r.ay, r.jry, rs), r.dy, r.remy);
    } else {
      fmt::print(os_, "{},{},{},{},{:d},{},{},{},{:d},{},{},{},{},{}", r.iter, r.piece, paper_units(r.jvx, rs),
                 acc_cell(r.ax, r.jrx, rs), r.dx, r.remx, paper_units(r.jvy, rs), acc_cell(r.ay, r.jry, rs), r.dy,
                 r.remy, sign(r.negx), sign(r.negy), r.pos.x, r.pos.y);
      os_ << (z_ ? z_cells(r, pc.cmd.cap_z) : std::string()) << '\n';
    }
    return;
  }
  if (!row0 && !r.dx && !r.dy && !r.dz) return;
  table_line(os_, std::to_string(r.iter), paper_units(r.jvx, rs), acc_cell(r.ax, r.jrx, rs), std::to_string(int(r.dx)),
             std::to_string(r.remx), paper_units(r.jvy, rs), acc_cell(r.ay, r.jry, rs), std::to_string(int(r.dy)),
             std::to_string(r.remy));
  if (paper_) {
    os_ << '\n';
  } else {
    fmt::print(os_, " {:>3} | {}{}{}  | {:>6} | {:>6} |", r.piece, sign(r.negx), sign(r.negy), z_ ? sign(r.negz) : " ",
               r.pos.x, r.pos.y);
    if (z_) fmt::print(os_, " {:>2} | {:>5} | {:>6} |", int(r.dz), r.remz, r.pos.z);
    os_ << '\n';
  }
}

void TraceSink::finish() {
  if (fmt_ == TraceFormat::Json) {
    os_ << (records_ == 0 ? "]" : "\n ]");
    if (!plan_ && z_) {
      fmt::print(os_, ",\n \"to\": [\n  {},\n  {},\n  {}\n ],\n \"commands\": {}", at_.x, at_.y, at_.z, pieces_);
    } else if (!plan_) {
      fmt::print(os_, ",\n \"to\": [\n  {},\n  {}\n ],\n \"commands\": {}", at_.x, at_.y, pieces_);
    }
    os_ << "\n}\n";
  } else if (fmt_ == TraceFormat::Table && !plan_) {
    fmt::print(os_, "program: {} commands from {} to {}\n", pieces_, point_text(from_, z_), point_text(at_, z_));
  }
}

void write_trace(std::ostream& os, const Plan& plan, const std::vector<Iteration>& iters, TraceFormat fmt) {
  write_trace(os, plan, initial_regs(plan.cmd()), iters, fmt);
}

void write_trace(std::ostream& os, const Plan& plan, const RegState& initial, const std::vector<Iteration>& iters,
                 TraceFormat fmt) {
  TraceSink t(os, plan, fmt);
  for (const Piece& pc : plan.pieces) t.piece(pc);
  t.initial(initial);
  for (const Iteration& it : iters) t.record(it);
  t.finish();
}

PathSink::PathSink(std::ostream& os, Point from, PathFormat fmt, bool third_axis)
    : os_(os), fmt_(fmt), from_(from), z_(third_axis) {}

void PathSink::start() {
  if (started_) return;
  started_ = true;
  if (fmt_ == PathFormat::Csv) os_ << (z_ ? "point,x,y,z\n" : "point,x,y\n");
  if (fmt_ == PathFormat::Json) os_ << '[';
  point(from_);
}

void PathSink::point(Point p) {
  if (fmt_ == PathFormat::Csv && z_) {
    fmt::print(os_, "{},{},{},{}\n", n_, p.x, p.y, p.z);
  } else if (fmt_ == PathFormat::Csv) {
    fmt::print(os_, "{},{},{}\n", n_, p.x, p.y);
  } else if (z_) {
    fmt::print(os_, "{}[{},{},{}]", n_ ? "," : "", p.x, p.y, p.z);
  } else {
    fmt::print(os_, "{}[{},{}]", n_ ? "," : "", p.x, p.y);
  }
  ++n_;
}

void PathSink::record(const Iteration& it) {
  start();
  if (it.step_x || it.step_y || it.step_z) point(it.pos);
}

void PathSink::finish() {
  start();
  if (fmt_ == PathFormat::Json) os_ << "]\n";
}

std::vector<Point> path_points(const Plan& plan, const std::vector<Iteration>& iters) {
  std::vector<Point> pts{plan.from};
  for (const auto& it : iters) {
    if (it.step_x || it.step_y || it.step_z) pts.push_back(it.pos);
  }
  return pts;
}

void write_path(std::ostream& os, const std::vector<Point>& points, PathFormat fmt) {
  if (points.empty()) return;
  bool z = false;
  for (const Point& p : points) z = z || p.z != 0;
  PathSink sink(os, points.front(), fmt, z);
  Iteration it;
  it.step_x = true;
  for (std::size_t i = 1; i < points.size(); ++i) {
    it.pos = points[i];
    sink.record(it);
  }
  sink.finish();
}

StatsSink::StatsSink(const Plan& plan, std::ostream* os, StatsFormat fmt) : plan_(plan), os_(os), fmt_(fmt) {
  point(plan.from);
}

void StatsSink::finish() {
  if (os_) write_stats(*os_, plan_, stats(), fmt_);
}

void StatsSink::point(Point p) {
  ++s_.points;
  const double d = plan_distance(plan_, double(p.x), double(p.y));
  sum_ += d;
  if (d > s_.max_dev) {
    s_.max_dev = d;
    s_.max_dev_at = p;
  }
}

void StatsSink::record(const Iteration& it) {
  s_.iterations = it.iter;  // counted across the run, also the iterations without a record
  s_.pulses_x += it.step_x;
  s_.pulses_y += it.step_y;
  s_.pulses_z += it.step_z;
  if (!it.step_x && !it.step_y) return;  // (a step of the third axis alone: no new point of the plane)
  ++s_.moves;
  point(it.pos);
}

const Stats& StatsSink::stats() {
  s_.mean_dev = sum_ / double(s_.points);
  return s_;
}

namespace {

// The width n of an arc's plan; 0 for a line (its capacity is its longer extent).
int bits(const Plan& plan) { return plan.is_arc() ? plan.arc().spec.bits : 0; }

}  // namespace

Stats compute_stats(const Plan& plan, const std::vector<Iteration>& iters) {
  StatsSink sink(plan);
  for (const auto& it : iters) sink.record(it);
  return sink.stats();
}

void write_stats(std::ostream& os, const Plan& plan, const Stats& s, StatsFormat fmt) {
  if (fmt == StatsFormat::Text) {
    const bool z = third_axis(plan);
    fmt::print(os, "iterations: {}\nmoves: {}\npulses_x: {}\npulses_y: {}\n", s.iterations, s.moves, s.pulses_x,
               s.pulses_y);
    if (z) fmt::print(os, "pulses_z: {}\n", s.pulses_z);
    fmt::print(os, "points: {}\n", s.points);
    fmt::print(os, "max_dev: {:.6f} at ({},{})\nmean_dev: {:.6f}\n", s.max_dev, s.max_dev_at.x, s.max_dev_at.y,
               s.mean_dev);
    fmt::print(os, "bits: {}\npreload: {}\n", bits(plan), to_string(plan.preload()));
    fmt::print(os, "from: {}\nto: {}\npieces: {}\n", point_text(plan.from, z), point_text(plan.to, z),
               plan.pieces.size());
    return;
  }
  nlohmann::ordered_json j;
  j["iterations"] = s.iterations;
  j["moves"] = s.moves;
  j["pulses_x"] = s.pulses_x;
  j["pulses_y"] = s.pulses_y;
  if (third_axis(plan)) j["pulses_z"] = s.pulses_z;
  j["points"] = s.points;
  j["max_dev"] = s.max_dev;
  j["max_dev_at"] = {s.max_dev_at.x, s.max_dev_at.y};
  j["mean_dev"] = s.mean_dev;
  j["bits"] = bits(plan);
  j["preload"] = to_string(plan.preload());
  j["from"] = {plan.from.x, plan.from.y};
  j["to"] = {plan.to.x, plan.to.y};
  if (third_axis(plan)) j["from"].push_back(plan.from.z), j["to"].push_back(plan.to.z);
  j["pieces"] = plan.pieces.size();
  os << j.dump(1) << '\n';
}

std::string describe(const Plan& plan) {
  std::ostringstream s;
  if (plan.is_program()) {  // a part program's blocks: the program file rebuilds them
    s << "--program (" << plan.pieces.size() << " commands from (" << plan.from.x << ',' << plan.from.y << ") to ("
      << plan.to.x << ',' << plan.to.y << "))";
    return s.str();
  }
  if (plan.is_line()) {
    const bool z = third_axis(plan);
    s << "--line --from " << plan.from.x << ',' << plan.from.y;
    if (z) s << ',' << plan.from.z;
    s << " --to " << plan.to.x << ',' << plan.to.y;
    if (z) s << ',' << plan.to.z;
    s << " --preload " << to_string(plan.preload());
    return s.str();
  }
  const ArcSpec& spec = plan.arc().spec;
  s << "--a " << spec.a << " --b " << spec.b << " --bits " << spec.bits << " --preload " << to_string(spec.preload);
  if (spec.center != Point{0, 0}) s << " --center " << spec.center.x << ',' << spec.center.y;
  if (spec.angle != 0) s << " --angle " << format_degrees(spec.angle);
  if (spec.dir != Direction::Ccw) s << " --dir cw";
  if (spec.from_theta) {
    s << " --from-theta " << format_degrees(*spec.from_theta);
  } else {
    s << " --from " << plan.from.x << ',' << plan.from.y;
  }
  if (spec.to_theta) {
    s << " --to-theta " << format_degrees(*spec.to_theta);
  } else {
    s << " --to " << plan.to.x << ',' << plan.to.y;
  }
  return s.str();
}

}  // namespace dda
