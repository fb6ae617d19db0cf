// SPDX-License-Identifier: Apache-2.0
// `dda --program` as a user runs it: every class of bad input is exit status
// 2 and one line "FILE:LINE:COLUMN: message" at the right place, with no file written;
// the options' own errors; a program from standard input; the per-block statistics.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "tests/cli_helpers.hpp"

namespace {

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
}

}  // namespace

TEST_CASE("cli program: each class of bad input is one FILE:LINE:COLUMN line, status 2, no file", "[cli]") {
  // (text, expected message after "FILE:") for each class of bad input (docs/programs.md),
  // in HNC's dialect (LinuxCNC's would refuse the moves without F first).
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"G01 X1\nG01 E5\n", "2:5: unknown word E"},                          // unknown word
      {"G12 X1\n", "1:1: unknown or unsupported code G12"},                 // unknown code
      {"G01 X1.2.3\n", "1:9: unexpected '.'"},                              // malformed number
      {"G01 X Y1\n", "1:7: a number must follow the letter"},               // axis word without its value
      {"G02 X10 Y0\n", "1:1: an arc needs a centre (I, J) or a radius R"},  // missing centre or radius words
      {"N7 G02 X10 Y0 I5 R5\n", "1:18: an arc takes a centre or a radius R, not both"},
      {"G02 X10 Y0 R4\n", "1:12: the end is out of reach: 10.0000 mm from the start, more than twice R 4.0000 mm"},
      {"G02 X10 Y0 I5.0011\n",
       "1:1: the end is 0.0022 mm off the arc's circle (radius 5.0011 mm; tolerance 0.002 mm)"},  // off-curve end
      {"G6.2 X10 Y0 A0 B2\n", "1:13: the semi-axis A must be positive"},
      {"G6.2 X10 Y0 A5 B-2\n", "1:16: the semi-axis B must be positive"},
      {"G41 G01 X1\n", "1:1: tool radius compensation (G41/G42) is not supported: program the tool's path"},
  };
  // The macro language's classes.
  const std::vector<std::pair<std::string, std::string>> macro_cases = {
      {"G01 X#7\n", "1:6: #7 is undefined: no value was assigned to it"},
      {"#1=0\n#2=5/#1\n", "2:5: division by zero"},
      {"#1=1\nWHILE #1 LT 3\nG01 X#1\n", "2:1: WHILE without ENDW in its program"},
      {"G01 X1\nELSE\n", "2:1: ELSE without IF"},
      {"%1\nM98 P7\nM30\n%2\nM99\n", "2:5: M98 calls program %7: there is none"},
      {"%1\nM98 P2\n%2\nM98 P2\nM99\n", "4:5: subprogram calls nested deeper than 8"},
      {"#1=0\nWHILE [1]\n#1=#1+1\nENDW\n", "2:1: more than 10000000 lines executed: a loop that does not end?"},
  };
  for (const auto& [text, want] : macro_cases) {
    Scratch s;
    const fs::path prog = s.dir / "m.nc", out = s.dir / "out.txt";
    write_file(prog, text);
    const Result r =
        run_dda(s, "stats --engine systemc --dialect hnc --program " + prog.string() + " --out " + out.string());
    INFO(text);
    CHECK(r.status == 2);
    CHECK(r.err == prog.string() + ":" + want + "\n");
    CHECK(s.user_files() == 1);
  }
  for (const auto& [text, want] : cases) {
    for (const std::string cmd : {"stats", "plot", "trace --engine rtl"}) {
      Scratch s;
      const fs::path prog = s.dir / "p.nc", out = s.dir / (cmd == "plot" ? "out.svg" : "out.txt");
      write_file(prog, text);
      const Result r = run_dda(s, cmd + " --dialect hnc --program " + prog.string() + " --out " + out.string());
      INFO("dda " << cmd << " on: " << text << "stderr: " << r.err);
      CHECK(r.status == 2);
      CHECK(r.out.empty());
      CHECK(r.err == prog.string() + ":" + want + "\n");
      CHECK(s.user_files() == 1);  // only the program: no output, no temporary file
    }
  }
  // vectors: no directory left either.
  Scratch s;
  const fs::path prog = s.dir / "p.nc";
  write_file(prog, "G01 X1\nG01 E5\n");
  const Result r =
      run_dda(s, "vectors --dialect hnc --program " + prog.string() + " --out-dir " + (s.dir / "set").string());
  CHECK(r.status == 2);
  CHECK(r.err == prog.string() + ":2:5: unknown word E\n");
  CHECK(s.user_files() == 1);
}

TEST_CASE("cli program: a block the hardware cannot hold is refused for systemc and rtl only", "[cli]") {
  Scratch s;
  const fs::path prog = s.dir / "big.nc";
  write_file(prog, "N10 G00 X200 Y0\nN20 G03 X-200 Y0 R200\n");
  for (const std::string engine : {"systemc", "rtl"}) {
    const Result r = run_dda(s, "stats --dialect hnc --program " + prog.string() + " --engine " + engine);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.rfind(prog.string() + ":2:5: block N20 (arc ccw): beyond the hardware's widths: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  const Result g = run_dda(s, "stats --dialect hnc --program " + prog.string() + " --format json");
  CHECK(g.status == 0);
  const auto j = nlohmann::json::parse(g.out);
  CHECK(j["totals"]["on_ends"] == true);
  CHECK(j["blocks"][1]["end"] == nlohmann::json::array({-200000, 0}));
}

TEST_CASE("cli program: the options' own errors", "[cli]") {
  Scratch s;
  const fs::path prog = s.dir / "p.nc";
  write_file(prog, "G01 X1 Y1\n");
  const std::string p = " --program " + prog.string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"stats" + p + " --a 5", "dda: error: --a is invalid with --program: the program gives the geometry\n"},
      {"stats" + p + " --line", "dda: error: --line is invalid with --program: the program gives the geometry\n"},
      {"stats --a 5 --b 3 --machine lathe", "dda: error: --machine, --start and --step go with --program FILE\n"},
      {"stats" + p + " --machine drill", "dda: error: machine = 'drill' is invalid: use mill or lathe\n"},
      {"stats" + p + " --step 0.0000001",
       "dda: error: step = 0.0000001 is invalid: the lattice unit is in millimetres, from 0.000001 (1 nm) to 1\n"},
      {"stats" + p + " --start 1",
       "dda: error: start = '1' is invalid: give X,Y in millimetres (e.g. 10,-2.5; up to 6 decimals)\n"},
      {"stats --program " + (s.dir / "none.nc").string(),
       "dda: error: program = '" + (s.dir / "none.nc").string() +
           "' is invalid: cannot read it (No such file or directory)\n"},
      {"stats --a 5 --b 3 --format csv", "dda: error: --format csv goes with --program\n"},
      {"feed" + p, "dda: error: --program is invalid with feed: the feed table is one arc's\n"},
  };
  for (const auto& [args, want] : cases) {
    const Result r = run_dda(s, args);
    INFO("dda " << args);
    CHECK(r.status == 2);
    CHECK(r.err == want);
  }
}

TEST_CASE("cli program: standard input, a lathe in diameters, the block table", "[cli]") {
  Scratch s;
  const fs::path prog = s.dir / "p.nc";
  write_file(prog, "N1 G00 X20 Z0\nN2 G01 U10 W-5\nN3 G02 X40 Z-15 R8\n");
  const Result file = run_dda(s, "stats --machine lathe --format csv --program " + prog.string());
  const Result in = run_dda(s, "stats --machine lathe --format csv --program - < " + prog.string());
  CHECK(file.status == 0);
  CHECK(in.status == 0);
  CHECK(file.out == in.out);
  // One row per block: line, block, kind, end (u, v) = (Z, X radius) in mm and steps.
  CHECK(file.out.rfind("line,block,kind,end_u_mm,end_v_mm,end_x,end_y,rounding,commands,steps,iterations,max_dev,"
                       "mean_dev,on_end,target,within_target\n1,N1,rapid,0,10,0,10000,0.000000,1,10000,10000,",
                       0) == 0);
  CHECK(file.out.find("\n2,N2,line,-5,15,-5000,15000,") != std::string::npos);
  CHECK(file.out.find("\n3,N3,arc cw,-15,20,-15000,20000,") != std::string::npos);
  CHECK(file.out.find(",yes,") != std::string::npos);
  const Result text = run_dda(s, "stats --machine lathe --program " + prog.string());
  CHECK(text.out.find("\ntargets: every block within its target\n") != std::string::npos);
  const Result zero = run_dda(s, "stats --machine lathe --preload zero --program " + prog.string());
  CHECK(zero.out.find("\ntargets: not targeted (zero preload: reported only)\n") != std::string::npos);
  // An error in a program from standard input names <stdin>.
  write_file(prog, "G01 X1\nG01 E5\n");
  const Result bad = run_dda(s, "path --dialect hnc --program - < " + prog.string());
  CHECK(bad.status == 2);
  CHECK(bad.err == "<stdin>:2:5: unknown word E\n");
}

TEST_CASE("cli program: a program longer than a core vector set holds is refused with its reason", "[cli]") {
  Scratch s;
  const fs::path prog = s.dir / "long.nc";
  // 4100 moves of one step each: 4100 core commands.
  write_file(prog, "#1=0\nWHILE #1 LT 4100\n#1=#1+1\nG01 X[#1*0.001]\nENDW\n");
  const Result r =
      run_dda(s, "vectors --dialect hnc --program " + prog.string() + " --out-dir " + (s.dir / "set").string());
  CHECK(r.status == 2);
  CHECK(r.err ==
        "dda: error: vectors: 4100 commands are too many: tb/hdl/dda_vec_tb.v holds 4096 (split the work into several "
        "sets, or give --bus: the motion block's set streams its commands)\n");
  CHECK(s.user_files() == 1);
  // The motion block's set streams the commands through its queue: it takes them.
  const Result b = run_dda(s, "vectors --bus --program " + prog.string() + " --out-dir " + (s.dir / "bus").string());
  CHECK(b.status == 0);
}

TEST_CASE("cli program: the third axis in the reports, and dda plot's views", "[cli]") {
  Scratch s;
  const fs::path prog = s.dir / "p.ngc";
  write_file(prog, "G21 G17 F100\nG1 X1 Y0\nG1 Z-0.5\nG2 X1 Y0 I-1 J0 Z-1\nG0 Z1\nM2\n");
  // Every report has the third axis' columns, the same on the three engines.
  const Result path = run_dda(s, "path --program " + prog.string());
  REQUIRE(path.status == 0);
  CHECK(path.out.rfind("point,x,y,z\n0,0,0,0\n", 0) == 0);
  CHECK(path.out.size() > 10);
  CHECK(path.out.substr(path.out.rfind('\n', path.out.size() - 2) + 1).find(",1000,0,1000\n") != std::string::npos);
  for (const std::string engine : {"systemc", "rtl"}) {
    CHECK(run_dda(s, "path --engine " + engine + " --program " + prog.string()).out == path.out);
  }
  const Result trace = run_dda(s, "trace --program " + prog.string());
  CHECK(trace.out.rfind("iter,seg,jvx,jrx,dx,rem_x,jvy,jry,dy,rem_y,dir_x,dir_y,x,y,jvz,jrz,dz,rem_z,dir_z,z\n", 0) ==
        0);
  const Result stats = run_dda(s, "stats --format csv --program " + prog.string());
  CHECK(stats.out.find(",end_w_mm,end_z\n") != std::string::npos);
  CHECK(stats.out.find(",-1,-1000\n") != std::string::npos);  // the helix's end: Z in mm and in steps
  // A program of the plane alone: no third axis' columns.
  const fs::path flat = s.dir / "flat.ngc";
  write_file(flat, "G21 G17 F100\nG1 X1 Y0\nG2 X1 Y0 I-1 J0\nM2\n");
  CHECK(run_dda(s, "path --program " + flat.string()).out.rfind("point,x,y\n", 0) == 0);
  // plot --view: the third axis against x or y.
  const fs::path svg = s.dir / "xz.svg";
  CHECK(run_dda(s, "plot --view xz --program " + prog.string() + " --out " + svg.string()).status == 0);
  std::ifstream in(svg);
  const std::string pic((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(pic.find(">x (steps)</text>") != std::string::npos);
  CHECK(pic.find(">z (steps)</text>") != std::string::npos);
  const Result bad = run_dda(s, "plot --view zz --program " + prog.string() + " --out " + svg.string());
  CHECK(bad.status == 2);
  CHECK(bad.err.find("view = 'zz' is invalid") != std::string::npos);
  // The motion block's vector set carries the third axis' pins, position and timings.
  const fs::path bus = s.dir / "bus";
  const Result withbus = run_dda(s, "vectors --bus --program " + prog.string() + " --out-dir " + bus.string());
  REQUIRE(withbus.status == 0);
  std::ifstream man(bus / "manifest.json");
  const std::string manifest((std::istreambuf_iterator<char>(man)), std::istreambuf_iterator<char>());
  CHECK(manifest.find("\"step_z_o\"") != std::string::npos);
  CHECK(manifest.find("\"pos_z_q\"") != std::string::npos);
  CHECK(manifest.find("\"timing_z\"") != std::string::npos);
  // The core's vector set has the third axis.
  CHECK(run_dda(s, "vectors --program " + prog.string() + " --out-dir " + (s.dir / "core").string()).status == 0);
}

TEST_CASE("cli program: planned speeds, the machine file, the speed picture and their errors", "[cli]") {
  Scratch s;
  const fs::path prog = s.dir / "p.ngc", cfg = s.dir / "m.json", svg = s.dir / "v.svg";
  write_file(prog, "G21 G90\nN1 G1 X20 F1200\nN2 G1 Y20\nG4 P1\nN3 G0 X0 Y0\nM2\n");
  write_file(cfg, R"({"rapid_mm_per_min": 3000, "axes": {"x": {"vmax_mm_per_min": 3000}}})");
  const std::string p = " --program " + prog.string();
  const Result csv = run_dda(s, "stats --speeds --format csv" + p);
  CHECK(csv.status == 0);
  CHECK(csv.out.rfind("line,block,kind,pieces,length_mm,feed_mm_min,entry_mm_min,cruise_mm_min,exit_mm_min,time_s,"
                      "dwell_s,rest,limit\n2,N1,line,1,20.000000,1200.000,0.000,1200.000,",
                      0) == 0);
  // (28 mm are too short to reach 6000 mm/min at 250 mm/s^2; the dwell before it, at rest.)
  CHECK(csv.out.find("\n5,N3,rapid,1,28.284271,6000.000,0.000,5045.378,0.000,0.672717,1.000000,yes,length\n") !=
        std::string::npos);
  // The file over the mill's defaults, an option over the file.
  const Result file = run_dda(s, "stats --format csv --machine-config " + cfg.string() + p);
  CHECK(file.out.find("\n5,N3,rapid,1,28.284271,3000.000,0.000,3000.000,") != std::string::npos);
  const Result opt = run_dda(s, "stats --format csv --rapid 1500 --machine-config " + cfg.string() + p);
  CHECK(opt.out.find("\n5,N3,rapid,1,28.284271,1500.000,0.000,1500.000,") != std::string::npos);
  const Result json = run_dda(s, "stats --speeds --format json" + p);
  CHECK(json.out.find("\"time_s\":") != std::string::npos);
  const Result pic = run_dda(s, "plot --speed " + svg.string() + " --accel 200 --clock 20e6" + p);
  CHECK(pic.status == 0);
  CHECK(slurp(svg).find("class=\"commanded\"") != std::string::npos);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"stats --a 5 --b 3 --speeds", "dda: error: --speeds and the machine's limits go with --program\n"},
      {"stats --speeds --engine rtl" + p,
       "dda: error: --speeds plans the feeds in the driver: no engine runs (leave --engine out)\n"},
      {"stats --accel 0" + p, "dda: error: accel = 0 is out of range: it must be positive\n"},
      {"stats --window 1" + p, "dda: error: machine limits: the window must be 2 to 100000 pieces\n"},
      {"plot --speed " + svg.string() + " --feed-rate 100" + p,
       "dda: error: --feed-rate and --vmin are an arc's, in steps: a program's feeds come from its F words (the "
       "minimum speed from the machine's limits)\n"},
      {"plot --speed " + svg.string() + " --rapid 100 --a 5 --b 3 --feed-rate 10 --accel 1 --clock 1e6",
       "dda: error: --machine-config, --junction-deviation, --rapid, --default-feed, --min-speed and --window go "
       "with "
       "--program\n"},
  };
  for (const auto& [args, want] : cases) {
    const Result r = run_dda(s, args);
    INFO("dda " << args);
    CHECK(r.status == 2);
    CHECK(r.err == want);
  }
  const Result bad_file = run_dda(s, "stats --machine-config " + prog.string() + p);
  CHECK(bad_file.status == 2);
  CHECK(bad_file.err.rfind("dda: error: machine config '" + prog.string() + "': not JSON: ", 0) == 0);
  // The slowest clock the block follows the plan at: a diagonal of 100 x 100 mm at 3000
  // mm/min (50 mm/s, reached at 100 mm/s^2: 1000 path steps/s at 0.05 mm) takes 707
  // iterations a second (sqrt(2) steps of path each), every one stepping X and Y
  // together: 57 clocks each at most (the norm unit's latency from one step to the next,
  // and the clock it hands its d over on). (ACCEL holds 100 mm/s^2 from 11,449 Hz on.)
  write_file(prog, "G21 G1 X100 Y100 F3000\nM2\n");
  const double slowest = 1000 / std::sqrt(2.0) * 57;
  const std::string set = " --out-dir " + (s.dir / "set").string();
  const Result slow =
      run_dda(s, "vectors --bus --speeds --step 0.05 --accel 200 --min-speed 30 --clock 38000" + set + p);
  CHECK(slow.status == 2);
  const std::string lead = "dda: error: the planned speeds need a clock of at least ";
  REQUIRE(slow.err.rfind(lead, 0) == 0);
  CHECK(std::stod(slow.err.substr(lead.size())) == Approx(slowest).epsilon(1e-4));
  CHECK(slow.err.find(" Hz with a 0.05 mm step, not 38000 Hz: an iteration takes a clock, one that steps 25, "
                      "steps come at most every 57 clocks") != std::string::npos);
  CHECK(!fs::exists(s.dir / "set"));
  const Result fast =
      run_dda(s, "vectors --bus --speeds --step 0.05 --accel 200 --min-speed 30 --clock 42000" + set + p);
  CHECK(fast.status == 0);
  CHECK(fs::exists(s.dir / "set" / "counts.hex"));
  // A feed move without F and no default feed: the block and the remedy.
  write_file(prog, "G1 X10\n");
  const Result nof = run_dda(s, "stats --speeds --dialect hnc" + p);
  CHECK(nof.status == 2);
  CHECK(nof.err.find(":1:1: block at line 1 (line): no feed rate: the program gives no F") != std::string::npos);
}
