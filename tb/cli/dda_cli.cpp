// The `dda` command: trace, path and stats of an ellipse arc on any engine.
//
// Exit status: 0 success; 1 run-time failure (I/O error, guard tripped, cross-check
// mismatch); 2 bad usage or bad input. Every error is one line on stderr. Output goes
// to stdout, or with --out to a file written atomically (temporary file, then rename).
#include "dda_cli.hpp"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>

#include "dda/golden.hpp"
#include "dda/hw_params.hpp"
#include "dda/report.hpp"
#include "engines.hpp"

namespace dda::cli {

namespace {

std::int64_t parse_int(const std::string& name, const std::string& s, const char* rule) {
  std::int64_t v = 0;
  const char* b = s.data();
  const char* e = s.data() + s.size();
  auto [p, ec] = std::from_chars(b, e, v);
  if (s.empty() || ec != std::errc() || p != e) {
    throw InputError(name + " = '" + s + "' is invalid: " + rule);
  }
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
  std::string a, b, bits, preload = "zero", from, to, engine = "golden", out, format, vcd;
};

void add_arc_options(CLI::App* sub, ArcOptions& o, const std::string& formats,
                     const std::string& default_format) {
  o.format = default_format;
  sub->add_option("--a", o.a, "semi-axis along X (positive integer, steps)")->required();
  sub->add_option("--b", o.b, "semi-axis along Y (positive integer, steps)")->required();
  sub->add_option("--bits", o.bits, "accumulator width n: capacity 2^n, needs 2^n >= max(a,b)")
      ->required();
  sub->add_option("--preload", o.preload, "accumulator preload: zero (the paper) or half");
  sub->add_option("--from", o.from, "start lattice point X,Y (default a,0)");
  sub->add_option("--to", o.to, "end lattice point X,Y (default 0,b)");
  sub->add_option("--engine", o.engine, "engine: " + engine_names());
  sub->add_option("--format", o.format, formats + " (default " + default_format + ")");
  sub->add_option("--out", o.out, "write to FILE (atomically) instead of stdout");
  sub->add_option("--vcd", o.vcd, "write a waveform of the run to FILE (systemc, rtl engines)");
}

Plan make_plan(const ArcOptions& o) {
  ArcSpec s;
  const char* pos = "a semi-axis must be a positive integer";
  s.a = parse_int("a", o.a, pos);
  s.b = parse_int("b", o.b, pos);
  const std::int64_t bits = parse_int("bits", o.bits, "n must be an integer with 2^n >= max(a, b)");
  if (bits < 1 || bits > 61) {
    throw InputError("bits = " + o.bits + " is invalid: n must be between 1 and 61 and 2^n >= max(a, b)");
  }
  s.bits = static_cast<int>(bits);
  if (o.preload == "zero") {
    s.preload = Preload::Zero;
  } else if (o.preload == "half") {
    s.preload = Preload::Half;
  } else {
    throw InputError("preload = '" + o.preload + "' is invalid: use zero or half");
  }
  if (!o.from.empty()) s.from = parse_point("from", o.from);
  if (!o.to.empty()) s.to = parse_point("to", o.to);
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

// Writes to stdout, or to a temporary file renamed over FILE only once all went well.
class Output {
 public:
  explicit Output(std::string path) : path_(std::move(path)) {
    if (path_.empty()) return;
    tmp_ = path_ + ".tmp." + std::to_string(::getpid());
    file_.open(tmp_, std::ios::out | std::ios::trunc | std::ios::binary);
    if (!file_) {
      throw GuardError("cannot write '" + path_ + "': " + std::strerror(errno));
    }
  }
  ~Output() {
    if (!committed_ && !tmp_.empty()) {
      file_.close();
      std::remove(tmp_.c_str());
    }
  }
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;
  std::ostream& stream() { return path_.empty() ? std::cout : file_; }
  void commit() {
    if (path_.empty()) {
      std::cout.flush();
      if (!std::cout) throw GuardError("error writing to standard output");
      return;
    }
    file_.flush();
    file_.close();
    if (file_.fail()) throw GuardError("error writing '" + path_ + "'");
    if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
      throw GuardError("cannot rename to '" + path_ + "': " + std::strerror(errno));
    }
    committed_ = true;
  }

 private:
  std::string path_, tmp_;
  std::ofstream file_;
  bool committed_ = false;
};

std::vector<Iteration> run_engine(const ArcOptions& o, const Plan& plan) {
  const EngineFn fn = find_engine(o.engine);
  if (!fn) throw InputError("engine = '" + o.engine + "' is invalid: use one of " + engine_names());
  EngineOptions eo;
  eo.vcd = o.vcd;
  if (!o.vcd.empty() && o.engine == "golden") {
    throw InputError("--vcd is invalid with engine golden: the golden model has no waveform");
  }
  return fn(plan, eo);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dda: ellipse DDA interpolator (golden model, SystemC model, RTL)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("dda ") + DDA_VERSION);

  ArcOptions tr, pa, st;
  auto* trace = app.add_subcommand("trace", "per-iteration register trace");
  add_arc_options(trace, tr, "csv, table or json", "csv");
  auto* path = app.add_subcommand("path", "lattice points of the path");
  add_arc_options(path, pa, "csv or json", "csv");
  auto* stats = app.add_subcommand("stats", "counts and deviation from the ideal ellipse");
  add_arc_options(stats, st, "text or json", "text");
  std::string gp_kind = "verilog", gp_out;
  auto* gen = app.add_subcommand("gen-params", "print the hardware widths and command fields");
  gen->add_option("--kind", gp_kind, "verilog (rtl/dda_params.vh) or markdown (docs/design.md tables)");
  gen->add_option("--out", gp_out, "write to FILE (atomically) instead of stdout");

  try {
    if (argc > 1 && argv[1][0] != '-') {
      std::string names;
      bool known = false;
      for (const auto* sub : app.get_subcommands({})) {
        names += (names.empty() ? "" : ", ") + sub->get_name();
        known = known || sub->get_name() == argv[1];
      }
      if (!known) throw InputError(std::string("command '") + argv[1] + "' is unknown: use one of " + names);
    }
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
      for (auto& ch : msg) if (ch == '\n') ch = ' ';
      std::cerr << "dda: error: " << msg << " (see dda --help)\n";
      return 2;
    }

    if (trace->parsed()) {
      const auto fmt = parse_enum<TraceFormat>(
          "format", tr.format,
          {{"csv", TraceFormat::Csv}, {"table", TraceFormat::Table}, {"json", TraceFormat::Json}});
      const Plan plan = make_plan(tr);
      const auto iters = run_engine(tr, plan);
      Output out(tr.out);
      write_trace(out.stream(), plan, iters, fmt);
      out.commit();
    } else if (path->parsed()) {
      const auto fmt = parse_enum<PathFormat>("format", pa.format,
                                              {{"csv", PathFormat::Csv}, {"json", PathFormat::Json}});
      const Plan plan = make_plan(pa);
      const auto iters = run_engine(pa, plan);
      Output out(pa.out);
      write_path(out.stream(), path_points(plan, iters), fmt);
      out.commit();
    } else if (stats->parsed()) {
      const auto fmt = parse_enum<StatsFormat>("format", st.format,
                                               {{"text", StatsFormat::Text}, {"json", StatsFormat::Json}});
      const Plan plan = make_plan(st);
      const auto iters = run_engine(st, plan);
      Output out(st.out);
      write_stats(out.stream(), plan, compute_stats(plan, iters), fmt);
      out.commit();
    } else if (gen->parsed()) {
      const bool verilog = parse_enum<bool>("kind", gp_kind, {{"verilog", true}, {"markdown", false}});
      Output out(gp_out);
      out.stream() << (verilog ? hw::verilog_header() : hw::markdown_tables());
      out.commit();
    }
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
