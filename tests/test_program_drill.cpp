// SPDX-License-Identifier: Apache-2.0
// LinuxCNC's drilling cycles in the reader (docs/programs.md, "Canned cycles"): each
// cycle's moves as LinuxCNC's rs274 prints them for the same program (the ends below are
// its output), the retract levels of G98 and G99, repeats in G91, and the refusals.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <array>
#include <string>
#include <vector>

#include "host/program/program.hpp"
#include "tests/program_helpers.hpp"

using namespace dda::program;
using dda::program::testing::error_in;
using dda::program::testing::lcnc;

namespace {

// A move's end as X, Y, Z in mm, and whether it is a rapid (on G17, u X, v Y, w Z).
struct End {
  bool rapid;
  double x, y, z;
};
std::vector<End> ends(const Program& p) {
  std::vector<End> e;
  for (const Move& m : p.moves) {
    e.push_back({m.kind == MoveKind::Rapid, double(m.to.u) / 1e6, double(m.to.v) / 1e6, double(m.w_to) / 1e6});
  }
  return e;
}

void check(const Program& p, const std::vector<End>& want) {
  const std::vector<End> got = ends(p);
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    INFO("move " << i);
    CHECK(got[i].rapid == want[i].rapid);
    CHECK(got[i].x == Approx(want[i].x).margin(1e-6));
    CHECK(got[i].y == Approx(want[i].y).margin(1e-6));
    CHECK(got[i].z == Approx(want[i].z).margin(1e-6));
  }
}

constexpr bool R = true, F = false;

}  // namespace

TEST_CASE("drilling: G81 and G82 drill, back to R (G99) or to where they started (G98)", "[program]") {
  // rs274: G0 Z5; to the hole at Z5, down to R, feed to the bottom, back to R (G99);
  // the second hole from R.
  check(lcnc("F100\nG0 Z5\nG81 X1 Y1 Z-1 R1\nX2\nM2\n"), {{R, 0, 0, 5},
                                                          {R, 1, 1, 5},
                                                          {R, 1, 1, 1},
                                                          {F, 1, 1, -1},
                                                          {R, 1, 1, 1},  //
                                                          {R, 2, 1, 1},
                                                          {F, 2, 1, -1},
                                                          {R, 2, 1, 1}});
  // G98: back to Z5, where the row of cycles started; G82 dwells (P) at the bottom.
  check(lcnc("F100\nG0 Z5\nG98 G82 X1 Y1 Z-1 R1 P0.5\nX2\nM2\n"), {{R, 0, 0, 5},
                                                                   {R, 1, 1, 5},
                                                                   {R, 1, 1, 1},
                                                                   {F, 1, 1, -1},
                                                                   {R, 1, 1, 5},  //
                                                                   {R, 2, 1, 5},
                                                                   {R, 2, 1, 1},
                                                                   {F, 2, 1, -1},
                                                                   {R, 2, 1, 5}});
}

TEST_CASE("drilling: G83 pecks back to R, G73 backs off 0.254 mm", "[program]") {
  check(lcnc("F100\nG0 Z2\nG83 X1 Y0 Z-2.5 R1 Q1\nM2\n"), {{R, 0, 0, 2},
                                                           {R, 1, 0, 2},
                                                           {R, 1, 0, 1},
                                                           {F, 1, 0, 0},
                                                           {R, 1, 0, 1},
                                                           {R, 1, 0, 0.254},
                                                           {F, 1, 0, -1},
                                                           {R, 1, 0, 1},
                                                           {R, 1, 0, -0.746},
                                                           {F, 1, 0, -2},
                                                           {R, 1, 0, 1},
                                                           {R, 1, 0, -1.746},
                                                           {F, 1, 0, -2.5},
                                                           {R, 1, 0, 1}});
  check(lcnc("F100\nG0 Z2\nG73 X1 Y0 Z-2.5 R1 Q1\nM2\n"), {{R, 0, 0, 2},
                                                           {R, 1, 0, 2},
                                                           {R, 1, 0, 1},
                                                           {F, 1, 0, 0},
                                                           {R, 1, 0, 0.254},
                                                           {F, 1, 0, -1},
                                                           {R, 1, 0, -0.746},
                                                           {F, 1, 0, -2},
                                                           {R, 1, 0, -1.746},
                                                           {F, 1, 0, -2.5},
                                                           {R, 1, 0, 1}});
}

TEST_CASE("drilling: G85 and G89 feed out, and L repeats step in G91", "[program]") {
  check(lcnc("F100\nG0 Z3\nG85 X1 Y1 Z-1 R1\nG89 X2 Z-1 R1 P1\nM2\n"), {{R, 0, 0, 3},
                                                                        {R, 1, 1, 3},
                                                                        {R, 1, 1, 1},
                                                                        {F, 1, 1, -1},
                                                                        {F, 1, 1, 1},
                                                                        {R, 1, 1, 1},  //
                                                                        {R, 2, 1, 1},
                                                                        {F, 2, 1, -1},
                                                                        {F, 2, 1, 1}});
  // G91: R from the starting level (Z3: R at 2), the bottom from R (Z-1: at 1), X steps
  // of 2 three times.
  check(lcnc("F100\nG0 Z3\nG91 G81 X2 Y0 Z-1 R-1 L3\nG90\nM2\n"), {{R, 0, 0, 3},
                                                                   {R, 2, 0, 3},
                                                                   {R, 2, 0, 2},
                                                                   {F, 2, 0, 1},
                                                                   {R, 2, 0, 2},  //
                                                                   {R, 4, 0, 2},
                                                                   {F, 4, 0, 1},
                                                                   {R, 4, 0, 2},
                                                                   {R, 6, 0, 2},
                                                                   {F, 6, 0, 1},
                                                                   {R, 6, 0, 2}});
}

TEST_CASE("drilling: what LinuxCNC refuses is refused with the reason", "[program]") {
  CHECK(error_in("F1\nG81 X1 Z-1\nM2\n") == "p.ngc:2:1: G81 needs R, the retract plane, when it starts");
  CHECK(error_in("F1\nG81 X1 R1\nM2\n") == "p.ngc:2:1: G81 needs Z, the bottom of the hole, when it starts");
  CHECK(error_in("F1\nG81 X1 Z2 R1\nM2\n") == "p.ngc:2:1: G81: the retract plane R lies below the bottom Z");
  CHECK(error_in("F1\nG82 X1 Z-1 R1\nM2\n") == "p.ngc:2:1: G82 needs P, the dwell in seconds, when it starts");
  CHECK(error_in("F1\nG83 X1 Z-1 R1 Q0\nM2\n") == "p.ngc:2:1: G83: Q (the depth of each peck) must be positive");
  CHECK(error_in("G81 X1 Z-1 R1\nM2\n") ==
        "p.ngc:1:1: G81 with no feed rate in force: give F (LinuxCNC refuses a feed move at zero feed)");
  CHECK(error_in("F1\nG81 X1 Z-1 R1 Q1\nM2\n") == "p.ngc:2:15: Q is not a word of G81");
  // While a cycle is in force (rs274 refuses each of these the same way).
  const std::string in_force = "F1\nG0 Z10\nG81 X0 Y0 Z-1 R2\n";
  CHECK(error_in(in_force + "G53 X10 Y10\nM2\n") ==
        "p.ngc:4:1: G53 goes with G00 or G01 only (LinuxCNC refuses it in a canned cycle)");
  CHECK(error_in(in_force + "R5\nX1\nM2\n") ==
        "p.ngc:4:1: R with no code that reads it: a canned cycle in force runs on X, Y or Z");
  CHECK(error_in(in_force + "G81 R5\nM2\n") ==
        "p.ngc:4:1: G81 needs an axis word (X, Y or Z): LinuxCNC refuses a motion code without one");
  CHECK(error_in("F1\nG84 X1 Z-1 R1\nM2\n") ==
        "p.ngc:2:1: G84: canned cycles that stop or reverse the spindle (G74, G84, G86-G88) are not supported");
  CHECK(error_in("F1\nG81 X1 Z-1 R1\nM2\n", Machine::Lathe)
            .rfind("p.ngc:2:1: G81: canned cycles drill along the axis normal to the plane", 0) == 0);
}
