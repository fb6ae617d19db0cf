// SPDX-License-Identifier: Apache-2.0
// The options every arc command shares (the geometry, the engine, the output) and how
// they become a plan; the number parsers every option goes through ("out of range",
// "is invalid": exit status 2).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "cli/options/program_cmd.hpp"
#include "host/planner/planner.hpp"
#include "model/datapath/errors.hpp"

namespace CLI {
class App;
}

namespace dda::cli {

// An integer option (InputError naming it and `rule` when it is not one).
std::int64_t parse_int(const std::string& name, const std::string& s, const char* rule);
// An integer option within [lo, hi]: "out of range" outside it.
std::int64_t parse_int_in(const std::string& name, const std::string& s, std::int64_t lo, std::int64_t hi);
Point parse_point(const std::string& name, const std::string& s);
Preload parse_preload(const std::string& v);

struct ArcOptions {
  bool line = false;
  std::string a, b, bits, preload = "half", from, to, from_theta, to_theta, center, dir = "ccw", angle,
                          engine = "golden", out, format, vcd;
  ProgramCli prog;  // --program FILE and its options
};

// Which of the run options a command takes besides the geometry (its --help lists only
// those; any other is refused, naming the command).
struct ArcUses {
  bool engine = true, vcd = true, out = true, format = true, program = true;
  std::string vcd_help = "write a waveform of the run to FILE (systemc, rtl engines)";
};

// The arc options on `sub`: the geometry, and the run options `uses` names.
void add_arc_options(CLI::App* sub, ArcOptions& o, const std::string& formats, const std::string& default_format,
                     ArcUses uses = {});

// --program excludes the arc's options, and its own options need it (InputError).
void check_program_options(const ArcOptions& o);

// The plan of the options given: an arc, a line, or (vectors) a part program's commands.
Plan make_plan(const ArcOptions& o);

// Parses options as a user writes them ({"--a", "10", ...}) into `app`'s options: a
// CLI11 parse error is an InputError with CLI11's message.
void parse_args(CLI::App& app, const std::vector<std::string>& args);

// The plan of the arc options (and --program with its options) written as for the `dda`
// command: the command's parsing and messages, for the Python module and the DPI-C
// functions. InputError for a bad option.
Plan plan_from_args(const std::vector<std::string>& args);

// One of the names of `m` (InputError listing them).
template <typename E>
E parse_enum(const std::string& name, const std::string& v, const std::map<std::string, E>& m) {
  const auto it = m.find(v);
  if (it != m.end()) return it->second;
  std::string allowed;
  for (const auto& [k, _] : m) allowed += (allowed.empty() ? "" : ", ") + k;
  throw InputError(name + " = '" + v + "' is invalid: use one of " + allowed);
}

}  // namespace dda::cli
