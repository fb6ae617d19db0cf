// SPDX-License-Identifier: Apache-2.0
// The `dda` command: trace, path and stats of an ellipse arc on any engine.
//
// Exit status: 0 success; 1 run-time failure (I/O error, guard tripped, cross-check
// mismatch); 2 bad usage or bad input. Every error is one line on stderr. Output goes
// to stdout, or with --out to a file written atomically (temporary file, then rename).
#include "dda_cli.hpp"

#include <unistd.h>
#include <CLI/CLI.hpp>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "accuracy/golden.hpp"
#include "datapath/hw_command.hpp"
#include "datapath/hw_params.hpp"
#include "engines.hpp"
#include "feed_report.hpp"
#include "motion/motion_map.hpp"
#include "motion/motion_model.hpp"
#include "output.hpp"
#include "pipeline/pipeline.hpp"
#include "program/program.hpp"
#include "program_cmd.hpp"
#include "report/program_report.hpp"
#include "report/report.hpp"
#include "temp_files.hpp"
#include "vectors.hpp"

namespace dda::cli {

namespace {

std::int64_t parse_int(const std::string& name, const std::string& s, const char* rule) {
  std::int64_t v = 0;
  const char* b = s.data();
  const char* e = s.data() + s.size();
  auto [p, ec] = std::from_chars(b, e, v);
  if (!s.empty() && ec == std::errc::result_out_of_range && p == e) {
    throw InputError(name + " = '" + s + "' is out of range: " + rule);
  }
  if (s.empty() || ec != std::errc() || p != e) {
    throw InputError(name + " = '" + s + "' is invalid: " + rule);
  }
  return v;
}

// An integer option within [lo, hi]: "out of range" outside it.
std::int64_t parse_int_in(const std::string& name, const std::string& s, std::int64_t lo, std::int64_t hi) {
  const std::string rule = "an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
  const std::int64_t v = parse_int(name, s, rule.c_str());
  if (v < lo || v > hi) throw InputError(name + " = '" + s + "' is out of range: " + rule);
  return v;
}

Point parse_point(const std::string& name, const std::string& s) {
  const char* rule = "a point is two integers X,Y";
  const auto comma = s.find(',');
  if (comma == std::string::npos) throw InputError(name + " = '" + s + "' is invalid: " + rule);
  try {
    return Point{parse_int(name, s.substr(0, comma), rule), parse_int(name, s.substr(comma + 1), rule)};
  } catch (const InputError&) {
    throw InputError(name + " = '" + s + "' is invalid: " + rule);
  }
}

struct ArcOptions {
  bool line = false;
  std::string a, b, bits, preload = "half", from, to, from_theta, to_theta, center, dir = "ccw", angle,
                          engine = "golden", out, format, vcd;
  ProgramCli prog;  // --program FILE and its options
};

void add_arc_options(CLI::App* sub, ArcOptions& o, const std::string& formats, const std::string& default_format) {
  o.format = default_format;
  sub->add_flag("--line", o.line,
                "a straight line from --from to --to through the same core (constant integrands; with half "
                "preload Bresenham's line); takes no ellipse option");
  sub->add_option("--a", o.a, "semi-axis a (positive integer, steps; required for an ellipse)");
  sub->add_option("--b", o.b, "semi-axis b (positive integer, steps; required for an ellipse)");
  sub->add_option("--bits", o.bits,
                  "accumulator width n: capacity 2^n, needs 2^n >= max(a,b) "
                  "(default: smallest valid + 4)");
  sub->add_option("--preload", o.preload,
                  "accumulator preload: half (default: the accurate mode) or zero (the paper's mode)");
  sub->add_option("--center", o.center, "centre lattice point X,Y (default 0,0)");
  sub->add_option("--angle", o.angle,
                  "turn the ellipse counter-clockwise by DEG degrees about its centre, so the "
                  "semi-axis a points in direction DEG (decimal, up to 6 decimals; multiples of 90 use "
                  "the exact integer datapath, other angles fixed-point coefficients)");
  sub->add_option("--dir", o.dir, "direction: ccw (default) or cw");
  sub->add_option("--from", o.from,
                  "start lattice point X,Y (default: centre + (semi-axis along X, 0); turned by a "
                  "non-multiple of 90 degrees: parametric angle 0)");
  sub->add_option("--to", o.to,
                  "end lattice point X,Y (default: a quarter turn on, parametric angle 90 when turned); "
                  "equal to --from: a full ellipse");
  sub->add_option("--from-theta", o.from_theta,
                  "start at parametric angle DEG: half preload starts on the ideal curve point (nearest "
                  "lattice point, the rest in the preloads), zero preload at the lattice point just "
                  "outside it (docs/golden-model.md)");
  sub->add_option("--to-theta", o.to_theta,
                  "end at parametric angle DEG, rounded to the lattice as --from-theta; equal to "
                  "--from-theta: a full ellipse");
  sub->add_option("--engine", o.engine, "engine: " + engine_names());
  sub->add_option("--format", o.format, formats + " (default " + default_format + ")");
  sub->add_option("--out", o.out, "write to FILE (atomically) instead of stdout");
  sub->add_option("--vcd", o.vcd, "write a waveform of the run to FILE (systemc, rtl engines)");
  add_program_options(sub, o.prog);
}

Preload parse_preload(const std::string& v) {
  if (v == "zero") return Preload::Zero;
  if (v == "half") return Preload::Half;
  throw InputError("preload = '" + v + "' is invalid: use zero or half");
}

Plan make_line(const ArcOptions& o) {
  for (const auto& [name, v] :
       {std::pair{"a", &o.a}, std::pair{"b", &o.b}, std::pair{"bits", &o.bits}, std::pair{"center", &o.center},
        std::pair{"angle", &o.angle}, std::pair{"from-theta", &o.from_theta}, std::pair{"to-theta", &o.to_theta}}) {
    if (!v->empty())
      throw InputError(std::string("--") + name + " is invalid with --line: a line takes --from and --to");
  }
  if (o.dir != "ccw") throw InputError("--dir is invalid with --line: a line runs from --from to --to");
  if (o.from.empty() || o.to.empty()) throw InputError("--line needs --from X,Y and --to X,Y");
  return plan_line(parse_point("from", o.from), parse_point("to", o.to), parse_preload(o.preload));
}

// --program excludes the arc's options; its own options need it.
void check_program_options(const ArcOptions& o) {
  if (!o.prog.given()) {
    if (o.prog.machine != "mill" || !o.prog.start.empty() || o.prog.step != "0.001") {
      throw InputError("--machine, --start and --step go with --program FILE");
    }
    return;
  }
  if (o.line) throw InputError("--line is invalid with --program: the program gives the geometry");
  for (const auto& [name, v] :
       {std::pair{"a", &o.a}, std::pair{"b", &o.b}, std::pair{"bits", &o.bits}, std::pair{"center", &o.center},
        std::pair{"angle", &o.angle}, std::pair{"from", &o.from}, std::pair{"to", &o.to},
        std::pair{"from-theta", &o.from_theta}, std::pair{"to-theta", &o.to_theta}}) {
    if (!v->empty()) {
      throw InputError(std::string("--") + name + " is invalid with --program: the program gives the geometry");
    }
  }
  if (o.dir != "ccw") throw InputError("--dir is invalid with --program: the program gives the geometry");
}

Plan make_plan(const ArcOptions& o) {
  check_program_options(o);
  // (Only `vectors` plans a program here: the hardware runs its commands.)
  if (o.prog.given()) return load_program(o.prog, parse_preload(o.preload), true).plan;
  if (o.line) return make_line(o);
  if (o.a.empty() || o.b.empty()) {
    throw InputError(std::string("--") + (o.a.empty() ? "a" : "b") +
                     " is required: an ellipse needs --a and --b (or give --line)");
  }
  ArcSpec s;
  const char* pos = "a semi-axis must be a positive integer";
  s.a = parse_int("a", o.a, pos);
  s.b = parse_int("b", o.b, pos);
  if (!o.bits.empty()) {
    const std::int64_t bits = parse_int("bits", o.bits, "n must be an integer with 2^n >= max(a, b)");
    if (bits < 1 || bits > 61) {
      throw InputError("bits = " + o.bits + " is invalid: n must be between 1 and 61 and 2^n >= max(a, b)");
    }
    s.bits = static_cast<int>(bits);
  }
  s.preload = parse_preload(o.preload);
  if (o.dir == "ccw") {
    s.dir = Direction::Ccw;
  } else if (o.dir == "cw") {
    s.dir = Direction::Cw;
  } else {
    throw InputError("dir = '" + o.dir + "' is invalid: use ccw or cw");
  }
  if (!o.center.empty()) s.center = parse_point("center", o.center);
  if (!o.angle.empty()) s.angle = parse_degrees("angle", o.angle);
  if (!o.from.empty() && !o.from_theta.empty()) {
    throw InputError("from and from-theta are both given: choose one");
  }
  if (!o.to.empty() && !o.to_theta.empty()) throw InputError("to and to-theta are both given: choose one");
  if (!o.from.empty()) s.from = parse_point("from", o.from);
  if (!o.from_theta.empty()) s.from_theta = parse_degrees("from-theta", o.from_theta);
  if (!o.to.empty()) s.to = parse_point("to", o.to);
  if (!o.to_theta.empty()) s.to_theta = parse_degrees("to-theta", o.to_theta);
  return plan_arc(s);
}

template <typename E>
E parse_enum(const std::string& name, const std::string& v, const std::map<std::string, E>& m) {
  const auto it = m.find(v);
  if (it != m.end()) return it->second;
  std::string allowed;
  for (const auto& [k, _] : m) allowed += (allowed.empty() ? "" : ", ") + k;
  throw InputError(name + " = '" + v + "' is invalid: use one of " + allowed);
}

// What a command makes of its run: a report over the stream, for one arc or line
// (`plan`) or for a part program (`program`: its run's options).
struct RunTarget {
  const Plan* plan = nullptr;
  const ProgramRun* program = nullptr;
  Point from() const {
    return plan ? plan->from
                : program::on_lattice(program->read.start.value_or(program::Point2{}), program->lattice.step);
  }
};

// Plans the arc (or opens the program), runs it through the chosen engine into the
// command's report (make_sink), and commits the output and the waveform only once
// everything succeeded.
template <typename MakeSink>
void run_arc_command(const ArcOptions& o, MakeSink make_sink) {
  if (!known_engine(o.engine)) throw InputError("engine = '" + o.engine + "' is invalid: use one of " + engine_names());
  if (!o.vcd.empty() && o.engine == "golden") {
    throw InputError("--vcd is invalid with engine golden: the golden model has no waveform");
  }
  if (!o.vcd.empty() && !o.out.empty()) {
    std::error_code e1, e2;
    if (std::filesystem::weakly_canonical(o.vcd, e1) == std::filesystem::weakly_canonical(o.out, e2)) {
      throw InputError("--vcd and --out name the same file '" + o.out + "': they must differ");
    }
  }
  if (!o.vcd.empty()) {
    std::error_code ec;
    const auto st = std::filesystem::status(o.vcd, ec);
    if (!ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st)) {
      throw InputError("vcd = '" + o.vcd + "' is invalid: a waveform is written to a regular file");
    }
  }
  check_program_options(o);
  const bool hardware = o.engine != "golden";
  std::optional<ProgramRun> prun;
  std::unique_ptr<std::istream> in;
  std::optional<Plan> plan;
  if (o.prog.given()) {
    prun = program_run(o.prog, parse_preload(o.preload), hardware);
    in = program::open_program(o.prog.file);
  } else {
    plan = make_plan(o);
    // (A command too wide for the hardware is refused before anything runs.)
    if (hardware)
      for (const Piece& pc : plan->pieces) hw::pack_command(pc.cmd);
  }
  Output out(o.out);  // both files are opened before the run: a bad path fails fast
  AtomicFile wave(o.vcd);
  EngineOptions eo;
  eo.vcd = wave.write_path();
  const RunTarget target{plan ? &*plan : nullptr, prun ? &*prun : nullptr};
  const std::unique_ptr<RunSink> sink = make_sink(out.stream(), target);
  const std::unique_ptr<Engine> engine = make_engine(o.engine, eo, *sink);
  if (prun) {
    run_program(*in, *prun, *engine, *sink);
  } else {
    run_plan(*plan, *engine, *sink);
  }
  out.commit();
  wave.commit();
}

// The options of `dda vectors` besides the arc's.
struct VectorsCli {
  ArcOptions arc;
  std::string out_dir, seed = "1", ce_percent = "100";
  std::vector<std::string> then;  // further arcs, each its options in one string
  vec::BusCli bus;
};

// The options of `dda feed` besides the arc's.
struct FeedCli {
  ArcOptions arc;
  bool summary = false;
  std::string label = "arc";
};

// The options of `dda gen-params`.
struct GenParamsCli {
  std::string kind = "verilog", out;
  int acc_width = hw::kAccWidth, cnt_width = hw::kCntWidth;
};

// Every subcommand's options, as the command line fills them in.
struct Cli {
  ArcOptions trace, path, stats, plot;
  VectorsCli vectors;
  FeedCli feed;
  GenParamsCli gen_params;
};

void set_up_trace(CLI::App* sub, Cli& c) { add_arc_options(sub, c.trace, "csv, table or json", "csv"); }

void set_up_path(CLI::App* sub, Cli& c) { add_arc_options(sub, c.path, "csv or json", "csv"); }

void set_up_stats(CLI::App* sub, Cli& c) { add_arc_options(sub, c.stats, "text or json", "text"); }

void set_up_vectors(CLI::App* sub, Cli& c) {
  VectorsCli& v = c.vectors;
  add_arc_options(sub, v.arc, "hex (with CSV and a JSON manifest)", "hex");
  sub->add_option("--out-dir", v.out_dir, "directory of the vector set (written atomically)");
  sub->add_option("--then", v.then, "\"ARC OPTIONS\" of a further arc run back to back (repeatable)");
  sub->add_option("--seed", v.seed, "seed of the ce pattern (default 1)");
  sub->add_option("--ce-percent", v.ce_percent, "chance in percent that ce_i is high on a cycle (default 100)");
  vec::add_bus_options(sub, v.bus);
}

void set_up_feed(CLI::App* sub, Cli& c) {
  add_arc_options(sub, c.feed.arc, "markdown", "markdown");
  sub->add_flag("--summary", c.feed.summary, "one row for the arc (the table of docs/results.md)");
  sub->add_option("--label", c.feed.label, "the arc's name in the --summary row");
}

void set_up_plot(CLI::App* sub, Cli& c) { add_arc_options(sub, c.plot, "svg", "svg"); }

void set_up_gen_params(CLI::App* sub, Cli& c) {
  GenParamsCli& g = c.gen_params;
  sub->add_option(
      "--kind", g.kind,
      "verilog (rtl/dda_params.vh), markdown (docs/design.md tables), json (the widths and "
      "the largest semi-axis they hold at the default width), vector-fields "
      "(tb/hdl/dda_vec_fields.vh), gtkw-systemc or gtkw-rtl (docs/dda_*.gtkw), registers (the "
      "architectural registers and their widths: scripts/formal.sh), motion-markdown, motion-c or "
      "motion-verilog (the motion block's register map: docs/design.md, fw/dda_motion_regs.h, "
      "rtl/dda_motion_regs.vh), motion-vector-fields (tb/hdl/dda_bus_vec_fields.vh), stepdir-diagram, gtkw-motion "
      "(docs/dda_motion.gtkw)");
  sub->add_option("--out", g.out, "write to FILE (atomically) instead of stdout");
  sub->add_option("--acc-width", g.acc_width,
                  "--kind verilog, json or registers at another accumulator width (formal proofs, scripts/synth --acc)")
      ->check(CLI::Range(4, hw::kAccWidth));
  sub->add_option("--cnt-width", g.cnt_width, "--kind verilog, json or registers at another counter width")
      ->check(CLI::Range(2, hw::kCntWidth));
}

void run_trace(const Cli& c, int, char**) {
  const auto fmt =
      parse_enum<TraceFormat>("format", c.trace.format,
                              {{"csv", TraceFormat::Csv}, {"table", TraceFormat::Table}, {"json", TraceFormat::Json}});
  run_arc_command(c.trace, [&](std::ostream& os, const RunTarget& t) {
    return t.plan ? std::make_unique<TraceSink>(os, *t.plan, fmt)
                  : std::make_unique<TraceSink>(os, t.program->lattice.preload, t.from(), fmt);
  });
}

void run_path(const Cli& c, int, char**) {
  const auto fmt =
      parse_enum<PathFormat>("format", c.path.format, {{"csv", PathFormat::Csv}, {"json", PathFormat::Json}});
  run_arc_command(c.path,
                  [&](std::ostream& os, const RunTarget& t) { return std::make_unique<PathSink>(os, t.from(), fmt); });
}

void run_stats(const Cli& c, int, char**) {
  using program::BlockStatsFormat;
  const auto fmt = parse_enum<BlockStatsFormat>(
      "format", c.stats.format,
      {{"text", BlockStatsFormat::Text}, {"csv", BlockStatsFormat::Csv}, {"json", BlockStatsFormat::Json}});
  if (fmt == BlockStatsFormat::Csv && !c.stats.prog.given()) throw InputError("--format csv goes with --program");
  run_arc_command(c.stats, [&](std::ostream& os, const RunTarget& t) -> std::unique_ptr<RunSink> {
    if (t.program) {
      return std::make_unique<program::BlockStatsSink>(os, t.program->lattice,
                                                       t.program->read.start.value_or(program::Point2{}), fmt);
    }
    return std::make_unique<StatsSink>(*t.plan, &os,
                                       fmt == program::BlockStatsFormat::Json ? StatsFormat::Json : StatsFormat::Text);
  });
}

// The vector set's options: the seed and ce pattern checked, and the command line as
// given (for the manifest; an argument with a space quoted).
vec::Options vector_options(const VectorsCli& v, int argc, char** argv) {
  vec::Options vo;
  vo.out_dir = v.out_dir;
  vo.seed = std::uint64_t(parse_int_in("seed", v.seed, 0, std::numeric_limits<std::int64_t>::max()));
  vo.ce_percent = int(parse_int_in("ce-percent", v.ce_percent, 1, 100));
  vo.command_line = "dda";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    vo.command_line += a.find(' ') == std::string::npos ? " " + a : " \"" + a + "\"";
  }
  return vo;
}

// The plans of the vector set: the arc (or program) given, then each --then arc.
std::vector<Plan> vector_plans(const VectorsCli& v) {
  std::vector<Plan> plans{make_plan(v.arc)};
  if (v.arc.prog.given() && !v.then.empty())
    throw InputError("--then is invalid with --program: one program is one run");
  for (const std::string& then : v.then) {
    CLI::App sub{"arc"};
    ArcOptions o;
    add_arc_options(&sub, o, "", "");
    try {
      sub.parse(then, false);
    } catch (const CLI::ParseError& e) {
      throw InputError("then = '" + then + "' is invalid: " + e.what());
    }
    plans.push_back(make_plan(o));
  }
  return plans;
}

void run_vectors(const Cli& c, int argc, char** argv) {
  const VectorsCli& v = c.vectors;
  parse_enum<int>("format", v.arc.format, {{"hex", 0}});
  if (v.out_dir.empty()) throw InputError("vectors needs --out-dir DIR");
  if (v.arc.engine != "golden")
    throw InputError("engine = '" + v.arc.engine + "' is invalid for vectors: they come from the golden model");
  if (!v.arc.out.empty() || (!v.arc.vcd.empty() && !v.bus.bus)) {
    throw InputError("vectors write --out-dir DIR, not --out (nor --vcd, but with --bus: the RTL's waveform)");
  }
  const vec::Options vo = vector_options(v, argc, argv);
  const std::vector<Plan> plans = vector_plans(v);
  if (v.bus.bus) {
    vec::BusOptions bo = vec::bus_options(v.bus);
    AtomicFile wave(v.arc.vcd);  // the RTL run beside the set: written only on success
    bo.vcd = wave.write_path();
    vec::write_bus_vector_set(plans, vo, bo);
    wave.commit();
  } else {
    vec::bus_options(v.bus);  // refuses the bus options without --bus
    vec::write_vector_set(plans, vo);
  }
}

void run_feed(const Cli& c, int, char**) {
  const ArcOptions& fd = c.feed.arc;
  parse_enum<int>("format", fd.format, {{"markdown", 0}});
  if (fd.prog.given()) throw InputError("--program is invalid with feed: the feed table is one arc's");
  if (fd.engine != "golden") throw InputError("--engine is invalid with feed: the planner computes the table");
  if (!fd.vcd.empty()) throw InputError("--vcd is invalid with feed: the table runs no engine");
  const Plan plan = make_plan(fd);
  Output out(fd.out);
  write_feed_report(out.stream(), plan, c.feed.summary, c.feed.label);
  out.commit();
}

// The plot's title: the command line without --out FILE, escaped as XML text.
std::string plot_title(int argc, char** argv) {
  std::string title = "dda";
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--out") == 0) {
      ++i;  // not part of the arc
      continue;
    }
    title += std::string(" ") + argv[i];
  }
  std::string esc;
  for (const char ch : title) esc += ch == '&' ? "&amp;" : ch == '<' ? "&lt;" : ch == '>' ? "&gt;" : std::string(1, ch);
  return esc;
}

void run_plot(const Cli& c, int argc, char** argv) {
  const ArcOptions& pl = c.plot;
  parse_enum<int>("format", pl.format, {{"svg", 0}});
  if (pl.out.empty() || pl.out == "-") throw InputError("plot needs --out FILE.svg: it writes a picture, not text");
  std::string ext = std::filesystem::path(pl.out).extension().string();
  for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  if (!ext.empty() && ext != ".svg") {
    throw InputError("out = '" + pl.out + "' is invalid: plot writes SVG (a file name ending in .svg)");
  }
  const std::string esc = plot_title(argc, argv);
  run_arc_command(pl, [&](std::ostream& os, const RunTarget& t) -> std::unique_ptr<RunSink> {
    if (t.program) {
      return std::make_unique<program::ProgramSvgSink>(os, t.program->lattice,
                                                       t.program->read.start.value_or(program::Point2{}), esc);
    }
    return std::make_unique<SvgSink>(os, *t.plan, esc);
  });
}

// What gen-params prints (--kind).
enum class GenKind {
  Verilog,
  Markdown,
  Json,
  VectorFields,
  GtkwSystemc,
  GtkwRtl,
  Registers,
  MotionMarkdown,
  MotionC,
  MotionVerilog,
  MotionVectorFields,
  GtkwMotion,
  StepdirDiagram,
};

// The text of one kind, at the accumulator and counter widths acc and cnt.
void write_gen_params(std::ostream& os, GenKind kind, int acc, int cnt) {
  switch (kind) {
    case GenKind::Verilog:
      os << hw::verilog_header(acc, cnt);
      break;
    case GenKind::Markdown:
      os << hw::markdown_tables();
      break;
    case GenKind::Json: {
      nlohmann::ordered_json j;
      j["acc_width"] = acc;
      j["cnt_width"] = cnt;
      j["cmd_width"] = hw::cmd_width(acc, cnt);
      j["max_semi_axis"] = hw::max_semi_axis(4, acc, cnt);  // default width: smallest valid + 4
      os << j.dump(1) << '\n';
      break;
    }
    case GenKind::VectorFields:
      os << vec::verilog_fields();
      break;
    case GenKind::GtkwSystemc:  // the waveforms' scopes: dda --engine systemc|rtl --vcd
      os << hw::gtkw(hw::signal_table(), "dda_systemc.gtkw", "SystemC");
      break;
    case GenKind::GtkwRtl:
      os << hw::gtkw(hw::signal_table(), "dda_rtl.gtkw", "dut.dda_core");
      break;
    case GenKind::Registers:  // the architectural registers: "name width" (scripts/formal.sh)
      for (const auto& r : hw::kSignals) {
        if (r.kind == hw::SigKind::Reg) os << r.name << ' ' << hw::field_width(r.width, acc, cnt) << '\n';
      }
      break;
    case GenKind::MotionMarkdown:  // the motion block's register map
      os << motion::markdown();
      break;
    case GenKind::MotionC:
      os << motion::c_header();
      break;
    case GenKind::MotionVerilog:
      os << motion::verilog_header();
      break;
    case GenKind::MotionVectorFields:  // the bus bench's field table
      os << vec::bus_verilog_fields();
      break;
    case GenKind::GtkwMotion:  // the motion block's waveform: dda vectors --bus --vcd
      os << motion::gtkw("dda_motion.gtkw", "dut.dda_motion", motion::kMaxDepthLog2);
      break;
    case GenKind::StepdirDiagram:  // the step/dir stage's edge-by-edge diagram (docs/design.md)
      os << motion::stage_diagram();
      break;
  }
}

void run_gen_params(const Cli& c, int, char**) {
  const GenParamsCli& g = c.gen_params;
  const GenKind kind = parse_enum<GenKind>("kind", g.kind,
                                           {{"verilog", GenKind::Verilog},
                                            {"markdown", GenKind::Markdown},
                                            {"json", GenKind::Json},
                                            {"vector-fields", GenKind::VectorFields},
                                            {"gtkw-systemc", GenKind::GtkwSystemc},
                                            {"gtkw-rtl", GenKind::GtkwRtl},
                                            {"registers", GenKind::Registers},
                                            {"motion-markdown", GenKind::MotionMarkdown},
                                            {"motion-c", GenKind::MotionC},
                                            {"motion-verilog", GenKind::MotionVerilog},
                                            {"motion-vector-fields", GenKind::MotionVectorFields},
                                            {"gtkw-motion", GenKind::GtkwMotion},
                                            {"stepdir-diagram", GenKind::StepdirDiagram}});
  const bool sized = kind == GenKind::Verilog || kind == GenKind::Json || kind == GenKind::Registers;
  if (!sized && (g.acc_width != hw::kAccWidth || g.cnt_width != hw::kCntWidth)) {
    throw InputError("--acc-width and --cnt-width go with --kind verilog, json or registers only");
  }
  Output out(g.out);
  write_gen_params(out.stream(), kind, g.acc_width, g.cnt_width);
  out.commit();
}

// The subcommands, in the order of the help: each one's options set up, and its run
// once the command line is parsed (argc and argv: the command line, for records of it).
struct Subcommand {
  const char* name;
  const char* help;
  void (*set_up)(CLI::App* sub, Cli& c);
  void (*run)(const Cli& c, int argc, char** argv);
};
const Subcommand kSubcommands[] = {
    {"trace", "per-iteration register trace", set_up_trace, run_trace},
    {"path", "lattice points of the path", set_up_path, run_path},
    {"stats", "counts and deviation from the ideal ellipse", set_up_stats, run_stats},
    {"vectors", "test vectors from the golden model (--out-dir DIR; docs/vectors.md)", set_up_vectors, run_vectors},
    {"feed", "the DDA's speed along the path at a constant feed increment, per piece", set_up_feed, run_feed},
    {"plot", "SVG picture of the path over the ideal ellipse (--out FILE.svg)", set_up_plot, run_plot},
    {"gen-params", "print the hardware widths and command fields", set_up_gen_params, run_gen_params},
};

// The first argument must be a command (or --help, -h, --version): an option before
// the command, or a command not known, is refused naming the commands.
void check_command_word(CLI::App& app, int argc, char** argv) {
  if (argc > 1 && argv[1][0] == '-' && std::strcmp(argv[1], "--help") != 0 && std::strcmp(argv[1], "-h") != 0 &&
      std::strcmp(argv[1], "--version") != 0) {
    throw InputError(std::string("option '") + argv[1] +
                     "' is unknown here: options follow a command (trace, path, stats, plot, vectors, gen-params)");
  }
  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const auto* sub : app.get_subcommands({})) {
      names += (names.empty() ? "" : ", ") + sub->get_name();
      known = known || sub->get_name() == argv[1];
    }
    if (!known) throw InputError(std::string("command '") + argv[1] + "' is unknown: use one of " + names);
  }
}

// Parses the command line. Returns the exit status when that ends the run: help or the
// version printed, or a usage error (one line on stderr, status 2).
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    for (auto& ch : msg)
      if (ch == '\n') ch = ' ';
    std::cerr << "dda: error: " << msg << " (see dda --help)\n";
    return 2;
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  install_signal_cleanup();  // a run ended by a signal leaves no temporary file
  CLI::App app{"dda: ellipse DDA interpolator (golden model, SystemC model, RTL)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("dda ") + DDA_VERSION);
  Cli options;
  std::vector<CLI::App*> subs;
  for (const Subcommand& s : kSubcommands) {
    subs.push_back(app.add_subcommand(s.name, s.help));
    s.set_up(subs.back(), options);
  }

  try {
    check_command_word(app, argc, argv);
    if (const std::optional<int> status = parse_command_line(app, argc, argv)) return *status;
    for (std::size_t i = 0; i < subs.size(); ++i) {
      if (subs[i]->parsed()) {
        kSubcommands[i].run(options, argc, argv);
        break;
      }
    }
  } catch (const program::ProgramError& e) {
    std::cerr << e.what() << '\n';  // FILE:LINE:COLUMN: message, as compilers print
    return 2;
  } catch (const InputError& e) {
    std::cerr << "dda: error: " << e.what() << '\n';
    return 2;
  } catch (const GuardError& e) {
    std::cerr << "dda: error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "dda: error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

}  // namespace dda::cli
