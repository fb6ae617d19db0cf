// SPDX-License-Identifier: Apache-2.0
// The options every arc command shares, and how they become a plan (arc_options.hpp).
#include "cli/options/arc_options.hpp"

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <limits>
#include <utility>

#include "cli/options/engine_names.hpp"
#include "host/geometry/fixed_trig.hpp"

namespace dda::cli {

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

// A line's end: X,Y, or X,Y,Z with the third axis.
Point parse_point3(const std::string& name, const std::string& s) {
  const auto last = s.rfind(',');
  if (last == std::string::npos || s.find(',') == last) return parse_point(name, s);
  const char* rule = "a line's point is two or three integers X,Y or X,Y,Z";
  try {
    Point p = parse_point(name, s.substr(0, last));
    p.z = parse_int(name, s.substr(last + 1), rule);
    return p;
  } catch (const InputError&) {
    throw InputError(name + " = '" + s + "' is invalid: " + rule);
  }
}

void add_arc_options(CLI::App* sub, ArcOptions& o, const std::string& formats, const std::string& default_format,
                     ArcUses uses) {
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
                  "start lattice point X,Y (with --line also X,Y,Z: the third axis; default: centre + (semi-axis along "
                  "X, 0); turned by a "
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
  if (uses.engine) sub->add_option("--engine", o.engine, "engine: " + engine_names() + " (default golden)");
  if (uses.format) sub->add_option("--format", o.format, formats + " (default " + default_format + ")");
  if (uses.out) sub->add_option("--out", o.out, "write to FILE (atomically; - or none: standard output)");
  if (uses.vcd) sub->add_option("--vcd", o.vcd, uses.vcd_help);
  if (uses.program) add_program_options(sub, o.prog);
}

Preload parse_preload(const std::string& v) {
  if (v == "zero") return Preload::Zero;
  if (v == "half") return Preload::Half;
  throw InputError("preload = '" + v + "' is invalid: use zero or half");
}

namespace {

Plan make_line(const ArcOptions& o) {
  for (const auto& [name, v] :
       {std::pair{"a", &o.a}, std::pair{"b", &o.b}, std::pair{"bits", &o.bits}, std::pair{"center", &o.center},
        std::pair{"angle", &o.angle}, std::pair{"from-theta", &o.from_theta}, std::pair{"to-theta", &o.to_theta}}) {
    if (!v->empty())
      throw InputError(std::string("--") + name + " is invalid with --line: a line takes --from and --to");
  }
  if (o.dir != "ccw") throw InputError("--dir is invalid with --line: a line runs from --from to --to");
  if (o.from.empty() || o.to.empty()) throw InputError("--line needs --from X,Y and --to X,Y");
  return plan_line(parse_point3("from", o.from), parse_point3("to", o.to), parse_preload(o.preload));
}

}  // namespace

// --program excludes the arc's options; its own options need it.
void check_program_options(const ArcOptions& o) {
  if (!o.prog.given()) {
    if (o.prog.machine != "mill" || !o.prog.start.empty() || o.prog.step != "0.001") {
      throw InputError("--machine, --start and --step go with --program FILE");
    }
    if (!o.prog.dialect.empty() || o.prog.block_delete || !o.prog.subroutine_path.empty()) {
      throw InputError("--dialect, --block-delete and --subroutine-path go with --program FILE");
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

void parse_args(CLI::App& app, const std::vector<std::string>& args) {
  app.allow_extras();
  try {
    app.parse(std::vector<std::string>(args.rbegin(), args.rend()));  // CLI11 takes them last first
  } catch (const CLI::ParseError& e) {
    throw InputError(e.what());
  }
  for (const std::string& arg : app.remaining()) {
    if (arg.empty() || arg[0] != '-') throw InputError("'" + arg + "' is unexpected: only options are taken");
    throw InputError("option " + arg.substr(0, arg.find('=')) + " is unknown");
  }
}

Plan plan_from_args(const std::vector<std::string>& args) {
  CLI::App app{"dda arc options"};
  ArcOptions o;
  ArcUses uses;
  uses.engine = uses.vcd = uses.out = uses.format = false;
  add_arc_options(&app, o, "", "", uses);
  parse_args(app, args);
  return make_plan(o);
}

}  // namespace dda::cli
