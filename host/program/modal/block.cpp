// SPDX-License-Identifier: Apache-2.0
// A block of the program reader (docs/programs.md, "The modal state" and "Offsets"): its
// words evaluated and sorted, its G and M codes into the modal state (RS274's order:
// the modes before the move), the codes recorded that do not move the tool, the offsets
// (G10, G52, G92, G54-G59.3, G43) and the moves that are not a block's motion (G28, G30).
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "host/program/reader.hpp"
#include "model/datapath/rounding.hpp"

namespace dda::program::detail {

std::int64_t pow10(int n) {
  std::int64_t p = 1;
  for (int i = 0; i < n; ++i) p *= 10;
  return p;
}

double length_mm(Length l) { return double(l) / double(kNmPerMm); }

namespace {

// a * num / den rounded half away from zero, in 128 bits.
std::int64_t scale_round(std::int64_t a, std::int64_t num, std::int64_t den) {
  return std::int64_t(round_div(i128(a) * num, den));
}

}  // namespace

Length Reader::length(const Word& w) const {
  const __int128 nm = m_.inch           ? static_cast<__int128>(scale_round(w.mantissa, 25400000, pow10(w.decimals)))
                      : w.decimals <= 6 ? static_cast<__int128>(w.mantissa) * pow10(6 - w.decimals)
                                        : static_cast<__int128>(scale_round(w.mantissa, 1, pow10(w.decimals - 6)));
  if (nm > kMaxLength || nm < -kMaxLength) fail(w.pos, name(w) + ": a length beyond 1000000 mm");
  return static_cast<Length>(nm);
}

// A code's number in tenths (G6.2: 62, G01: 10), or an integer word's value.
int Reader::tenths(const Word& w) const {
  if (w.decimals > 1 && w.mantissa % pow10(w.decimals - 1) != 0) fail(w.pos, "no code " + name(w));
  // (A mantissa has at most 18 digits: checked before the product, which could overflow.)
  if (w.decimals == 0 && (w.mantissa < 0 || w.mantissa > 10000)) fail(w.pos, "no code " + name(w));
  const std::int64_t t = w.decimals == 0 ? w.mantissa * 10 : w.mantissa / pow10(w.decimals - 1);
  if (t < 0 || t > 100000) fail(w.pos, "no code " + name(w));
  return int(t);
}

std::int64_t Reader::integer(const Word& w) const {
  if (w.decimals > 0 && w.mantissa % pow10(w.decimals) != 0) fail(w.pos, name(w) + ": a whole number is needed");
  return w.mantissa / pow10(w.decimals);
}

// A word that does not move the tool: counted, and kept while fewer than asked.
void Reader::ignore(const Word& w) {
  if (sum_.ignored.size() < out_.keep_ignored) sum_.ignored.push_back({w.pos, name(w)});
  ++sum_.ignored_count;
}

void Reader::block(const Line& l) {
  if (l.words.empty() && l.assigns.empty()) return;
  if (contour_) return contour_line(l);
  std::vector<Word> words;  // expressions evaluated now, in the variables' present state
  words.reserve(l.words.size());
  for (const Word& w : l.words) words.push_back(macro_.value_word(l, w));
  if (!l.assigns.empty()) macro_.assign_all(l);  // after the line's reads
  if (words.empty()) return;
  Block b;
  for (const Word& w : words) sort_word(w, b);
  const int before = m_.motion;
  set_modes(b);
  if (b.group[kNonModal] && tenths(*b.group[kNonModal]) == 40 && b.m98) {
    fail(*b.m98, "M98 in a dwell (G04) block: a call stands in its own block");
  }
  consume(b);
  int non_modal_code = b.group[kNonModal] ? tenths(*b.group[kNonModal]) : -1;
  if (non_modal_code == 40) {
    dwell(b);
    non_modal_code = -1;  // (in LinuxCNC the block's axis words move after the dwell)
  }
  if (b.m98) {
    call_ = m98_call(b);
  } else if (non_modal_code >= 0 && non_modal_code != 530) {
    non_modal(b);
  } else if (drill_code(m_.motion)) {
    drill_block(b, words.front().pos, before, non_modal_code == 530);
  } else if (b.group[kMotion] && turning_code(m_.motion)) {
    cycle_.initial.reset();
    turning_cycle(b, b.group[kMotion]->pos);
  } else {
    const bool arc = m_.motion == 20 || m_.motion == 30;
    // (LinuxCNC moves on G00 or G01 without an axis word too: a move of length 0.)
    const bool still = dialect_ == Dialect::LinuxCnc && b.group[kMotion] && (m_.motion == 0 || m_.motion == 10);
    if (!b.axes.empty() || (b.group[kMotion] && arc) || still) {
      cycle_.initial.reset();  // (a move other than a cycle ends a row of cycles)
      motion(b, b.group[kMotion] ? b.group[kMotion]->pos : words.front().pos, non_modal_code == 530);
    } else if (non_modal_code == 530) {
      fail(b.group[kNonModal]->pos, "G53 moves in machine coordinates: it needs an axis word");
    }
  }
  if (b.stop) stop_ = true;
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
      if (b.spindle) fail(w.pos, "S twice in one block");
      b.spindle = &w;
      ignore(w);
      break;
    case 'T':
      ignore(w);
      break;
    case 'F':
      if (b.feed) fail(w.pos, "F twice in one block");
      b.feed = &w;
      break;
    case 'O':
      fail(w.pos, dialect_ == Dialect::LinuxCnc
                      ? "O" + w.text +
                            ": a program number line is Fanuc's (--dialect fanuc); LinuxCNC's O-words "
                            "name a subroutine or a loop (o100 sub, o100 call)"
                      : "O" + w.text + ": a program number stands alone on its line");
    default:
      const bool e_word = w.letter == 'E' && dialect_ == Dialect::LinuxCnc;  // (G70's)
      if (!e_word && std::string_view("XYZUVWIJKRABCQPLHD").find(w.letter) == std::string_view::npos) {
        fail(w.pos, std::string("unknown word ") + w.letter);
      }
      if (b.axes.count(w.letter)) fail(w.pos, std::string(1, w.letter) + " twice in one block");
      b.axes[w.letter] = &w;
  }
}

// A G code: into its modal group, recorded (it does not move the tool) or refused.
void Reader::g_code(const Word& w, Block& b) {
  const int g = tenths(w);
  const bool lathe = opt_.machine == Machine::Lathe;
  const bool lcnc_cycle = dialect_ == Dialect::LinuxCnc && (turning_code(g) || (drill_code(g) && !lathe));
  if (g == 0 || g == 10 || g == 20 || g == 30 || g == 62 || g == 63 || lcnc_cycle) {
    set_group(b, kMotion, w, "motion");
  } else if (g == 170 || g == 180 || g == 190) {
    if (lathe && g != 180) fail(w.pos, "a lathe works in G18 (Z and X)");
    set_group(b, kPlane, w, "plane");
  } else if (g == 200 || g == 210) {
    set_group(b, kUnits, w, "unit");
  } else if (g == 900 || g == 910) {
    set_group(b, kDistance, w, "distance mode");
  } else if (g == 901 || g == 911) {
    set_group(b, kArcDistance, w, "arc distance mode");
  } else if (g == 360 || g == 370) {
    if (!lathe) fail(w.pos, "G36/G37 (diameter or radius X) are lathe codes (--machine lathe)");
    set_group(b, kXMode, w, "X mode");
  } else if (g == 70 || g == 80) {
    set_group(b, kXMode, w, "X mode");
  } else if (g == 410 || g == 420 || g == 411 || g == 421) {
    fail(w.pos, "tool radius compensation (G41/G42) is not supported: program the tool's path");
  } else if (g == 400) {
    set_group(b, kComp, w, "cutter compensation");
    ignore(w);
  } else if (g >= 540 && g <= 593 && (g % 10 == 0 || g >= 590)) {
    if (g > 590 && g != 591 && g != 592 && g != 593) fail(w.pos, "no code " + name(w));
    set_group(b, kWork, w, "work offset");
    ignore(w);
  } else if (!g_recorded(g, w, b)) {
    fail(w.pos, "unknown or unsupported code " + name(w));
  }
}

// The codes read and recorded (or refused naming their feature: g_refused); false: unknown.
bool Reader::g_recorded(int g, const Word& w, Block& b) {
  const bool hnc_lathe_feed = opt_.machine == Machine::Lathe && dialect_ != Dialect::LinuxCnc;
  switch (g) {
    case 40:   // dwell
    case 100:  // G10: offsets
    case 280:  // G28, G28.1, G30, G30.1: stored positions
    case 281:
    case 300:
    case 301:
    case 520:  // G52: a local offset
    case 530:  // G53: a move in machine coordinates
    case 920:  // G92 and G92.1-G92.3: the G92 offset
    case 921:
    case 922:
    case 923:
      set_group(b, kNonModal, w, "non-modal code");
      if (g == 40) ignore(w);
      return true;
    case 430:  // tool length offsets: recorded, they act on the third axis
    case 431:
    case 432:
    case 490:
      set_group(b, kToolLength, w, "tool length offset");
      ignore(w);
      return true;
    case 610:  // path control, kept for the feed planner (P, Q read with G64)
    case 611:
    case 640:
      set_group(b, kPath, w, "path control");
      ignore(w);
      return true;
    case 930:
    case 940:
    case 950:
      set_group(b, kFeedMode, w, "feed mode");
      return true;
    case 960:  // spindle speed modes and its clamp, kept for the feed planner
    case 970:
    case 500:
      set_group(b, kSpindle, w, "spindle speed mode");
      ignore(w);
      return true;
    case 980:  // canned-cycle return levels; on HNC's and Fanuc's lathes, feed modes
    case 990:
      set_group(b, hnc_lathe_feed ? kFeedMode : kReturn, w, hnc_lathe_feed ? "feed mode" : "return mode");
      if (!hnc_lathe_feed) ignore(w);
      return true;
    case 800:  // canned cycle cancel: no motion mode, unless the block gives one
      b.cancel_cycle = true;
      ignore(w);
      return true;
    default:
      g_refused(g, w);
      return false;
  }
}

// The codes refused naming their feature (docs/programs.md, "The modal state").
void Reader::g_refused(int g, const Word& w) const {
  switch (g) {
    case 330:
    case 331:
    case 760:
      fail(w.pos, name(w) + ": threading (G33, G33.1, G76) is not supported");
    case 382:
    case 383:
    case 384:
    case 385:
      fail(w.pos, name(w) + ": probing (G38.2-G38.5) is not supported: the probe input comes with the machine inputs");
    case 50:
    case 51:
    case 52:
    case 53:
      fail(w.pos, name(w) + ": splines (G5, G5.1, G5.2, G5.3) are not supported: convert them to lines and arcs");
    case 730:
    case 810:
    case 820:
    case 830:
    case 850:
    case 890:  // (LinuxCNC's, on a mill, are read: host/program/cycles/drill.cpp)
      fail(w.pos, name(w) + (opt_.machine == Machine::Lathe
                                 ? ": canned cycles drill along the axis normal to the plane, which a lathe (G18) "
                                   "lacks: they are not supported on a lathe"
                                 : ": canned cycles in HNC's and Fanuc's dialects are not supported (LinuxCNC's "
                                   "G73, G81-G83, G85 and G89 are read in --dialect linuxcnc)"));
    case 740:
    case 840:
    case 860:
    case 870:
    case 880:
      fail(w.pos, name(w) + ": canned cycles that stop or reverse the spindle (G74, G84, G86-G88) are not supported");
    case 700:
    case 710:
    case 711:
    case 712:
    case 720:
    case 721:
    case 722:  // (LinuxCNC's are read: host/program/cycles/lathe.cpp)
      fail(w.pos, name(w) +
                      ": lathe turning cycles in HNC's and Fanuc's form (G71 U R, G71 P Q U W) are not supported: "
                      "program the passes (LinuxCNC's G70-G72 are read in --dialect linuxcnc)");
    case 150:
    case 160:
      fail(w.pos, name(w) + ": polar coordinates (G15, G16) are not supported");
    case 171:
    case 181:
    case 191:
      fail(w.pos, name(w) + ": planes of the secondary linear axes (U, V, W) are not supported");
    default:
      return;
  }
}

// An M code: the program's end, a call, a return, recorded (spindle, coolant, tool
// change, stops) or refused.
void Reader::m_code(const Word& w, Block& b) {
  const std::int64_t m = integer(w);
  if (m == 2 || m == 30) {
    b.end = true;
  } else if (m == 0 || m == 1) {
    b.stop = true;  // (M01, the optional stop, as with its switch on)
    ignore(w);
  } else if ((m >= 0 && m <= 9) || m == 19 || (m >= 48 && m <= 53) || m == 60 || m == 61 || (m >= 62 && m <= 68) ||
             (m >= 100 && m <= 199)) {
    ignore(w);  // stops, spindle, tool change, coolant, overrides, I/O: they do not move the tool
  } else if (m == 98) {
    b.m98 = w.pos;
  } else if (m == 99) {
    return_ = true;
  } else if (m >= 70 && m <= 73 && dialect_ == Dialect::LinuxCnc) {
    modal_state(w, m);
  } else {
    fail(w.pos, "unknown or unsupported code " + name(w));
  }
}

// LinuxCNC's M70 (save the modal state), M71 (forget it), M72 (restore it), M73 (save
// it until the subroutine returns).
void Reader::modal_state(const Word& w, std::int64_t m) {
  ignore(w);
  if (m == 70) saved_ = m_;
  if (m == 71) saved_.reset();
  if (m == 73) call_saved_.back() = m_;
  if (m != 72) return;
  if (!saved_) fail(w.pos, "M72: no modal state saved by M70 to restore");
  const int motion = m_.motion;  // (LinuxCNC's M72 leaves the motion mode)
  m_ = *saved_;
  m_.motion = motion;
  sync_params();
}

void Reader::set_group(Block& b, Group g, const Word& w, const char* what) const {
  if (b.group[g]) fail(w.pos, "G" + b.group[g]->text + " and G" + w.text + " in one block: one " + what + " per block");
  b.group[g] = &w;
}

// The modal codes take effect before the block's motion (RS274's order).
void Reader::set_modes(const Block& b) {
  if (b.group[kFeedMode]) {
    const int g = tenths(*b.group[kFeedMode]);
    m_.inverse_time = g == 930;
    m_.per_rev = g == 950 || g == 990;
  }
  const int feed_mode = m_.inverse_time ? 2 : m_.per_rev ? 1 : 0;
  // S is the spindle speed (rpm under G97, the surface speed under G96), except with G50,
  // where it is the spindle's clamp on HNC's and Fanuc's lathes. A change between G96
  // and G97 without S leaves the speed unknown (a control keeps the rpm it turns at).
  const int spindle_code = b.group[kSpindle] ? tenths(*b.group[kSpindle]) : 0;
  if (spindle_code == 960 || spindle_code == 970) {
    const bool css = spindle_code == 960;
    if (css != m_.css && !b.spindle) m_.spindle = 0;
    m_.css = css;
  }
  if (b.spindle && spindle_code != 500) {
    const Word& w = *b.spindle;
    const double s = double(w.mantissa) / double(pow10(w.decimals));
    if (s < 0) fail(w.pos, "the spindle speed S must not be negative");
    m_.spindle = s;
  }
  if (b.group[kPath]) {
    m_.exact_stop = tenths(*b.group[kPath]) != 640;
    m_.path_tolerance = 0;
  }
  if (b.feed) {
    const Word& w = *b.feed;
    const double f = double(w.mantissa) / double(pow10(w.decimals));
    if (f <= 0) fail(w.pos, "the feed F must be positive");
    m_.feed = f;
    m_.feed_mode_of_f = feed_mode;
  }
  if (b.group[kPlane]) m_.plane = tenths(*b.group[kPlane]);
  if (b.group[kUnits]) m_.inch = tenths(*b.group[kUnits]) == 200;
  if (b.group[kXMode]) {
    const int x = tenths(*b.group[kXMode]);
    m_.diameter = x == 360 || x == 70;
  }
  if (b.group[kWork]) {
    const int g = tenths(*b.group[kWork]);
    m_.cs = g < 590 ? (g - 540) / 10 : g == 590 ? 5 : g - 591 + 6;
    sync_params();
  }
  if (b.group[kToolLength]) {
    const int g = tenths(*b.group[kToolLength]);
    // (Without a tool table every tool's length is 0, as with rs274's table of zeros:
    // G43.1 gives its length in Z.)
    const auto z = b.axes.find('Z');
    tool_length_ = g == 431 && z != b.axes.end() ? length(*z->second) : 0;
  }
  if (b.group[kDistance]) m_.incremental = tenths(*b.group[kDistance]) == 910;
  if (b.group[kArcDistance]) m_.ijk_absolute = tenths(*b.group[kArcDistance]) == 901;
  if (b.group[kReturn]) m_.retract_old_z = tenths(*b.group[kReturn]) == 980;
  if (b.group[kMotion]) m_.motion = tenths(*b.group[kMotion]);
  if (b.cancel_cycle && !b.group[kMotion]) m_.motion = -1;
  if (b.cancel_cycle) cycle_.initial.reset();
}

// The words a block's other codes read, recorded and taken out of its axes: H with
// G43, P and Q with G64.
void Reader::consume(Block& b) {
  const auto take = [&](char c) {
    const auto it = b.axes.find(c);
    if (it == b.axes.end()) return;
    ignore(*it->second);
    b.axes.erase(it);
  };
  if (b.group[kToolLength] && tenths(*b.group[kToolLength]) != 490) take('H');
  if (b.group[kToolLength] && tenths(*b.group[kToolLength]) == 431) take('Z');
  if (b.group[kPath] && tenths(*b.group[kPath]) == 640) {
    if (const auto p = b.axes.find('P'); p != b.axes.end()) {
      m_.path_tolerance = length(*p->second);
      if (m_.path_tolerance < 0) fail(p->second->pos, "G64 P (the path tolerance) must not be negative");
    }
    take('P');
    take('Q');
  }
}

// G04: P (or, on HNC and Fanuc, X or U) is the dwell time, nothing moves (in LinuxCNC
// the block's axis words move after the dwell: P is taken out of its words).
void Reader::dwell(Block& b) {
  const auto seconds = [&](const Word& w, double per_second) {
    const double t = double(w.mantissa) / double(pow10(w.decimals)) / per_second;
    if (t < 0) fail(w.pos, "the dwell time of G04 must not be negative");
    dwell_ += t;
  };
  if (dialect_ == Dialect::LinuxCnc) {
    const auto p = b.axes.find('P');
    if (p == b.axes.end()) fail(b.group[kNonModal]->pos, "G04 needs P, the dwell time in seconds");
    seconds(*p->second, 1);
    ignore(*p->second);
    b.axes.erase(p);
    return;
  }
  for (const auto& [c, w] : b.axes) {
    if (c != 'P' && c != 'X' && c != 'U') fail(w->pos, std::string(1, c) + " in a dwell (G04) block");
    // (Fanuc's P counts milliseconds, HNC's seconds; X and U are seconds in both.)
    seconds(*w, c == 'P' && dialect_ == Dialect::Fanuc ? 1000 : 1);
    ignore(*w);
  }
  b.axes.clear();  // (the time, not a move)
}

// M98 P (program number) L (repeats, default 1), or Fanuc's P of more than four digits:
// the repeats, then the program number (P21234: O1234 twice). Nothing else moves.
Reader::Call Reader::m98_call(const Block& b) const {
  if (return_) fail(*b.m98, "M98 and M99 in one block: call or return, not both");
  const auto p = b.axes.find('P');
  if (p == b.axes.end()) fail(*b.m98, "M98 needs P, the number of the program to call");
  Call c;
  c.program = integer(*p->second);
  c.pos = p->second->pos;
  const auto rl = b.axes.find('L');
  if (dialect_ == Dialect::Fanuc && c.program > 9999 && rl == b.axes.end()) {
    c.repeats = c.program / 10000;
    c.program %= 10000;
  }
  if (rl != b.axes.end()) {
    c.repeats = integer(*rl->second);
    if (c.repeats < 1 || c.repeats > 9999) fail(rl->second->pos, "L (the repeat count) must be from 1 to 9999");
  }
  for (const auto& [ch, w] : b.axes) {
    if (ch != 'P' && ch != 'L') fail(w->pos, std::string(1, ch) + " in an M98 block: a call moves nothing");
  }
  return c;
}

}  // namespace dda::program::detail
