// SPDX-License-Identifier: Apache-2.0
// dda blocks: each motion block as the reader gives it, streamed (one row per block).
#include "cli/blocks/blocks_cmd.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <array>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/options/output.hpp"
#include "host/program/program.hpp"

namespace dda::cli {

namespace {

using program::Length;
using program::Move;

// A point of the move's plane (u, v) and the normal coordinate w as machine X, Y, Z in mm
// (the start's w for the start and the centre, the end's for the end).
std::array<double, 3> xyz(const Move& mv, program::Point2 p, Length w_nm) {
  const double u = double(p.u) / double(program::kNmPerMm), v = double(p.v) / double(program::kNmPerMm);
  const double w = double(w_nm) / double(program::kNmPerMm);
  if (mv.plane == 180) return {v, w, u};
  if (mv.plane == 190) return {w, u, v};
  return {u, v, w};
}

bool curved(const Move& mv) { return mv.kind != program::MoveKind::Rapid && mv.kind != program::MoveKind::Line; }

void write_json(std::ostream& os, const Move& mv) {
  nlohmann::ordered_json j;
  j["line"] = mv.pos.line;
  j["n"] = mv.block_number ? nlohmann::ordered_json(*mv.block_number) : nlohmann::ordered_json(nullptr);
  j["kind"] = std::string(program::kind_name(mv.kind));
  j["plane"] = mv.plane / 10;
  j["from"] = xyz(mv, mv.from, mv.w);
  j["to"] = xyz(mv, mv.to, mv.w_to);
  j["center"] = curved(mv) ? nlohmann::ordered_json(xyz(mv, mv.center, mv.w)) : nlohmann::ordered_json(nullptr);
  j["turns"] = curved(mv) ? mv.turns : 0;
  j["feed"] = mv.feed;
  os << j.dump() << '\n';
}

void write_text(std::ostream& os, const Move& mv) {
  const auto to = xyz(mv, mv.to, mv.w_to);
  os << fmt::format("{:>6} {:<11} X{:.4f} Y{:.4f} Z{:.4f}", mv.pos.line, program::kind_name(mv.kind), to[0], to[1],
                    to[2]);
  if (curved(mv)) {
    const auto c = xyz(mv, mv.center, mv.w);
    os << fmt::format("  centre X{:.4f} Y{:.4f} Z{:.4f}", c[0], c[1], c[2]);
    if (mv.turns > 1) os << fmt::format(" turns {}", mv.turns);
  }
  os << '\n';
}

}  // namespace

void add_blocks_options(CLI::App* sub, BlocksCli& b) {
  add_program_options(sub, b.prog);
  sub->add_option("--format", b.format, "text (default) or json (one object per line)");
  sub->add_option("--out", b.out, "write to FILE (atomically) instead of standard output");
}

void run_blocks(const BlocksCli& b) {
  if (b.format != "text" && b.format != "json") {
    throw InputError("format = '" + b.format + "' is invalid: use text or json");
  }
  if (!b.prog.given()) throw InputError("blocks needs --program FILE");
  const ProgramRun run = program_run(b.prog, Preload::Half, false);
  const auto in = program::open_program(b.prog.file);
  Output out(b.out);
  std::ostream& os = out.stream();
  const bool json = b.format == "json";
  if (!json) os << "  line kind        end (mm)\n";
  std::uint64_t count = 0;
  const program::ReadSummary s = program::read_stream(*in, run.file, run.read, [&](const Move& mv) {
    ++count;
    if (json) {
      write_json(os, mv);
    } else {
      write_text(os, mv);
    }
  });
  if (json) {
    nlohmann::ordered_json j;
    j["end"] = true;
    j["blocks"] = count;
    j["dialect"] = std::string(program::dialect_name(s.dialect));
    j["plane"] = s.plane / 10;
    j["ended"] = s.ended;
    j["ignored"] = s.ignored_count;
    os << j.dump() << '\n';
  } else {
    os << fmt::format("{} blocks; dialect {}; plane G{}; {} words that do not move the tool\n", count,
                      program::dialect_name(s.dialect), s.plane / 10, s.ignored_count);
  }
  out.commit();
}

}  // namespace dda::cli
