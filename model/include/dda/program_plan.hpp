// SPDX-License-Identifier: Apache-2.0
// The planner for part programs (issue 15, docs/programs.md): a program's motion blocks
// onto the lattice, each cut into core commands by the arc and line planners, all of
// them back to back in one plan that every engine runs. Programmed geometry between
// lattice points (centres, radii, semi-axes) is kept in sub-step units (1/2^kSubBits
// step); end points are rounded to the nearest lattice point.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dda/plan.hpp"
#include "dda/program.hpp"

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

struct BlockPlan {
  Move move;
  Point from, to;               // lattice ends; `to` is the programmed end rounded
  double rounding = 0;          // steps between the programmed end and `to`
  Plan plan;                    // the block's commands (none for a move that rounds to nothing)
  std::size_t first_piece = 0;  // index of its first piece in ProgramPlan::plan
};

struct ProgramPlan {
  LatticeOptions lattice;
  Point start;                    // the tool's start on the lattice
  double start_rounding = 0;      // steps between the programmed start and `start`
  std::vector<BlockPlan> blocks;  // one per motion block, in program order
  Plan plan;                      // every block's pieces, back to back: what the engines run
};

// Plan every motion block. A block the planners refuse throws ProgramError naming it
// ("FILE:LINE:COLUMN: block N (arc cw): reason"). A program without a motion block
// throws too (there is nothing to run).
ProgramPlan plan_program(const Program& prog, const LatticeOptions& opt, const std::string& file);

// Refuse (ProgramError naming the first block at fault) a plan with a command the
// hardware's widths cannot hold: what `--engine systemc|rtl` runs.
void check_hardware(const ProgramPlan& pp, const std::string& file);

// Distance (steps, floating point: measurement only) of point (x, y) from a block's
// programmed geometry: the segment between its programmed ends, its circle or its
// ellipse (as programmed, before any rounding).
double block_distance(const BlockPlan& b, Length step, double x, double y);

// A block's accuracy target (steps) against its programmed geometry, with half preload:
// the targets of docs/results.md (lines 0.5, circles and axis-aligned ellipses up to
// aspect ratio 4 0.8, other ellipses 1.0) plus the larger rounding of its two ends
// (`from_rounding`: the previous block's); infinity with zero preload (reported, not
// targeted).
double block_target(const BlockPlan& b, double from_rounding, Preload preload);

// Which block a piece of ProgramPlan::plan belongs to.
std::size_t block_of_piece(const ProgramPlan& pp, std::size_t piece);

}  // namespace dda::program
