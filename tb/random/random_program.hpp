// SPDX-License-Identifier: Apache-2.0
// Random part programs of lines, rapids, circular arcs and elliptical arcs at random
// angles in the XY plane, written as G-code (LinuxCNC words, G6.2/G6.3 for the
// ellipses) with their geometry kept beside the text in floating point: a reference for
// what the program means that is independent of the reader, the planner's pieces and
// the speed plan (the time-optimal profile of tests/test_speed.cpp is computed on it).
#pragma once

#include <array>
#include <random>
#include <string>
#include <vector>

namespace dda::randgen {

// One block's curve: a line from (x0, y0) to (x1, y1), or an arc of the ellipse centred
// at (cx, cy) with semi-axes a (at q radians from +X) and b (a circle: a = b) from the
// parameter t0 over the signed sweep; its feed in mm/s.
struct Curve {
  bool line = true;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double cx = 0, cy = 0, a = 0, b = 0, q = 0;
  double t0 = 0, sweep = 0;
  double feed = 0;
  double length() const;
  // |d(point)/dt| on the ellipse at the parameter t.
  double speed(double t) const;
  // The unit tangent in the direction of travel at the parameter t.
  std::array<double, 2> tangent(double t) const;
  // The radius of curvature at the parameter t (a line: infinity).
  double radius(double t) const;
};

struct RandomProgram {
  std::string text;
  std::vector<Curve> curves;
};

// `blocks` blocks from the origin at feeds of 300, 1000, 3000 and 6000 mm/min (rapids at
// 6000), each block tangent to the one before or at a corner; with `ellipses`, elliptical
// arcs among the circular ones. The program starts with G21 G90 G64 and ends with M2.
RandomProgram random_program(std::mt19937_64& rng, int blocks, bool ellipses);

// The G-code of the arc `c` from (x, y), with c.a, c.b, c.q, c.t0 and c.sweep given: sets
// c's centre (and, for a circle, its radius) from the rounded words the block writes,
// moves (x, y) to the block's rounded end.
std::string curve_block(Curve& c, double& x, double& y, bool circle, bool ccw);

}  // namespace dda::randgen
