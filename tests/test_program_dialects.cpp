// SPDX-License-Identifier: Apache-2.0
// The reader's dialects (docs/programs.md, "Dialects"): LinuxCNC's RS274NGC (O-words,
// named parameters, its functions and precedence, offsets), Fanuc's program numbers and
// calls, and where they differ from HNC's. Values are LinuxCNC's own, as its rs274
// prints them (scripts/rs274-compare.py checks whole programs the same way).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "host/program/program.hpp"

using namespace dda::program;

namespace {

constexpr Length mm(double v) { return Length(v * 1e6 + (v < 0 ? -0.5 : 0.5)); }

Program read_in(const std::string& text, std::optional<Dialect> d, Machine m = Machine::Mill,
                bool block_delete = false) {
  ReadOptions o;
  o.machine = m;
  o.dialect = d;
  o.block_delete = block_delete;
  return read(text, "p.nc", o);
}
Program lcnc(const std::string& text) { return read_in(text, Dialect::LinuxCnc); }

std::string error_in(const std::string& text, std::optional<Dialect> d, Machine m = Machine::Mill) {
  try {
    read_in(text, d, m);
  } catch (const ProgramError& e) {
    return e.what();
  }
  return "";
}

// The X of the program's first move, in mm: how a test reads a value out.
double x_of(const std::string& text, std::optional<Dialect> d) {
  const Program p = read_in(text, d);
  REQUIRE(!p.moves.empty());
  return double(p.moves.front().to.u) / double(kNmPerMm);
}
double lcnc_value(const std::string& expr) { return x_of("F100\nG1 X[" + expr + "]\nM2\n", Dialect::LinuxCnc); }

}  // namespace

TEST_CASE("dialects: a program says its dialect by its first line only one dialect reads", "[program]") {
  CHECK(read_in("o100 sub\no100 endsub\nM2\n", std::nullopt).dialect == Dialect::LinuxCnc);
  CHECK(read_in("#<x> = 1\nM2\n", std::nullopt).dialect == Dialect::LinuxCnc);
  CHECK(read_in("%\nO1234\nG0 X1\nM30\n%\n", std::nullopt).dialect == Dialect::Fanuc);
  CHECK(read_in("%1\nG0 X1\nM30\n", std::nullopt).dialect == Dialect::Hnc);
  CHECK(read_in("#1=1\nWHILE #1 LT 2\n#1=#1+1\nENDW\n", std::nullopt).dialect == Dialect::Hnc);
  CHECK(read_in("G6.2 X10 Y0 A5 B3 I5 J0\n", std::nullopt).dialect == Dialect::Hnc);
  // A plain program: LinuxCNC's on a mill, HNC's on a lathe.
  CHECK(read_in("G0 X1\nM2\n", std::nullopt).dialect == Dialect::LinuxCnc);
  CHECK(read_in("G0 X1 Z1\nM2\n", std::nullopt, Machine::Lathe).dialect == Dialect::Hnc);
  // --dialect wins over what the program shows.
  CHECK(read_in("G0 X1\nM2\n", Dialect::Fanuc).dialect == Dialect::Fanuc);
}

TEST_CASE("dialects: LinuxCNC's functions take degrees and its precedence groups AND with OR", "[program]") {
  CHECK(lcnc_value("SIN[30]") == Approx(0.5).margin(1e-6));
  CHECK(lcnc_value("COS[60] + TAN[45]") == Approx(1.5).margin(1e-6));
  CHECK(lcnc_value("ATAN[1]/[2]") == Approx(26.565051).margin(1e-6));        // two arguments
  CHECK(lcnc_value("ASIN[1/2.1+-0.345]") == Approx(7.538391).margin(1e-6));  // rs274's value
  CHECK(lcnc_value("ACOS[0.5]") == Approx(60).margin(1e-6));
  CHECK(lcnc_value("[1 OR 0 AND 0]") == 0);  // (1 OR 0) AND 0: one level, from the left
  CHECK(lcnc_value("2 ** 3 ** 2") == 64);    // ** groups from the left too
  CHECK(lcnc_value("-2 ** 2") == 4);         // unary minus binds tightest
  CHECK(lcnc_value("-7 MOD 3") == 2);        // of the divisor's sign
  CHECK(lcnc_value("1 XOR 1") == 0);
  CHECK(lcnc_value("1 + 2 * 3 GT 6") == 1);  // comparisons below + and *
  CHECK(lcnc_value("FIX[-2.5] * 100 + FUP[-2.5] * 10 + ROUND[-2.5]") == Approx(-300 - 20 - 3));
  CHECK(lcnc_value("EXP[1]") == Approx(2.718282).margin(1e-6));
  CHECK(lcnc_value("LN[10]") == Approx(2.302585).margin(1e-6));
  // An ASIN divided by a bracket is a division, not a second argument (rs274: 2.000545).
  CHECK(lcnc_value("2 + ASIN[1/2.1+-0.345] / [ATAN[FIX[4.4] * 2.1 * SQRT[16.8]] /[-18]]**2") ==
        Approx(2.000545).margin(1e-6));
  // HNC reads the same words its own way: radians, one-argument ATAN, AND above OR.
  CHECK(x_of("G1 X[SIN[30]]\n", Dialect::Hnc) == Approx(std::sin(30.0)).margin(1e-6));
  CHECK(x_of("G1 X[ATAN[1]/[2]]\n", Dialect::Hnc) == Approx(std::atan(1.0) / 2).margin(1e-6));
  CHECK(x_of("G1 X[1 OR 0 AND 0]\n", Dialect::Hnc) == 1);
  CHECK(error_in("F1\nG1 X[ATAN[1]]\nM2\n", Dialect::LinuxCnc) ==
        "p.nc:2:6: LinuxCNC's ATAN takes two arguments: ATAN[y]/[x]");
}

TEST_CASE("dialects: LinuxCNC's parameters: numbered from 0, named, set after the line's reads", "[program]") {
  CHECK(lcnc_value("#5") == 0);  // never set: 0
  CHECK(x_of("F1\n#<_g> = 3\n#<l> = 4\nG1 X[#<_g> * 10 + #<l>]\nM2\n", Dialect::LinuxCnc) == 34);
  CHECK(x_of("F1\n#1 = 5 #2 = #1\nG1 X#2\nM2\n", Dialect::LinuxCnc) == 0);  // #2 took the old #1
  CHECK(x_of("F1\n#<a> = 1\nG1 X[EXISTS[#<a>] * 10 + EXISTS[#<b>]]\nM2\n", Dialect::LinuxCnc) == 10);
  CHECK(x_of("F1\n#atan[1]/[1] = 3\nG1 X#45\nM2\n", Dialect::LinuxCnc) == 3);  // a number by a function
  CHECK(error_in("F1\nG1 X#<nowhere>\nM2\n", Dialect::LinuxCnc) ==
        "p.nc:2:5: #<nowhere> is undefined: no value was assigned to it");
}

TEST_CASE("dialects: O-word subroutines take #1-#30 as their own and return a value", "[program]") {
  const Program p = lcnc(
      "F100\n#1 = 5\n#<_seen> = 0\n#<mine> = 9\n"
      "o<sq> sub\n"
      "  #<_seen> = [#1 * 100 + #2 * 10 + #3]\n"  // the arguments; #3 not given: 0
      "  #<mine> = 1\n"                           // a local of the sub's own
      "  o<sq> return [#1 + #2]\n"
      "o<sq> endsub\n"
      "o<sq> call [7] [8]\n"
      "G1 X#1 Y#<_seen>\n"  // the caller's #1 again
      "G1 X#<_value> Y#<mine>\n"
      "M2\n");
  REQUIRE(p.moves.size() == 2);
  CHECK(p.moves[0].to == Point2{mm(5), mm(780)});
  CHECK(p.moves[1].to == Point2{mm(15), mm(9)});
  // A name computed from a parameter: the subroutine of that number.
  const Program c = lcnc("F1\no1 sub\nG1 X1\no1 endsub\no2 sub\nG1 X2\no2 endsub\n#<s> = 2\no#<s> call\nM2\n");
  REQUIRE(c.moves.size() == 1);
  CHECK(c.moves[0].to.u == mm(2));
  CHECK(error_in("o#1 sub\no#1 endsub\nM2\n", Dialect::LinuxCnc) ==
        "p.nc:1:1: a computed O-word name (o#<name>) goes with call only");
}

TEST_CASE("dialects: a subroutine in a file of its name beside the program or on the path", "[program]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("dda_subfile_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "side.ngc") << "o<side> sub\n  G91 G1 X#1\n  G90\n  G1 X[#1 + 1] Y9\no<side> endsub\nM2\n";
  std::ofstream(dir / "bad.ngc") << "o<bad> sub\n  G1 X#<nowhere>\no<bad> endsub\n";
  ReadOptions o;
  o.dialect = Dialect::LinuxCnc;
  const Program p = read("F1\no<side> call [2]\no<side> call [3]\nM2\n", (dir / "main.ngc").string(), o);
  std::vector<Point2> ends;
  for (const Move& m : p.moves) ends.push_back(m.to);
  CHECK(ends == std::vector<Point2>{{mm(2), 0}, {mm(3), mm(9)}, {mm(6), mm(9)}, {mm(4), mm(9)}});
  // An error inside the file names the file and its line; a file that is missing, by its path.
  const auto error = [&](const std::string& text) {
    try {
      read(text, (dir / "main.ngc").string(), o);
    } catch (const ProgramError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(error("F1\no<bad> call\nM2\n") == (dir / "bad.ngc").string() +
                                              ":2:7: #<nowhere> is undefined: no value was "
                                              "assigned to it");
  CHECK(error("F1\no<gone> call\nM2\n")
            .find("no o<gone> sub in this program, nor a file " + (dir / "gone.ngc").string()) != std::string::npos);
  // Then the folders of the subroutine path, in order (the program's own first).
  fs::create_directories(dir / "lib1");
  fs::create_directories(dir / "lib2");
  std::ofstream(dir / "lib1" / "deep.ngc") << "o<deep> sub\n  G1 X7\no<deep> endsub\n";
  std::ofstream(dir / "lib2" / "deep.ngc") << "o<deep> sub\n  G1 X8\no<deep> endsub\n";
  std::ofstream(dir / "lib2" / "side.ngc") << "o<side> sub\n  G1 X99\no<side> endsub\n";
  o.subroutine_path = {(dir / "lib0").string(), (dir / "lib1").string(), (dir / "lib2").string()};
  const Program q = read("F1\no<deep> call\no<side> call [5]\nM2\n", (dir / "main.ngc").string(), o);
  REQUIRE(q.moves.size() == 3);
  CHECK(q.moves[0].to.u == mm(7));   // lib1's, the first folder that has it
  CHECK(q.moves[1].to.u == mm(12));  // side.ngc beside the program comes first (G91 X5)
  CHECK(error("F1\no<gone> call\nM2\n")
            .find((dir / "lib0" / "gone.ngc").string() + ", " + (dir / "lib1" / "gone.ngc").string()) !=
        std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("dialects: O-word loops and branches", "[program]") {
  const Program p = lcnc(
      "F1\n#<i> = 0\n"
      "o1 while [#<i> LT 3]\n  #<i> = [#<i> + 1]\n  o2 if [#<i> EQ 2]\n    o1 continue\n  o2 endif\n"
      "  G1 X#<i>\no1 endwhile\n"                         // X1, X3
      "o3 repeat [2]\n  G91 G1 X10\no3 endrepeat\nG90\n"  // X13, X23
      "o4 do\n  #<i> = [#<i> - 1]\n  o5 if [#<i> EQ 1]\n    o4 break\n  o5 elseif [#<i> EQ 2]\n    G1 X2\n"
      "  o5 else\n    G1 X99\n  o5 endif\no4 while [#<i> GT 0]\n"  // X2, then the break
      "G1 X#<i>\n"                                                 // X1
      "M2\n");
  std::vector<Length> xs;
  for (const Move& m : p.moves) xs.push_back(m.to.u);
  CHECK(xs == std::vector<Length>{mm(1), mm(3), mm(13), mm(23), mm(2), mm(1)});
  CHECK(error_in("o1 while [1]\no2 endwhile\nM2\n", Dialect::LinuxCnc) == "p.nc:2:1: o2 endwhile without its while");
  // LinuxCNC leaves only a while or do loop by break or continue, and says so when it
  // reaches one in a repeat (the feed before it runs).
  CHECK(error_in("F1\no1 repeat [3]\nG1 X1\no1 break\no1 endrepeat\nM2\n", Dialect::LinuxCnc) ==
        "p.nc:4:1: o1 break or continue outside an o1 while or do loop (LinuxCNC's repeat takes neither)");
  CHECK(error_in("o1 if [1]\nM2\n", Dialect::LinuxCnc) ==
        "p.nc:1:1: o1: a block opened here is not closed (sub, if, while, do or repeat)");
  CHECK(error_in("o1 call\nM2\n", Dialect::LinuxCnc).rfind("p.nc:1:1: o1 call: no o1 sub in this program", 0) == 0);
  CHECK(error_in("o1 sob\nM2\n", Dialect::LinuxCnc).rfind("p.nc:1:4: an O-word keyword expected", 0) == 0);
  CHECK(error_in("o100 sub\n", Dialect::Hnc).rfind("p.nc:1:1: an O-word statement is LinuxCNC's", 0) == 0);
  CHECK(error_in("o<x> call\n", Dialect::Fanuc).rfind("p.nc:1:1: an O-word statement is LinuxCNC's", 0) == 0);
}

TEST_CASE("dialects: LinuxCNC's M70-M73 save and restore the modal state", "[program]") {
  // M70 saves G20, M72 brings it back; M73 in a subroutine restores G90 (and G21) when
  // it returns. rs274 prints the same four moves.
  const Program p =
      lcnc("F1\nG20\nM70\nG21\nM72\nG1 X1\no1 sub\nM73\nG91\nG1 X1\no1 endsub\nG21\no1 call\nG1 X1\nG1 X1\nM2\n");
  std::vector<Length> xs;
  for (const Move& m : p.moves) xs.push_back(m.to.u);
  CHECK(xs == std::vector<Length>{mm(25.4), mm(26.4), mm(1), mm(1)});
  CHECK(error_in("M72\nM2\n", Dialect::LinuxCnc) == "p.nc:1:1: M72: no modal state saved by M70 to restore");
}

TEST_CASE("dialects: a G1, G2 or G3 without a feed rate is refused but in HNC's dialect", "[program]") {
  CHECK(error_in("G1 X1\nM2\n", Dialect::LinuxCnc) ==
        "p.nc:1:1: G1 with no feed rate in force: give F (LinuxCNC refuses a feed move at zero feed)");
  CHECK(error_in("G2 X2 I1\nM2\n", Dialect::LinuxCnc).rfind("p.nc:1:1: G2 with no feed rate", 0) == 0);
  CHECK(error_in("G0 X1\nM2\n", Dialect::LinuxCnc).empty());  // a rapid needs none
  CHECK(error_in("G1 X1\nM2\n", Dialect::Hnc).empty());       // the HNC examples carry no F
  CHECK(error_in("G1 X1\nM30\n", Dialect::Fanuc) ==
        "p.nc:1:1: G1 with no feed rate in force: give F (Fanuc's controls alarm at a feed move at zero feed)");
  CHECK(error_in("G93 G1 X1 F2\nG1 X2\nM2\n", Dialect::LinuxCnc) ==
        "p.nc:2:1: G93 (inverse time): every feed move needs its own F");
  CHECK(error_in("F1\nG1 X1\n", Dialect::LinuxCnc) ==
        "p.nc:3:1: the program ends without M02, M30 or a closing '%' (LinuxCNC refuses it: end it with M30)");
}

TEST_CASE("dialects: a plane switch keeps the tool where it is", "[program]") {
  const Program p = lcnc("G0 X0 Y10\nG19\nG1 Y5 F100\nM2\n");
  REQUIRE(p.moves.size() == 2);
  CHECK(p.plane == 170);  // the two axes: X and Y, the first move's plane
  CHECK(p.moves[1].from == Point2{0, mm(10)});
  CHECK(p.moves[1].to == Point2{0, mm(5)});  // LinuxCNC: Y5 Z0, X still 0
  CHECK(p.moves[1].w == 0);
  // An arc in the new plane lies in it (Y, Z), at the tool's X (the planner refuses it
  // until the third axis).
  const Program q = lcnc("G0 X3 Y10\nG19 G2 Y0 Z10 J0 K10 F1\nM2\n");
  REQUIRE(q.moves.size() == 2);
  CHECK(q.moves[1].plane == 190);
  CHECK(q.moves[1].from == Point2{mm(10), 0});
  CHECK(q.moves[1].to == Point2{0, mm(10)});
  CHECK(q.moves[1].center == Point2{mm(10), mm(10)});
  CHECK(q.moves[1].w == mm(3));
  CHECK(q.moves[1].w_to == mm(3));
}

TEST_CASE("dialects: arc ends within LinuxCNC's tolerance run, HNC's stays 0.002 mm", "[program]") {
  // 0.01 mm off a 5 mm radius: LinuxCNC accepts up to 0.0283 mm (or 0.1% of the radius).
  const std::string off = "F1\nG2 X10.01 Y0 I5 J0\nM2\n";
  REQUIRE(error_in(off, Dialect::LinuxCnc).empty());
  CHECK(lcnc(off).moves[0].end_off == mm(0.01));
  CHECK(error_in(off, Dialect::Hnc).rfind("p.nc:2:1: the end is 0.0100 mm off the arc's circle", 0) == 0);
  CHECK(error_in("F1\nG2 X10.0283 Y0 I5 J0\nM2\n", Dialect::LinuxCnc).rfind("p.nc:2:1: the end is 0.0283 mm off", 0) ==
        0);
  // 0.1 mm off a 100 mm radius: within 0.1%.
  CHECK(error_in("F1\nG2 X200.1 Y0 I100 J0\nM2\n", Dialect::LinuxCnc).empty());
  CHECK(!error_in("F1\nG2 X200.2 Y0 I100 J0\nM2\n", Dialect::LinuxCnc).empty());
  // Inches: 0.002 in times the square root of 2.
  CHECK(error_in("G20 F1\nG2 X2.00282 Y0 I1 J0\nM2\n", Dialect::LinuxCnc).empty());
  CHECK(!error_in("G20 F1\nG2 X2.00283 Y0 I1 J0\nM2\n", Dialect::LinuxCnc).empty());
}

TEST_CASE("dialects: offsets move the program's origin, G53 and G28 the machine's", "[program]") {
  const Program p = lcnc(
      "F1\nG10 L2 P1 X10 Y20\nG1 X1 Y1\n"  // G54 offset: machine 11, 21
      "G92 X0 Y0\nG1 X1 Y0\n"              // G92: here is 0,0; machine 12, 21
      "G92.1\nG52 X5\nG1 X0 Y0\n"          // G52: machine 15, 20
      "G92.1\nG53 G0 X3 Y4\n"              // machine coordinates
      "G10 L20 P2 X0 Y0\nG55 G1 X1 Y1\n"   // G55 set so that here (3, 4) reads 0,0
      "G0 X7 Y7\nG28.1\nG0 X0 Y0\nG28\n"   // G28: to where G28.1 stored (machine 10, 11)
      "M2\n");
  std::vector<Point2> ends;
  for (const Move& m : p.moves) ends.push_back(m.to);
  CHECK(ends == std::vector<Point2>{{mm(11), mm(21)},
                                    {mm(12), mm(21)},
                                    {mm(15), mm(20)},
                                    {mm(3), mm(4)},
                                    {mm(4), mm(5)},
                                    {mm(10), mm(11)},
                                    {mm(3), mm(4)},
                                    {mm(3), mm(4)},
                                    {mm(10), mm(11)}});
  // An offset of an axis the machine lacks is recorded.
  CHECK(error_in("G10 L2 P1 X1 A5\nM2\n", Dialect::LinuxCnc).empty());
  // A turned system (G10 L2 R): program X1 is machine (offset + 1 turned by 90 degrees);
  // arc centres turn with it; G10 L20 keeps the other axis' program position.
  const Program r = lcnc("F1\nG10 L2 P1 X10 R90\nG1 X1 Y0\nG3 X0 Y1 I-1 J0\nG10 L20 P1 X0\nG1 Y0\nM2\n");
  REQUIRE(r.moves.size() == 3);
  CHECK(r.moves[0].to == Point2{mm(10), mm(1)});
  CHECK(r.moves[1].center == Point2{mm(10), 0});
  CHECK(r.moves[1].to == Point2{mm(9), 0});
  CHECK(r.moves[2].to == Point2{mm(10), 0});  // L20 at program (0, 1) with X0: the offset stays
}

TEST_CASE("dialects: LinuxCNC 2.9's numbered labels and M98 subprograms", "[program]") {
  // (rs274: X1 then X5; the label in the middle is run through: X1, X2.)
  std::vector<Length> xs;
  for (const Move& m : lcnc("F1\nG0 X1\nM98 P100\nM2\nO100\nG0 X5\nM99\n").moves) xs.push_back(m.to.u);
  CHECK(xs == std::vector<Length>{mm(1), mm(5)});
  xs.clear();
  for (const Move& m : lcnc("F1\nG0 X1\nO1234 (a label)\nG0 X2\nM99\nG0 X3\n").moves) xs.push_back(m.to.u);
  CHECK(xs == std::vector<Length>{mm(1), mm(2)});  // M99 in the main program ends it
}

TEST_CASE("dialects: Fanuc's programs, calls and arc centres", "[program]") {
  const std::string text =
      "%\nO1000 (MAIN)\nF1\nM98 P21001\nM98 P1001 L2\nG90.1 G2 X50 Y0 I45 J0\nM30\n"
      "O1001\nG91 G1 X10\nG90\nM99\n%\nG1 X1000\n";  // after the closing '%': not read
  const Program p = read_in(text, std::nullopt);
  CHECK(p.dialect == Dialect::Fanuc);
  REQUIRE(p.moves.size() == 5);
  CHECK(p.moves[3].to.u == mm(40));
  CHECK(p.moves[4].center == Point2{mm(45), 0});  // G90.1: the centre itself
  CHECK(error_in("M98 P7\nM30\n", Dialect::Fanuc) == "p.nc:1:5: M98 calls program O7: there is none");
}

TEST_CASE("dialects: block delete, long numbers and line ends as LinuxCNC reads them", "[program]") {
  const std::string text = "F1\n/G1 X5\nG1 X1.23456789012345678901 Y0.0000004\r\r\nM2\n";
  CHECK(read_in(text, Dialect::LinuxCnc).moves.size() == 2);  // the switch off: '/' ignored
  const Program on = read_in(text, Dialect::LinuxCnc, Machine::Mill, true);
  REQUIRE(on.moves.size() == 1);
  CHECK(on.moves[0].to == Point2{mm(1.234568), 0});  // to the nanometre, halves away from zero
  // An 18-digit code or M number is no code (not a product that overflows).
  CHECK(error_in("G999999999999999999\nM2\n", Dialect::LinuxCnc) == "p.nc:1:1: no code G999999999999999999");
  CHECK(error_in("M999999999999999999\nM2\n", Dialect::LinuxCnc) ==
        "p.nc:1:1: unknown or unsupported code M999999999999999999");
}

TEST_CASE("dialects: what the reader cannot run yet is refused naming the feature", "[program]") {
  const auto refused = [](const std::string& text) { return error_in("F1\n" + text + "\nM2\n", Dialect::LinuxCnc); };
  CHECK(refused("G41 G1 X1") ==
        "p.nc:2:1: tool radius compensation (G41/G42) is not supported: program the tool's path");
  CHECK(refused("G33 Z-1 K1") == "p.nc:2:1: G33: threading (G33, G33.1, G76) is not supported");
  CHECK(refused("G38.2 Z-1").rfind("p.nc:2:1: G38.2: probing (G38.2-G38.5) is not supported", 0) == 0);
  CHECK(refused("G5 X1 Y1 I1 J1 P1 Q1").rfind("p.nc:2:1: G5: splines (G5, G5.1, G5.2, G5.3) are not supported", 0) ==
        0);
  CHECK(refused("G1 X1 A30") ==
        "p.nc:2:7: A: rotary axes (A, B, C) are not supported: the interpolator drives linear axes");
  CHECK(refused("G1 U1") == "p.nc:2:4: U: secondary linear axes (U, V, W) are not supported");
  CHECK(refused("G1 @1 ^30") == "p.nc:2:4: polar coordinates (@ and ^ words) are not supported");
  // Read, for the planner to refuse until the third axis: a plunge and a helix.
  const Program plunge = lcnc("F1\nG1 Z-1\nG2 X2 I1 Z1\nM2\n");
  REQUIRE(plunge.moves.size() == 2);
  CHECK(plunge.moves[0].w_to == mm(-1));
  CHECK(plunge.moves[1].kind == MoveKind::ArcCw);
  CHECK(plunge.moves[1].w == mm(-1));
  CHECK(plunge.moves[1].w_to == mm(1));
  CHECK(refused("G86 X1 Y1 Z-1 R1 P1") ==
        "p.nc:2:1: G86: canned cycles that stop or reverse the spindle (G74, G84, G86-G88) are not supported");
  CHECK(refused("$H").rfind("p.nc:2:1: a '$' line is a command to a Grbl controller", 0) == 0);
  CHECK(refused("(a (nested) comment)") == "p.nc:2:4: a comment inside a comment: LinuxCNC refuses nested comments");
  CHECK(refused("G0 X1 O1234").rfind("p.nc:2:7: O1234: a program number line is Fanuc's (--dialect fanuc)", 0) == 0);
  CHECK(refused("O1234 (a title)").empty());  // alone on its line: a program (LinuxCNC 2.9 too)
  // Recorded, not moving: tool changes, path control, spindle and coolant, tool length.
  const Program p = lcnc("T1 M6 G43 H1 G64 P0.01 Q0.01 S1000 M3 M8 G96\nG61.1 G97 M9 M5 G49\nM2\n");
  CHECK(p.moves.empty());
  CHECK(p.ignored.size() == 16);
}
