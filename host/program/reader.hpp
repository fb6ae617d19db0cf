// SPDX-License-Identifier: Apache-2.0
// Inside the program reader: the interpreter of a program's lines (docs/programs.md). Its
// parts: the flow (macro/flow.cpp: the passes, HNC's statements and calls, LinuxCNC's
// O-words), a block's words and modal state (modal/block.cpp: G and M codes, the
// offsets) and its motion (modal/motion.cpp: lines, arcs and ellipses on the plane).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <list>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host/program/cycles/turning.hpp"
#include "host/program/grammar/line.hpp"
#include "host/program/macro/macro.hpp"
#include "host/program/program.hpp"

namespace dda::program::detail {

// Every length and position stays within 1000000 mm (1e12 nm), far inside 64 bits.
inline constexpr Length kMaxLength = 1000000 * kNmPerMm;

std::int64_t pow10(int n);
double length_mm(Length l);

// G70, G71, G71.1, G71.2, G72, G72.1, G72.2 (in tenths): LinuxCNC's lathe turning cycles.
bool turning_code(int g);
// G73, G81, G82, G83, G85, G89 (in tenths): LinuxCNC's drilling cycles the reader expands.
bool drill_code(int g);

// The modal state besides the position and offsets.
struct Modal {
  int motion = -1;  // G-code in tenths: 0, 10, 20, 30, 62, 63; -1: none yet
  int plane = 170;
  bool inch = false;
  bool incremental = false;
  bool ijk_absolute = false;   // G90.1: arc centres absolute
  bool diameter = false;       // X (and U) as diameters: G7 (LinuxCNC) or G36 (HNC, Fanuc lathes)
  bool inverse_time = false;   // G93
  bool retract_old_z = false;  // G98: canned cycles retract to where they started; G99 (default): to R
  int cs = 0;                  // the work offset in force: 0 G54 .. 8 G59.3
  double feed = 0;
  bool per_rev = false;       // G95 (G99 on HNC's and Fanuc's lathes)
  int feed_mode_of_f = 0;     // the feed mode F was given in: 0 per minute, 1 per revolution, 2 inverse time
  double spindle = 0;         // S
  bool css = false;           // G96
  bool exact_stop = false;    // G61, G61.1
  Length path_tolerance = 0;  // G64 P
};

// Where the interpreter's results go besides the summary: each move, and how many
// ignored words to keep.
struct Output {
  const std::function<void(const Move&)>& on_move;
  std::size_t keep_ignored;
};

// The axes X, Y and Z by index.
using Axes = std::array<Length, 3>;

class Reader {
 public:
  Reader(std::istream& in, const std::string& file, const ReadOptions& opt, const Output& out);
  ReadSummary run();

  // The modal groups of the G codes, one code of each in a block.
  enum Group : std::size_t {
    kMotion,
    kPlane,
    kUnits,
    kDistance,
    kArcDistance,
    kFeedMode,
    kXMode,
    kComp,
    kToolLength,
    kWork,
    kPath,
    kReturn,
    kSpindle,
    kNonModal,
    kGroups
  };
  // A block's words sorted by kind: its N, its G codes by group, its other words by
  // letter (axes, centre offsets, parameters), and what its M codes ask for.
  struct Block {
    std::optional<std::int64_t> n;
    std::array<const Word*, kGroups> group{};
    std::map<char, const Word*> axes;
    const Word* feed = nullptr;
    const Word* spindle = nullptr;  // S
    bool stop = false;              // M00 or M01
    bool end = false;               // M02 or M30: the program ends after the block
    bool cancel_cycle = false;      // G80
    std::optional<SourcePos> m98;   // M98: the block calls a subprogram
  };

 private:
  [[noreturn]] void fail(const SourcePos& p, const std::string& msg) const {
    throw ProgramError(src_->file, p.line, p.column, msg);
  }
  std::string name(const Word& w) const { return std::string(1, w.letter) + w.text; }
  Length length(const Word& w) const;
  int tenths(const Word& w) const;
  std::int64_t integer(const Word& w) const;
  void ignore(const Word& w);

  // Flow (macro/flow.cpp).
  Dialect detect();
  struct Call {
    std::int64_t program = 0, repeats = 1;
    SourcePos pos;
  };
  void exec(const LinePos& begin, std::size_t end, int depth);
  LinePos step(const Line& l, const LinePos& at, const LinePos& next, int depth);
  LinePos o_step(const Line& l, const LinePos& at, const LinePos& next, int depth);
  LinePos o_branch(std::size_t mark);
  void call(const Call& c, int depth);
  void o_call(const Line& l, int depth);
  void run_sub(const std::string& name, const std::vector<double>& args, const SourcePos& at, int depth);

  // Blocks (modal/block.cpp).
  void block(const Line& l);
  void sort_word(const Word& w, Block& b);
  void g_code(const Word& w, Block& b);
  bool g_recorded(int g, const Word& w, Block& b);
  void g_refused(int g, const Word& w) const;
  void m_code(const Word& w, Block& b);
  void modal_state(const Word& w, std::int64_t m);
  void set_group(Block& b, Group g, const Word& w, const char* what) const;
  void set_modes(const Block& b);
  void dwell(Block& b);
  Call m98_call(const Block& b) const;
  void non_modal(const Block& b);
  void set_offsets(const Block& b);
  void home(const Block& b, int g);
  void traverse(const Axes& to, const Block& b, const SourcePos& where);
  void consume(Block& b);
  void sync_params();
  void sync_position();
  Length offset(int axis) const;
  // Machine and program coordinates of a point (X, Y, Z): the program's point plus the
  // G92 offset, turned by the work offset's rotation, plus the work offset (and on Z the
  // tool length), as LinuxCNC maps them; exact integers when nothing turns.
  Axes to_program(const Axes& machine) const;
  Axes to_machine(const Axes& program) const;
  std::pair<double, double> turn(double x, double y, double sign) const;
  Axes word_axes(const Block& b, bool machine, Axes base) const;

  // Motion (modal/motion.cpp).
  void fix_lattice();
  void motion(const Block& b, const SourcePos& where, bool machine);
  void emit(Move& mv, const Axes& to);
  Axes target(const Block& b, bool machine, const SourcePos& where) const;
  void check_letters(const Block& b) const;
  void arc(Move& mv, const Block& b, const SourcePos& where);
  void arc_by_centre(Move& mv, const Block& b, const SourcePos& where);
  void arc_by_radius(Move& mv, const Word& r, const SourcePos& where);
  void ellipse(Move& mv, const Block& b, const SourcePos& where);

  // LinuxCNC's lathe turning cycles G70-G72 (cycles/lathe.cpp): the contour is read by
  // running its subroutine with each words line captured (contour_line) instead of run.
  struct Contour {
    std::list<turning::Segment> segs;
    turning::Pt at;  // the contour's end so far (Z, X)
    int motion = 0;
    bool incremental = false, ijk_absolute = false;
  };
  void turning_cycle(const Block& b, const SourcePos& where);
  void contour_line(const Line& l);
  void contour_segment(Contour& c, const std::map<char, double>& v, turning::Pt end, const SourcePos& where);
  void turning_pass(const Block& cycle, const SourcePos& where, const turning::Pass& p);

  // LinuxCNC's drilling cycles (cycles/drill.cpp): a hole's coordinates in the plane in
  // force (u, v) and along its normal: the retract plane R, the bottom and the level
  // each hole retracts to.
  struct Hole {
    double u = 0, v = 0, r = 0, bottom = 0, clear = 0;
  };
  void drill_block(const Block& b, const SourcePos& first, int before, bool machine);
  void drill_cycle(const Block& b, const SourcePos& where, int before);
  void drill_hole(const Block& b, const SourcePos& where, int g, const Hole& h);
  void drill_move(const Block& cycle, const SourcePos& where, bool feed, double u, double v, double w);

  // The plane's axes: u, v and the normal w as indices of X, Y, Z; the letters of the
  // centre words along u and v.
  struct PlaneAxes {
    int u, v, w;
    char iu, iv;
  };
  static PlaneAxes plane_axes(int plane);

  std::string file_;
  ReadOptions opt_;
  Output out_;
  Dialect dialect_ = Dialect::LinuxCnc;
  Modal m_;
  // A dwell and a program stop read since the last move: the next move carries them.
  double dwell_ = 0;
  bool stop_ = false;
  ReadSummary sum_;
  Axes pos_{};          // the tool, in machine coordinates (nm; X a radius)
  int lattice_ = 0;     // the plane of the two axes, fixed by the first block that needs the position
  int move_plane_ = 0;  // the plane of the move being built: an arc's plane in force, else lattice_
  // Offsets (nm): the work offsets G54-G59.3, G92's (or G52's) and the tool length's.
  std::array<Axes, 9> work_{};
  std::array<double, 9> rotation_{};  // each work offset's XY rotation (G10 L2 R), degrees
  Axes g92_{};
  Axes g92_stored_{};  // G92.3 restores it
  Length tool_length_ = 0;
  Axes g28_{}, g30_{};  // G28.1 and G30.1's stored positions (machine)
  Macro macro_;
  // The text being run: the program's own, or a subroutine file's (LinuxCNC's o<name>
  // call of a file name.ngc beside the program), each read and structured once.
  struct Source {
    Source(std::istream& in, const std::string& f) : file(f), lines(in, f) {}
    Source(std::unique_ptr<std::istream> in, const std::string& f) : file(f), own(std::move(in)), lines(*own, f) {}
    std::string file;
    std::unique_ptr<std::istream> own;
    LineStream lines;
    Structure st;
  };
  Source main_;
  Source* src_ = &main_;
  std::map<std::string, std::unique_ptr<Source>> files_;
  Source* subroutine_file(const std::string& name, const SourcePos& at);
  std::uint64_t executed_ = 0;
  std::optional<Call> call_;                     // M98 in the block just run
  bool return_ = false;                          // M99, or LinuxCNC's endsub or return, in the line just run
  std::map<std::size_t, std::int64_t> repeats_;  // o.. repeat: passes left, by its mark
  // LinuxCNC's saved modal state: M70 (saved_), M73 (restored when the call returns).
  std::optional<Modal> saved_;
  std::vector<std::optional<Modal>> call_saved_{1};
  Contour* contour_ = nullptr;  // a turning cycle's contour being read
  // The drilling cycles' sticky values (program units as written): R, the bottom, the
  // peck; and the level the cycles in a row started from.
  struct CycleState {
    double r = 0, bottom = 0, q = 0;
    std::optional<double> initial;
  } cycle_;
};

}  // namespace dda::program::detail
