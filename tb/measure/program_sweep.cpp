// SPDX-License-Identifier: Apache-2.0
// Accuracy sweep of arcs as part programs give them: lattice start and end
// points rounded from random points of the curve, full turns by point and by angle,
// aspect ratios up to 1000, half of the ellipses rotated, and lines; a, b log-uniform in
// [1, M], default width. Every case runs with half preload (the accuracy targets) and,
// every fourth case, with zero preload (reported). Per class: cases, refusals, the worst
// and mean distance of every path point from the ideal curve (a line: from the line between its ends)
// with the case that gave the worst, whether every path started and ended on its points
// (full turns: closed), and the share of the arcs' steps that ran in line pieces.
//   usage: program_sweep [--cases N] [--seed S] [--max-axis M] [--shard I/N] [--json FILE]
//          program_sweep --merge FILE...   (sum the shards' JSON, print the Markdown table)
// scripts/program-sweep.sh runs it in shards with GNU parallel and writes the table into
// docs/results.md. Every case draws from its own (seed, index) stream.
#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "host/accuracy/accuracy.hpp"
#include "host/accuracy/golden.hpp"
#include "tb/random/dda_random.hpp"

using namespace dda;

namespace {

constexpr const char* kClasses[] = {"line", "axis-aligned, aspect <= 4", "axis-aligned, aspect 4 to 1000",
                                    "rotated, aspect <= 4", "rotated, aspect 4 to 1000"};
constexpr int kNumClasses = 5;

struct Row {
  long cases = 0, refused = 0, full_point = 0, full_angle = 0, exact_ends = 0;
  double worst = 0, sum = 0;
  long points = 0;
  std::uint64_t steps = 0, line_steps = 0;
  std::string worst_case;
  void add(const Row& o) {
    cases += o.cases, refused += o.refused, full_point += o.full_point, full_angle += o.full_angle;
    exact_ends += o.exact_ends, sum += o.sum, points += o.points, steps += o.steps, line_steps += o.line_steps;
    if (!o.worst_case.empty() && (worst_case.empty() || o.worst > worst)) worst = o.worst, worst_case = o.worst_case;
  }
};

nlohmann::json to_json(const Row& r) {
  return {{"cases", r.cases},
          {"refused", r.refused},
          {"full_point", r.full_point},
          {"full_angle", r.full_angle},
          {"exact_ends", r.exact_ends},
          {"worst", r.worst},
          {"sum", r.sum},
          {"points", r.points},
          {"steps", r.steps},
          {"line_steps", r.line_steps},
          {"worst_case", r.worst_case}};
}
Row from_json(const nlohmann::json& j) {
  Row r;
  r.cases = j.at("cases"), r.refused = j.at("refused"), r.full_point = j.at("full_point");
  r.full_angle = j.at("full_angle"), r.exact_ends = j.at("exact_ends"), r.worst = j.at("worst");
  r.sum = j.at("sum"), r.points = j.at("points"), r.steps = j.at("steps"), r.line_steps = j.at("line_steps");
  r.worst_case = j.at("worst_case");
  return r;
}

int class_of(const Plan& p) {
  if (p.is_line()) return 0;
  const ArcGeometry& g = p.arc();
  const bool thin = std::max(g.spec.a, g.spec.b) > 4 * std::min(g.spec.a, g.spec.b);
  return (g.rotated ? 3 : 1) + (thin ? 1 : 0);
}

// Runs a plan, measuring every path point; returns whether it started and ended on its
// points (a full turn: back on its start).
bool measure(const Plan& p, Row& row) {
  const auto dev = [&](Point q) { return plan_distance(p, double(q.x), double(q.y)); };
  double worst = dev(p.from), sum = worst;
  long points = 1;
  Point end = p.from;
  bool joined = true;  // every piece starts where the previous one ended, and ends on its point
  for (const Piece& pc : p.pieces) {
    joined = joined && pc.from == end;
    Datapath dp(pc.cmd, end);
    Point last = end;
    while (!dp.done()) {
      dp.step();
      if (dp.pos() == last) continue;
      last = dp.pos();
      const double d = dev(last);
      worst = std::max(worst, d);
      sum += d;
      ++points;
      if (p.is_arc()) {
        ++row.steps;
        row.line_steps += pc.kind == PieceKind::Line;
      }
    }
    end = dp.pos();
    joined = joined && end == pc.to;
  }
  row.sum += sum;
  row.points += points;
  if (worst > row.worst || row.worst_case.empty()) {
    row.worst = std::max(row.worst, worst);
    row.worst_case = "dda path " + describe(p);
  }
  return joined && end == p.to && (!p.is_arc() || !p.arc().full || p.to == p.from);
}

Plan with_preload(const Plan& p, Preload pre) {
  if (p.is_line()) return plan_line(p.from, p.to, pre);
  ArcSpec s = p.arc().spec;
  s.preload = pre;
  return plan_arc(s);
}

void print_table(const Row (&half)[kNumClasses], const Row (&zero)[kNumClasses]) {
  std::printf(
      "| class | preload | cases | refused | full turns (by point / angle) | ends exact | worst (steps) | "
      "target | mean (steps) | steps in line pieces | worst case |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int z = 0; z < 2; ++z) {
    for (int c = 0; c < kNumClasses; ++c) {
      const Row& r = z ? zero[c] : half[c];
      const double mean = r.points ? r.sum / double(r.points) : 0.0;
      const double share = r.steps ? 100.0 * double(r.line_steps) / double(r.steps) : 0.0;
      std::printf(
          "| %s | %s | %ld | %ld | %ld / %ld | %ld of %ld | %.3f | %s | %.3f | %s | `%s` |\n", kClasses[c],
          z ? "zero" : "half", r.cases, r.refused, r.full_point, r.full_angle, r.exact_ends, r.cases, r.worst,
          z ? "(reported)"
            : fmt::format("{:.1f}", c == 0   ? kTargetLine
                                    : c == 1 ? kTargetAligned
                                             : kTargetOther)
                  .c_str(),
          mean,
          c == 0 ? "-" : (std::to_string(r.line_steps) + " (" + std::to_string(share).substr(0, 5) + "%)").c_str(),
          r.worst_case.c_str());
    }
  }
  Row arcs;
  for (int c = 1; c < kNumClasses; ++c) arcs.add(half[c]);
  std::printf(
      "\nHalf preload, all arcs: %llu steps, %llu of them (%.3f%%) in line pieces inside arcs (lead-in, "
      "lead-out, closing and anchoring lines, lines across sharp tips).\n",
      static_cast<unsigned long long>(arcs.steps), static_cast<unsigned long long>(arcs.line_steps),
      arcs.steps ? 100.0 * double(arcs.line_steps) / double(arcs.steps) : 0.0);
}

// The rows of every class, half and zero preload.
struct Rows {
  Row half[kNumClasses], zero[kNumClasses];
};

// Sums the shards' JSON files (--merge).
void merge_shards(const std::vector<std::string>& files, Rows& rows) {
  for (const auto& f : files) {
    std::ifstream in(f);
    if (!in) throw std::runtime_error("cannot read " + f);
    const auto j = nlohmann::json::parse(in);
    for (int c = 0; c < kNumClasses; ++c) {
      rows.half[c].add(from_json(j.at("half").at(c)));
      rows.zero[c].add(from_json(j.at("zero").at(c)));
    }
  }
}

// Draws and measures case i: with half preload, and every fourth case with zero preload
// too; a planner fault (GuardError) names the case and stops the sweep.
void run_case(long i, std::uint64_t seed, std::int64_t max_axis, Rows& rows) {
  RandomArcs gen(case_seed(seed, std::uint64_t(i)), max_axis, 8, ArcKind::Program);
  std::optional<Plan> drawn;
  try {
    drawn = gen.next();
  } catch (const GuardError& e) {
    throw std::runtime_error("case " + std::to_string(i) + " (dda path " + gen.drawn_options() + "): " + e.what());
  }
  if (!drawn) {  // refused (with the preload drawn): counted in the class drawn, half rows
    const auto k = gen.drawn();
    const int c =
        k == RandomArcs::Drawn::Line ? 0 : (k == RandomArcs::Drawn::Rotated ? 3 : 1) + (gen.drawn_thin() ? 1 : 0);
    ++rows.half[c].refused;
    return;
  }
  const int c = class_of(*drawn);
  for (int z = 0; z < (i % 4 == 0 ? 2 : 1); ++z) {
    Row& row = z ? rows.zero[c] : rows.half[c];
    try {
      const Plan p = with_preload(*drawn, z ? Preload::Zero : Preload::Half);
      ++row.cases;
      const bool full = p.is_arc() && p.arc().full, to_theta = p.is_arc() && p.arc().spec.to_theta;
      row.full_point += full && !to_theta;
      row.full_angle += full && to_theta;
      row.exact_ends += measure(p, row);
    } catch (const InputError&) {
      ++row.refused;
    } catch (const GuardError& e) {
      throw std::runtime_error("case " + std::to_string(i) + " (dda path " + describe(*drawn) + ", preload " +
                               (z ? "zero" : "half") + "): " + e.what());
    }
  }
}

// Writes the shard's totals (--json), for --merge.
void write_json(const std::string& file, const Rows& rows) {
  nlohmann::json j;
  j["half"] = nlohmann::json::array();
  j["zero"] = nlohmann::json::array();
  for (int c = 0; c < kNumClasses; ++c) {
    j["half"].push_back(to_json(rows.half[c]));
    j["zero"].push_back(to_json(rows.zero[c]));
  }
  std::ofstream out(file);
  out << j.dump(1) << '\n';
  if (!out) throw std::runtime_error("cannot write " + file);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"accuracy sweep of arcs as part programs give them"};
  long cases = 20000;
  std::uint64_t seed = 2026;
  std::int64_t max_axis = 32768;
  std::string shard_text = "0/1", json;
  std::vector<std::string> merge;
  app.add_option("--cases", cases, "number of cases (default 20000)")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "seed (default 2026)");
  app.add_option("--max-axis", max_axis, "largest semi-axis (default 32768)")->check(CLI::PositiveNumber);
  app.add_option("--shard", shard_text, "run only the cases I, I+N, ... (I/N)");
  app.add_option("--json", json, "write the shard's totals as JSON to FILE");
  app.add_option("--merge", merge, "sum the shards' JSON files and print the table");
  CLI11_PARSE(app, argc, argv);
  Rows rows;
  try {
    if (!merge.empty()) {
      merge_shards(merge, rows);
      print_table(rows.half, rows.zero);
      return 0;
    }
    const Shard shard = parse_shard(shard_text);
    for (long i = 0; i < cases; ++i) {
      if (shard.has(std::uint64_t(i))) run_case(i, seed, max_axis, rows);
    }
    if (!json.empty()) {
      write_json(json, rows);
    } else {
      print_table(rows.half, rows.zero);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "program_sweep: %s\n", e.what());
    return 1;
  }
  return 0;
}
