// SPDX-License-Identifier: Apache-2.0
// LinuxCNC's lathe turning cycles G70-G72 in the reader (docs/programs.md, "Lathe turning
// cycles"): the passes checked by what they must do (a finishing pass without allowance
// is the contour; no roughing cut enters the finishing allowance; the depths step by I)
// and against the passes LinuxCNC's rs274 prints for the same program; what LinuxCNC
// refuses (or would loop on for ever) refused with the reason.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "host/program/program.hpp"
#include "tests/program_helpers.hpp"

using namespace dda::program;
using dda::program::testing::error_in;
using dda::program::testing::lcnc;

namespace {

// A move's end (or centre) in the Z-X plane, in mm: the lattice's u is Z, v is X.
double z_of(const Point2& p) { return double(p.u) / double(kNmPerMm); }
double x_of(const Point2& p) { return double(p.v) / double(kNmPerMm); }

// A shaft: a face at X2, a convex quarter arc up to X6, a taper and a last step.
const std::string kContour =
    "G18 G21 G90 F300\n"
    "o1 sub\n"
    "  G0 X0 Z1\n"
    "  G1 X2 Z0\n"
    "  Z-5\n"
    "  G3 X6 Z-9 I0 K-4\n"
    "  G1 X7 Z-12\n"
    "  Z-15\n"
    "o1 endsub\n"
    "G0 X9 Z2\n";

// The contour's X at z (from Z0 to Z-15).
double profile(double z) {
  if (z >= -5) return 2;
  if (z >= -9) return 2 + std::sqrt(std::max(0.0, 16 - (z + 9) * (z + 9)));
  if (z >= -12) return 6 + (z + 9) / -3;
  return 7;
}

}  // namespace

TEST_CASE("turning: a finishing pass without allowance runs the contour itself", "[program]") {
  const Program p = lcnc(kContour + "G70 Q1 X9 Z2 D0 P1\nM2\n");
  // The G0 before the cycle, the cycle's rapid to its X, Z, the rapids to the start and
  // along the approach (the contour's first move), then the contour.
  REQUIRE(p.moves.size() == 9);
  const struct {
    MoveKind kind;
    double x, z;
  } want[] = {{MoveKind::Rapid, 9, 2},   {MoveKind::Rapid, 9, 2},  {MoveKind::Rapid, 9, 2},
              {MoveKind::Rapid, 0, 1},   {MoveKind::Line, 2, 0},   {MoveKind::Line, 2, -5},
              {MoveKind::ArcCcw, 6, -9}, {MoveKind::Line, 7, -12}, {MoveKind::Line, 7, -15}};
  for (std::size_t i = 0; i < p.moves.size(); ++i) {
    INFO("move " << i);
    CHECK(p.moves[i].kind == want[i].kind);
    CHECK(x_of(p.moves[i].to) == Approx(want[i].x).margin(1e-6));
    CHECK(z_of(p.moves[i].to) == Approx(want[i].z).margin(1e-6));
  }
  CHECK(x_of(p.moves[6].center) == Approx(2).margin(1e-6));
  CHECK(z_of(p.moves[6].center) == Approx(-9).margin(1e-6));
}

TEST_CASE("turning: roughing stays out of the finishing allowance, a depth of cut at a time", "[program]") {
  const double d = 0.25, depth = 0.6;
  const Program p = lcnc(kContour + "G71 Q1 X9 Z2 D0.25 I0.6 R0.3\nM2\n");
  REQUIRE(p.moves.size() > 20);
  int cuts = 0;
  for (std::size_t i = 1; i < p.moves.size(); ++i) {
    const Move& m = p.moves[i];
    const double x = x_of(m.to), z = z_of(m.to);
    INFO("move " << i << " to X" << x << " Z" << z);
    if (z <= 0 && z >= -15) CHECK(x >= profile(z) + d - 1e-4);
    // A cut: a feed along Z that ends in the retract (a rapid), at one of the depths
    // 9 - k I (the feeds along the contour's own flats end otherwise).
    const bool retract = i + 1 < p.moves.size() && p.moves[i + 1].kind == MoveKind::Rapid;
    if (m.kind == MoveKind::Line && m.from.v == m.to.v && m.from.u != m.to.u && retract) {
      const double k = (9 - x) / depth;
      CHECK(std::fabs(k - std::round(k)) < 1e-6);
      ++cuts;
    }
  }
  CHECK(cuts >= 9);  // from X9 down to the face's X2.25: eleven depths, some of them short
}

TEST_CASE("turning: the passes are LinuxCNC's", "[program]") {
  // LinuxCNC's test g72-iterations-present (tests/programs/linuxcnc-interp), facing X50
  // to X100 in cuts of 3 mm with a retract of 0.1 mm; rs274 prints these ends.
  const Program p = lcnc(
      "G18 G21 F400\no100 sub\nG1 X50 Z-40 F10000\nX100 Z-39.999\no100 endsub\n"
      "G72 Q100 X50 Z0 I3 R0.1\nG0 X0 Z0\nM30\n");
  const struct {
    MoveKind kind;
    double x, z;
  } want[] = {{MoveKind::Rapid, 50, 0},      {MoveKind::Rapid, 50, 0},      {MoveKind::Rapid, 50, 0},
              {MoveKind::Line, 100, 0},      {MoveKind::Rapid, 99.9, 0.1},  {MoveKind::Rapid, 50.1, 0.1},
              {MoveKind::Rapid, 50, 0},      {MoveKind::Rapid, 50, -3},     {MoveKind::Line, 100, -3},
              {MoveKind::Rapid, 99.9, -2.9}, {MoveKind::Rapid, 50.1, -2.9}, {MoveKind::Rapid, 50, -3},
              {MoveKind::Rapid, 50, -6},     {MoveKind::Line, 100, -6}};
  REQUIRE(p.moves.size() > std::size(want));
  for (std::size_t i = 0; i < std::size(want); ++i) {
    INFO("move " << i);
    CHECK(p.moves[i].kind == want[i].kind);
    CHECK(x_of(p.moves[i].to) == Approx(want[i].x).margin(1e-6));
    CHECK(z_of(p.moves[i].to) == Approx(want[i].z).margin(1e-6));
  }
  // The last cut reaches the contour's end at Z-39.999, and the program's G0 follows.
  CHECK(z_of(p.moves.back().to) == Approx(0).margin(1e-6));
  CHECK(x_of(p.moves.back().to) == Approx(0).margin(1e-6));
}

TEST_CASE("turning: corners rounded (A) and chamfered (C) in the contour", "[program]") {
  const std::string sub =
      "G18 G21 G90 F300\no2 sub\nG0 X0 Z1\nG1 X2 Z0\nZ-4 C0.5\nX6\nZ-8 A1\nX8\no2 endsub\nG0 X10 Z2\n";
  const Program p = lcnc(sub + "G70 Q2 X10 Z2 D0 P1\nM2\n");
  // The chamfer cuts 0.5 off both sides of the corner X2 Z-4; the rounding of radius 1
  // ends 1 mm from the corner X6 Z-8 on both sides, about X7 Z-7 (rs274 prints the same).
  std::vector<std::pair<double, double>> ends;
  for (const Move& m : p.moves) ends.emplace_back(x_of(m.to), z_of(m.to));
  const auto has = [&](double x, double z) {
    return std::any_of(ends.begin(), ends.end(),
                       [&](const auto& e) { return std::fabs(e.first - x) < 1e-6 && std::fabs(e.second - z) < 1e-6; });
  };
  CHECK(has(2, -3.5));
  CHECK(has(2.5, -4));
  CHECK(has(6, -7));
  CHECK(has(7, -8));
  const auto arc = std::find_if(p.moves.begin(), p.moves.end(),
                                [](const Move& m) { return m.kind != MoveKind::Line && m.kind != MoveKind::Rapid; });
  REQUIRE(arc != p.moves.end());
  CHECK(arc->kind == MoveKind::ArcCw);
  CHECK(x_of(arc->center) == Approx(7).margin(1e-6));
  CHECK(z_of(arc->center) == Approx(-7).margin(1e-6));
}

TEST_CASE("turning: what LinuxCNC refuses, or would loop on, is refused with the reason", "[program]") {
  CHECK(error_in(kContour + "G71 X9 Z2 D0.2\nM2\n") ==
        "p.ngc:11:1: G71 needs Q, the number of the subroutine that holds the contour");
  CHECK(error_in(kContour + "G71 Q7 X9 Z2\nM2\n").rfind("p.ngc:11:5: o7 call: no o7 sub in this program", 0) == 0);
  CHECK(error_in("G17 F1\no1 sub\nG1 X1\no1 endsub\nG70 Q1\nM2\n") ==
        "p.ngc:5:1: G70 works in the plane G18 (Z, X) only, as in LinuxCNC");
  CHECK(error_in(kContour + "G72 Q1 X9 Z2 I0\nM2\n") == "p.ngc:11:1: G72: I (the depth of each cut) must be positive");
  CHECK(error_in(kContour + "G71 Q1 X9 Z2 U0.1\nM2\n") ==
        "p.ngc:11:14: U: secondary linear axes (U, V, W) are not supported");
  CHECK(error_in(kContour + "G70 Q1 X9 Z2 I1\nM2\n") == "p.ngc:11:14: I is not a word of G70");
  // Bounds on the work of one block (LinuxCNC has none).
  CHECK(error_in(kContour + "G70 Q1 X9 Z2 P1001\nM2\n") ==
        "p.ngc:11:14: P (the number of finishing passes) is at most 1000");
  CHECK(error_in(kContour + "G71 Q1 X9 Z2 I0.00001\nM2\n") ==
        "p.ngc:11:1: G71 Q1: I (the depth of cut) is too small: more than 100000 depths");
  // Nothing to cut: LinuxCNC would take the contour's end as its position without moving.
  CHECK(error_in("G18 F1\no4 sub\nG1 X5 Z-10\no4 endsub\nG0 X10 Z0\nG71 Q4 X10 Z0 I1\nM2\n") ==
        "p.ngc:6:1: G71 Q4: the contour needs at least two moves (the approach and a cut)");
  CHECK(error_in(kContour + "G70 Q1 X9 Z2 P0\nM2\n") ==
        "p.ngc:11:1: G70 Q1: P (the number of finishing passes) must be at least 1");
  // Z rises again after the taper: a roughing cannot follow it.
  CHECK(error_in("G18 F1\no3 sub\nG0 X0 Z1\nG1 X2 Z0\nZ-4\nX3 Z-2\nX4 Z-6\no3 endsub\nG0 X9 Z2\nG71 Q3 X9 Z2\nM2\n") ==
        "p.ngc:10:1: G71 Q3: the contour is not monotonic (X must not rise as Z falls, or the reverse)");
  // A centre word read as an offset (G90.1 inside the contour is not run): LinuxCNC's
  // roughing never ends on this one.
  CHECK(error_in("G18 G21 F200\no5 sub\nG0 X2 Z1\nG1 X4 Z0\nZ-5\nG90.1 G2 X8 Z-9 I8 K-5\nG1 X10 Z-12\no5 endsub\n"
                 "G0 X12 Z3\nG71 Q5 X12 Z3 D0.2 I1 R0.3\nM2\n") ==
        "p.ngc:10:1: G71 Q5: the roughing passes do not end (LinuxCNC's would loop for ever)");
  // HNC's and Fanuc's cycles take other words.
  ReadOptions hnc;
  hnc.dialect = Dialect::Hnc;
  hnc.machine = Machine::Lathe;
  CHECK_THROWS_WITH(read("G71 U1 R0.5 P10 Q20\nM30\n", "p.nc", hnc),
                    Catch::Contains("lathe turning cycles in HNC's and Fanuc's form"));
}
