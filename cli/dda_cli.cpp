// SPDX-License-Identifier: Apache-2.0
// The `dda` command: trace, path and stats of an ellipse arc on any engine.
//
// Exit status: 0 success; 1 run-time failure (I/O error, guard tripped, cross-check
// mismatch); 2 bad usage or bad input. Every error is one line on stderr. Output goes
// to stdout, or with --out to a file written atomically (temporary file, then rename).
#include "cli/dda_cli.hpp"

#include <fmt/format.h>
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

#include "cli/blocks/blocks_cmd.hpp"
#include "cli/engines.hpp"
#include "cli/entries/entries_cmd.hpp"
#include "cli/gen_params_cmd.hpp"
#include "cli/options/arc_options.hpp"
#include "cli/options/output.hpp"
#include "cli/options/program_cmd.hpp"
#include "cli/options/temp_files.hpp"
#include "cli/pace_cmd.hpp"
#include "cli/run_cmd.hpp"
#include "cli/speed_cmd.hpp"
#include "cli/vectors.hpp"
#include "cli/vectors_cmd.hpp"
#include "host/accuracy/golden.hpp"
#include "host/pipeline/pipeline.hpp"
#include "host/program/program.hpp"
#include "host/report/feed_report.hpp"
#include "host/report/program_report.hpp"
#include "host/report/report.hpp"
#include "host/speed/pace_plan.hpp"
#include "model/datapath/hw_command.hpp"
#include "model/datapath/hw_params.hpp"
#include "model/motion/build.hpp"
#include "model/motion/motion_map.hpp"
#include "model/motion/motion_model.hpp"
#include "tb/measure/pace_report.hpp"

namespace dda::cli {

namespace {

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
    prun->third_axis = moves_third_axis(o.prog.file, *prun);
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

// The options of `dda feed` besides the arc's.
struct FeedCli {
  ArcOptions arc;
  bool summary = false;
  std::string label = "arc";
  PaceCli pace;
};

// The options of `dda gen-params`.
// Every subcommand's options, as the command line fills them in.
struct Cli {
  ArcOptions trace, path, stats, plot;
  SpeedCli stats_speed;
  std::string plot_view = "xy";
  std::string plot_speed;  // --speed FILE.svg
  CLI::Option* plot_speed_opt = nullptr;
  PaceCli plot_pace;
  SpeedCli plot_speed_limits;
  VectorsCli vectors;
  FeedCli feed;
  GenParamsCli gen_params;
  BlocksCli blocks;
  RunCli run;
  EntriesCli entries;
  std::string build = "";  // `dda build SPEC`
};

void set_up_trace(CLI::App* sub, Cli& c) { add_arc_options(sub, c.trace, "csv, table or json", "csv"); }

void set_up_path(CLI::App* sub, Cli& c) { add_arc_options(sub, c.path, "csv or json", "csv"); }

void set_up_stats(CLI::App* sub, Cli& c) {
  add_arc_options(sub, c.stats, "text or json (and csv with --program)", "text");
  add_speed_options(sub, c.stats_speed);
}

void set_up_vectors(CLI::App* sub, Cli& c) { add_vectors_options(sub, c.vectors); }

void set_up_feed(CLI::App* sub, Cli& c) {
  ArcUses uses;
  uses.engine = uses.vcd = uses.program = false;  // the planner's table of one arc
  add_arc_options(sub, c.feed.arc, "markdown, or csv (one row per iteration) with --feed-rate", "markdown", uses);
  sub->add_flag("--summary", c.feed.summary, "one row for the arc (the table of docs/results.md)");
  sub->add_option("--label", c.feed.label, "the arc's name in the --summary row (default: empty)");
  add_pace_options(sub, c.feed.pace);
}

void set_up_plot(CLI::App* sub, Cli& c) {
  add_arc_options(sub, c.plot, "svg", "svg");
  sub->add_option("--view", c.plot_view,
                  "xy (default: the plane of the two ellipse axes), xz or yz: the third axis against x or y");
  c.plot_speed_opt =
      sub->add_option("--speed", c.plot_speed,
                      "FILE.svg: the pacer's reference model run on the arc (--feed-rate, --accel, --clock), its speed "
                      "against the path length with the feed and the ideal trapezoid (--out: the path too, optional)");
  add_pace_options(sub, c.plot_pace);
  add_speed_options(sub, c.plot_speed_limits, false, false);
}

void set_up_gen_params(CLI::App* sub, Cli& c) { add_gen_params_options(sub, c.gen_params); }

void run_trace(const Cli& c, int, char**) {
  const auto fmt =
      parse_enum<TraceFormat>("format", c.trace.format,
                              {{"csv", TraceFormat::Csv}, {"table", TraceFormat::Table}, {"json", TraceFormat::Json}});
  run_arc_command(c.trace, [&](std::ostream& os, const RunTarget& t) {
    return t.plan ? std::make_unique<TraceSink>(os, *t.plan, fmt)
                  : std::make_unique<TraceSink>(os, t.program->lattice.preload, t.from(), fmt, t.program->third_axis);
  });
}

void run_path(const Cli& c, int, char**) {
  const auto fmt =
      parse_enum<PathFormat>("format", c.path.format, {{"csv", PathFormat::Csv}, {"json", PathFormat::Json}});
  run_arc_command(c.path, [&](std::ostream& os, const RunTarget& t) {
    return std::make_unique<PathSink>(os, t.from(), fmt, t.plan ? third_axis(*t.plan) : t.program->third_axis);
  });
}

void run_stats(const Cli& c, int, char**) {
  using program::BlockStatsFormat;
  const auto fmt = parse_enum<BlockStatsFormat>(
      "format", c.stats.format,
      {{"text", BlockStatsFormat::Text}, {"csv", BlockStatsFormat::Csv}, {"json", BlockStatsFormat::Json}});
  if (fmt == BlockStatsFormat::Csv && !c.stats.prog.given()) throw InputError("--format csv goes with --program");
  if (c.stats_speed.wanted()) return run_speed_report(c.stats, c.stats_speed);
  run_arc_command(c.stats, [&](std::ostream& os, const RunTarget& t) -> std::unique_ptr<RunSink> {
    if (t.program) {
      return std::make_unique<program::BlockStatsSink>(
          os, t.program->lattice, t.program->read.start.value_or(program::Point2{}), fmt, t.program->third_axis);
    }
    return std::make_unique<StatsSink>(*t.plan, &os,
                                       fmt == program::BlockStatsFormat::Json ? StatsFormat::Json : StatsFormat::Text);
  });
}

void run_vectors(const Cli& c, int argc, char** argv) { run_vectors(c.vectors, argc, argv); }

void run_feed(const Cli& c, int, char**) {
  const FeedCli& f = c.feed;
  const ArcOptions& fd = f.arc;
  const bool paced = f.pace.paced();
  const int format = parse_enum<int>("format", fd.format, {{"markdown", 0}, {"csv", 1}});
  if (!paced && f.pace.any_given()) throw InputError("--accel, --clock and --vmin go with --feed-rate");
  if (!paced && format == 1)
    throw InputError("--format csv is the pacer's profile: give --feed-rate, --accel, --clock");
  const PaceOptions po = paced ? pace_options(f.pace) : PaceOptions{};
  if (paced && format == 1 && f.summary) throw InputError("--summary is a markdown row: not with --format csv");
  const Plan plan = make_plan(fd);
  if (paced) check_followable(plan, po);
  Output out(fd.out);
  if (!paced) {
    write_feed_report(out.stream(), plan, f.summary, f.label);
  } else if (format == 1) {
    write_pace_csv(out.stream(), plan, po);
  } else {
    write_pace_report(out.stream(), plan, po, f.summary, f.label);
  }
  out.commit();
}

// The plot's title: the command line without --out FILE, escaped as XML text.
std::string plot_title(int argc, char** argv) {
  std::string title = "dda";
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--out") == 0 || std::strcmp(argv[i], "--speed") == 0) {
      ++i;  // not part of the arc
      continue;
    }
    title += std::string(" ") + argv[i];
  }
  std::string esc;
  for (const char ch : title) esc += ch == '&' ? "&amp;" : ch == '<' ? "&lt;" : ch == '>' ? "&gt;" : std::string(1, ch);
  return esc;
}

// `dda plot --speed FILE.svg --feed-rate ...`: the pacer's run on one arc or line.
void run_speed_plot(const Cli& c, const std::string& title) {
  const ArcOptions& pl = c.plot;
  check_svg_name("speed", c.plot_speed);
  if (pl.prog.given()) {
    if (c.plot_pace.feed_opt->count() || c.plot_pace.vmin_opt->count())
      throw InputError(
          "--feed-rate and --vmin are an arc's, in steps: a program's feeds come from its F words "
          "(the minimum speed from the machine's limits)");
    if (!pl.out.empty() || c.plot_view != "xy")
      throw InputError("--speed with --program draws the speed alone: leave --out and --view out");
    const double clock = c.plot_pace.clock_opt->count() ? c.plot_pace.clock_hz : 40e6;
    return run_program_speed_plot(pl, c.plot_speed_limits, c.plot_speed,
                                  c.plot_pace.accel_opt->count() ? &c.plot_pace.accel : nullptr, clock, title);
  }
  if (c.plot_speed_limits.any_given())
    throw InputError(
        "--machine-config, --junction-deviation, --rapid, --default-feed, --min-speed and --window go with --program");
  if (!c.plot_pace.paced()) throw InputError("--speed runs the pacer: give --feed-rate, --accel, --clock");
  if (pl.out.empty() && (pl.engine != "golden" || !pl.vcd.empty() || c.plot_view != "xy"))
    throw InputError("--engine, --vcd and --view go with --out (the path's picture): --speed runs the reference model");
  if (!pl.out.empty() && std::filesystem::weakly_canonical(pl.out) == std::filesystem::weakly_canonical(c.plot_speed))
    throw InputError("--speed and --out name the same file '" + pl.out + "': the two pictures need two files");
  const PaceOptions po = pace_options(c.plot_pace);
  const Plan plan = make_plan(pl);
  check_followable(plan, po);
  Output out(c.plot_speed);
  write_speed_svg(out.stream(), plan, po, title);
  out.commit();
}

void run_plot(const Cli& c, int argc, char** argv) {
  const ArcOptions& pl = c.plot;
  parse_enum<int>("format", pl.format, {{"svg", 0}});
  const bool speed = c.plot_speed_opt->count() > 0;
  if (!speed && c.plot_pace.any_given())
    throw InputError("--feed-rate, --accel, --clock and --vmin go with --speed FILE.svg");
  if (!speed && c.plot_speed_limits.any_given())
    throw InputError(
        "--machine-config, --junction-deviation, --rapid, --default-feed, --min-speed and --window go with --speed");
  if (!speed && (pl.out.empty() || pl.out == "-"))
    throw InputError("plot needs --out FILE.svg: it writes a picture, not text");
  if (!pl.out.empty()) check_svg_name("out", pl.out);
  const View view = parse_enum<View>("view", c.plot_view, {{"xy", View::XY}, {"xz", View::XZ}, {"yz", View::YZ}});
  const std::string esc = plot_title(argc, argv);
  if (speed) {
    run_speed_plot(c, esc);
    if (pl.out.empty()) return;
  }
  run_arc_command(pl, [&](std::ostream& os, const RunTarget& t) -> std::unique_ptr<RunSink> {
    if (t.program) {
      return std::make_unique<program::ProgramSvgSink>(os, t.program->lattice,
                                                       t.program->read.start.value_or(program::Point2{}), esc, view);
    }
    return std::make_unique<SvgSink>(os, *t.plan, esc, view);
  });
}

void run_gen_params(const Cli& c, int, char**) { run_gen_params(c.gen_params); }

void set_up_build(CLI::App* sub, Cli& c) {
  sub->add_option(
      "spec", c.build,
      "the choices, key=value separated by commas (model/motion/build.hpp; empty: the default build): " + [] {
        std::string keys;
        for (const auto& p : motion::kBuildParams)
          keys += fmt::format("{}{} ({} .. {}: {})", keys.empty() ? "" : ", ", p.key, p.min, p.max, p.meaning);
        return keys;
      }());
}

// The RTL parameters of a build, a line `NAME VALUE` each (scripts/synth sets the same).
void run_build(const Cli& c, int, char**) {
  for (const auto& [name, value] : motion::rtl_params(motion::parse_build(c.build))) fmt::print("{} {}\n", name, value);
}

void set_up_blocks(CLI::App* sub, Cli& c) { add_blocks_options(sub, c.blocks); }

void run_blocks(const Cli& c, int, char**) { run_blocks(c.blocks); }

void set_up_run(CLI::App* sub, Cli& c) { add_run_options(sub, c.run); }

void set_up_entries(CLI::App* sub, Cli& c) { add_entries_options(sub, c.entries); }

void run_entries(const Cli& c, int, char**) { run_entries(c.entries); }

void run_run(const Cli& c, int, char**) { run_run(c.run); }

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
    {"feed",
     "the DDA's speed along the path at a constant feed increment, per piece; with --feed-rate the pacer's run: "
     "speed profile and figures",
     set_up_feed, run_feed},
    {"plot", "SVG picture of the path over the ideal ellipse (--out FILE.svg)", set_up_plot, run_plot},
    {"gen-params", "print the hardware widths and command fields", set_up_gen_params, run_gen_params},
    {"build", "the motion block's RTL parameters for a build (key=value,...; docs/design.md \"Builds\")", set_up_build,
     run_build},
    {"blocks", "the motion blocks a part program reads as, in machine coordinates (--program FILE)", set_up_blocks,
     run_blocks},
    {"entries", "each piece's block-entry words (27 a piece: ENTRY + 4k, then CTRL.commit)", set_up_entries,
     run_entries},
    {"run", "run a part program live on a motion block (PROGRAM --port sim; exit statuses in --help)", set_up_run,
     run_run},
};

// The first argument must be a command (or --help, -h, --version): an option before
// the command, or a command not known, is refused naming the commands.
void check_command_word(CLI::App& app, int argc, char** argv) {
  if (argc > 1 && argv[1][0] == '-' && std::strcmp(argv[1], "--help") != 0 && std::strcmp(argv[1], "-h") != 0 &&
      std::strcmp(argv[1], "--version") != 0) {
    throw InputError(
        std::string("option '") + argv[1] +
        "' is unknown here: options follow a command (trace, path, stats, plot, vectors, gen-params, build, blocks)");
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

// An argument the command does not take: an option of another command is refused naming
// this one (and why, where that is not plain), any other as unknown.
[[noreturn]] void refuse_extra(const CLI::App& app, const CLI::App& sub, const std::string& arg) {
  static const std::map<std::pair<std::string, std::string>, std::string> kWhy = {
      {{"feed", "--engine"}, "the planner computes the table"},
      {{"feed", "--vcd"}, "the table runs no engine"},
      {{"feed", "--program"}, "the feed table is one arc's"},
      {{"vectors", "--engine"}, "vectors come from the golden model"},
      {{"vectors", "--out"}, "a vector set is written to --out-dir DIR"},
  };
  const std::string cmd = sub.get_name(), opt = arg.substr(0, arg.find('='));
  const std::string see = " (dda " + cmd + " --help lists its options)";
  if (opt.empty() || opt[0] != '-') throw InputError("'" + arg + "' is unexpected: dda " + cmd + " takes options only");
  for (const CLI::App* other : app.get_subcommands({})) {
    if (other->get_option_no_throw(opt) == nullptr) continue;
    const auto why = kWhy.find({cmd, opt});
    throw InputError(opt + " is invalid with " + cmd + (why != kWhy.end() ? ": " + why->second : see));
  }
  throw InputError("option " + opt + " is unknown" + see);
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
    subs.back()->allow_extras();  // refused after the parse, naming the command (refuse_extra)
    s.set_up(subs.back(), options);
  }

  try {
    check_command_word(app, argc, argv);
    if (const std::optional<int> status = parse_command_line(app, argc, argv)) return *status;
    for (std::size_t i = 0; i < subs.size(); ++i) {
      if (subs[i]->parsed()) {
        if (!subs[i]->remaining().empty()) refuse_extra(app, *subs[i], subs[i]->remaining().front());
        kSubcommands[i].run(options, argc, argv);
        break;
      }
    }
  } catch (const ExitStatus& e) {
    return e.status();  // (its message said)
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
