// SPDX-License-Identifier: Apache-2.0
// What a careless user gives the `dda` command: each gets one line naming what is wrong
// and exit status 2, and no file the tool did not write is ever deleted or overwritten.
#define CATCH_CONFIG_MAIN
#include <signal.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "tests/cli_helpers.hpp"

namespace {

const std::string kPaper = "--a 10 --b 6 --bits 4 --preload zero";

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
}

// Files in `dir` whose names hold ".tmp." or ".old.": a run's temporary files.
int temporaries(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    const auto name = e.path().filename().string();
    n += name.find(".tmp.") != std::string::npos || name.find(".old.") != std::string::npos;
  }
  return n;
}

// dda ARGS is refused: exit status 2, one line that starts "dda: error: " + want, and
// no file left in the scratch directory (no output, no temporary file).
void expect_refused(const Scratch& s, const std::string& args, const std::string& want) {
  const Result r = run_dda(s, args);
  INFO("dda " << args << "\nstderr: " << r.err);
  CHECK(r.status == 2);
  CHECK(r.err.rfind("dda: error: " + want, 0) == 0);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(s.user_files() == 0);
}

}  // namespace

TEST_CASE("cli input: vectors --out-dir never deletes a file it did not write", "[cli][files]") {
  Scratch s;
  const fs::path dir = s.dir / "set";
  fs::create_directories(dir);
  write_file(dir / "manifest.json", "{}");
  write_file(dir / "notes.txt", "mine");
  Result r = run_dda(s, "vectors " + kPaper + " --out-dir " + dir.string());
  CHECK(r.status == 2);
  CHECK(r.err.find("is not one `dda vectors` wrote: nothing is replaced") != std::string::npos);
  CHECK(slurp(dir / "notes.txt") == "mine");
  CHECK(slurp(dir / "manifest.json") == "{}");

  // A set the tool wrote, with a user's file put beside it: refused, the file survives.
  const fs::path set = s.dir / "own";
  REQUIRE(run_dda(s, "vectors " + kPaper + " --out-dir " + set.string()).status == 0);
  write_file(set / "notes.txt", "mine");
  r = run_dda(s, "vectors " + kPaper + " --out-dir " + set.string());
  CHECK(r.status == 2);
  CHECK(r.err ==
        "dda: error: out-dir = '" + set.string() +
            "' is invalid: it holds 'notes.txt', which is not a file of its vector set: nothing is replaced\n");
  CHECK(slurp(set / "notes.txt") == "mine");

  // Without the foreign file the set is replaced, and nothing temporary is left.
  fs::remove(set / "notes.txt");
  r = run_dda(s, "vectors --line --from 0,0 --to 7,3 --out-dir " + set.string());
  CHECK(r.status == 0);
  CHECK(slurp(set / "manifest.json").find("--line") != std::string::npos);
  CHECK(temporaries(s.dir) == 0);

  // A non-empty directory without a manifest, and a file: refused.
  const fs::path plain = s.dir / "plain";
  fs::create_directories(plain);
  write_file(plain / "a.txt", "x");
  r = run_dda(s, "vectors " + kPaper + " --out-dir " + plain.string());
  CHECK(r.status == 2);
  CHECK(r.err.find("holds no vector set (no manifest.json)") != std::string::npos);
  CHECK(slurp(plain / "a.txt") == "x");
  r = run_dda(s, "vectors " + kPaper + " --out-dir " + (plain / "a.txt").string());
  CHECK(r.status == 2);
  CHECK(r.err.find("it exists and is not a directory") != std::string::npos);
}

TEST_CASE("cli input: a run ended by SIGTERM leaves no temporary file", "[cli][files]") {
  Scratch s;
  const fs::path out = s.dir / "trace.csv";
  // A long run (an arc of 2^20 steps written as a trace), stopped once its temporary
  // file exists.
  const std::string cmd =
      std::string(DDA_BIN) + " trace --a 1048576 --b 1048575 --out " + out.string() + " >/dev/null 2>&1 & echo $!";
  FILE* p = ::popen(cmd.c_str(), "r");
  REQUIRE(p);
  int pid = 0;
  REQUIRE(std::fscanf(p, "%d", &pid) == 1);
  ::pclose(p);
  bool seen = false;
  for (int i = 0; i < 200 && !seen; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    seen = temporaries(s.dir) > 0;
  }
  REQUIRE(seen);
  ::kill(pid, SIGTERM);
  for (int i = 0; i < 200 && ::kill(pid, 0) == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  CHECK(temporaries(s.dir) == 0);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("cli input: a killed run's temporary file is removed by the next run", "[cli][files]") {
  Scratch s;
  const fs::path out = s.dir / "path.csv";
  // A PID that is not running (above the kernel's pid_max).
  write_file(s.dir / "path.csv.tmp.999999999", "left by a killed run");
  write_file(s.dir / "path.csv.tmp.notapid", "a user's file");
  CHECK(run_dda(s, "path " + kPaper + " --out " + out.string()).status == 0);
  CHECK_FALSE(fs::exists(s.dir / "path.csv.tmp.999999999"));
  CHECK(slurp(s.dir / "path.csv.tmp.notapid") == "a user's file");
}

TEST_CASE("cli input: --out - writes standard output", "[cli]") {
  Scratch s;
  const Result a = run_dda(s, "path " + kPaper);
  const Result b = run_dda(s, "path " + kPaper + " --out -");
  CHECK(b.status == 0);
  CHECK(b.out == a.out);
  CHECK_FALSE(fs::exists(s.dir / "-"));
}

TEST_CASE("cli input: plot writes SVG only", "[cli][plot][errors]") {
  Scratch s;
  const Result r = run_dda(s, "plot " + kPaper + " --out " + (s.dir / "x.png").string());
  CHECK(r.status == 2);
  CHECK(r.err == "dda: error: out = '" + (s.dir / "x.png").string() +
                     "' is invalid: plot writes SVG (a file name ending in .svg)\n");
  CHECK(s.user_files() == 0);
}

TEST_CASE("cli input: a directory or a missing file as the program", "[cli][program][errors]") {
  Scratch s;
  Result r = run_dda(s, "stats --program " + s.dir.string());
  CHECK(r.status == 2);
  CHECK(r.err == "dda: error: program = '" + s.dir.string() + "' is invalid: it is a directory\n");
  r = run_dda(s, "stats --program " + (s.dir / "none.ngc").string());
  CHECK(r.status == 2);
  CHECK(r.err.rfind("dda: error: program = '" + (s.dir / "none.ngc").string() + "' is invalid: cannot read it", 0) ==
        0);
}

TEST_CASE("cli input: numbers out of range, nan and inf are named", "[cli][errors]") {
  Scratch s;
  const std::string dir = " --out-dir " + (s.dir / "set").string();
  const std::pair<std::string, std::string> cases[] = {
      {"stats --a 99999999999999999999 --b 6", "a = '99999999999999999999' is out of range"},
      {"stats --a nan --b 6", "a = 'nan' is invalid"},
      {"stats --a 10 --b 6 --angle inf", "angle = 'inf' is invalid"},
      {"stats --a 10 --b 6 --from-theta nan", "from-theta = 'nan' is invalid"},
      {"vectors " + kPaper + " --seed -1" + dir, "seed = '-1' is out of range: an integer from 0 to"},
      {"vectors " + kPaper + " --ce-percent 0" + dir, "ce-percent = '0' is out of range: an integer from 1 to 100"},
      {"vectors " + kPaper + " --bus --ce-percent 0" + dir, "ce-percent = '0' is out of range"},
      {"vectors " + kPaper + " --ce-percent 101" + dir, "ce-percent = '101' is out of range"},
      {"vectors " + kPaper + " --bus --feed-rate nan --clock 1000" + dir, "feed-rate = nan is out of range"},
      {"vectors " + kPaper + " --bus --feed-rate 100 --clock inf" + dir, "clock = inf is out of range"},
      {"vectors " + kPaper + " --bus --feed-rate -5 --clock 1000" + dir, "feed-rate = -5 is out of range"},
  };
  for (const auto& [args, want] : cases) expect_refused(s, args, want);
}

// The highest feed a refusal names: "at most N steps/s".
double named_feed(const std::string& err) {
  const auto at = err.find("at most ");
  return at == std::string::npos ? 0 : std::stod(err.substr(at + 8));
}

// The pin monitor's speed of the feed from `dda feed --summary`'s row (its 12th cell).
double pin_speed_of_feed(const std::string& row) {
  std::vector<std::string> cells;
  std::stringstream ss(row);
  for (std::string cell; std::getline(ss, cell, '|');) cells.push_back(cell);
  REQUIRE(cells.size() > 12);
  return std::stod(cells[12]);
}

TEST_CASE("cli input: a feed the block cannot follow is refused, naming the highest it follows",
          "[cli][errors][pacer]") {
  Scratch s;
  // A full circle and a 4:1 ellipse at 40 MHz and 4e7 steps/s^2, a quarter of 300 x 200 at
  // 2 MHz: far beyond, refused with one line on each command that paces an arc.
  const std::string circle = "--a 2000 --b 2000 --from 2000,0 --to 2000,0 --accel 4e7 --clock 4e7";
  const std::string ellipse = "--a 2000 --b 500 --from 2000,0 --to 2000,0 --accel 4e7 --clock 4e7";
  const std::string quarter =
      "--a 300 --b 200 --preload half --from-theta 0 --to-theta 90 --accel 1.5e7 --vmin 1000 "
      "--clock 2e6";
  const std::string refusal = "--feed-rate 5000000 steps/s is beyond what the block follows on this path";
  expect_refused(s, "feed " + circle + " --feed-rate 5e6", refusal);
  expect_refused(s, "plot " + circle + " --feed-rate 5e6 --speed " + (s.dir / "v.svg").string(), refusal);
  expect_refused(s,
                 "vectors --bus " + circle + " --feed-rate 5e6 --timing 2,2,3,1 --out-dir " + (s.dir / "set").string(),
                 refusal);
  for (const std::string& arc : {circle, ellipse, quarter}) {
    const Result r = run_dda(s, "feed " + arc + " --feed-rate 1e6");
    INFO(arc << "\nstderr: " << r.err);
    REQUIRE(r.status == 2);
    const double most = named_feed(r.err);
    REQUIRE(most > 1000);
    // At the named feed the pacer's run passes the pin monitor (speed within 1%,
    // acceleration within 5% of A) and reaches the feed at cruise; 2% above it is refused.
    const Result at = run_dda(s, "feed " + arc + " --feed-rate " + std::to_string(std::llround(most)) + " --summary");
    INFO(at.err);
    REQUIRE(at.status == 0);
    CHECK(pin_speed_of_feed(at.out) > 0.99);
    CHECK(run_dda(s, "feed " + arc + " --feed-rate " + std::to_string(std::llround(most * 1.02))).status == 2);
  }
  // A short line at a high feed never reaches what the block cannot follow: the ramp at A
  // ends before it, so nothing is refused.
  CHECK(run_dda(s, "feed --line --from 0,0 --to 3000,1000 --feed-rate 5e6 --accel 4e7 --clock 4e7 --summary").status ==
        0);
}

TEST_CASE("cli input: each command's help lists its own options only", "[cli][errors]") {
  Scratch s;
  // (command, options its help must list, options it must not)
  const std::tuple<std::string, std::vector<std::string>, std::vector<std::string>> cases[] = {
      {"trace", {"--engine", "--vcd", "--out", "--program", "--format"}, {"--out-dir", "--bus", "--summary"}},
      {"stats", {"--engine", "--program", "(default text)"}, {"--out-dir", "--seed", "--label"}},
      {"feed", {"--out", "--summary", "(default markdown)"}, {"--engine", "--vcd", "--program", "--machine"}},
      {"vectors", {"--out-dir", "--bus", "--seed", "--program", "--vcd"}, {"--engine", "--out "}},
      {"gen-params", {"--kind"}, {"--a ", "--engine"}},
  };
  for (const auto& [cmd, has, lacks] : cases) {
    const Result r = run_dda(s, cmd + " --help");
    INFO("dda " << cmd << " --help\n" << r.out);
    CHECK(r.status == 0);
    for (const std::string& o : has) CHECK(r.out.find(o) != std::string::npos);
    for (const std::string& o : lacks) CHECK(r.out.find(o) == std::string::npos);
  }
}

TEST_CASE("cli input: an option that does not apply is refused, not ignored", "[cli][errors]") {
  Scratch s;
  const std::pair<std::string, std::string> cases[] = {
      {"feed " + kPaper + " --engine rtl", "--engine is invalid with feed"},
      {"feed " + kPaper + " --vcd " + (s.dir / "w.vcd").string(), "--vcd is invalid with feed"},
      {"vectors " + kPaper + " --vcd " + (s.dir / "w.vcd").string() + " --out-dir " + (s.dir / "set").string(),
       "--vcd goes with --bus in vectors"},
      {"vectors " + kPaper + " --engine rtl --out-dir " + (s.dir / "set").string(),
       "--engine is invalid with vectors: vectors come from the golden model"},
      {"vectors " + kPaper + " --out " + (s.dir / "x").string() + " --out-dir " + (s.dir / "set").string(),
       "--out is invalid with vectors: a vector set is written to --out-dir DIR"},
      {"feed " + kPaper + " --seed 3", "--seed is invalid with feed (dda feed --help lists its options)"},
      {"stats " + kPaper + " --no-such-option 1", "option --no-such-option is unknown (dda stats --help"},
      {"stats " + kPaper + " stray", "'stray' is unexpected: dda stats takes options only"},
      {"stats " + kPaper + " --machine lathe", "--machine, --start and --step go with --program FILE"},
  };
  for (const auto& [args, want] : cases) expect_refused(s, args, want);
  // feed writes --out as every other table does.
  const fs::path out = s.dir / "feed.md";
  const Result r = run_dda(s, "feed " + kPaper + " --out " + out.string());
  CHECK(r.status == 0);
  CHECK(r.out.empty());
  CHECK(slurp(out).rfind("| piece |", 0) == 0);
}

TEST_CASE("cli input: the pacer's run takes its options together and refuses a stop that never ends", "[cli][errors]") {
  Scratch s;
  const std::string pace = "feed " + kPaper + " --feed-rate 2000 --accel 2e5 --clock 40e6";
  const std::pair<std::string, std::string> cases[] = {
      {"feed " + kPaper + " --accel 2e5", "--accel, --clock and --vmin go with --feed-rate"},
      {"feed " + kPaper + " --format csv", "--format csv is the pacer's profile"},
      {pace + " --vmin 0", "--vmin 0 with an acceleration never ends the last piece"},
      {pace + " --vmin 3000", "--vmin = 3000 is out of range: steps/s, 0 to the feed"},
      {pace + " --vmin -5", "--vmin = -5 is out of range: steps/s, 0 to the feed"},
      {"feed " + kPaper + " --vmin -1", "--accel, --clock and --vmin go with --feed-rate"},
      {"feed " + kPaper + " --feed-rate 0 --accel 2e5 --clock 40e6", "--feed-rate = 0 is out of range"},
      {"feed " + kPaper + " --feed-rate nan --accel 2e5 --clock 40e6", "--feed-rate = nan is out of range"},
      {"feed " + kPaper + " --feed-rate 2000 --accel 2e5", "--clock = 0 is out of range"},
      {"feed " + kPaper + " --feed-rate 5e7 --accel 2e5 --clock 40e6",
       "pace: 50000000 steps/s is not below one step per clock"},
      {pace + " --format csv --summary", "--summary is a markdown row: not with --format csv"},
  };
  for (const auto& [args, want] : cases) expect_refused(s, args, want);
  // The profile: a header and one row per iteration, ending on the arc's end point.
  const Result r = run_dda(s, pace + " --format csv");
  REQUIRE(r.status == 0);
  CHECK(r.out.rfind("iteration,clock,time_s,commanded_steps_per_s,path_steps_per_s,path_steps,x,y,z\n", 0) == 0);
  CHECK(r.out.find("\n27,") != std::string::npos);
  REQUIRE(r.out.size() > 7);
  CHECK(r.out.compare(r.out.size() - 7, 7, ",0,6,0\n") == 0);
}

TEST_CASE("cli input: characters named as characters, and a refused program prints nothing", "[cli][program][errors]") {
  Scratch s;
  const std::pair<std::string, std::string> cases[] = {
      {"G01 X1\nG01 Y2 \xc3\xa9\n", ":2:8: unexpected character '\xc3\xa9' (U+00E9)\n"},
      {"G01 X1\nG01 Y2 \xff\n", ":2:8: unexpected byte 0xFF (not UTF-8 text)\n"},
      {"G01 X1\x07\n", ":1:7: unexpected control character 0x07\n"},
  };
  for (const auto& [text, want] : cases) {
    const fs::path prog = s.dir / "p.ngc";
    write_file(prog, text);
    for (const std::string cmd : {"stats", "path", "trace"}) {
      const Result r = run_dda(s, cmd + " --program " + prog.string());
      INFO("dda " << cmd << " on: " << text);
      CHECK(r.status == 2);
      CHECK(r.out.empty());
      CHECK(r.err == prog.string() + want);
    }
  }
}

TEST_CASE("cli input: a vector set larger than --max-size is refused before it is written", "[cli][errors]") {
  Scratch s;
  const std::string set = (s.dir / "set").string();
  // (arguments, the start of the message)
  const std::pair<std::string, std::string> cases[] = {
      // Counting stops at the limit, and the whole is estimated.
      {"vectors " + kPaper + " --out-dir " + set + " --max-size 100", "the vector set would take about "},
      {"vectors --a 20000 --b 15000 --out-dir " + set + " --max-size 64K", "the vector set would take about "},
      {"vectors " + kPaper + " --bus --out-dir " + set + " --max-size 1K", "the vector set would take "},
      {"vectors " + kPaper + " --out-dir " + set + " --max-size 0", "max-size = '0' is out of range"},
      {"vectors " + kPaper + " --out-dir " + set + " --max-size 2P", "max-size = '2P' is invalid"},
      {"vectors " + kPaper + " --out-dir " + set + " --max-size -5", "max-size = '-5' is invalid"},
  };
  for (const auto& [args, want] : cases) expect_refused(s, args, want);
  // Within the limit the set is written, and byte for byte as without one.
  const std::string other = (s.dir / "other").string();
  REQUIRE(run_dda(s, "vectors " + kPaper + " --out-dir " + set + " --max-size 1M").status == 0);
  REQUIRE(run_dda(s, "vectors " + kPaper + " --out-dir " + other).status == 0);
  // A limit one byte below the set's size: counted to its end, the size is exact. (The
  // manifest records the command line, so the set is larger by the longer command.)
  std::uintmax_t size = 0;
  for (const auto& e : fs::directory_iterator(other)) size += fs::file_size(e.path());
  const std::string limit = " --max-size " + std::to_string(size - 1), third = (s.dir / "third").string();
  const Result exact = run_dda(s, "vectors " + kPaper + " --out-dir " + third + limit);
  const std::uintmax_t want = size + third.size() - other.size() + limit.size();
  INFO(exact.err);
  CHECK(exact.status == 2);
  CHECK(exact.err.find("would take about") == std::string::npos);
  CHECK(exact.err.find("(" + std::to_string(want) + " bytes)") != std::string::npos);
  CHECK(!fs::exists(s.dir / "third"));
  for (const char* f : {"cmds.hex", "cycle_in.hex", "cycle_exp.hex", "cycles.csv", "iter.hex", "iterations.csv"}) {
    INFO(f);
    CHECK(slurp(fs::path(set) / f) == slurp(fs::path(other) / f));
  }
}

TEST_CASE("cli input: plot --speed draws the pacer's run, under the feed, and refuses what it cannot draw",
          "[cli][plot][errors]") {
  Scratch s;
  const std::string arc = "plot --a 600 --b 200 --preload half";
  const std::string pace = " --feed-rate 2e5 --accel 2e7 --clock 40e6";
  const std::string svg = (s.dir / "speed.svg").string(), png = (s.dir / "speed.png").string();
  const std::pair<std::string, std::string> cases[] = {
      {arc + " --speed " + svg, "--speed runs the pacer: give --feed-rate, --accel, --clock"},
      {arc + pace + " --out " + svg, "--feed-rate, --accel, --clock and --vmin go with --speed FILE.svg"},
      {arc + pace + " --speed " + png, "speed = '" + png + "' is invalid: plot writes SVG"},
      {arc + pace + " --speed -", "speed = '-' is invalid: plot writes SVG"},
      {arc + pace + " --speed " + svg + " --engine rtl", "--engine, --vcd and --view go with --out"},
      {arc + pace + " --speed " + svg + " --view xz", "--engine, --vcd and --view go with --out"},
      {arc + pace + " --speed " + svg + " --out " + svg, "--speed and --out name the same file"},
      {arc + pace + " --speed ''", "speed = '' is invalid: plot writes SVG"},
      {arc + pace + " --speed " + svg + " --vmin -5", "--vmin = -5 is out of range"},
      {arc + " --vmin -1 --out " + svg, "--feed-rate, --accel, --clock and --vmin go with --speed FILE.svg"},
      {arc + " --feed-rate 0 --accel 2e7 --clock 40e6 --speed " + svg, "--feed-rate = 0 is out of range"},
      {"plot --program " + std::string(DDA_SOURCE_DIR) + "/examples/circles.ngc" + pace + " --speed " + svg,
       "--feed-rate and --vmin are an arc's, in steps: a program's feeds come from its F words"},
      {arc + " --feed-rate 2e5 --accel 2e7 --clock 40e6 --vmin 0 --speed " + svg, "--vmin 0 with an acceleration"},
  };
  for (const auto& [args, want] : cases) expect_refused(s, args, want);
  // The picture: the commanded and the path speed, the feed, the ideal trapezoid; no
  // point of either speed above the feed's line (SVG's y grows downwards).
  const Result r = run_dda(s, arc + pace + " --speed " + svg);
  REQUIRE(r.status == 0);
  CHECK(r.out.empty());
  std::ifstream in(svg);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto attr = [&](const std::string& cls, const std::string& name) {
    const auto at = text.find("class=\"" + cls + "\"");
    REQUIRE(at != std::string::npos);
    const auto from = text.find(name + "=\"", at) + name.size() + 2;
    return text.substr(from, text.find('"', from) - from);
  };
  const double feed_y = std::stod(attr("feed", "y1"));
  for (const char* cls : {"commanded", "path-speed"}) {
    std::istringstream pts(attr(cls, "points"));
    std::string xy;
    int n = 0;
    while (pts >> xy) {
      CHECK(std::stod(xy.substr(xy.find(',') + 1)) >= feed_y - 0.05);
      ++n;
    }
    CHECK(n > 100);
  }
  CHECK(text.find("class=\"ideal\"") != std::string::npos);
  CHECK(text.find("feed 200000 steps/s") != std::string::npos);
  // With --out, the path's picture too.
  const std::string path_svg = (s.dir / "path.svg").string();
  REQUIRE(run_dda(s, arc + pace + " --speed " + svg + " --out " + path_svg).status == 0);
  CHECK(fs::exists(path_svg));
}
