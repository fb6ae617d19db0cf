// SPDX-License-Identifier: Apache-2.0
// The program reader's interpreter: each line's words (program_grammar.cpp) through the
// modal state of RS274 into motion blocks (docs/programs.md), read from a stream in two
// passes (the structure first, program_macro.cpp; then the run, a line at a time); and
// the files it reads, standard input through a temporary file.
#include "program/program.hpp"

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "datapath/rounding.hpp"
#include "geometry/fixed_trig.hpp"
#include "program_detail.hpp"
#include "program_macro.hpp"

namespace dda::program {

namespace {

using detail::Word;

std::int64_t pow10(int n) {
  std::int64_t p = 1;
  for (int i = 0; i < n; ++i) p *= 10;
  return p;
}

// a * num / den rounded half away from zero, in 128 bits.
std::int64_t scale_round(std::int64_t a, std::int64_t num, std::int64_t den) {
  return std::int64_t(round_div(i128(a) * num, den));
}

double length_mm(Length l) { return double(l) / double(kNmPerMm); }

// Every length and position stays within 1000000 mm (1e12 nm), far inside 64 bits.
constexpr Length kMaxLength = 1000000 * kNmPerMm;

struct Modal {
  int motion = -1;  // G-code in tenths: 0, 10, 20, 30, 62, 63; -1: none yet
  int plane = 170;
  bool inch = false;
  bool incremental = false;
  bool diameter = true;  // lathe: X and U as diameters (G36), or radii (G37)
  double feed = 0;
};

// Where the interpreter's results go besides the summary: each move, and how many
// ignored words to keep.
struct Output {
  const std::function<void(const Move&)>& on_move;
  std::size_t keep_ignored;
};

class Reader {
 public:
  Reader(std::istream& in, const std::string& file, const ReadOptions& opt, const Output& out)
      : file_(file), opt_(opt), out_(out), macro_(file), lines_(in, file) {
    if (opt.machine == Machine::Lathe) m_.plane = 180;
    if (opt.start) sum_.start = *opt.start;
    at_ = sum_.start;
  }

  ReadSummary run() {
    st_ = detail::structure(lines_, file_);  // pass 1: every line parsed, the statements matched
    // Pass 2. The main program: the first with a word or a statement; the others are called.
    for (std::size_t i = 0; i < st_.programs.size(); ++i) {
      if (st_.programs[i].content) {
        exec(i, 0);
        break;
      }
    }
    return std::move(sum_);
  }

 private:
  [[noreturn]] void fail(const SourcePos& p, const std::string& msg) const {
    throw ProgramError(file_, p.line, p.column, msg);
  }
  std::string name(const Word& w) const { return std::string(1, w.letter) + w.text; }

  Length length(const Word& w) const {
    const __int128 nm = m_.inch           ? static_cast<__int128>(scale_round(w.mantissa, 25400000, pow10(w.decimals)))
                        : w.decimals <= 6 ? static_cast<__int128>(w.mantissa) * pow10(6 - w.decimals)
                                          : static_cast<__int128>(scale_round(w.mantissa, 1, pow10(w.decimals - 6)));
    if (nm > kMaxLength || nm < -kMaxLength) fail(w.pos, name(w) + ": a length beyond 1000000 mm");
    return static_cast<Length>(nm);
  }
  // A code's number in tenths (G6.2: 62, G01: 10), or an integer word's value.
  int tenths(const Word& w) const {
    if (w.decimals > 1 && w.mantissa % pow10(w.decimals - 1) != 0) fail(w.pos, "no code " + name(w));
    const std::int64_t t = w.decimals == 0 ? w.mantissa * 10 : w.mantissa / pow10(w.decimals - 1);
    if (t < 0 || t > 100000) fail(w.pos, "no code " + name(w));
    return int(t);
  }
  std::int64_t integer(const Word& w) const {
    if (w.decimals > 0 && w.mantissa % pow10(w.decimals) != 0) fail(w.pos, name(w) + ": a whole number is needed");
    return w.mantissa / pow10(w.decimals);
  }

  // A word that does not move the tool: counted, and kept while fewer than asked.
  void ignore(const Word& w) {
    if (sum_.ignored.size() < out_.keep_ignored) sum_.ignored.push_back({w.pos, name(w)});
    ++sum_.ignored_count;
  }

  struct Call {
    std::int64_t program = 0, repeats = 1;
    SourcePos pos;
  };
  void exec(std::size_t program, int depth);
  detail::LinePos step(const detail::Line& l, const detail::LinePos& at, const detail::LinePos& next);
  void call(const Call& c, int depth);

  // The modal groups of the G codes, one code of each in a block: motion, plane, units,
  // distance mode, the lathe's X mode (G36/G37), cutter compensation, dwell, work offset.
  enum Group : std::size_t { kMotion, kPlane, kUnits, kDistance, kXMode, kComp, kDwell, kWork, kGroups };
  // A block's words sorted by kind: its N, its G codes by group, its other words by
  // letter (axes, centre offsets, parameters), and what its M codes ask for.
  struct Block {
    std::optional<std::int64_t> n;
    std::array<const Word*, kGroups> group{};
    std::map<char, const Word*> axes;
    bool end = false;              // M02 or M30: the program ends after the block
    std::optional<SourcePos> m98;  // M98: the block calls a subprogram
  };
  void block(const detail::Line& l);
  void sort_word(const Word& w, Block& b);
  void g_code(const Word& w, Block& b);
  void m_code(const Word& w, Block& b);
  void set_group(Block& b, Group g, const Word& w, const char* what) const;
  void set_modes(const Block& b);
  void dwell(const Block& b);
  Call m98_call(const Block& b) const;
  void motion(const std::map<char, const Word*>& axes, const SourcePos& where, std::optional<std::int64_t> n);
  void arc(Move& mv, const std::map<char, const Word*>& axes, const SourcePos& where);
  void ellipse(Move& mv, const std::map<char, const Word*>& axes, const SourcePos& where);

  // The letters of the plane's two axes and their centre offsets, per machine and plane.
  struct PlaneLetters {
    char u, v, iu, iv, inc_u, inc_v;  // inc_*: the lathe's incremental letters (0: none)
  };
  PlaneLetters letters() const {
    if (opt_.machine == Machine::Lathe) return {'Z', 'X', 'K', 'I', 'W', 'U'};
    if (m_.plane == 180) return {'Z', 'X', 'K', 'I', 0, 0};
    if (m_.plane == 190) return {'Y', 'Z', 'J', 'K', 0, 0};
    return {'X', 'Y', 'I', 'J', 0, 0};
  }

  std::string file_;
  ReadOptions opt_;
  Output out_;
  Modal m_;
  ReadSummary sum_;
  Point2 at_;
  // Macros (program_macro.hpp): variables, the programs and the control flow.
  detail::Macro macro_;
  detail::LineStream lines_;
  detail::Structure st_;
  std::uint64_t executed_ = 0;
  std::optional<Call> call_;  // M98 in the block just run
  bool return_ = false;       // M99 in the block just run
};

// Runs a program's lines, each read when it runs: statements steer, blocks move (and call).
void Reader::exec(std::size_t program, int depth) {
  const detail::ProgramText p = st_.programs[program];
  detail::Line l;
  for (detail::LinePos pc = p.begin; pc.number < p.end;) {
    const detail::LinePos next = lines_.read(pc, l);
    if (++executed_ > opt_.max_lines) {
      fail(SourcePos{l.number, 1},
           fmt::format("more than {} lines executed: a loop that does not end?", opt_.max_lines));
    }
    if (l.stmt != detail::Stmt::None) {
      pc = step(l, pc, next);
      continue;
    }
    block(l);
    pc = next;
    if (sum_.ended) return;
    if (return_) {
      return_ = false;
      if (depth == 0) fail(SourcePos{l.number, 1}, "M99 in the main program: no caller to return to");
      return;
    }
    if (call_) {
      const Call c = *call_;
      call_.reset();
      call(c, depth);
      if (sum_.ended) return;
    }
  }
}

// A statement line at `at`: where the program goes on.
detail::LinePos Reader::step(const detail::Line& l, const detail::LinePos& at, const detail::LinePos& next) {
  const auto match = [&]() -> const detail::StmtMark& { return st_.marks[st_.mark(at.offset).jump]; };
  switch (l.stmt) {
    case detail::Stmt::Assign:
      macro_.assign(l);
      return next;
    case detail::Stmt::While:  // a false condition goes past its ENDW, or its ELSE or ENDIF
    case detail::Stmt::If:
      return macro_.truth(l) ? next : match().next;
    case detail::Stmt::EndW:  // back to its WHILE's test
      return match().at;
    case detail::Stmt::Else:  // the end of the IF's true branch: past its ENDIF
      return match().next;
    default:
      return next;
  }
}

// M98: runs the subprogram c.program c.repeats times.
void Reader::call(const Call& c, int depth) {
  std::size_t target = st_.programs.size();
  for (std::size_t i = 0; i < st_.programs.size(); ++i) {
    if (st_.programs[i].number == c.program) target = i;
  }
  if (target == st_.programs.size()) fail(c.pos, fmt::format("M98 calls program %{}: there is none", c.program));
  if (depth + 1 > detail::kMaxCallDepth) {
    fail(c.pos, fmt::format("subprogram calls nested deeper than {}", detail::kMaxCallDepth));
  }
  for (std::int64_t k = 0; k < c.repeats && !sum_.ended; ++k) {
    // #30 and #32 (lathe: X as programmed and Z) or #30 and #31 (mill: the plane's
    // first and second axes) hold the current position at each call, in mm.
    const bool lathe = opt_.machine == Machine::Lathe;
    const double unit = double(kNmPerMm) * (m_.inch ? 25.4 : 1.0);  // the program's unit (G20/G21)
    const double u = double(at_.u) / unit, v = double(at_.v) / unit;
    macro_.set(30, lathe ? (m_.diameter ? 2 * v : v) : u);
    macro_.set(lathe ? 32 : 31, lathe ? u : v);
    exec(target, depth + 1);
  }
}

void Reader::block(const detail::Line& l) {
  if (l.words.empty()) return;
  std::vector<Word> words;  // expressions evaluated now, in the variables' present state
  words.reserve(l.words.size());
  for (const Word& w : l.words) words.push_back(macro_.value_word(l, w));
  Block b;
  for (const Word& w : words) sort_word(w, b);
  set_modes(b);
  if (b.group[kDwell] && b.m98) fail(*b.m98, "M98 in a dwell (G04) block: a call stands in its own block");
  if (b.group[kDwell]) {
    dwell(b);
  } else if (b.m98) {
    call_ = m98_call(b);
  } else {
    if (const auto p = b.axes.find('P'); p != b.axes.end()) fail(p->second->pos, "P is read only with G04 and M98");
    if (const auto rl = b.axes.find('L'); rl != b.axes.end()) fail(rl->second->pos, "L is read only with M98");
    const bool moves = !b.axes.empty() || (b.group[kMotion] && (m_.motion == 20 || m_.motion == 30));
    if (moves) motion(b.axes, b.group[kMotion] ? b.group[kMotion]->pos : words.front().pos, b.n);
  }
  if (b.end) sum_.ended = true;
}

// One word of a block into its place in `b`: an unknown word, or a letter twice, fails.
void Reader::sort_word(const Word& w, Block& b) {
  switch (w.letter) {
    case 'N':
      b.n = integer(w);
      break;
    case 'G':
      g_code(w, b);
      break;
    case 'M':
      m_code(w, b);
      break;
    case 'S':
    case 'T':
      ignore(w);
      break;
    case 'F': {
      const double f = double(w.mantissa) / double(pow10(w.decimals));
      if (f <= 0) fail(w.pos, "the feed F must be positive");
      m_.feed = f;
      break;
    }
    default:
      if (std::string_view("XYZUVWIJKRABQPL").find(w.letter) == std::string_view::npos) {
        fail(w.pos, std::string("unknown word ") + w.letter);
      }
      if (b.axes.count(w.letter)) fail(w.pos, std::string(1, w.letter) + " twice in one block");
      b.axes[w.letter] = &w;
  }
}

// A G code: into its modal group, ignored (it does not move the tool) or refused.
void Reader::g_code(const Word& w, Block& b) {
  const int g = tenths(w);
  if (g == 0 || g == 10 || g == 20 || g == 30 || g == 62 || g == 63) {
    set_group(b, kMotion, w, "motion");
  } else if (g == 170 || g == 180 || g == 190) {
    if (opt_.machine == Machine::Lathe && g != 180) fail(w.pos, "a lathe works in G18 (Z and X)");
    set_group(b, kPlane, w, "plane");
  } else if (g == 200 || g == 210) {
    set_group(b, kUnits, w, "unit");
  } else if (g == 900 || g == 910) {
    set_group(b, kDistance, w, "distance mode");
  } else if (g == 360 || g == 370) {
    if (opt_.machine != Machine::Lathe) fail(w.pos, "G36/G37 (diameter or radius X) are lathe codes (--machine lathe)");
    set_group(b, kXMode, w, "X mode");
  } else if (g == 400) {
    ignore(w);
  } else if (g == 410 || g == 420) {
    fail(w.pos, "tool radius compensation (G41/G42) is not supported: program the tool's path");
  } else if (g == 40) {
    set_group(b, kDwell, w, "dwell");
    ignore(w);
  } else if ((g >= 540 && g <= 590 && g % 10 == 0) || g == 940 || g == 950 || g == 800) {
    ignore(w);
  } else {
    fail(w.pos, "unknown or unsupported code " + name(w));
  }
}

// An M code: the program's end, a call, a return, ignored (spindle, coolant) or refused.
void Reader::m_code(const Word& w, Block& b) {
  const std::int64_t m = integer(w);
  if (m == 2 || m == 30) {
    b.end = true;
  } else if (m == 0 || m == 1 || m == 3 || m == 4 || m == 5 || m == 8 || m == 9) {
    ignore(w);
  } else if (m == 98) {
    b.m98 = w.pos;
  } else if (m == 99) {
    return_ = true;
  } else {
    fail(w.pos, "unknown or unsupported code " + name(w));
  }
}

void Reader::set_group(Block& b, Group g, const Word& w, const char* what) const {
  if (b.group[g]) fail(w.pos, "G" + b.group[g]->text + " and G" + w.text + " in one block: one " + what + " per block");
  b.group[g] = &w;
}

// The modal codes take effect before the block's motion (RS274's order).
void Reader::set_modes(const Block& b) {
  if (b.group[kPlane]) m_.plane = tenths(*b.group[kPlane]);
  if (b.group[kUnits]) m_.inch = tenths(*b.group[kUnits]) == 200;
  if (b.group[kDistance]) m_.incremental = tenths(*b.group[kDistance]) == 910;
  if (b.group[kXMode]) m_.diameter = tenths(*b.group[kXMode]) == 360;
  if (b.group[kMotion]) m_.motion = tenths(*b.group[kMotion]);
}

// G04: X, U or P is the dwell time, nothing moves.
void Reader::dwell(const Block& b) {
  for (const auto& [c, w] : b.axes) {
    if (c != 'X' && c != 'U' && c != 'P') fail(w->pos, std::string(1, c) + " in a dwell (G04) block");
    ignore(*w);
  }
}

// M98 P (program number) L (repeats, default 1): nothing else moves.
Reader::Call Reader::m98_call(const Block& b) const {
  if (return_) fail(*b.m98, "M98 and M99 in one block: call or return, not both");
  const auto p = b.axes.find('P');
  if (p == b.axes.end()) fail(*b.m98, "M98 needs P, the number of the program to call");
  Call c;
  c.program = integer(*p->second);
  c.pos = p->second->pos;
  if (const auto rl = b.axes.find('L'); rl != b.axes.end()) {
    c.repeats = integer(*rl->second);
    if (c.repeats < 1 || c.repeats > 9999) fail(rl->second->pos, "L (the repeat count) must be from 1 to 9999");
  }
  for (const auto& [ch, w] : b.axes) {
    if (ch != 'P' && ch != 'L') fail(w->pos, std::string(1, ch) + " in an M98 block: a call moves nothing");
  }
  return c;
}

void Reader::motion(const std::map<char, const Word*>& axes, const SourcePos& where, std::optional<std::int64_t> n) {
  if (m_.motion < 0) fail(where, "a move with no motion mode (G00, G01, G02, G03, G6.2, G6.3) in force");
  const PlaneLetters pl = letters();
  const bool ellipse_mode = m_.motion == 62 || m_.motion == 63;
  const bool arc_mode = m_.motion == 20 || m_.motion == 30;
  for (const auto& [c, w] : axes) {
    const bool axis = c == pl.u || c == pl.v || (pl.inc_u && (c == pl.inc_u || c == pl.inc_v));
    const bool centre = c == pl.iu || c == pl.iv;
    if (axis) continue;
    if (centre && (arc_mode || ellipse_mode)) continue;
    if (c == 'R' && arc_mode) continue;
    if ((c == 'A' || c == 'B' || c == 'Q') && ellipse_mode) continue;
    if (c == 'X' || c == 'Y' || c == 'Z' || c == 'U' || c == 'V' || c == 'W') {
      fail(w->pos, std::string(1, c) + " is not an axis of the " +
                       (opt_.machine == Machine::Lathe ? std::string("lathe (Z and X)")
                                                       : "plane in force (G17 X Y, G18 Z X, G19 Y Z)"));
    }
    if (centre || c == 'I' || c == 'J' || c == 'K') fail(w->pos, std::string(1, c) + " is not a centre word here");
    fail(w->pos, std::string(1, c) + (c == 'R' ? " is read only with G02/G03" : " is read only with G6.2/G6.3"));
  }
  const bool lathe = opt_.machine == Machine::Lathe;
  const auto v_len = [&](const Word& w) {  // the lathe's X and U: diameters unless G37
    const Length l = length(w);
    return lathe && m_.diameter ? l / 2 : l;
  };
  Point2 to = at_;
  if (const auto u = axes.find(pl.u); u != axes.end())
    to.u = m_.incremental ? at_.u + length(*u->second) : length(*u->second);
  if (const auto v = axes.find(pl.v); v != axes.end())
    to.v = m_.incremental ? at_.v + v_len(*v->second) : v_len(*v->second);
  if (pl.inc_u) {
    const auto iu = axes.find(pl.inc_u), iv = axes.find(pl.inc_v);
    if (iu != axes.end() && axes.count(pl.u)) fail(iu->second->pos, std::string("both ") + pl.u + " and " + pl.inc_u);
    if (iv != axes.end() && axes.count(pl.v)) fail(iv->second->pos, std::string("both ") + pl.v + " and " + pl.inc_v);
    if (iu != axes.end()) to.u = at_.u + length(*iu->second);
    if (iv != axes.end()) to.v = at_.v + v_len(*iv->second);
  }
  for (const Length c : {to.u, to.v}) {
    if (c > kMaxLength || c < -kMaxLength) fail(where, "the move leaves the 1000000 mm the reader holds");
  }
  Move mv;
  mv.pos = where;
  mv.block_number = n;
  mv.from = at_;
  mv.to = to;
  mv.feed = m_.feed;
  if (m_.motion == 0 || m_.motion == 10) {
    mv.kind = m_.motion == 0 ? MoveKind::Rapid : MoveKind::Line;
  } else if (arc_mode) {
    mv.kind = m_.motion == 20 ? MoveKind::ArcCw : MoveKind::ArcCcw;
    arc(mv, axes, where);
  } else {
    mv.kind = m_.motion == 62 ? MoveKind::EllipseCw : MoveKind::EllipseCcw;
    ellipse(mv, axes, where);
  }
  out_.on_move(mv);
  at_ = to;
}

// The centre of a circle of radius r through p and q (distinct), on the side that makes
// the turn from p to q in direction cw sweep at most half a turn (short) or at least (long).
std::pair<double, double> centre_through(double px, double py, double qx, double qy, double r, bool cw,
                                         bool short_arc) {
  const double mx = (px + qx) / 2, my = (py + qy) / 2;
  const double dx = qx - px, dy = qy - py;
  const double d = std::hypot(dx, dy);
  const double h = std::sqrt(std::max(0.0, r * r - d * d / 4));
  // Left of the chord (counter-clockwise side): a ccw short arc has its centre there.
  const double lx = -dy / d, ly = dx / d;
  const bool left = (!cw) == short_arc;
  const double s = left ? h : -h;
  return {mx + s * lx, my + s * ly};
}

void Reader::arc(Move& mv, const std::map<char, const Word*>& axes, const SourcePos& where) {
  const PlaneLetters pl = letters();
  const auto iu = axes.find(pl.iu), iv = axes.find(pl.iv), r = axes.find('R');
  const bool has_centre = iu != axes.end() || iv != axes.end();
  if (r != axes.end() && has_centre) fail(r->second->pos, "an arc takes a centre or a radius R, not both");
  if (r == axes.end() && !has_centre) {
    fail(where, std::string("an arc needs a centre (") + pl.iu + ", " + pl.iv + ") or a radius R");
  }
  const bool cw = mv.kind == MoveKind::ArcCw;
  if (has_centre) {
    // Centre words are offsets from the start (RS274); the lathe's I is a radius.
    mv.center = mv.from;
    if (iu != axes.end()) mv.center.u += length(*iu->second);
    if (iv != axes.end()) mv.center.v += length(*iv->second);
    const double r0 = std::hypot(double(mv.from.u - mv.center.u), double(mv.from.v - mv.center.v));
    const double r1 = std::hypot(double(mv.to.u - mv.center.u), double(mv.to.v - mv.center.v));
    if (r0 < 1) fail(where, "the arc's centre is its start point");
    if (std::fabs(r1 - r0) > double(kEndTolerance)) {
      fail(where, fmt::format("the end is {:.4f} mm off the arc's circle (radius {:.4f} mm; tolerance {:.3f} mm)",
                              length_mm(Length(std::llround(std::fabs(r1 - r0)))), r0 / double(kNmPerMm),
                              length_mm(kEndTolerance)));
    }
    mv.radius = Length(std::llround(r0));
    mv.full = mv.from == mv.to;
    return;
  }
  const Length rr = length(*r->second);
  if (rr == 0) fail(r->second->pos, "the radius R must not be 0");
  if (mv.from == mv.to) fail(r->second->pos, "a full circle needs a centre, not R");
  const double d = std::hypot(double(mv.to.u - mv.from.u), double(mv.to.v - mv.from.v));
  const double ar = std::fabs(double(rr));
  if (d > 2 * ar + double(kEndTolerance)) {
    fail(r->second->pos, fmt::format("the end is out of reach: {:.4f} mm from the start, more than twice R {:.4f} mm",
                                     d / double(kNmPerMm), ar / double(kNmPerMm)));
  }
  const auto [cx, cy] =
      centre_through(double(mv.from.u), double(mv.from.v), double(mv.to.u), double(mv.to.v), ar, cw, rr > 0);
  mv.center = Point2{Length(std::llround(cx)), Length(std::llround(cy))};
  mv.radius = Length(std::llround(ar));
}

void Reader::ellipse(Move& mv, const std::map<char, const Word*>& axes, const SourcePos& where) {
  const PlaneLetters pl = letters();
  const auto a = axes.find('A'), b = axes.find('B'), q = axes.find('Q');
  if (a == axes.end() || b == axes.end()) fail(where, "an ellipse block needs its semi-axes A and B");
  mv.a = length(*a->second);
  mv.b = length(*b->second);
  if (mv.a <= 0) fail(a->second->pos, "the semi-axis A must be positive");
  if (mv.b <= 0) fail(b->second->pos, "the semi-axis B must be positive");
  mv.q_millideg = q == axes.end() ? 0 : integer(*q->second);
  const bool cw = mv.kind == MoveKind::EllipseCw;
  // The deterministic fixed-point sines (fixed_trig.hpp), so that every machine computes
  // the same centre to the nanometre.
  const SinCos qt = sincos_udeg(mv.q_millideg * 1000);
  const double c = std::ldexp(double(qt.c), -kTrigFrac), s = std::ldexp(double(qt.s), -kTrigFrac);
  const double A = double(mv.a), B = double(mv.b);
  // To the ellipse's frame, with the minor axis stretched to A: the ellipse is a circle.
  const auto to_frame = [&](double x, double y) {
    return std::pair<double, double>{c * x + s * y, (-s * x + c * y) * A / B};
  };
  const auto from_frame = [&](double x, double y) {
    const double yy = y * B / A;
    return std::pair<double, double>{c * x - s * yy, s * x + c * yy};
  };
  const auto iu = axes.find(pl.iu), iv = axes.find(pl.iv);
  if (iu != axes.end() || iv != axes.end()) {
    mv.center = mv.from;
    if (iu != axes.end()) mv.center.u += length(*iu->second);
    if (iv != axes.end()) mv.center.v += length(*iv->second);
  } else {
    if (mv.from == mv.to) fail(where, "a full ellipse needs its centre (I, K)");
    const auto [px, py] = to_frame(double(mv.from.u), double(mv.from.v));
    const auto [qx, qy] = to_frame(double(mv.to.u), double(mv.to.v));
    const double d = std::hypot(qx - px, qy - py);
    if (d > 2 * A + double(kEndTolerance)) fail(where, "the end is out of reach of an ellipse with these A, B and Q");
    // The circle's centre for the shorter arc; the frame keeps the turning sense.
    const auto [fx, fy] = centre_through(px, py, qx, qy, A, cw, true);
    const auto [cx, cy] = from_frame(fx, fy);
    if (!(std::fabs(cx) <= double(4 * kMaxLength) && std::fabs(cy) <= double(4 * kMaxLength))) {
      fail(where, "the ellipse's centre leaves the range the reader holds");
    }
    mv.center = Point2{Length(std::llround(cx)), Length(std::llround(cy))};
  }
  // Both ends on the ellipse, within the tolerance along the radius.
  const std::array<Point2, 2> ends{mv.from, mv.to};
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const double x = double(ends[i].u - mv.center.u), y = double(ends[i].v - mv.center.v);
    const double xe = c * x + s * y, ye = -s * x + c * y;
    const double rho = std::hypot(xe / A, ye / B);
    // (At the centre itself the distance to the curve is the smaller semi-axis.)
    const double off = rho < 1e-12 ? std::min(A, B) : std::fabs(rho - 1) * std::hypot(x, y) / rho;
    if (off > double(kEndTolerance)) {
      fail(where, fmt::format("the {} is {:.4f} mm off the ellipse (tolerance {:.3f} mm)", i == 0 ? "start" : "end",
                              off / double(kNmPerMm), length_mm(kEndTolerance)));
    }
  }
  mv.full = mv.from == mv.to;
}

[[noreturn]] void cannot_read(const std::string& path, int err) {
  throw InputError("program = '" + path + "' is invalid: cannot read it (" + std::strerror(err) + ")");
}

// A read-only stream buffer over a C file (of the program `path`), which it closes;
// seekable, and a seek within what it holds (a loop's jump back to its WHILE, most
// often) costs no system call. A read error is an InputError.
class FileBuf : public std::streambuf {
 public:
  FileBuf(std::FILE* f, const std::string& path) : f_(f), path_(path) {}
  ~FileBuf() override { std::fclose(f_); }
  FileBuf(const FileBuf&) = delete;
  FileBuf& operator=(const FileBuf&) = delete;

 protected:
  int_type underflow() override {
    start_ += egptr() - eback();
    const std::size_t n = std::fread(buf_.data(), 1, buf_.size(), f_);
    if (n == 0 && std::ferror(f_)) cannot_read(path_, errno);
    setg(buf_.data(), buf_.data(), buf_.data() + n);
    return n == 0 ? traits_type::eof() : traits_type::to_int_type(buf_[0]);
  }
  pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode which) override {
    if (dir == std::ios_base::cur) return seekpos(pos_type(start_ + (gptr() - eback()) + off), which);
    if (dir == std::ios_base::beg) return seekpos(pos_type(off), which);
    return pos_type(off_type(-1));  // (from the end: not needed)
  }
  pos_type seekpos(pos_type pos, std::ios_base::openmode /*which*/) override {
    const off_type p = pos;
    if (p >= start_ && p <= start_ + (egptr() - eback())) {
      setg(eback(), eback() + (p - start_), egptr());
      return pos;
    }
    if (p < 0 || fseeko(f_, p, SEEK_SET) != 0) return pos_type(off_type(-1));
    start_ = p;
    setg(buf_.data(), buf_.data(), buf_.data());
    return pos;
  }

 private:
  std::FILE* f_;
  std::string path_;
  std::array<char, 65536> buf_;
  off_type start_ = 0;  // the file's offset of eback()
};

class FileStream : public std::istream {
 public:
  FileStream(std::FILE* f, const std::string& path) : std::istream(nullptr), buf_(f, path) { rdbuf(&buf_); }

 private:
  FileBuf buf_;
};

// Standard input, which cannot seek, copied to an anonymous temporary file (removed by
// the system when it is closed).
std::FILE* copy_stdin() {
  std::FILE* f = std::tmpfile();
  if (!f) cannot_read("-", errno);
  const auto give_up = [f] {
    const int err = errno;
    std::fclose(f);
    cannot_read("-", err);
  };
  std::vector<char> chunk(65536);
  for (std::streamsize n; (n = std::cin.rdbuf()->sgetn(chunk.data(), std::streamsize(chunk.size()))) > 0;) {
    if (std::fwrite(chunk.data(), 1, std::size_t(n), f) != std::size_t(n)) give_up();
  }
  if (std::fflush(f) != 0 || std::fseek(f, 0, SEEK_SET) != 0) give_up();
  return f;
}

}  // namespace

Program read(std::string_view text, const std::string& file, const ReadOptions& opt) {
  std::istringstream in{std::string(text)};
  Program p;
  const std::function<void(const Move&)> keep = [&p](const Move& m) { p.moves.push_back(m); };
  ReadSummary s = Reader(in, file, opt, Output{keep, std::numeric_limits<std::size_t>::max()}).run();
  p.ignored = std::move(s.ignored);
  p.start = s.start;
  p.ended = s.ended;
  return p;
}

ReadSummary read_stream(std::istream& in, const std::string& file, const ReadOptions& opt,
                        const std::function<void(const Move&)>& on_move) {
  return Reader(in, file, opt, Output{on_move, kMaxIgnoredKept}).run();
}

std::unique_ptr<std::istream> open_program(const std::string& path) {
  if (path == "-") return std::make_unique<FileStream>(copy_stdin(), path);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError("program = '" + path + "' is invalid: it is a directory");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) cannot_read(path, errno);
  return std::make_unique<FileStream>(f, path);
}

}  // namespace dda::program
