// SPDX-License-Identifier: Apache-2.0
// The motion block (rtl/dda_motion.v) on a Wishbone bus: the register map is generated
// from its one definition and cannot drift; the RTL runs in lockstep with the block's
// reference model (every port, block register and core register after every edge)
// while a bus master queues the golden planner's commands; the position counters end
// on the arcs' end points.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <cctype>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include "host/accuracy/golden.hpp"
#include "host/driver/motion_driver.hpp"
#include "model/datapath/hw_command.hpp"
#include "model/motion/motion_map.hpp"
#include "tb/engines/motion_harness.hpp"
#include "tb/random/dda_random.hpp"
#include "tb/random/motion_mix.hpp"

using namespace dda;
using namespace dda::motion;

namespace {

std::string slurp(const std::string& rel) {
  std::ifstream f(std::string(DDA_SOURCE_DIR) + "/" + rel, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::uint32_t addr(std::string_view name) { return reg_offset(name); }
std::uint32_t field(std::string_view reg, std::string_view name, std::uint32_t v) { return get_field(reg, name, v); }
std::uint32_t bit(std::string_view reg, std::string_view name) { return field_bit(reg, name); }

}  // namespace

TEST_CASE("motion_map: the checked-in files are generated from the register map", "[motion][default-widths]") {
  CHECK_NOTHROW(check());
  CHECK(slurp("rtl/dda_motion_regs.vh") == verilog_header());
  CHECK(slurp("fw/dda_motion_regs.h") == c_header());
  CHECK(slurp("docs/design.md").find(markdown()) != std::string::npos);
}

TEST_CASE("motion_map: the C header's command layout finds every field where an entry has it", "[motion]") {
  // Its DDA_MOTION_CMD_<NAME>_AT and _WIDTH, read from the file as firmware reads them,
  // against the words entry_words packs for a line and an arc, field by field.
  const std::string h = slurp("fw/dda_motion_regs.h");
  const std::regex re(R"(#define DDA_MOTION_CMD_(\w+)_AT (\d+)u[^\n]*\n#define DDA_MOTION_CMD_\1_WIDTH (\d+)u)");
  std::map<std::string, std::pair<int, int>> at;
  for (auto it = std::sregex_iterator(h.begin(), h.end(), re); it != std::sregex_iterator(); ++it)
    at[(*it)[1]] = {std::stoi((*it)[2]), std::stoi((*it)[3])};
  REQUIRE(at.size() == hw::kCmdFields.size());
  const Plan line = plan_line(Point{-40, 7, 3}, Point{900, -350, 41}, Preload::Half);
  ArcSpec spec;  // the paper's quarter ellipse
  spec.a = 10;
  spec.b = 6;
  spec.bits = 4;
  const Plan arc = plan_arc(spec);
  for (const Command& c : {line.pieces.front().cmd, arc.pieces.front().cmd}) {
    const std::vector<std::uint32_t> w = entry_words(c, 0x12345678u, 2);
    const CmdFields f = hw::command_fields(c);
    for (std::size_t i = 0; i < hw::kCmdFields.size(); ++i) {
      std::string name(hw::kCmdFields[i].name);
      for (char& ch : name) ch = char(std::toupper(static_cast<unsigned char>(ch)));
      INFO(name);
      REQUIRE(at.count(name) == 1);
      const auto [lsb, width] = at[name];
      CHECK(width == hw::kCmdFields[i].width);
      std::uint64_t v = 0;
      for (int k = 0; k < width; ++k)
        v |= std::uint64_t((w[std::size_t((lsb + k) / 32)] >> ((lsb + k) % 32)) & 1u) << k;
      CHECK(v == (f[i] & ((std::uint64_t{1} << width) - 1)));
    }
  }
}

TEST_CASE("motion_map: a changed field drifts from every checked-in file, an overlap is refused",
          "[motion][default-widths]") {
  Map m = map();
  for (auto& f : m.fields) {
    if (f.reg == "STATUS" && f.name == "err") f.lsb = 26;  // moved (to a free bit)
  }
  CHECK_NOTHROW(check(m));
  CHECK(slurp("rtl/dda_motion_regs.vh") != verilog_header(m));
  CHECK(slurp("fw/dda_motion_regs.h") != c_header(m));
  CHECK(slurp("docs/design.md").find(markdown(m)) == std::string::npos);
  Map o = map();
  for (auto& f : o.fields) {
    if (f.reg == "STATUS" && f.name == "err") f.lsb = 2;  // onto STATUS.full
  }
  CHECK_THROWS_WITH(check(o), Catch::Contains("STATUS.full and STATUS.err overlap"));
  Map r = map();
  r.regs[3].offset = r.regs[2].offset;
  CHECK_THROWS_WITH(check(r), Catch::Contains("overlap"));
}

TEST_CASE("motion: identification, configuration and register access on classic and pipelined cycles", "[motion]") {
  for (const bool pipelined : {false, true}) {
    INFO((pipelined ? "pipelined" : "classic"));
    MotionHarness h;
    WishboneMaster m(h, 5, pipelined, 30);
    h.set_reset(false);
    m.idle(2);
    h.set_reset(true);
    CHECK(m.read(addr("ID")) == kId);
    CHECK(field("VERSION", "major", m.read(addr("VERSION"))) == std::uint32_t(kVersionMajor));
    const std::uint32_t cfg = m.read(addr("CONFIG"));
    CHECK(field("CONFIG", "entry_words", cfg) == std::uint32_t(kEntryWords));
    CHECK(field("CONFIG", "depth_log2", cfg) == std::uint32_t(kHarnessDepthLog2));
    CHECK(field("CONFIG", "acc_width", cfg) == std::uint32_t(hw::kAccWidth));
    m.write(addr("POS_X"), 0xFFFFFFF6u);
    CHECK(m.read(addr("POS_X")) == 0xFFFFFFF6u);
    m.write(addr("IRQ_ENABLE"), 0xFFFFFFFFu);
    CHECK(m.read(addr("IRQ_ENABLE")) == 0x1Fu);
    // A commit of nothing is a partial entry: refused, sticky, and an interrupt.
    m.write(addr("CTRL"), bit("CTRL", "commit"));
    const std::uint32_t st = m.read(addr("STATUS"));
    CHECK(field("STATUS", "err", st) == 1);
    CHECK(field("STATUS", "err_partial", st) == 1);
    CHECK(field("STATUS", "level", st) == 0);
    CHECK(h.outputs().irq);
    m.write(addr("IRQ_STATUS"), 0xFFFFFFFFu);
    m.write(addr("CTRL"), bit("CTRL", "clear"));
    CHECK(field("STATUS", "err", m.read(addr("STATUS"))) == 0);
    CHECK_FALSE(h.outputs().irq);
  }
}

TEST_CASE("motion_map: every register reads its documented reset value on the RTL and the reference model",
          "[motion]") {
  // (The harness checks the RTL against the reference model on every edge.)
  MotionHarness h;
  WishboneMaster m(h, 3, false, 0);
  h.set_reset(false);
  m.idle(4);
  h.set_reset(true);
  m.idle(4);
  for (const Register& r : kRegisters) {
    if (r.name == "ENTRY") continue;
    INFO(r.name);
    const std::uint32_t got = m.read(r.offset);
    if (r.access == Access::WO) {
      CHECK(got == 0);
    } else if (r.reset == kResetBuild) {
      CHECK(got == MotionModel(harness_build()).read(r.offset));
    } else {
      CHECK(got == std::uint32_t(r.reset));
    }
  }
  // The firmware header and the docs say the same (generated from the map).
  const std::string header = c_header();
  CHECK_THAT(header, Catch::Contains("#define DDA_MOTION_OVERRIDE_RESET 0x00000100u"));
  CHECK_THAT(header, Catch::Contains("#define DDA_MOTION_STATUS_RESET 0x00000002u"));
  CHECK_THAT(markdown(), Catch::Contains("| 0x5C | `OVERRIDE` | RW | 0x00000100 |"));
}

TEST_CASE("motion: byte lanes: 8- and 16-bit stores change their bytes only, entry words only whole", "[motion]") {
  MotionHarness h;
  WishboneMaster m(h, 7, false, 20);
  m.write(addr("POS_X"), 0x11223344u);
  m.write(addr("POS_X"), 0xAABBCCDDu, 0x1);
  CHECK(m.read(addr("POS_X")) == 0x112233DDu);
  m.write(addr("POS_X"), 0xAABBCCDDu, 0xC);
  CHECK(m.read(addr("POS_X")) == 0xAABB33DDu);
  m.write(addr("POS_X"), 0u, 0x0);  // no lane: nothing changes
  CHECK(m.read(addr("POS_X")) == 0xAABB33DDu);
  // A 16-bit store to STEP_X's low half sets steplen and keeps stepspace.
  m.write(addr("STEP_X"), 0x00070005u);
  m.write(addr("STEP_X"), 0x00090003u, 0x3);
  CHECK(m.read(addr("STEP_X")) == 0x00070003u);
  m.write(addr("IRQ_ENABLE"), 0xFFFFFFFFu, 0xE);  // the enables sit in lane 0
  CHECK(m.read(addr("IRQ_ENABLE")) == 0u);
  m.write(addr("IRQ_ENABLE"), 0x5u, 0x1);
  CHECK(m.read(addr("IRQ_ENABLE")) == 5u);
  // CTRL acts only on the bits of the lanes selected: a commit outside them is no commit.
  m.write(addr("CTRL"), bit("CTRL", "commit"), 0x2);
  CHECK(field("STATUS", "err", m.read(addr("STATUS"))) == 0);
  // An entry word with lanes missing is refused whole: not written, a sticky error.
  m.write(addr("ENTRY"), 0x12345678u, 0x3);
  std::uint32_t st = m.read(addr("STATUS"));
  CHECK(field("STATUS", "err", st) == 1);
  CHECK(field("STATUS", "err_lanes", st) == 1);
  CHECK(m.read(addr("ENTRY_MASK")) == 0u);
  m.write(addr("ENTRY"), 0x12345678u);
  CHECK(m.read(addr("ENTRY_MASK")) == 1u);
  m.write(addr("CTRL"), bit("CTRL", "clear"), 0x1);
  st = m.read(addr("STATUS"));
  CHECK(field("STATUS", "err", st) == 0);
  CHECK(field("STATUS", "err_lanes", st) == 0);
}

TEST_CASE("motion: writing 1 to one interrupt bit clears it alone, in its lane only", "[motion]") {
  const Plan p = plan_arc(paper_example());
  MotionHarness h;
  WishboneMaster m(h, 9, false, 0);
  MotionDriver d(m, 9);
  m.write(addr("IRQ_ENABLE"), 7u);
  m.write(addr("IRQ_LEVEL"), 2u);
  for (const auto& piece : p.pieces) d.queue(piece.cmd);
  d.drain();
  m.write(addr("CTRL"), bit("CTRL", "commit"));  // a partial entry: the err event
  const std::uint32_t all = bit("IRQ_STATUS", "done") | bit("IRQ_STATUS", "err") | bit("IRQ_STATUS", "low");
  REQUIRE(m.read(addr("IRQ_STATUS")) == all);
  m.write(addr("IRQ_STATUS"), 0xFFFFFFFFu, 0xE);  // lanes without the bits: nothing cleared
  CHECK(m.read(addr("IRQ_STATUS")) == all);
  m.write(addr("IRQ_STATUS"), bit("IRQ_STATUS", "err"));
  CHECK(m.read(addr("IRQ_STATUS")) == (all & ~bit("IRQ_STATUS", "err")));
  CHECK(h.outputs().irq);
  m.write(addr("IRQ_STATUS"), bit("IRQ_STATUS", "done") | bit("IRQ_STATUS", "low"));
  CHECK(m.read(addr("IRQ_STATUS")) == 0u);
  CHECK_FALSE(h.outputs().irq);
}

TEST_CASE("motion: a position preset on the edge a pulse starts counts that pulse on top of the value written",
          "[motion]") {
  const Plan p = plan_arc(paper_example());
  // The same run twice: the first finds the edge of the first X pulse, the second writes
  // POS_X so that the block takes the write on that very edge.
  struct Run {
    std::uint64_t rise_edge = 0;
    int dir = 0;
    std::uint32_t pos_after = 0;
  };
  const auto run = [&](std::uint64_t preset_edge) {
    MotionHarness h;
    WishboneMaster m(h, 4, false, 0);
    MotionDriver d(m, 4, false);
    std::uint64_t edge = 0;  // the edges taken so far
    m.each_cycle = [&] { ++edge; };
    Run r;
    h.set_ce(false);
    for (const auto& piece : p.pieces) d.queue(piece.cmd, 0x10000000u);
    h.set_ce(true);
    if (preset_edge == 0) {
      while (h.model().rise_x() == 0) m.idle(1);
      r.rise_edge = edge;
      r.dir = h.model().rise_x();
      return r;
    }
    while (edge + 1 < preset_edge) m.idle(1);
    bool seen = false;
    m.each_cycle = [&] {
      ++edge;
      if (edge == preset_edge + 1) {  // before the edge after the write's: the write's edge
        seen = true;
        r.dir = h.model().rise_x();
        r.pos_after = std::uint32_t(h.model().regs()[breg("pos_x_q")]);
      }
    };
    m.write(addr("POS_X"), 1000u);
    REQUIRE(seen);
    return r;
  };
  const Run first = run(0);
  REQUIRE(first.dir != 0);
  const Run preset = run(first.rise_edge);
  CHECK(preset.dir == first.dir);  // the pulse did start on the edge that took the write
  CHECK(preset.pos_after == std::uint32_t(1000 + first.dir));
}

TEST_CASE("motion: the paper's example through the queue ends on its end point", "[motion]") {
  const Plan p = plan_arc(paper_example());
  MotionHarness h;
  WishboneMaster m(h, 1, false, 0);
  MotionDriver d(m, 1);
  m.write(addr("POS_X"), std::uint32_t(p.from.x));
  m.write(addr("POS_Y"), std::uint32_t(p.from.y));
  for (const auto& piece : p.pieces) d.queue(piece.cmd);
  d.drain();
  CHECK(std::int32_t(m.read(addr("POS_X"))) == p.to.x);
  CHECK(std::int32_t(m.read(addr("POS_Y"))) == p.to.y);
  CHECK(m.read(addr("DONE_COUNT")) == p.pieces.size());
  CHECK(m.read(addr("ERR_COUNT")) == 0);
}

TEST_CASE("motion: random arcs queued while the block runs, in lockstep with the reference model", "[motion]") {
  const std::uint64_t seed = test_seed(61);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  std::mt19937_64 rng(seed);
  RandomArcs gen(seed, 300, 4, ArcKind::Program);
  for (const bool pipelined : {false, true}) {
    MotionHarness h;
    WishboneMaster m(h, seed + pipelined, pipelined, 25);
    // ce_i low a tenth of the cycles.
    m.each_cycle = [&] { h.set_ce(rng() % 10 != 0); };
    MotionDriver d(m, seed);
    std::uint64_t pieces = 0;
    for (int arcs = 0; arcs < 12;) {
      const auto plan = gen.next();
      if (!plan) continue;
      ++arcs;
      INFO("arc " << gen.drawn_options());
      // The position counters are preset to the arc's start, then count its steps.
      d.drain();
      m.write(addr("POS_X"), std::uint32_t(plan->from.x));
      m.write(addr("POS_Y"), std::uint32_t(plan->from.y));
      for (const auto& piece : plan->pieces) d.queue(piece.cmd);
      pieces += plan->pieces.size();
      d.drain();
      CHECK(std::int32_t(m.read(addr("POS_X"))) == plan->to.x);
      CHECK(std::int32_t(m.read(addr("POS_Y"))) == plan->to.y);
    }
    CHECK(m.read(addr("DONE_COUNT")) == pieces);
  }
}

TEST_CASE("motion: abort, overflow, partial commit and reset in the middle of a queue", "[motion]") {
  const std::uint64_t seed = test_seed(67);
  INFO("seed " << seed);
  std::mt19937_64 rng(seed);
  RandomArcs gen(seed, 500, 4, ArcKind::Whole);
  MotionHarness h;
  WishboneMaster m(h, seed, true, 10);
  for (int round = 0; round < 6; ++round) {
    // Fill the queue beyond its depth with ce_i low (the core takes one command and
    // waits): the extra commits overflow.
    h.set_ce(false);
    std::vector<Command> cmds;
    while (cmds.size() < (std::size_t{1} << kHarnessDepthLog2) + 3) {
      if (auto p = gen.next()) {
        for (const auto& piece : p->pieces) cmds.push_back(piece.cmd);
      }
    }
    for (const auto& c : cmds) {
      const auto w = entry_words(c);
      for (std::size_t k = 0; k < w.size(); ++k) m.write(addr("ENTRY") + 4 * std::uint32_t(k), w[k]);
      m.write(addr("CTRL"), bit("CTRL", "commit"));
    }
    std::uint32_t st = m.read(addr("STATUS"));
    CHECK(field("STATUS", "err_overflow", st) == 1);
    CHECK(field("STATUS", "full", st) == 1);
    h.set_ce(true);
    // A partial entry, then an abort in the middle of an arc (or a reset).
    m.write(addr("ENTRY"), 1);
    m.write(addr("CTRL"), bit("CTRL", "commit"));
    m.idle(int(rng() % 200));
    const std::int32_t x0 = std::int32_t(m.read(addr("POS_X")));
    if (round % 3 == 2) {
      h.set_reset(false);
      m.idle(1);
      h.set_reset(true);
      st = m.read(addr("STATUS"));
      CHECK(st == bit("STATUS", "empty"));
      continue;
    }
    m.write(addr("CTRL"), bit("CTRL", "abort"));
    st = m.read(addr("STATUS"));
    CHECK(field("STATUS", "aborted", st) == 1);
    CHECK(field("STATUS", "level", st) == 0);
    CHECK(field("STATUS", "busy", st) == 0);
    CHECK(field("ENTRY_MASK", "words", m.read(addr("ENTRY_MASK"))) == 0);
    // The position moved by at most the steps of the cycles since it was read, and
    // stays where the abort left it.
    const std::int32_t x1 = std::int32_t(m.read(addr("POS_X")));
    CHECK(std::abs(x1 - x0) <= 64);
    m.idle(50);
    CHECK(std::int32_t(m.read(addr("POS_X"))) == x1);
    m.write(addr("CTRL"), bit("CTRL", "clear"));
    m.write(addr("IRQ_STATUS"), 7);
  }
}

TEST_CASE("motion: 100 random arcs with aborts, resets, partial commits and overflows, on both bus modes", "[motion]") {
  const std::uint64_t seed = test_seed(79);
  INFO("seed " << seed << " (DDA_SEED reruns it)");
  std::uint64_t input_trips = 0, thresholds = 0;
  for (const bool pipelined : {false, true}) {
    MotionHarness h;
    const MixStats st = run_motion_mix(h, seed + pipelined, 50, pipelined);
    input_trips += st.input_trips;
    thresholds += st.threshold_batches;
    INFO(st.pieces << " pieces, " << h.cycle() << " cycles");
    CHECK(st.arcs == 50);
    CHECK(st.position_checks > 0);
    CHECK(st.piece_checks > 0);
    CHECK(st.spatial > 0);       // the third axis in the mix,
    CHECK(st.pulses_z > 0);      // its pulses through its stage,
    CHECK(st.turned > 0);        // arcs turned onto another plane by the entry's axes
    CHECK(st.paced_pieces > 0);  // pieces paced by the pacer, with a hold and an override change
    CHECK(st.holds > 0);
    CHECK(st.glitches > 0);  // glitches on the machine's inputs, ignored
  }
  CHECK(input_trips > 0);  // batches stopped by an input
  CHECK(thresholds > 0);   // paced batches with the pacer's comparisons at their thresholds
}
