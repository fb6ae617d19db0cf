// SPDX-License-Identifier: Apache-2.0
// The part-program reader (docs/programs.md): G-code of RS274 / ISO 6983 with
// modal groups, read with PEGTL into the motion blocks a program describes, in the
// machine's plane and in integer nanometres (1e-6 mm), with each block's source
// position. It is the planner's side, before the lattice: the geometry is as the
// program gives it (centres, radii and semi-axes anywhere), checked (an arc's end on
// its curve, a reachable radius), and nothing else is decided here.
//
// Bad input throws ProgramError, whose message is one line "FILE:LINE:COLUMN: message"
// (the CLI prints it and exits with status 2).
#pragma once

#include <cstdint>
#include <functional>
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/datapath/errors.hpp"

namespace dda::program {

class ProgramError : public InputError {
 public:
  ProgramError(const std::string& file, std::size_t line, std::size_t column, const std::string& message);
  std::size_t line() const { return line_; }
  std::size_t column() const { return column_; }

 private:
  std::size_t line_, column_;
};

// Lengths in nanometres of the program's unit (1e-6 mm); angles in 0.001 degree.
using Length = std::int64_t;
inline constexpr Length kNmPerMm = 1000000;
// An arc's end may be off its curve by this much (as real controls check the radius to
// the end against the radius to the start): 0.002 mm in the HNC and Fanuc dialects and
// for ellipses. The LinuxCNC dialect takes LinuxCNC's own rule (docs/programs.md, "Arcs
// and ellipses"): refused only when the difference exceeds both kLinuxCncEndTolerance
// (mm programs; kLinuxCncEndToleranceInch in inch programs) and 0.1% of the radius.
inline constexpr Length kEndTolerance = 2000;
inline constexpr Length kLinuxCncEndTolerance = 28284;      // 0.02 mm times the square root of 2
inline constexpr Length kLinuxCncEndToleranceInch = 71842;  // 0.002 in times the square root of 2

// A point of the machine's plane: (u, v) = mill G17 (X, Y), G18 (Z, X), G19 (Y, Z);
// lathe (Z, X as a radius). The lattice's x is u, its y is v.
struct Point2 {
  Length u = 0, v = 0;
  friend bool operator==(const Point2& a, const Point2& b) { return a.u == b.u && a.v == b.v; }
};

enum class Machine { Mill, Lathe };
// The G-code dialects the reader knows (docs/programs.md, "Dialects"): LinuxCNC's
// RS274NGC, HNC-21T's (the lathe paper's control) and Fanuc's.
enum class Dialect { LinuxCnc, Hnc, Fanuc };
std::string_view dialect_name(Dialect d);  // "linuxcnc", "hnc", "fanuc"
enum class MoveKind { Rapid, Line, ArcCw, ArcCcw, EllipseCw, EllipseCcw };
// How F is read: units per minute (G94; G98 on HNC's and Fanuc's lathes), units per
// spindle revolution (G95; G99 there), inverse time (G93: the move takes 1/F minutes).
enum class FeedMode { PerMinute, PerRevolution, InverseTime };
std::string_view kind_name(MoveKind k);  // "rapid", "line", "arc cw", ...

struct SourcePos {
  std::size_t line = 0, column = 0;  // 1-based
};

// One motion block. Clockwise is seen from the positive side of the axis normal to the
// plane (G17: +Z, G18: +Y, G19: +X): on the lattice (u right, v up) a clockwise block
// turns clockwise in G17 and G19 and in G18 as the ZX plane is drawn with Z right and X
// up (a lathe's rear-tool-post view).
struct Move {
  SourcePos pos;
  std::optional<std::int64_t> block_number;  // N
  MoveKind kind = MoveKind::Line;
  Point2 from, to;
  // Arcs and ellipses: the centre (absolute); arcs: the radius (to the start), full
  // turn (end equal to start, given by a centre).
  Point2 center;
  Length radius = 0;
  bool full = false;
  // Ellipses: semi-axes a (along the direction q) and b, q in 0.001 degree from +u.
  Length a = 0, b = 0;
  std::int64_t q_millideg = 0;
  // Arcs: the turns it starts (P, default 1): turns - 1 full circles, then the arc.
  int turns = 1;
  // Arcs and ellipses: how far the end lies off the curve through the start (within the
  // dialect's tolerance); the planner allows it.
  Length end_off = 0;
  int plane = 170;  // the plane of from, to and center: the run's (ReadSummary::plane), or an arc's in force
  // The machine coordinate along the axis normal to the move's plane (G17: Z) at its
  // start and at its end: they differ on a 3-D line, a plunge or a helix.
  Length w = 0, w_to = 0;
  // The feed in force (F as written, 0 if none yet), read by feed_mode, in inches when
  // inch (G20) is in force, else millimetres.
  double feed = 0;
  FeedMode feed_mode = FeedMode::PerMinute;
  bool inch = false;
  bool feed_stale = false;  // F was given under another feed mode (and not since)
  // The spindle: S in force (0 if none yet), in rpm under G97 or, under G96 (css),
  // the surface speed in m/min (ft/min in inches).
  double spindle = 0;
  bool css = false;
  // Path control in force (the speed planner reads it): exact stop (G61, G61.1) rests at
  // the block's end; continuous (G64) blends within path_tolerance (G64 P; 0: none).
  bool exact_stop = false;
  Length path_tolerance = 0;
  // What the program asks between the move before and this one: a dwell (G04, seconds)
  // and a program stop (M00, M01); the tool is at rest for both.
  double dwell = 0;
  bool stop = false;
};

// A word that does not move the tool, accepted and reported ("S1200", "M03", "G54").
struct Ignored {
  SourcePos pos;
  std::string word;
};

struct Program {
  std::vector<Move> moves;
  std::vector<Ignored> ignored;
  Point2 start;
  bool ended = false;  // M02 or M30 seen (text after it is not read)
  Dialect dialect = Dialect::LinuxCnc;
  int plane = 170;         // the plane of the two axes (G17 170, G18 180, G19 190)
  double dwell_after = 0;  // a dwell (seconds) after the last move
};

struct ReadOptions {
  Machine machine = Machine::Mill;
  std::optional<Point2> start;  // default (0, 0)
  // Macro programs: lines executed in all before the run is refused as a loop that does
  // not end (docs/programs.md, "Macros").
  std::uint64_t max_lines = 10000000;
  // The dialect; none: detected from the program (docs/programs.md, "Dialects").
  std::optional<Dialect> dialect;
  // The block delete switch: on, a block starting with '/' is skipped; off (as on a
  // control at power-on), the '/' is ignored and the block runs.
  bool block_delete = false;
  // Where LinuxCNC's o<name> call finds a subroutine file name.ngc after the program's
  // own folder: these folders in order (LinuxCNC's SUBROUTINE_PATH).
  std::vector<std::string> subroutine_path;
};

// Reads a program's text; `file` names it in error messages. (It reads the text as a
// stream with read_stream, keeping every move and every ignored word.)
Program read(std::string_view text, const std::string& file, const ReadOptions& opt = {});

// What a streamed read leaves besides the moves.
struct ReadSummary {
  std::vector<Ignored> ignored;     // the first kMaxIgnoredKept words that do not move (in order)
  std::uint64_t ignored_count = 0;  // all of them
  Point2 start;
  bool ended = false;
  Dialect dialect = Dialect::LinuxCnc;
  int plane = 170;
  // A dwell (seconds) after the last move, before the program's end.
  double dwell_after = 0;
};
inline constexpr std::size_t kMaxIgnoredKept = 1000;
// Reads the program from `in` (a seekable stream: tellg/seekg must work) and calls
// on_move for each motion block as the interpreter reaches it, in program order.
// Memory: the structure of the programs and statements (offsets of '%' headers and of
// WHILE/ENDW/IF/ELSE/ENDIF lines), the variables, the call stack and one line at a
// time; never the whole text or a record per line. Two passes: the first parses every
// line and matches the statements, so that every syntax or structure error is thrown
// before any on_move call; the second seeks back and runs the lines, parsing each when
// it runs (an error at run time, an undefined variable for one, may follow some calls).
// Throws ProgramError as read() does.
ReadSummary read_stream(std::istream& in, const std::string& file, const ReadOptions& opt,
                        const std::function<void(const Move&)>& on_move);
// Opens a program for read_stream: a path, or "-" for standard input (copied to an
// anonymous temporary file, removed by the system when closed, since standard input
// cannot seek). A path that is a directory, missing or unreadable throws InputError with
// one line: "program = 'PATH' is invalid: it is a directory" / "...: cannot read it (<strerror>)".
std::unique_ptr<std::istream> open_program(const std::string& path);

}  // namespace dda::program
