// Writes the golden model's expected values for the Icarus bench tb/icarus/dda_core_tb.v.
//
//   usage: gen_core_vectors --a 10 --b 6 --bits 4 [--preload zero|half]
//                           [--from X,Y] [--to X,Y] --out-dir DIR
//
// Files (all read with $readmemh; lines starting with // are comments):
//   DIR/cmd.hex     the command word (dda::hw::pack_command), DDA_CMD_WIDTH bits as one
//                   hex number, most significant digit first.
//   DIR/count.hex   the number of iterations, one hex number.
//   DIR/expect.hex  one line per iteration: every architectural register after that
//                   iteration, as one wide hex number.
//
// expect.hex layout: the 21 registers of dda::hw::kRegisters (the design doc's register
// table) in table order, the first one leftmost (most significant). Each field is
// zero-padded to a whole number of hex digits (width rounded up to a multiple of 4) and
// fields are separated by '_' (allowed inside a $readmemh number). With AccWidth = 51 and
// CntWidth = 17, left to right (digits):
//   u_int_x.jv_q(13) u_int_x.jr_q(13) u_int_x.inc_on_x_q(13) u_int_x.inc_on_y_q(13)
//   u_int_y.jv_q(13) u_int_y.jr_q(13) u_int_y.inc_on_x_q(13) u_int_y.inc_on_y_q(13)
//   u_cnt_x.cnt_q(5) u_cnt_y.cnt_q(5) cap_q(13) cdir_x_q(1) cdir_y_q(1) dir_x_q(1)
//   dir_y_q(1) step_x_q(1) step_y_q(1) u_ctrl.state_q(1) u_ctrl.done_q(1) u_ctrl.err_q(1)
//   u_ctrl.iter_q(1)
// = 149 hex digits, 596 bits. The bench builds the same word from the RTL registers.
//
// jv, jr and cnt come from the golden record (Iteration::after), step_* from
// Iteration::step_*; the registers loaded once per command (corrections, cap, cdir_*)
// from the fields of plan.cmd(). dir_*_q change only with a step of their axis (they
// take cdir_*_q then) and are 0 from reset: dir_x_q is the command's dir_x once any X
// step has happened in the run up to and including this iteration, else 0 (Y alike).
// Control after an iteration (rtl/dda_ctrl.v): iter_q = 1, err_q = 0, and done_q = 1
// with state_q = idle when both counters are 0 after the iteration (the bench loads no
// second command), otherwise done_q = 0 with state_q = run.
//
// Exit status: 0 success, 1 run-time failure (guard tripped, I/O error), 2 bad input.
#include <CLI/CLI.hpp>
#include <array>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "dda/golden.hpp"
#include "dda/hw_command.hpp"
#include "dda/hw_params.hpp"

namespace {

using dda::GuardError;
using dda::InputError;

dda::Point parse_point(const std::string& name, const std::string& s) {
  const auto comma = s.find(',');
  dda::Point p;
  auto num = [&](std::string_view t, std::int64_t& v) {
    auto [q, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    return !t.empty() && ec == std::errc() && q == t.data() + t.size();
  };
  const std::string_view sv(s);
  if (comma == std::string::npos || !num(sv.substr(0, comma), p.x) || !num(sv.substr(comma + 1), p.y)) {
    throw InputError(name + " = '" + s + "' is invalid: a point is two integers X,Y");
  }
  return p;
}

std::string hex(std::uint64_t v, int digits) {
  static const char* kDigits = "0123456789abcdef";
  std::string s(static_cast<std::size_t>(digits), '0');
  for (int i = digits - 1; i >= 0; --i, v >>= 4) s[static_cast<std::size_t>(i)] = kDigits[v & 0xf];
  return s;
}

int hex_digits(int width) { return (width + 3) / 4; }

void write_file(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!f) throw GuardError("cannot write '" + path + "': " + std::strerror(errno));
  f << text;
  f.close();
  if (!f) throw GuardError("cannot write '" + path + "': " + std::strerror(errno));
}

// The command word as hex, most significant digit first (pack_command is LSB-first words).
std::string command_hex(const dda::Command& c) {
  const auto words = dda::hw::pack_command(c);
  const int digits = hex_digits(dda::hw::kCmdWidth);
  std::string s;
  for (int d = digits - 1; d >= 0; --d) {
    const int bit = 4 * d;  // a digit never straddles two 32-bit words
    s += "0123456789abcdef"[(words[static_cast<std::size_t>(bit / 32)] >> (bit % 32)) & 0xf];
  }
  return s;
}

using Fields = std::array<std::uint64_t, dda::hw::kCmdFields.size()>;

// The value of command field `name` (kCmdFields order, as command_fields returns them).
std::uint64_t field(const Fields& f, std::string_view name) {
  for (std::size_t i = 0; i < dda::hw::kCmdFields.size(); ++i) {
    if (dda::hw::kCmdFields[i].name == name) return f[i];
  }
  throw GuardError("no command field " + std::string(name) + " in hw_params.hpp");
}

// X and Y steps seen so far in the run (this iteration included): dir_*_q is 0 until
// the first step of its axis.
struct StepsSeen {
  bool x = false, y = false;
};

// One expect.hex line: the registers after iteration `it`, in kRegisters order.
std::string expect_line(const dda::Iteration& it, const Fields& f, const StepsSeen& seen) {
  using dda::hw::kAccMask;
  const bool last = it.after.cnt_x == 0 && it.after.cnt_y == 0;
  const auto idle = static_cast<std::uint64_t>(dda::hw::State::Idle);
  const auto run = static_cast<std::uint64_t>(dda::hw::State::Run);
  const auto acc = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & kAccMask; };
  const auto cnt = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & dda::hw::kCntMax; };
  const std::map<std::string_view, std::uint64_t> value{
      {"u_int_x.jv_q", acc(it.after.jv_x)},
      {"u_int_x.jr_q", acc(it.after.jr_x)},
      {"u_int_x.inc_on_x_q", field(f, "inc_x_on_x")},
      {"u_int_x.inc_on_y_q", field(f, "inc_x_on_y")},
      {"u_int_y.jv_q", acc(it.after.jv_y)},
      {"u_int_y.jr_q", acc(it.after.jr_y)},
      {"u_int_y.inc_on_x_q", field(f, "inc_y_on_x")},
      {"u_int_y.inc_on_y_q", field(f, "inc_y_on_y")},
      {"u_cnt_x.cnt_q", cnt(it.after.cnt_x)},
      {"u_cnt_y.cnt_q", cnt(it.after.cnt_y)},
      {"cap_q", field(f, "cap")},
      {"cdir_x_q", field(f, "dir_x")},
      {"cdir_y_q", field(f, "dir_y")},
      {"dir_x_q", seen.x ? field(f, "dir_x") : 0u},
      {"dir_y_q", seen.y ? field(f, "dir_y") : 0u},
      {"step_x_q", it.step_x ? 1u : 0u},
      {"step_y_q", it.step_y ? 1u : 0u},
      {"u_ctrl.state_q", last ? idle : run},
      {"u_ctrl.done_q", last ? 1u : 0u},
      {"u_ctrl.err_q", 0},
      {"u_ctrl.iter_q", 1},
  };
  std::string line;
  for (const auto& r : dda::hw::kRegisters) {
    const auto v = value.find(r.name);
    if (v == value.end()) {
      throw GuardError("gen_core_vectors does not know register " + std::string(r.name) +
                       " of hw_params.hpp: update expect_line() and the bench");
    }
    if (!line.empty()) line += '_';
    line += hex(v->second, hex_digits(r.width));
  }
  return line;
}

int run_main(int argc, char** argv) {
  dda::ArcSpec spec;
  std::string preload = "zero", from, to, out_dir;
  CLI::App app{"gen_core_vectors: golden expected values for the Icarus bench of dda_core"};
  app.add_option("--a", spec.a, "semi-axis along X (positive integer)")->required();
  app.add_option("--b", spec.b, "semi-axis along Y (positive integer)")->required();
  app.add_option("--bits", spec.bits, "accumulator width n (2^n >= max(a, b))")->required();
  app.add_option("--preload", preload, "accumulator preload: zero (the paper) or half");
  app.add_option("--from", from, "start lattice point X,Y (default a,0)");
  app.add_option("--to", to, "end lattice point X,Y (default 0,b)");
  app.add_option("--out-dir", out_dir, "directory for cmd.hex, expect.hex, count.hex (must exist)")
      ->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  if (preload == "zero") {
    spec.preload = dda::Preload::Zero;
  } else if (preload == "half") {
    spec.preload = dda::Preload::Half;
  } else {
    throw InputError("preload = '" + preload + "' is invalid: use zero or half");
  }
  if (!from.empty()) spec.from = parse_point("from", from);
  if (!to.empty()) spec.to = parse_point("to", to);

  const dda::Plan plan = dda::plan_arc(spec);
  if (plan.segs.size() != 1) {
    std::fprintf(stderr, "gen_core_vectors: the arc has %zu pieces; this bench runs one command\n",
                 plan.segs.size());
    return 2;
  }
  const auto fields = dda::hw::command_fields(plan.cmd());  // throws if a value does not fit
  const auto records = dda::run_records(plan);

  std::ostringstream what;
  what << "a=" << spec.a << " b=" << spec.b << " bits=" << spec.bits << " preload=" << preload
       << " from=(" << plan.from.x << ',' << plan.from.y << ") to=(" << plan.to.x << ','
       << plan.to.y << ')';

  std::ostringstream cmd;
  cmd << "// cmd.hex: " << what.str() << "; DDA_CMD_WIDTH = " << dda::hw::kCmdWidth
      << " bits, most significant digit first\n"
      << command_hex(plan.cmd()) << '\n';

  std::ostringstream exp;
  exp << "// expect.hex: " << what.str() << "; registers after each iteration, one line each\n"
      << "// fields left to right (hex digits):";
  for (const auto& r : dda::hw::kRegisters) exp << ' ' << r.name << '(' << hex_digits(r.width) << ')';
  exp << '\n';
  StepsSeen seen;
  for (const auto& it : records) {
    seen.x = seen.x || it.step_x;
    seen.y = seen.y || it.step_y;
    exp << expect_line(it, fields, seen) << '\n';
  }

  std::ostringstream count;
  count << hex(records.size(), 8) << '\n';

  write_file(out_dir + "/cmd.hex", cmd.str());
  write_file(out_dir + "/expect.hex", exp.str());
  write_file(out_dir + "/count.hex", count.str());
  std::cout << "gen_core_vectors: " << what.str() << ": " << records.size() << " iterations -> "
            << out_dir << '\n';
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run_main(argc, argv);
  } catch (const InputError& e) {
    std::cerr << "gen_core_vectors: error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "gen_core_vectors: error: " << e.what() << '\n';
    return 1;
  }
}
