// SPDX-License-Identifier: Apache-2.0
// The part-program reader (host/program/program.hpp, docs/programs.md): the G-code
// it accepts becomes the motion blocks the program describes, in nanometres of the
// plane; every class of bad input is one "FILE:LINE:COLUMN: message" at the right place.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "host/geometry/det_math.hpp"
#include "host/program/program.hpp"

using namespace dda::program;

namespace {

// The reader's tests are written in HNC-21T's dialect, the project's first (a plain
// program would be read as LinuxCNC's on a mill: docs/programs.md, "Dialects").
ReadOptions options_for(Machine m) {
  ReadOptions o;
  o.machine = m;
  o.dialect = Dialect::Hnc;
  return o;
}

constexpr Length mm(double v) { return Length(v * 1e6 + (v < 0 ? -0.5 : 0.5)); }

Program mill(const std::string& text) { return read(text, "p.nc", options_for(Machine::Mill)); }
Program lathe(const std::string& text) { return read(text, "p.nc", options_for(Machine::Lathe)); }

// The error a program raises ("" if none).
std::string error_of(const std::string& text, Machine m = Machine::Mill) {
  try {
    read(text, "p.nc", options_for(m));
  } catch (const ProgramError& e) {
    return e.what();
  }
  return "";
}

// Every field of a move, for comparing two reads.
std::string describe(const Move& m) {
  std::ostringstream os;
  os.precision(17);
  os << m.pos.line << ':' << m.pos.column << " N" << (m.block_number ? std::to_string(*m.block_number) : "-") << ' '
     << kind_name(m.kind) << " from " << m.from.u << ',' << m.from.v << " to " << m.to.u << ',' << m.to.v << " centre "
     << m.center.u << ',' << m.center.v << " r " << m.radius << (m.full ? " full" : "") << " a " << m.a << " b " << m.b
     << " q " << m.q_millideg << " F " << m.feed;
  return os.str();
}

// The examples/ directory, beside this file's tests/.
std::filesystem::path examples_dir() {
  return std::filesystem::path(__FILE__).parent_path().parent_path() / "examples";
}

}  // namespace

TEST_CASE("program: lines, modal motion, incremental moves, block numbers and comments", "[program]") {
  const Program p = mill(
      "%\n(a contour)\nN10 G21 G90 G00 X1 Y2 ; rapid to the start\nN20 G01 X10 Y5 F250\nX20\nG91 Y-5.5\nM30\nX99\n");
  REQUIRE(p.moves.size() == 4);
  CHECK(p.ended);
  CHECK(p.moves[0].kind == MoveKind::Rapid);
  CHECK(p.moves[0].to == Point2{mm(1), mm(2)});
  CHECK(*p.moves[0].block_number == 10);
  CHECK(p.moves[1].kind == MoveKind::Line);
  CHECK(p.moves[1].feed == 250);
  CHECK(p.moves[2].to == Point2{mm(20), mm(5)});  // G01 and F stay in force
  CHECK(p.moves[2].kind == MoveKind::Line);
  CHECK(p.moves[3].from == Point2{mm(20), mm(5)});
  CHECK(p.moves[3].to == Point2{mm(20), mm(-0.5)});
  CHECK(p.moves[3].pos.line == 6);
}

TEST_CASE("program: circular arcs by centre (off the lattice) and by radius, and full circles", "[program]") {
  const Program p = mill("G17 G02 X10 Y0 I5 J0\nG03 X0 Y0 R5.0003\nG02 X10 Y0 R-10\nG02 X10 Y0 I-2.5 J0.0004\n");
  REQUIRE(p.moves.size() == 4);
  CHECK(p.moves[0].kind == MoveKind::ArcCw);
  CHECK(p.moves[0].center == Point2{mm(5), 0});
  CHECK(p.moves[0].radius == mm(5));
  // R > 0: the short arc; from (10, 0) back to (0, 0) counter-clockwise: centre just
  // below the chord's middle.
  CHECK(std::llabs(p.moves[1].center.u - mm(5)) <= 1);
  CHECK(p.moves[1].center.v < 0);
  // R < 0: the long arc, clockwise from (0, 0) to (10, 0): centre above the chord.
  CHECK(p.moves[2].center.v == mm(std::sqrt(75.0)));
  CHECK(p.moves[2].radius == mm(10));
  // A full circle, its centre off the lattice.
  CHECK(p.moves[3].full);
  CHECK(p.moves[3].center == Point2{mm(7.5), mm(0.0004)});
}

TEST_CASE("program: a lathe programs X as a diameter (G36) or a radius (G37), U and W incrementally", "[program]") {
  const Program p = lathe("G00 X20 Z0\nG01 U10 W-5\nG37 X20\nG36 G02 X40 Z-15 R5\n");
  REQUIRE(p.moves.size() == 4);
  CHECK(p.moves[0].to == Point2{0, mm(10)});        // (Z, X radius)
  CHECK(p.moves[1].to == Point2{mm(-5), mm(15)});   // U10: 5 more in radius
  CHECK(p.moves[2].to == Point2{mm(-5), mm(20)});   // G37: X20 is the radius
  CHECK(p.moves[3].to == Point2{mm(-15), mm(20)});  // back to diameters
  CHECK(p.moves[3].kind == MoveKind::ArcCw);
  CHECK(error_of("G01 Y5\n", Machine::Lathe) == "p.nc:1:5: Y is not an axis of the lathe (Z and X)");
  CHECK(error_of("G17\n", Machine::Lathe) == "p.nc:1:1: a lathe works in G18 (Z and X)");
}

TEST_CASE("program: ellipse blocks G6.2 and G6.3 with and without a centre", "[program]") {
  // A 30-degree ellipse, a = 20, b = 10, centred at the origin; from its +a vertex to its
  // +b vertex counter-clockwise (lathe plane, radius programming).
  const double q = 30.0 * 3.14159265358979323846 / 180.0;
  const double ax = 20 * std::cos(q), ay = 20 * std::sin(q), bx = -10 * std::sin(q), by = 10 * std::cos(q);
  const std::string start = "G37 G00 Z" + std::to_string(ax) + " X" + std::to_string(ay) + "\n";
  const std::string end = " Z" + std::to_string(bx) + " X" + std::to_string(by);
  const Program with =
      lathe(start + "G6.3" + end + " A20 B10 Q30000 K" + std::to_string(-ax) + " I" + std::to_string(-ay) + "\n");
  const Program without = lathe(start + "G6.3" + end + " A20 B10 Q30000\n");
  REQUIRE(with.moves.size() == 2);
  REQUIRE(without.moves.size() == 2);
  for (const Program* p : {&with, &without}) {
    const Move& e = p->moves[1];
    CHECK(e.kind == MoveKind::EllipseCcw);
    CHECK(std::llabs(e.center.u) <= 2);  // the origin, to the rounding of 1e-6 mm
    CHECK(std::llabs(e.center.v) <= 2);
    CHECK(e.a == mm(20));
    CHECK(e.b == mm(10));
    CHECK(e.q_millideg == 30000);
  }
  // Clockwise between the same points without a centre: the shorter clockwise arc has
  // the centre on the other side.
  const Program cw = lathe(start + "G6.2" + end + " A20 B10 Q30000\n");
  CHECK(cw.moves[1].kind == MoveKind::EllipseCw);
  CHECK(std::hypot(double(cw.moves[1].center.u), double(cw.moves[1].center.v)) > double(mm(5)));
}

TEST_CASE("program: words that do not move the tool are accepted and reported", "[program]") {
  const Program p = mill("G54 T1 M03 S1200 M08\nG04 P500\nG01 X1 F100\nM09 M05\nM02\n");
  CHECK(p.moves.size() == 1);
  REQUIRE(p.ignored.size() == 9);
  CHECK(p.ignored[0].word == "G54");
  CHECK(p.ignored[3].word == "S1200");
  CHECK(p.ignored[5].word == "G04");
  CHECK(p.ignored[6].word == "P500");
}

TEST_CASE("program: inches (G20) are read exactly in nanometres", "[program]") {
  const Program p = mill("G20 G01 X1 Y-0.0005\n");
  CHECK(p.moves[0].to == Point2{25400000, -12700});
}

TEST_CASE("program: every class of bad input names its file, line and column", "[program]") {
  CHECK(error_of("G01 X1\nG01 E5\n") == "p.nc:2:5: unknown word E");
  CHECK(error_of("G12 X1\n") == "p.nc:1:1: unknown or unsupported code G12");
  CHECK(error_of("G01 X1.2.3\n") == "p.nc:1:9: unexpected '.'");
  CHECK(error_of("G01 X Y1\n") == "p.nc:1:7: a number must follow the letter");
  CHECK(error_of("G01 X1 (open comment\n") == "p.nc:1:21: a comment opened with '(' must close on its line");
  CHECK(error_of("X1\n") == "p.nc:1:1: a move with no motion mode (G00, G01, G02, G03, G6.2, G6.3) in force");
  CHECK(error_of("G02 X10 Y0\n") == "p.nc:1:1: an arc needs a centre (I, J) or a radius R");
  CHECK(error_of("G02 X10 Y0 I5 R5\n") == "p.nc:1:15: an arc takes a centre or a radius R, not both");
  CHECK(error_of("G02 X10 Y0 I4\n") ==
        "p.nc:1:1: the end is 2.0000 mm off the arc's circle (radius 4.0000 mm; tolerance 0.002 mm)");
  CHECK(error_of("G02 X10 Y0 I5.0009\n").empty());  // the radii differ by 0.0018 mm: within the tolerance
  CHECK(error_of("G02 X10 Y0 I5.0011\n") ==
        "p.nc:1:1: the end is 0.0022 mm off the arc's circle (radius 5.0011 mm; tolerance 0.002 mm)");
  CHECK(error_of("G02 X10 Y0 R4\n") ==
        "p.nc:1:12: the end is out of reach: 10.0000 mm from the start, more than twice R 4.0000 mm");
  CHECK(error_of("G02 X0 Y0 R4\n") == "p.nc:1:11: a full circle needs a centre, not R");
  CHECK(error_of("G6.2 X10 Y0 A0 B2\n") == "p.nc:1:13: the semi-axis A must be positive");
  CHECK(error_of("G6.2 X10 Y0 A5 B-2\n") == "p.nc:1:16: the semi-axis B must be positive");
  CHECK(error_of("G6.2 X10 Y0 A5\n") == "p.nc:1:1: an ellipse block needs its semi-axes A and B");
  CHECK(error_of("G6.2 X30 Y0 A5 B2\n") == "p.nc:1:1: the end is out of reach of an ellipse with these A, B and Q");
  CHECK(error_of("G41 G01 X1\n") ==
        "p.nc:1:1: tool radius compensation (G41/G42) is not supported: program the tool's path");
  // (A move of the axis normal to the plane is read; the planner refuses it until the
  // third axis: tests/test_program_plan.cpp.)
  CHECK(mill("G01 X1 Z5\n").moves.at(0).w_to == mm(5));
  CHECK(error_of("G01 G02 X1\n") == "p.nc:1:5: G01 and G02 in one block: one motion per block");
  CHECK(error_of("G01 X1 X2\n") == "p.nc:1:8: X twice in one block");
  CHECK(error_of("G01 X1 F0\n") == "p.nc:1:8: the feed F must be positive");
}

TEST_CASE("program macros: variables, expressions and words given by expressions", "[program]") {
  const Program p = mill(
      "#1=2\n#2=[#1+1]*4-6/3 (10)\n#[#1+1]=-#2 (#3 = -10)\nG01 X#2 Y[#3/4]\nX[SQRT[16]+ABS[-1]+INT[2.9]]\n"
      "Y[2*SIN[PI/6]] (1)\nX[ATAN[1]*4/PI] Y[TAN[0]+COS[0]]\n");
  REQUIRE(p.moves.size() == 4);
  CHECK(p.moves[0].to == Point2{mm(10), mm(-2.5)});
  CHECK(p.moves[1].to == Point2{mm(7), mm(-2.5)});
  CHECK(p.moves[2].to == Point2{mm(7), mm(1)});
  CHECK(p.moves[3].to == Point2{mm(1), mm(1)});
}

TEST_CASE("program macros: IF/ELSE, nested WHILE, subprograms with L and the position at a call", "[program]") {
  // A 3 x 2 grid: nested loops; IF picks a line or a rapid; %5 called twice per row.
  const Program p = mill(
      "%1\n#1=0\nWHILE #1 LT 2\n #2=0\n WHILE #2 LT 3\n  IF [#2 EQ 1]\n   G00 X#2 Y#1\n  ELSE\n   G01 X#2 Y#1\n"
      "  ENDIF\n  #2=#2+1\n ENDW\n M98 P5 L2\n #1=#1+1\nENDW\nM30\n%5\nG01 X[#30+1] Y#31\nM99\n");
  REQUIRE(p.moves.size() == 10);
  CHECK(p.moves[0].kind == MoveKind::Line);
  CHECK(p.moves[1].kind == MoveKind::Rapid);
  CHECK(p.moves[1].to == Point2{mm(1), 0});
  CHECK(p.moves[3].to == Point2{mm(3), 0});  // %5 from X2: X3, then X4
  CHECK(p.moves[4].to == Point2{mm(4), 0});
  CHECK(p.moves[4].pos.line == 18);
  CHECK(p.moves[9].to == Point2{mm(4), mm(1)});
  // On a lathe #30 is X as programmed (a diameter) and #32 is Z.
  const Program q = lathe("%1\nG00 X20 Z-3\nM98 P2\nM30\n%2\nG01 X[#30+2] Z[#32-1]\nM99\n");
  REQUIRE(q.moves.size() == 2);
  CHECK(q.moves[1].to == Point2{mm(-4), mm(11)});
}

TEST_CASE("program macros: the paper's loop runs 304 times, deterministically", "[program]") {
  // ../shared/spec/lathe-macro-program.md: the loop tests before it increments; in IEEE
  // double the 305th test sees theta = 136.0000000000002 degrees > 136 and stops.
  const Program p = lathe(
      "%1\nG00 X20 Z-12.679492\nM98 P2\nM30\n%2\n#11=#30\n#12=#32\n#1=PI/3\nWHILE #1 LE [PI*136/180]\n"
      "#1=#1+PI/720\n#11=25*COS[#1]*SIN[-PI/6]+15*SIN[#1]*COS[-PI/6]+5\n"
      "#12=25*COS[#1]*COS[-PI/6]-15*SIN[#1]*SIN[-PI/6]-30\nG01 X[2*#11] Z[#12]\nENDW\nM99\n");
  REQUIRE(p.moves.size() == 1 + 304);
  // The last chord ends at the 136-degree point (to the nanometre).
  CHECK(std::llabs(p.moves.back().to.u - mm(-40.364226)) <= 1);
  CHECK(std::llabs(p.moves.back().to.v - mm(23.015624)) <= 1);
}

TEST_CASE("program macros: every class of bad macro is one FILE:LINE:COLUMN message", "[program]") {
  CHECK(error_of("G01 X#7\n") == "p.nc:1:6: #7 is undefined: no value was assigned to it");
  CHECK(error_of("#1=0\n#2=5/#1\n") == "p.nc:2:5: division by zero");
  CHECK(error_of("#1=SQRT[-4]\n") == "p.nc:1:4: SQRT of a negative number (-4)");
  CHECK(error_of("#1=1\nWHILE #1 LT 3\nG01 X#1\n") == "p.nc:2:1: WHILE without ENDW in its program");
  CHECK(error_of("G01 X1\nELSE\n") == "p.nc:2:1: ELSE without IF");
  CHECK(error_of("ENDW\n") == "p.nc:1:1: ENDW without WHILE");
  CHECK(error_of("IF [1]\nG01 X1\n") == "p.nc:1:1: IF without ENDIF in its program");
  CHECK(error_of("IF [1]\nWHILE [1]\nENDIF\n") == "p.nc:3:1: ENDIF inside an open WHILE");
  CHECK(error_of("%1\nM98 P7\nM30\n%2\nM99\n") == "p.nc:2:5: M98 calls program %7: there is none");
  CHECK(error_of("%1\nM98 P2\n%2\nM98 P2\nM99\n") == "p.nc:4:5: subprogram calls nested deeper than 8");
  CHECK(error_of("#1=0\nWHILE [1]\n#1=#1+1\nENDW\n") ==
        "p.nc:2:1: more than 10000000 lines executed: a loop that does not end?");
  CHECK(error_of("G01 X1\nM99\n") == "p.nc:2:1: M99 in the main program: no caller to return to");
  CHECK(error_of("#1=[2\n") == "p.nc:1:6: ']' expected: an expression's bracket must close");
  CHECK(error_of("#1 5\n") ==
        "p.nc:1:4: '=' expected: a macro variable at the start of a line is assigned (#n = expression)");
  CHECK(error_of("#1=*3\n") == "p.nc:1:4: an expression expected (a number, #n, [..], PI or a function)");
  CHECK(error_of("#1.5=3\n") == "p.nc:1:1: #1.5: a variable number is a whole number from 0 to 999");
  CHECK(error_of("M98 X1 P2\n") == "p.nc:1:5: X in an M98 block: a call moves nothing");
  CHECK(error_of("G01 X1 L2\n") == "p.nc:1:8: L is read only with M98");
}

TEST_CASE("det_math: the macro language's sines are within 5 units in the last place", "[program]") {
  // Against the local long-double libm (an independent reference; det_math itself uses
  // none), over seeded draws up to 1e5 radians.
  std::mt19937_64 rng(16);
  const auto ulps = [](double got, long double want) {
    const double w = double(want);
    const double ulp = std::nextafter(std::fabs(w), 1e300) - std::fabs(w);
    return double(std::fabs((long double)got - want)) / ulp;
  };
  double worst = 0;
  for (int i = 0; i < 200000; ++i) {
    const double scale = i % 3 == 0 ? 1e5 : i % 3 == 1 ? 7.0 : 1e-3;
    const double x = (double(rng() % 2000000001) / 1e9 - 1.0) * scale;
    worst = std::max(worst, ulps(dda::det::sin(x), std::sin((long double)x)));
    worst = std::max(worst, ulps(dda::det::cos(x), std::cos((long double)x)));
    worst = std::max(worst, ulps(dda::det::atan(3 * x), std::atan((long double)(3 * x))));
  }
  CHECK(worst <= 5.0);
  CHECK(dda::det::sin(0.0) == 0.0);
  CHECK(dda::det::cos(0.0) == 1.0);
  CHECK(dda::det::atan(0.0) == 0.0);
}

TEST_CASE("program macros: M98 with M99 in one block, exact literals, comments, duplicate programs, long lines",
          "[program]") {
  // A call and a return in one block, or a call in a dwell block: refused, not deferred.
  CHECK(error_of("%1\nM98 P2\nM30\n%2\nM98 P3 M99\n%3\nM99\n") ==
        "p.nc:5:1: M98 and M99 in one block: call or return, not both");
  CHECK(error_of("%1\nG04 X1 M98 P2\n%2\nM99\n") ==
        "p.nc:2:8: M98 in a dwell (G04) block: a call stands in its own block");
  // Decimal literals are read correctly rounded, as IEEE 754 reads them: 0.07 == 7/100.
  CHECK(mill("IF [0.07 EQ 7/100]\nG01 X1\nELSE\nG01 X2\nENDIF\n").moves[0].to.u == mm(1));
  // Comments before a statement; a comparison before a digit; a byte-order mark.
  CHECK(mill("(set up) #1=5\nN10 (c) #2=#1 LT3\nG01 X#1 Y#2\n").moves[0].to == Point2{mm(5), 0});
  CHECK(mill("\xEF\xBB\xBFG01 X1\n").moves.size() == 1);
  // A program number defined twice; a line too long to be G-code; deep nesting stays an error.
  CHECK(error_of("%2\nG01 X1\n%2\nM99\n") == "p.nc:3:1: program %2 is defined twice (first at line 1)");
  CHECK(error_of("#1=" + std::string(5000, '[') + "1" + std::string(5000, ']') + "\n") ==
        "p.nc:1:4097: a line of more than 4096 characters");
  CHECK(error_of("#1=" + std::string(2000, '[') + "1" + std::string(2000, ']') + "\nG01 X#1\n").empty());
  // #30 is in the program's unit: inches under G20.
  const Program q = lathe("%1\nG20 G00 X2 Z-1\nM98 P2\nM30\n%2\nG01 X[#30+1] Z#32\nM99\n");
  CHECK(q.moves[1].to == Point2{mm(-25.4), mm(38.1)});
  // An ellipse block that starts at its centre: the reader's message.
  CHECK(error_of("G00 X20 Z0\nG6.3 X20 Z-10 A10 B5 K0 I0\n", Machine::Lathe) ==
        "p.nc:2:1: the start is 5.0000 mm off the ellipse (tolerance 0.002 mm)");
}

TEST_CASE("program stream: read_stream gives every example's moves as read() does", "[program]") {
  std::size_t programs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examples_dir())) {
    if (entry.path().extension() != ".ngc") continue;
    INFO(entry.path().filename().string());
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    ReadOptions ro;
    if (text.str().find("--machine lathe") != std::string::npos) ro.machine = Machine::Lathe;
    const Program whole = read(text.str(), "x.ngc", ro);
    std::vector<Move> streamed;
    const auto file = open_program(entry.path().string());
    const ReadSummary s = read_stream(*file, "x.ngc", ro, [&](const Move& m) { streamed.push_back(m); });
    REQUIRE(!whole.moves.empty());
    REQUIRE(streamed.size() == whole.moves.size());
    for (std::size_t k = 0; k < streamed.size(); ++k) CHECK(describe(streamed[k]) == describe(whole.moves[k]));
    CHECK(s.ignored_count == whole.ignored.size());
    REQUIRE(s.ignored.size() == whole.ignored.size());
    for (std::size_t k = 0; k < s.ignored.size(); ++k) CHECK(s.ignored[k].word == whole.ignored[k].word);
    CHECK(s.ended == whole.ended);
    CHECK(s.start == whole.start);
    ++programs;
  }
  CHECK(programs >= 10);
}

TEST_CASE("program stream: open_program refuses a directory and a missing file", "[program]") {
  const std::string dir = examples_dir().string();
  CHECK_THROWS_WITH(open_program(dir), "program = '" + dir + "' is invalid: it is a directory");
  const std::string missing = dir + "/no-such-program.ngc";
  CHECK_THROWS_WITH(open_program(missing),
                    "program = '" + missing + "' is invalid: cannot read it (No such file or directory)");
}

TEST_CASE("program stream: the first kMaxIgnoredKept ignored words are kept and all counted", "[program]") {
  std::string text = "G01 X1\n";
  for (int k = 0; k < 1500; ++k) text += "S100\n";
  std::istringstream in(text);
  std::size_t moves = 0;
  const ReadSummary s = read_stream(in, "p.nc", options_for(Machine::Mill), [&](const Move&) { ++moves; });
  CHECK(moves == 1);
  CHECK(s.ignored_count == 1500);
  REQUIRE(s.ignored.size() == kMaxIgnoredKept);
  CHECK(s.ignored.front().pos.line == 2);
  CHECK(s.ignored.back().pos.line == 1 + kMaxIgnoredKept);
  CHECK(s.ignored.back().word == "S100");
  CHECK(read(text, "p.nc", options_for(Machine::Mill)).ignored.size() == 1500);  // read() keeps them all
}

TEST_CASE("program stream: bad text is refused before any move, a run-time error after the moves before it",
          "[program]") {
  std::size_t moves = 0;
  const auto count = [&](const Move&) { ++moves; };
  std::istringstream syntax("G01 X1\nX2\nG01 X1.2.3\n");
  CHECK_THROWS_WITH(read_stream(syntax, "p.nc", options_for(Machine::Mill), count), "p.nc:3:9: unexpected '.'");
  std::istringstream unmatched("G01 X1\r\nX2\r\nENDW\r\n");
  CHECK_THROWS_WITH(read_stream(unmatched, "p.nc", options_for(Machine::Mill), count), "p.nc:3:1: ENDW without WHILE");
  CHECK(moves == 0);
  std::istringstream undefined("G01 X1\nX2\nX#4\n");
  CHECK_THROWS_WITH(read_stream(undefined, "p.nc", options_for(Machine::Mill), count),
                    "p.nc:3:2: #4 is undefined: no value was assigned to it");
  CHECK(moves == 2);
}
