// SPDX-License-Identifier: Apache-2.0
// The planner for part programs (docs/programs.md): a program's motion blocks onto the
// lattice, each cut into core commands by the arc and line planners, back to back in
// the order the engines run them. Programmed geometry between
// lattice points (centres, radii, semi-axes) is kept in sub-step units (1/2^kSubBits
// step); end points are rounded to the nearest lattice point.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "host/planner/plan.hpp"
#include "host/program/program.hpp"

namespace dda::program {

struct LatticeOptions {
  Length step = 1000;  // nanometres per lattice step (--step MM; default 0.001 mm)
  Preload preload = Preload::Half;
};

// Decimal millimetres as a user writes them on the command line ("-2.5", ".0005", "10":
// an optional sign, at most 7 whole digits and 6 decimals) to nanometres, exactly;
// nullopt for any other text.
std::optional<Length> parse_mm(const std::string& text);
// The lattice unit from its text in millimetres ("0.001"): a whole number of nanometres
// from 1 nm to 1 mm, else InputError naming the rule.
Length parse_step(const std::string& mm);
// The tool's start as a user gives it (mill X,Y; lathe X,Z with X a diameter, halved as
// the reader halves diameters) as a point of the plane.
Point2 start_point(Machine m, Length first, Length second);

// A length in lattice steps, rounded to the nearest (halves away from zero), and in
// sub-step units (1/2^kSubBits step).
std::int64_t to_steps(Length v, Length step);
std::int64_t to_sub_steps(Length v, Length step);
// A point of the plane on the lattice (each coordinate rounded as to_steps), and the
// distance (steps) between a lattice point and the programmed point it stands for.
Point on_lattice(Point2 p, Length step);
double rounding(Point q, Point2 p, Length step);

// Arcs of a radius beyond kMaxDatapathRadius steps (the sub-step geometry's semi-axes
// hold 2^20 steps) run as chords: lines between lattice points next to the circle, each
// chord's sagitta at most kChordSagitta steps (program_chords.cpp).
inline constexpr std::int64_t kMaxDatapathRadius = (std::int64_t{1} << 20) - 2;
inline constexpr double kChordSagitta = 0.05;
bool beyond_datapath(const Move& mv, Length step);
Plan plan_chords(const Move& mv, Length step, Preload preload, Point from, Point to);

struct BlockPlan {
  Move move;
  Point from, to;               // lattice ends; `to` is the programmed end rounded
  double rounding = 0;          // steps between the programmed end and `to`
  Plan plan;                    // the block's commands (none for a move that rounds to nothing)
  std::size_t first_piece = 0;  // index of its first piece in ProgramPlan::plan
  int rot = 0;                  // its plane's axes turned onto the run's (Piece::rot)
};
// A block's programmed end in the run's axes, in nanometres (Move::to and w_to are in
// the block's own plane's axes).
inline Point run_end_nm(const BlockPlan& b) { return to_run_axes(Point{b.move.to.u, b.move.to.v, b.move.w_to}, b.rot); }

struct ProgramPlan {
  LatticeOptions lattice;
  Point start;                    // the tool's start on the lattice
  double start_rounding = 0;      // steps between the programmed start and `start`
  std::vector<BlockPlan> blocks;  // one per motion block, in program order
  Plan plan;                      // every block's pieces, back to back: what the engines run
};

// How many motion blocks the planner holds before it plans the oldest: the lookahead
// a speed planner will use. Each block is planned on its own today, so the window only
// bounds what is held.
inline constexpr std::size_t kDefaultWindow = 16;

// The streaming planner: motion blocks in, in program order; each block planned once
// `window` blocks stand behind it (or at finish()), and handed to on_block with its
// lattice ends and pieces. A block the planners refuse throws ProgramError naming it.
class BlockPlanner {
 public:
  BlockPlanner(const LatticeOptions& opt, Point2 start, std::string file, std::size_t window,
               std::function<void(BlockPlan&&)> on_block);
  Point start() const { return start_; }
  double start_rounding() const { return start_rounding_; }
  void move(const Move& mv);
  // Plans what the window holds; throws ProgramError if nothing at all ran (no motion
  // block, or every move shorter than a step).
  void finish();
  std::uint64_t pieces() const { return pieces_; }
  Point end() const { return at_; }

 private:
  void plan_front();
  Plan plan_curve(const Move& mv, Point from, Point to) const;
  LatticeOptions opt_;
  std::string file_;
  std::size_t window_;
  std::function<void(BlockPlan&&)> on_block_;
  std::deque<Move> held_;
  int run_plane_ = 0;  // the plane of the two axes: the first move's
  Point start_, at_;
  double start_rounding_ = 0;
  std::uint64_t pieces_ = 0, blocks_ = 0;
  SourcePos last_{1, 1};
};

// Plan every motion block (the whole program in memory: tests and vector sets). A block the planners refuse throws
// ProgramError naming it
// ("FILE:LINE:COLUMN: block N (arc cw): reason"). A program without a motion block
// throws too (there is nothing to run).
ProgramPlan plan_program(const Program& prog, const LatticeOptions& opt, const std::string& file);

// Refuse (ProgramError naming the first block at fault) a plan with a command the
// hardware's widths cannot hold: what `--engine systemc|rtl` runs.
void check_hardware(const ProgramPlan& pp, const std::string& file);
void check_hardware(const BlockPlan& b, const std::string& file);

// Distance (steps, floating point: measurement only) of point (x, y) from a block's
// programmed geometry: the segment between its programmed ends, its circle or its
// ellipse (as programmed, before any rounding).
double block_distance(const BlockPlan& b, Length step, double x, double y);
// The same distance with the block's geometry converted to steps once (a report asks it
// of every point of the block).
class BlockDistance {
 public:
  BlockDistance(const BlockPlan& b, Length step);
  double operator()(double x, double y) const;
  // The distances of n lattice points (out[k] of pts[k]): the same values, in a loop
  // without a branch per point on lines and circles, which the compiler vectorizes.
  void operator()(const Point* pts, std::size_t n, double* out) const;

 private:
  enum class Kind { Segment, Circle, Ellipse } kind_;
  double x0_ = 0, y0_ = 0, ux_ = 0, uy_ = 0, len2_ = 0;  // segment: start, direction, length^2
  double cx_ = 0, cy_ = 0, r_ = 0, a_ = 0, b_ = 0;       // circle and ellipse: centre, radius, semi-axes
  std::int64_t angle_udeg_ = 0;
};

// A block's accuracy target (steps) against its programmed geometry, with half preload:
// the targets of docs/results.md (lines 0.5, circles and axis-aligned ellipses up to
// aspect ratio 4 0.8, other ellipses 1.0) plus the larger rounding of its two ends
// (`from_rounding`: the previous block's); infinity with zero preload (reported, not
// targeted).
double block_target(const BlockPlan& b, double from_rounding, Preload preload);

// A block as messages name it ("block N20 (arc cw)", "block at line 7 (line)"), and
// ProgramError "FILE:LINE:COLUMN: block N20 (arc cw): why".
std::string block_name(const Move& mv);
[[noreturn]] void block_error(const std::string& file, const Move& mv, const std::string& why);

// Which block a piece of ProgramPlan::plan belongs to.
std::size_t block_of_piece(const ProgramPlan& pp, std::size_t piece);

}  // namespace dda::program
