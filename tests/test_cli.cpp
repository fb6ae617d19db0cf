// SPDX-License-Identifier: Apache-2.0
// The `dda` command as a user runs it: outputs, exit status, error messages, files.
#define CATCH_CONFIG_MAIN
#include <sys/wait.h>
#include <unistd.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include "host/accuracy/golden.hpp"
#include "tests/cli_helpers.hpp"

namespace {

const std::string kPaper = "--a 10 --b 6 --bits 4 --preload zero";  // the paper's mode, named

std::string fmt_distance(const std::string& prefix, double d) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", d);
  return prefix + buf;
}

// Bad input: status 2, one line on stderr naming the value and the rule, nothing written.
void expect_usage_error(const std::string& args, const std::string& needle) {
  Scratch s;
  // (A plot is written to an SVG file, every other output to any file.)
  const fs::path out = s.dir / (args.rfind("plot", 0) == 0 ? "out.svg" : "out.txt");
  const Result r = run_dda(s, args + " --out " + out.string());
  INFO("dda " << args << "\nstderr: " << r.err);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.rfind("dda: error: ", 0) == 0);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.err.find(needle) != std::string::npos);
  CHECK(s.user_files() == 0);
}

}  // namespace

TEST_CASE("cli: trace csv of the paper's example is byte-identical to the spec", "[cli]") {
  Scratch s;
  const Result r = run_dda(s, "trace " + kPaper + " --format csv");
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out == slurp(std::string(DDA_TEST_DATA) + "/table1-exact-trace.csv"));
}

TEST_CASE("cli: --out writes the same bytes to a file", "[cli]") {
  Scratch s;
  const fs::path out = s.dir / "t.csv";
  const Result r = run_dda(s, "trace " + kPaper + " --out " + out.string());
  CHECK(r.status == 0);
  CHECK(r.out.empty());
  CHECK(slurp(out) == slurp(std::string(DDA_TEST_DATA) + "/table1-exact-trace.csv"));
  CHECK(s.user_files() == 1);  // no temporary file left behind
}

TEST_CASE("cli: trace table prints row 0 and the rows with a pulse", "[cli]") {
  Scratch s;
  const Result r = run_dda(s, "trace " + kPaper + " --format table");
  CHECK(r.status == 0);
  std::istringstream is(r.out);
  std::string line;
  int rows = 0;
  while (std::getline(is, line)) rows += line.rfind("| ", 0) == 0 && line.find("iter") == std::string::npos;
  CHECK(rows == 16);  // row 0 + 15 iterations with a pulse
  CHECK(r.out.find("|    27 |    10.0000 |    24.3333 |  1 |     0 |") != std::string::npos);
  CHECK(r.out.find("stopped") != std::string::npos);
}

TEST_CASE("cli: trace json holds the full records", "[cli]") {
  Scratch s;
  const Result r = run_dda(s, "trace " + kPaper + " --format json");
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["cap"] == 960);
  CHECK(j["scale"] == 60);
  REQUIRE(j["iterations"].size() == 27);
  const auto& last = j["iterations"][26];
  CHECK(last["iter"] == 27);
  CHECK(last["sum_x"] == 1460);
  CHECK(last["step_x"] == true);
  CHECK(last["x"] == 0);
  CHECK(last["y"] == 6);
}

TEST_CASE("cli: path of the paper's example", "[cli]") {
  Scratch s;
  const Result r = run_dda(s, "path " + kPaper + " --format csv");
  CHECK(r.status == 0);
  CHECK(r.out ==
        "point,x,y\n0,10,0\n1,10,1\n2,10,2\n3,10,3\n4,9,3\n5,9,4\n6,8,4\n7,7,5\n8,6,5\n9,6,6\n"
        "10,5,6\n11,4,6\n12,3,6\n13,2,6\n14,1,6\n15,0,6\n");
}

TEST_CASE("cli: stats of the paper's example", "[cli]") {
  Scratch s;
  Result r = run_dda(s, "stats " + kPaper);
  CHECK(r.status == 0);
  CHECK(r.out.find("iterations: 27\n") != std::string::npos);
  CHECK(r.out.find("moves: 15\n") != std::string::npos);
  CHECK(r.out.find("pulses_x: 10\n") != std::string::npos);
  CHECK(r.out.find("pulses_y: 6\n") != std::string::npos);
  CHECK(r.out.find("points: 16\n") != std::string::npos);
  CHECK(r.out.find("max_dev: 1.10") != std::string::npos);
  CHECK(r.out.find(" at (6,6)\n") != std::string::npos);
  CHECK(r.out.find("mean_dev: ") != std::string::npos);
  r = run_dda(s, "stats " + kPaper + " --format json");
  CHECK(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["moves"] == 15);
  CHECK(j["max_dev_at"] == nlohmann::json::array({6, 6}));
  CHECK(j["max_dev"].get<double>() == Approx(1.104).margin(5e-4));
}

TEST_CASE("cli: bad semi-axes", "[cli][errors]") {
  expect_usage_error("trace --a 0 --b 6 --bits 4", "a = 0 is invalid: a semi-axis must be a positive integer");
  expect_usage_error("trace --a -3 --b 6 --bits 4", "a = -3 is invalid");
  expect_usage_error("trace --a 2.5 --b 6 --bits 4", "a = '2.5' is invalid: a semi-axis must be a positive integer");
  expect_usage_error("path --a 10 --b x --bits 4", "b = 'x' is invalid");
  expect_usage_error("stats --a 10 --b 0 --bits 4", "b = 0 is invalid");
  expect_usage_error("stats --a 4000000000 --b 4000000000 --bits 32", "out of range");
}

TEST_CASE("cli: bad accumulator width", "[cli][errors]") {
  expect_usage_error("trace --a 10 --b 6 --bits 3",
                     "bits = 3 is invalid: n must satisfy 2^n >= max(a, b) (smallest valid n here is 4)");
  expect_usage_error("trace --a 10 --b 6 --bits 0", "bits = 0 is invalid");
  expect_usage_error("trace --a 10 --b 6 --bits four", "bits = 'four' is invalid");
  expect_usage_error("trace --a 16 --b 2 --bits 4 --preload zero --from 0,3 --to -16,0",
                     "bits = 4 is too small for this arc");
}

TEST_CASE("cli: points off the ellipse, out of order, unreachable, malformed", "[cli][errors]") {
  // The distance in the message is the library's (tested against a reference elsewhere).
  expect_usage_error("trace " + kPaper + " --from 3,0",
                     fmt_distance("from point (3,0) is ", dda::ellipse_distance(10, 6, 3, 0)) +
                         " steps from the ellipse: start and end must lie within 1.0000 step of it");
  expect_usage_error("path " + kPaper + " --to 0,8", "to point (0,8) is 2.0000 steps from the ellipse");
  // Ends the counted path cannot reach are reached: see "cli: lattice ends".
  expect_usage_error("trace " + kPaper + " --from 1,2 --from-theta 30", "from and from-theta are both given");
  expect_usage_error("trace " + kPaper + " --to-theta north", "to-theta = 'north' is invalid: an angle in degrees");
  expect_usage_error("trace " + kPaper + " --from 1,2,3", "from = '1,2,3' is invalid: a point is two integers X,Y");
  expect_usage_error("trace " + kPaper + " --to abc", "to = 'abc' is invalid");
}

TEST_CASE("cli: bad options", "[cli][errors]") {
  expect_usage_error("trace --a 10 --b 6 --bits 4 --preload full", "preload = 'full' is invalid: use zero or half");
  expect_usage_error("trace " + kPaper + " --format xml", "format = 'xml' is invalid: use one of csv, json, table");
  expect_usage_error("stats " + kPaper + " --format csv", "--format csv goes with --program");
  expect_usage_error("trace " + kPaper + " --engine spice", "engine = 'spice' is invalid");
  expect_usage_error("trace " + kPaper + " --dir left", "dir = 'left' is invalid: use ccw or cw");
  expect_usage_error("trace " + kPaper + " --angle 30.1234567",
                     "angle = '30.1234567' is invalid: an angle in degrees, a decimal with at most 6 decimals");
  expect_usage_error("trace " + kPaper + " --angle 1e3", "angle = '1e3' is invalid");
  expect_usage_error("trace " + kPaper + " --from-theta 1234567890", "from-theta = '1234567890' is invalid");
  expect_usage_error("path --a 32768 --b 100 --angle 30 --bits 31", "bits = 31 is too large for this rotated ellipse");
  expect_usage_error("path --a 500 --b 300 --angle 30 --from-theta 10 --to 0,0", "to point (0,0) is");
  expect_usage_error("trace " + kPaper + " --angle x", "angle = 'x' is invalid");
  expect_usage_error("trace " + kPaper + " --center 1", "center = '1' is invalid: a point is two integers X,Y");
  expect_usage_error("trace --a 10 --b 6 --bits 21",
                     "bits = 21 is invalid: at most 16 bits above the smallest valid width (4)");
  expect_usage_error("stats --a 120000 --b 120000 --bits 17 --engine rtl",
                     "cap = 1887436800000000 does not fit the hardware's 51-bit field: it must be in [0, 2^50)");
  expect_usage_error("--bogus", "option '--bogus' is unknown here");
  expect_usage_error("trace " + kPaper + " --frobnicate 1", "frobnicate");
  expect_usage_error("trace --b 6 --bits 4", "--a is required");
  expect_usage_error("nosuchcommand", "command 'nosuchcommand' is unknown: use one of trace, path, stats");
}

TEST_CASE("cli: I/O failure exits 1 and leaves no file", "[cli][errors]") {
  Scratch s;
  const Result r = run_dda(s, "trace " + kPaper + " --out " + (s.dir / "no" / "such" / "dir.csv").string());
  CHECK(r.status == 1);
  CHECK(r.err.rfind("dda: error: cannot write", 0) == 0);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(s.user_files() == 0);
}

TEST_CASE("cli: an existing output file is replaced only on success", "[cli][errors]") {
  Scratch s;
  const fs::path out = s.dir / "keep.csv";
  std::ofstream(out) << "previous\n";
  const Result r = run_dda(s, "trace --a 10 --b 6 --bits 3 --out " + out.string());
  CHECK(r.status == 2);
  CHECK(slurp(out) == "previous\n");
}

TEST_CASE("cli: help and version exit 0", "[cli]") {
  Scratch s;
  Result r = run_dda(s, "--help");
  CHECK(r.status == 0);
  CHECK(r.out.find("trace") != std::string::npos);
  r = run_dda(s, "trace --help");
  CHECK(r.status == 0);
  CHECK(r.out.find("--preload") != std::string::npos);
  r = run_dda(s, "--version");
  CHECK(r.status == 0);
}

TEST_CASE("cli: every engine prints the golden engine's rows", "[cli][engines]") {
  Scratch s;
  for (const std::string engine : {"systemc", "rtl"}) {
    INFO("engine " << engine);
    for (const std::string sub : {"trace --format csv", "trace --format json", "path", "stats"}) {
      for (const std::string& arc :
           {kPaper, std::string("--a 37 --b 900 --bits 14 --preload half --from 30,526 --to 3,898")}) {
        INFO(sub << ' ' << arc);
        const Result g = run_dda(s, sub + " " + arc + " --engine golden");
        const Result e = run_dda(s, sub + " " + arc + " --engine " + engine);
        CHECK(g.status == 0);
        CHECK(e.status == 0);
        CHECK(e.err.empty());
        CHECK(e.out == g.out);
      }
    }
  }
}

// The lathe paper's oblique ellipse: 695,000 iterations in 5 pieces through
// all three engines, the same path, ending exactly on the end point the golden plan
// names.
TEST_CASE("cli: the lathe example runs through every engine with the same path", "[cli][engines]") {
  Scratch s;
  const std::string arc =
      "--a 25000 --b 15000 --angle 330 --center -30000,5000 --from-theta 60 --to-theta 136 --dir ccw";
  for (const std::string pre : {"zero", "half"}) {
    INFO("preload " << pre);
    const Result g = run_dda(s, "path " + arc + " --preload " + pre);
    const Result st = run_dda(s, "stats --format json " + arc + " --preload " + pre);
    REQUIRE(g.status == 0);
    REQUIRE(st.status == 0);
    // The path's last point (rows "index,x,y") is the plan's end point.
    const auto last = g.out.substr(g.out.rfind('\n', g.out.size() - 2) + 1);
    const auto j = nlohmann::json::parse(st.out);
    INFO(last);
    CHECK(last.substr(last.find(',') + 1) ==
          std::to_string(j["to"][0].get<long long>()) + "," + std::to_string(j["to"][1].get<long long>()) + "\n");
    CHECK(j["pieces"].get<int>() >= 2);
    for (const std::string engine : {"systemc", "rtl"}) {
      INFO("engine " << engine);
      const Result e = run_dda(s, "path " + arc + " --preload " + pre + " --engine " + engine);
      CHECK(e.status == 0);
      CHECK(e.out == g.out);
    }
  }
}

TEST_CASE("cli: --vcd writes the systemc and rtl waveforms, and is refused for golden", "[cli][engines]") {
  Scratch s;
  for (const std::string engine : {"systemc", "rtl"}) {
    INFO("engine " << engine);
    const fs::path vcd = s.dir / (engine + ".vcd");
    const Result r = run_dda(s, "trace " + kPaper + " --engine " + engine + " --vcd " + vcd.string());
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out == slurp(std::string(DDA_TEST_DATA) + "/table1-exact-trace.csv"));  // rows only
    const std::string v = slurp(vcd);
    CHECK(v.find("$scope module u_int_x $end") != std::string::npos);
    CHECK(v.find(" jr_q ") != std::string::npos);
  }
  expect_usage_error("trace " + kPaper + " --vcd x.vcd", "--vcd is invalid with engine golden");
}

TEST_CASE("cli: waveform and output files appear only on success", "[cli][errors]") {
  Scratch s;
  // An unwritable waveform path: a one-line error and status 1, before any run.
  for (const std::string engine : {"systemc", "rtl"}) {
    const Result r =
        run_dda(s, "trace " + kPaper + " --engine " + engine + " --vcd " + (s.dir / "no" / "w.vcd").string());
    CHECK(r.status == 1);
    CHECK(r.err.rfind("dda: error: cannot write", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  // The waveform is not left behind when the output cannot be written.
  const Result r = run_dda(s, "trace " + kPaper + " --engine rtl --vcd " + (s.dir / "w.vcd").string() + " --out " +
                                  (s.dir / "no" / "t.csv").string());
  CHECK(r.status == 1);
  CHECK(s.user_files() == 0);
  // The same file for both: refused.
  const Result same = run_dda(
      s, "trace " + kPaper + " --engine rtl --vcd " + (s.dir / "x").string() + " --out " + (s.dir / "x").string());
  CHECK(same.status == 2);
  CHECK(same.err.find("--vcd and --out name the same file") != std::string::npos);
  CHECK(s.user_files() == 0);
  // The waveform gets exactly the requested name, whatever its extension.
  const Result ok = run_dda(s, "trace " + kPaper + " --engine systemc --vcd " + (s.dir / "w.fst").string());
  CHECK(ok.status == 0);
  CHECK(fs::exists(s.dir / "w.fst"));
  CHECK(s.user_files() == 1);
}

TEST_CASE("cli: a waveform must go to a regular file", "[cli][errors]") {
  Scratch s;
  const fs::path fifo = s.dir / "fifo";
  REQUIRE(std::system(("mkfifo " + fifo.string()).c_str()) == 0);
  const Result r = run_dda(s, "stats " + kPaper + " --engine systemc --vcd " + fifo.string());
  CHECK(r.status == 2);
  CHECK(r.err.find("is invalid: a waveform is written to a regular file") != std::string::npos);
  CHECK(fs::is_fifo(fifo));
}

TEST_CASE("cli: --out to a device writes to it and leaves it a device", "[cli]") {
  Scratch s;
  const Result r = run_dda(s, "stats " + kPaper + " --out /dev/null");
  CHECK(r.status == 0);
  CHECK(r.out.empty());
  CHECK(fs::is_character_file("/dev/null"));
}

TEST_CASE("cli: whole ellipses, every quadrant, both directions", "[cli][ellipse]") {
  Scratch s;
  // Three quarters counter-clockwise from the top to the right vertex.
  Result r = run_dda(s, "path " + kPaper + " --from 0,6 --to 10,0");
  CHECK(r.status == 0);
  CHECK(r.out.rfind("point,x,y\n0,0,6\n", 0) == 0);
  CHECK(r.out.find(",-10,0\n") != std::string::npos);
  CHECK(r.out.find(",0,-6\n") != std::string::npos);
  CHECK(r.out.substr(r.out.size() - 6) == ",10,0\n");
  // A full turn: every X and Y step of the four quarters, back at the start.
  r = run_dda(s, "stats " + kPaper + " --from 10,0 --to 10,0 --format json");
  REQUIRE(r.status == 0);
  auto j = nlohmann::json::parse(r.out);
  CHECK(j["pulses_x"] == 40);
  CHECK(j["pulses_y"] == 24);
  CHECK(j["points"] == 61);  // 60 moves on a closed path: the start is counted once more
  // Clockwise from the right vertex down to the bottom, about a moved centre.
  r = run_dda(s, "path --a 10 --b 6 --bits 5 --preload half --center 100,-50 --dir cw --from 110,-50 --to 100,-56");
  CHECK(r.status == 0);
  CHECK(r.out.rfind("point,x,y\n0,110,-50\n", 0) == 0);
  CHECK(r.out.substr(r.out.size() - 9) == ",100,-56\n");
  // Parametric angles and a quarter turn: a = 10 now points along Y.
  r = run_dda(s, "path --a 10 --b 6 --bits 5 --angle 90 --from-theta 0 --to-theta 90");
  CHECK(r.status == 0);
  CHECK(r.out.rfind("point,x,y\n0,0,10\n", 0) == 0);
  CHECK(r.out.substr(r.out.size() - 6) == ",-6,0\n");
}

TEST_CASE("cli: plot draws the paper's example: 16 markers, axes, legend, the largest deviation", "[cli][plot]") {
  Scratch s;
  const fs::path svg = s.dir / "paper.svg";
  const Result r = run_dda(s, "plot " + kPaper + " --out " + svg.string());
  REQUIRE(r.status == 0);
  CHECK(r.out.empty());
  std::ifstream in(svg);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto count = [&](const std::string& needle) {
    std::size_t n = 0;
    for (auto i = text.find(needle); i != std::string::npos; i = text.find(needle, i + 1)) ++n;
    return n;
  };
  CHECK(text.rfind("<svg ", 0) == 0);
  CHECK(text.find("</svg>") != std::string::npos);
  CHECK(count("<circle class=\"pt\"") == 16);  // the 16 points of the spec's path
  CHECK(count("x (steps)") == 1);
  CHECK(count("y (steps)") == 1);
  CHECK(count("<g class=\"legend\">") == 1);
  CHECK(count("<linearGradient") == 1);
  CHECK(count("max 1.10 @ (6,6)") == 1);
  CHECK(count("class=\"ideal\"") == 1);
  // Every marker's colour and tooltip come from its distance: the worst one is red.
  CHECK(text.find("<title>(6,6) 1.104</title>") != std::string::npos);
}

TEST_CASE("cli: plot refuses to write to stdout and names bad formats", "[cli][plot][errors]") {
  Scratch s;
  const Result r = run_dda(s, "plot " + kPaper);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err == "dda: error: plot needs --out FILE.svg: it writes a picture, not text\n");
  expect_usage_error("plot " + kPaper + " --format png", "format = 'png' is invalid");
  expect_usage_error("plot --a 10 --b 6 --bits 2", "bits = 2 is invalid");
}

// Half preload is every subcommand's default; the paper's mode is named.
TEST_CASE("cli: half preload is the default, the paper's mode is --preload zero", "[cli]") {
  Scratch s;
  const Result d = run_dda(s, "stats --a 10 --b 6 --bits 4");
  CHECK(d.status == 0);
  CHECK(d.out.find("preload: half\n") != std::string::npos);
  const Result h = run_dda(s, "trace --a 10 --b 6 --bits 4 --preload half");
  CHECK(run_dda(s, "trace --a 10 --b 6 --bits 4").out == h.out);
  CHECK(run_dda(s, "trace " + kPaper).out != h.out);
}

// A straight line through the same core: Bresenham's line with half preload (every point
// within half a step of the line between its ends, checked here against that line itself), the same
// rows on every engine, cut into pieces past the counters' range, in vectors and plots.
TEST_CASE("cli: --line runs on every engine, in vectors and in plots", "[cli][line]") {
  Scratch s;
  for (const std::string& line :
       {std::string("--line --from 3,-2 --to -17,5"), std::string("--line --from 0,0 --to 0,9"),
        std::string("--line --from 1,1 --to 140000,-70001 --preload zero")}) {
    INFO(line);
    const Result g = run_dda(s, "path " + line);
    REQUIRE(g.status == 0);
    for (const std::string engine : {"systemc", "rtl"}) {
      INFO("engine " << engine);
      CHECK(run_dda(s, "path " + line + " --engine " + engine).out == g.out);
      CHECK(run_dda(s, "trace " + line + " --engine " + engine).out == run_dda(s, "trace " + line).out);
    }
  }
  // Every point of the half-preload line within half a step of the line between its ends, the ends exact.
  const Result p = run_dda(s, "path --line --from 3,-2 --to -17,5 --format csv");
  std::istringstream rows(p.out);
  std::string row;
  std::getline(rows, row);  // header
  int n = 0;
  long long x = 0, y = 0;
  while (std::getline(rows, row)) {
    long long i = 0;
    char c1 = 0, c2 = 0;
    std::istringstream(row) >> i >> c1 >> x >> c2 >> y;
    // Distance from the infinite line through (3,-2) and (-17,5): |7 (x - 3) + 20 (y + 2)| / sqrt(449).
    CHECK(std::abs(7.0 * double(x - 3) + 20.0 * double(y + 2)) / std::sqrt(449.0) <= 0.5);
    ++n;
  }
  CHECK(n == 21);  // one iteration per step of the longer axis: 20 moves
  CHECK(x == -17);
  CHECK(y == 5);
  const Result st = run_dda(s, "stats --line --from 1,1 --to 140000,-70001 --format json");
  REQUIRE(st.status == 0);
  const auto j = nlohmann::json::parse(st.out);
  CHECK(j["pieces"] == 2);  // longer than the 17-bit counters
  CHECK(j["max_dev"].get<double>() <= 0.5);
  CHECK(j["iterations"] == 139999);
  const Result t = run_dda(s, "trace --line --from 0,0 --to 7,3 --format table");
  CHECK(t.out.find("units: steps (scaled values / the capacity 7)") != std::string::npos);
  // Vectors and a plot of a line.
  const auto dir = s.dir / "vec_line";
  CHECK(run_dda(s, "vectors --line --from 0,0 --to 7,3 --out-dir " + dir.string()).status == 0);
  CHECK(std::filesystem::exists(dir / "manifest.json"));
  const auto svg = s.dir / "line.svg";
  CHECK(run_dda(s, "plot --line --from 0,0 --to 7,3 --out " + svg.string()).status == 0);
  CHECK(std::filesystem::file_size(svg) > 0);
}

TEST_CASE("cli: --line with ellipse options, or of length 0, is bad usage", "[cli][line][errors]") {
  expect_usage_error("path --line --from 0,0 --to 0,0", "has length 0");
  expect_usage_error("path --line --from 0,0 --to 5,1 --a 3", "--a is invalid with --line");
  expect_usage_error("path --line --from 0,0 --to 5,1 --angle 30", "--angle is invalid with --line");
  expect_usage_error("path --line --from 0,0 --to 5,1 --dir cw", "--dir is invalid with --line");
  expect_usage_error("path --line --from 0,0", "--line needs --from X,Y and --to X,Y");
  expect_usage_error("path --b 5 --from 0,0", "--a is required");
}

// Lattice start and end points anywhere within a step of the curve, as part
// programs give them, are accepted and the path starts and ends exactly there; full
// turns close, given by points or by angles.
TEST_CASE("cli: lattice ends that the counted path missed are reached, full turns close", "[cli][ellipse]") {
  Scratch s;
  const struct {
    std::string arc;
    std::string from, to;
  } cases[] = {
      {"--a 37 --b 8 --center 50,-2202 --from 15,-2204 --to 84,-2199 --dir cw", "15,-2204", "84,-2199"},
      {"--a 10 --b 6 --bits 4 --preload zero --from 9,3 --to 0,7", "9,3", "0,7"},
      {"--a 10 --b 6 --bits 4 --preload zero --from 10,0 --to 9,0 --dir cw", "10,0", "9,0"},
      {"--a 100 --b 60 --from-theta 30 --to-theta 30", "87,30", "87,30"},
      {"--a 737 --b 5 --from-theta 131.028 --to-theta 131.028", "-484,4", "-484,4"},
      {"--a 12 --b 1529 --center -1464,-2740 --dir cw --from -1455,-3799 --to -1452,-3118", "-1455,-3799",
       "-1452,-3118"},
      {"--a 13 --b 442 --center 1004,1488 --dir cw --angle 346.452379 --from 1099,1851 --to 1088,1864", "1099,1851",
       "1088,1864"},
      // Tips sharper than the lattice, crossed in short lines by the anchored planner.
      {"--a 2 --b 113 --angle 280.613133 --from-theta 0 --to-theta 0", "0,-2", "0,-2"},
      {"--a 100 --b 4 --angle 30 --from-theta 10 --to-theta 10", "85,50", "85,50"},
  };
  for (const auto& c : cases) {
    INFO(c.arc);
    const Result r = run_dda(s, "path " + c.arc);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("\n0," + c.from + "\n") != std::string::npos);  // the first row
    const auto last = r.out.substr(r.out.rfind('\n', r.out.size() - 2) + 1);
    CHECK(last.substr(last.find(',') + 1) == c.to + "\n");
    for (const std::string engine : {"systemc", "rtl"}) {
      INFO("engine " << engine);
      CHECK(run_dda(s, "path " + c.arc + " --engine " + engine).out == r.out);
    }
  }
}

// The default width fits the hardware's fields whenever some width does.
TEST_CASE("cli: the default width runs on the hardware engines", "[cli][engines]") {
  Scratch s;
  const Result g = run_dda(s, "stats --a 50000 --b 50000");
  REQUIRE(g.status == 0);
  CHECK(g.out.find("bits: 18\n") != std::string::npos);  // 2^18 * 50000^2 < 2^50
  const Result r = run_dda(s, "stats --a 50000 --b 50000 --engine rtl");
  CHECK(r.status == 0);
  CHECK(r.out == g.out);
}

TEST_CASE("cli: vectors --bus writes the motion block's set, and --pipelined and --abort-after need --bus",
          "[cli][motion][errors]") {
  Scratch s;
  const fs::path dir = s.dir / "bvec";
  Result r = run_dda(s, "vectors " + kPaper + " --bus --pipelined --abort-after 20 --out-dir " + dir.string());
  INFO("stderr: " << r.err);
  REQUIRE(r.status == 0);
  for (const char* f : {"counts.hex", "cycle_in.hex", "cycle_exp.hex", "manifest.json"}) CHECK(fs::exists(dir / f));
  const auto m = nlohmann::json::parse(slurp(dir / "manifest.json"));
  CHECK(m["bus_cycles"] == "pipelined");
  CHECK(m["abort_after"] == 20);
  CHECK(m["layout"]["cycle_exp"][0]["name"] == "wb_ack_o");
  const fs::path bad = s.dir / "bad";
  r = run_dda(s, "vectors " + kPaper + " --pipelined --out-dir " + bad.string());
  CHECK(r.status == 2);
  CHECK(r.err ==
        "dda: error: --pipelined, --bridge, --build, --abort-after, --timing*, --polarity, --feed*, --clock, "
        "--accel, --vmin, --override*, --hold-at, --resume-at, --soft-stop-at and --watchdog go with --bus only\n");
  CHECK_FALSE(fs::exists(bad));
  r = run_dda(s, "vectors " + kPaper + " --bus --abort-after 0 --out-dir " + bad.string());
  CHECK(r.status == 2);
  CHECK_FALSE(fs::exists(bad));
}

TEST_CASE("cli: vectors --bus --bridge writes the bridged block's set, and careless bridge options are refused",
          "[cli][motion][bridges][errors]") {
  Scratch s;
  for (const std::string bridge : {"axil", "spi"}) {
    const fs::path dir = s.dir / bridge;
    Result r = run_dda(s, "vectors " + kPaper + " --bus --bridge " + bridge + " --out-dir " + dir.string());
    INFO("stderr: " << r.err);
    REQUIRE(r.status == 0);
    const auto m = nlohmann::json::parse(slurp(dir / "manifest.json"));
    CHECK(m["bus"] == bridge);
    CHECK_FALSE(m.contains("bus_cycles"));
    CHECK(m["layout"]["cycle_exp"][0]["name"] == (bridge == "axil" ? "s_awready_o" : "spi_miso_o"));
  }
  const fs::path bad = s.dir / "bad";
  Result r = run_dda(s, "vectors " + kPaper + " --bus --bridge axil --pipelined --out-dir " + bad.string());
  CHECK(r.status == 2);
  CHECK(r.err == "dda: error: --pipelined chooses Wishbone cycles: it does not go with --bridge\n");
  r = run_dda(s, "vectors " + kPaper + " --bus --bridge i2c --out-dir " + bad.string());
  CHECK(r.status == 2);
  r = run_dda(s, "vectors " + kPaper + " --bridge spi --out-dir " + bad.string());
  CHECK(r.status == 2);
  r = run_dda(s, "vectors --bus --bridge spi --io-scenario estop --pipelined --out-dir " + bad.string());
  CHECK(r.status == 2);
  CHECK_FALSE(fs::exists(bad));
}

TEST_CASE("cli: vectors --bus --build writes a build's set and refuses what the build does not have",
          "[cli][motion][errors]") {
  Scratch s;
  // The board's build behind SPI, a machine-input scenario: its manifest names the build.
  const fs::path dir = s.dir / "estop";
  Result r = run_dda(s, "vectors --bus --bridge spi --build pacer=0 --io-scenario estop --out-dir " + dir.string());
  INFO("stderr: " << r.err);
  REQUIRE(r.status == 0);
  const auto m = nlohmann::json::parse(slurp(dir / "manifest.json"));
  CHECK(m["build"] == "depth_log2=7,inputs=1,axes=3,pacer=0");
  CHECK(m["bus"] == "spi");
  CHECK(m["io_scenario"] == "estop");
  // The default build's manifest names it too.
  const fs::path plain = s.dir / "plain";
  r = run_dda(s, "vectors " + kPaper + " --bus --out-dir " + plain.string());
  REQUIRE(r.status == 0);
  CHECK(nlohmann::json::parse(slurp(plain / "manifest.json"))["build"] == "depth_log2=7,inputs=1,axes=3,pacer=1");
  const fs::path bad = s.dir / "bad";
  const std::vector<std::pair<std::string, std::string>> refused{
      {"--bus --build pacer=0 --feed-rate 1000 --clock 1e6 --accel 1e5",
       "--accel, --speeds and --override pace entries by the pacer: the build has none (pacer=0; --feed-rate paces "
       "by the feed increment)"},
      {"--bus --build pacer=0 --override 50",
       "--accel, --speeds and --override pace entries by the pacer: the build has none (pacer=0; --feed-rate paces "
       "by the feed increment)"},
      {"--bus --build pacer=2", "build: pacer=2 is not a whole number in 0 .. 1"},
      {"--bus --build lathe=1", "build: no choice 'lathe' (the choices: depth_log2, inputs, axes, pacer)"},
      {"--build pacer=0", ""},
      {"--bus --build pacer=0 --vcd " + (s.dir / "w.vcd").string(),
       "--vcd runs the default build's RTL: it does not go with another --build"},
  };
  for (const auto& [opts, err] : refused) {
    INFO(opts);
    r = run_dda(s, "vectors " + kPaper + " " + opts + " --out-dir " + bad.string());
    CHECK(r.status == 2);
    if (!err.empty()) CHECK(r.err == "dda: error: " + err + "\n");
    CHECK_FALSE(fs::exists(bad));
  }
  r = run_dda(s, "vectors --bus --build inputs=0 --io-scenario homing --out-dir " + bad.string());
  CHECK(r.status == 2);
  CHECK(r.err == "dda: error: --io-scenario needs the machine inputs: the build has none (inputs=0)\n");
  // A scenario the build or the bus cannot run is refused before it runs.
  const std::vector<std::pair<std::string, std::string>> scenario_refused{
      {"--build pacer=0 --io-scenario limit-decel",
       "--io-scenario limit-decel needs the pacer (its ramped stops, its registers): the build has none (pacer=0)"},
      {"--build axes=2 --io-scenario homing",
       "--io-scenario homing moves or reads the third axis: the build has two axes (axes=2)"},
      {"--bridge spi --io-scenario overflow",
       "--io-scenario overflow times its accesses closer than an SPI frame (some 300 clocks): run it on Wishbone or "
       "--bridge axil"},
  };
  for (const auto& [opts, err] : scenario_refused) {
    INFO(opts);
    r = run_dda(s, "vectors --bus " + opts + " --out-dir " + bad.string());
    CHECK(r.status == 2);
    CHECK(r.err == "dda: error: " + err + "\n");
    CHECK_FALSE(fs::exists(bad));
  }
  // Two axes: a move of Z is refused, a planar arc is written.
  r = run_dda(s, "vectors --line --from 0,0,0 --to 30,20,10 --bus --build axes=2 --out-dir " + bad.string());
  CHECK(r.status == 2);
  CHECK(r.err ==
        "dda: error: the build has two axes (axes=2): a move of the third axis or on another plane is refused\n");
  CHECK_FALSE(fs::exists(bad));
  r = run_dda(s, "vectors " + kPaper + " --bus --build axes=2 --out-dir " + (s.dir / "lathe").string());
  CHECK(r.status == 0);
}
