// SPDX-License-Identifier: Apache-2.0
#include "tb/random/regress.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/datapath/hw_params.hpp"
#include "tb/random/dda_random.hpp"

namespace dda {

int MixedStats::pairs_covered() const {
  int n = 0;
  for (const auto& s : quadrant_pairs) {
    for (const auto& e : s) n += (e[0] > 0) + (e[1] > 0);
  }
  return n;
}

void MixedStats::add(const MixedStats& o) {
  arcs += o.arcs;
  iterations += o.iterations;
  cycles += o.cycles;
  ce_stalled += o.ce_stalled;
  resets += o.resets;
  pieces += o.pieces;
  line_pieces += o.line_pieces;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 2; ++k) quadrant_pairs[i][j][k] += o.quadrant_pairs[i][j][k];
  full += o.full;
  circles += o.circles;
  turned += o.turned;
  rotated += o.rotated;
  thin += o.thin;
  lines += o.lines;
  program += o.program;
  spatial += o.spatial;
  refused += o.refused;
}

namespace {

nlohmann::json to_json(const MixedStats& st) {
  nlohmann::json j;
  j["arcs"] = st.arcs;
  j["iterations"] = st.iterations;
  j["cycles"] = st.cycles;
  j["ce_stalled"] = st.ce_stalled;
  j["resets"] = st.resets;
  j["pieces"] = st.pieces;
  j["line_pieces"] = st.line_pieces;
  nlohmann::json q = nlohmann::json::array();
  for (const auto& s : st.quadrant_pairs)
    for (const auto& e : s)
      for (const long v : e) q.push_back(v);
  j["quadrant_pairs"] = q;
  for (const auto& [k, v] :
       {std::pair{"full", st.full}, std::pair{"circles", st.circles}, std::pair{"turned", st.turned},
        std::pair{"rotated", st.rotated}, std::pair{"thin", st.thin}, std::pair{"lines", st.lines},
        std::pair{"program", st.program}, std::pair{"spatial", st.spatial}, std::pair{"refused", st.refused}}) {
    j[k] = v;
  }
  return j;
}

MixedStats from_json(const nlohmann::json& j) {
  MixedStats st;
  st.arcs = j.at("arcs");
  st.iterations = j.at("iterations");
  st.cycles = j.at("cycles");
  st.ce_stalled = j.at("ce_stalled");
  st.resets = j.at("resets");
  st.pieces = j.at("pieces");
  st.line_pieces = j.at("line_pieces");
  const auto& q = j.at("quadrant_pairs");
  int n = 0;
  for (auto& s : st.quadrant_pairs)
    for (auto& e : s)
      for (long& v : e) v = q.at(std::size_t(n++));
  for (auto [k, v] :
       {std::pair{"full", &st.full}, std::pair{"circles", &st.circles}, std::pair{"turned", &st.turned},
        std::pair{"rotated", &st.rotated}, std::pair{"thin", &st.thin}, std::pair{"lines", &st.lines},
        std::pair{"program", &st.program}, std::pair{"spatial", &st.spatial}, std::pair{"refused", &st.refused}}) {
    *v = j.at(k);
  }
  return st;
}

void print(const char* name, const std::string& what, const MixedStats& st) {
  std::printf(
      "%s regression: %s: %ld arcs in %llu pieces (%llu line pieces; %llu with ce stalls, %llu reset "
      "mid-arc), %llu iterations and %llu cycles compared, 0 mismatches\n",
      name, what.c_str(), st.arcs, static_cast<unsigned long long>(st.pieces),
      static_cast<unsigned long long>(st.line_pieces), static_cast<unsigned long long>(st.ce_stalled),
      static_cast<unsigned long long>(st.resets), static_cast<unsigned long long>(st.iterations),
      static_cast<unsigned long long>(st.cycles));
  std::printf(
      "coverage: %d of 32 (start quadrant, end quadrant, direction) combinations, %ld full "
      "ellipses, %ld circles, %ld turned by 90 or 270 degrees, %ld rotated by other angles, %ld "
      "with aspect ratio > 100, %ld lines, %ld arcs with lattice ends as programs give them, %ld moves "
      "of the third axis; %ld draws refused by the planner\n",
      st.pairs_covered(), st.full, st.circles, st.turned, st.rotated, st.thin, st.lines, st.program, st.spatial,
      st.refused);
}

}  // namespace

MixedStats run_mixed(CoreHarness& h, std::uint64_t seed, long cases, Shard shard) {
  reset_core(h);
  MixedStats st;
  for (long i = 0; i < cases; ++i) {
    if (!shard.has(std::uint64_t(i))) continue;
    const std::uint64_t cs = case_seed(seed, std::uint64_t(i));
    constexpr ArcKind kKinds[] = {ArcKind::Quarter, ArcKind::Whole, ArcKind::Program, ArcKind::Spatial};
    const ArcKind kind = kKinds[i % 4];
    RandomArcs gen(cs, 4096, 8, kind);
    std::optional<Plan> plan;
    while (!(plan = gen.next())) {
    }
    st.refused += long(gen.rejected());
    std::mt19937_64 rng(cs ^ 0x5eedULL);
    DriveOptions opt;
    opt.keep_records = false;
    const unsigned what = unsigned(rng() % 8);
    if (what == 0 || (what == 1 && rng() % 2)) {  // random ce_i stalls
      opt.ce = [&](std::uint64_t) { return rng() % 4 != 0; };
      ++st.ce_stalled;
    }
    if (what == 1) {  // a reset on any edge the arc runs through (with ce high)
      const std::uint64_t span = run(*plan).iterations + 2 * plan->pieces.size() + 1;
      opt.reset_at_cycle = 1 + rng() % span;
    }
    try {
      const DriveResult r = drive_arc(h, *plan, opt);
      st.iterations += r.iterations;
      st.cycles += r.cycles;
      st.pieces += plan->pieces.size();
      for (const Piece& pc : plan->pieces) st.line_pieces += pc.kind == PieceKind::Line;
      if (!r.was_reset) {
        const Plan& p = *plan;
        const bool cw = p.is_arc() && p.arc().spec.dir == Direction::Cw;
        ++st.quadrant_pairs[p.pieces.front().quadrant - 1][p.pieces.back().quadrant - 1][cw];
        st.lines += p.is_line();
        st.program += kind == ArcKind::Program && p.is_arc();
        st.spatial += kind == ArcKind::Spatial;
        if (p.is_arc()) {
          const ArcGeometry& g = p.arc();
          st.full += g.full;
          st.circles += g.spec.a == g.spec.b;
          st.turned += quarter_turns(g.spec) == 1 || quarter_turns(g.spec) == 3;
          st.rotated += g.rotated;
          st.thin += std::max(g.spec.a, g.spec.b) > 100 * std::min(g.spec.a, g.spec.b);
        }
      }
      if (r.was_reset) {
        ++st.resets;
        // Idle, no pulse, ready for the next command.
        h.set_ce(true);
        h.tick();
        const Signals s = h.sample();
        if (CoreModel::busy(s) || CoreModel::step_of(s) != Point{} || CoreModel::iterated(s) || CoreModel::done(s) ||
            !h.cmd_ready()) {
          throw MismatchError(std::string(h.name()) + " not idle after a reset");
        }
      }
    } catch (const GuardError& e) {
      const std::string where = "case " + std::to_string(i) + " (" + describe(*plan) + "): " + e.what();
      if (dynamic_cast<const MismatchError*>(&e)) throw MismatchError(where);
      throw GuardError(where);
    }
    ++st.arcs;
  }
  return st;
}

int regress_main(CoreHarness& h, int argc, char* argv[]) {
  CLI::App app{std::string(h.name()) + " regression against the reference model (scripts/regress.sh)"};
  long cases = 2000;
  std::uint64_t seed = 1;
  std::string shard_text = "0/1", json;
  std::vector<std::string> merge;
  app.add_option("--arcs", cases, "number of cases of the run (default 2000)")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "seed of the run (default 1)");
  app.add_option("--shard", shard_text, "run only the cases I, I+N, I+2N, ... (I/N, default 0/1)");
  app.add_option("--json", json, "also write the totals as JSON to FILE");
  app.add_option("--merge", merge, "sum the JSON files of a run's shards and print the totals (runs nothing)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (!merge.empty()) {
      // The shards of one run, each once: same run and engine, indices 0 .. N-1.
      MixedStats total;
      std::string what;
      std::vector<bool> seen;
      for (const std::string& f : merge) {
        std::ifstream in(f);
        if (!in) throw std::runtime_error("cannot read " + f);
        const nlohmann::json j = nlohmann::json::parse(in);
        const std::string run = j.at("run"), engine = j.at("engine");
        if (!what.empty() && run != what) throw std::runtime_error(f + " is of another run: " + run + ", not " + what);
        if (engine != h.name()) throw std::runtime_error(f + " is of engine " + engine + ", not " + h.name());
        const Shard sh = parse_shard(j.at("shard"));
        if (seen.empty()) seen.assign(sh.count, false);
        if (sh.count != seen.size())
          throw std::runtime_error(f + ": shard " + std::string(j.at("shard")) + " of another cut");
        if (seen[sh.index]) throw std::runtime_error(f + ": shard " + std::string(j.at("shard")) + " given twice");
        seen[sh.index] = true;
        what = run;
        total.add(from_json(j.at("totals")));
      }
      for (std::size_t k = 0; k < seen.size(); ++k) {
        if (!seen[k])
          throw std::runtime_error("shard " + std::to_string(k) + "/" + std::to_string(seen.size()) + " is missing");
      }
      print(h.name(), what + ", " + std::to_string(merge.size()) + " shards merged", total);
      return 0;
    }
    const Shard shard = parse_shard(shard_text);
    const MixedStats st = run_mixed(h, seed, cases, shard);
    const std::string run = "seed " + std::to_string(seed) + ", " + std::to_string(cases) + " cases";
    print(h.name(), run + (shard.count > 1 ? ", shard " + shard_text : ""), st);
    if (!json.empty()) {
      nlohmann::json j;
      j["engine"] = h.name();
      j["run"] = run;
      j["shard"] = shard_text;
      j["totals"] = to_json(st);
      std::ofstream out(json);
      out << j.dump(1) << '\n';
      if (!out) throw std::runtime_error("cannot write " + json);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s regression: FAIL (rerun: %s --seed %llu --arcs %ld --shard %s): %s\n", h.name(), argv[0],
                 static_cast<unsigned long long>(seed), cases, shard_text.c_str(), e.what());
    return 1;
  }
  return 0;
}

}  // namespace dda
