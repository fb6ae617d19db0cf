// SPDX-License-Identifier: Apache-2.0
// What the planner (the driver software) produces: an arc's specification, its pieces
// (one hardware command each) and the facts the runner and the reports need.
#pragma once

#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "model/datapath/datapath.hpp"
#include "model/datapath/hw_params.hpp"

namespace dda {

enum class Preload { Zero, Half };
const char* to_string(Preload p);

enum class Direction { Ccw, Cw };
const char* to_string(Direction d);

// An arc of the ellipse with semi-axes a, b, turned counter-clockwise by `angle` about
// its centre (so the semi-axis a points in direction angle). Angles that are multiples
// of 90 degrees use the exact integer datapath (integrands a^2 |v|, b^2 |u|); any other
// angle uses fixed-point coefficients (docs/golden-model.md, "Rotated ellipses") and
// needs a radius of curvature at the tips, min(a,b)^2 / max(a,b), above 1/4 step.
struct ArcSpec {
  std::int64_t a = 0, b = 0;
  std::int64_t angle = 0;  // micro-degrees (fixed_trig.hpp), reduced modulo a turn
  int bits = 0;            // n: capacity 2^n in the paper's units; 0 = default_bits()
  Preload preload = Preload::Zero;
  Point center;  // lattice point
  Direction dir = Direction::Ccw;
  // Start and end: absolute lattice points, or parametric angles in micro-degrees
  // (exclusive with the point). Defaults: the quarter arc from the end of the a
  // semi-axis to the end of the b semi-axis (parametric angles 0 and 90).
  std::optional<Point> from, to;
  std::optional<std::int64_t> from_theta, to_theta;
  // Geometry between lattice points (part programs, docs/golden-model.md): with sub > 0, a and b are
  // in units of 2^-sub step and the centre is center + center_frac / 2^sub (each
  // component of center_frac in [0, 2^sub)). Such arcs run on the fixed-point datapath
  // of rotated ellipses (whatever the angle) and the anchored planner.
  int sub = 0;
  Point center_frac;
  // Largest distance (steps) the start and end points may lie from the curve; 0 means
  // kPointTolerance (planner.hpp).
  double tolerance = 0;
};

// The semi-axes and the centre in steps (floating point: measurement and drawing only).
double a_steps(const ArcSpec& s);
double b_steps(const ArcSpec& s);
double center_x(const ArcSpec& s);
double center_y(const ArcSpec& s);
// A semi-axis in whole steps, rounded up (limits, widths and guards).
std::int64_t steps_ceil(const ArcSpec& s, std::int64_t v);

// What a piece draws: part of the ellipse, or a straight line (constant integrands, no
// corrections; the capacity is the line's longer extent, so with half preload it is
// Bresenham's line).
enum class PieceKind { Arc, Line };

// One monotone piece of an arc (each axis moves one way): one hardware command.
// Pieces of an axis-aligned ellipse meet at its vertices (lattice points), or where the
// path stalled short of one; those of a rotated ellipse where an axis turns.
struct Piece {
  Point from, to;
  int quadrant = 1;  // 1..4: the quadrant (about the centre) it runs in
  PieceKind kind = PieceKind::Arc;
  Command cmd;
  std::uint64_t iteration_bound = 0;  // a run of this piece that passes it is stopped
  int rot = 0;                        // its core axes drive the run's turned by rot (to_run_axes)
};

// Fixed-point coefficients of a rotated ellipse (docs/golden-model.md, "Rotated
// ellipses"): with (x, y) the lattice position relative to the centre, the tangent of
// the counter-clockwise turn is (p x - qx y, qy x - p y), scaled so that the capacity
// is 2^kRotCapBits. For angles that are multiples of 90 degrees: p = 0, qx = ax^2,
// qy = by^2 exactly and the capacity is 2^n a b.
struct Coefficients {
  std::int64_t p = 0, qx = 0, qy = 0;
};
// Capacity of rotated ellipses: 2^kRotCapBits, the largest power of two the hardware's
// AccWidth-bit registers hold below 2^(AccWidth-1): 2^49 at the default widths.
inline constexpr int kRotCapBits = hw::kAccWidth - 2;
// Fraction bits of the ideal start point (a parametric angle's point on the curve).
inline constexpr int kPosFrac = 32;

// What a plan draws, one of three kinds, each with only the facts that kind has.
//
// An ellipse arc: the spec as planned and what the planner derived from it.
struct ArcGeometry {
  ArcSpec spec;    // with bits resolved
  Point arc_from;  // lattice start of the arc proper (after a lead-in line)
  // The start the DDA represents: arc_from + (frac_x, frac_y) / 2^kPosFrac. With half
  // preload and a parametric start it is the ideal curve point (the first piece's
  // accumulator preloads carry the fraction); otherwise 0.
  std::int64_t frac_x = 0, frac_y = 0;
  bool full = false;            // one full turn: equal lattice ends or equal angles
  bool rotated = false;         // the fixed-point datapath: angle not a multiple of 90
                                // degrees, or sub-step geometry (spec.sub > 0)
  std::int64_t ax = 0, by = 0;  // quarter turns: semi-axes along X and Y (a, b swapped by
                                // odd turns); rotated: a and b
  std::int64_t scale = 1;       // a*b: divide register values by it
  Coefficients coef;
};
// A straight line between the plan's ends (plan_line).
struct LineGeometry {
  Preload preload = Preload::Half;
};
// A part program's blocks back to back (program_plan.hpp): each block's own plan holds
// its geometry.
struct ProgramGeometry {
  Preload preload = Preload::Half;
};

// A validated path: its kind's geometry, its lattice ends, its pieces and the guard
// bound. A default Plan is a line with no piece (a move shorter than a step).
struct Plan {
  std::variant<LineGeometry, ArcGeometry, ProgramGeometry> geometry;
  Point from, to;  // lattice start and end of the path
  std::vector<Piece> pieces;
  std::uint64_t iteration_bound = 0;  // sum of the pieces' bounds

  const Command& cmd() const { return pieces.front().cmd; }
  bool is_arc() const { return std::holds_alternative<ArcGeometry>(geometry); }
  bool is_line() const { return std::holds_alternative<LineGeometry>(geometry); }
  bool is_program() const { return std::holds_alternative<ProgramGeometry>(geometry); }
  // The arc's geometry (std::bad_variant_access for a line or a program).
  const ArcGeometry& arc() const { return std::get<ArcGeometry>(geometry); }
  ArcGeometry& arc() { return std::get<ArcGeometry>(geometry); }
  Preload preload() const;
};

}  // namespace dda
