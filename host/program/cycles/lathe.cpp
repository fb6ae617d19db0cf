// SPDX-License-Identifier: Apache-2.0
// LinuxCNC's lathe turning cycles in the reader (docs/programs.md, "Lathe turning
// cycles"), as Debian's LinuxCNC runs them: a rapid to the block's X and Z; the contour
// read by calling its subroutine, whose flow and parameters run as usual while each
// words line adds a segment (its motion words only) instead of moving; then every pass
// (host/program/cycles/turning.cpp) run as an ordinary block in absolute program coordinates.
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "host/program/reader.hpp"

namespace dda::program::detail {

bool turning_code(int g) { return g == 700 || g == 710 || g == 711 || g == 712 || g == 720 || g == 721 || g == 722; }

namespace {

using turning::Pt;

std::string code_name(int g) { return g % 10 ? fmt::format("G{}.{}", g / 10, g % 10) : fmt::format("G{}", g / 10); }

// LinuxCNC's modal group 1 besides G0-G3: a contour line with one of these adds nothing.
bool other_motion(int g) {
  return g == 50 || g == 51 || g == 52 || g == 330 || g == 331 || (g >= 382 && g <= 385) || g == 730 || g == 740 ||
         g == 760 || (g >= 800 && g <= 890 && g % 10 == 0) || turning_code(g);
}

}  // namespace

// G70 Q.. X Z D E P, G71/G72 Q.. X Z D I R: the passes of the contour in
// subroutine Q, from X, Z (default: where the tool is).
void Reader::turning_cycle(const Block& b, const SourcePos& where) {
  const int g = m_.motion;
  const std::string code = code_name(g);
  const std::string_view letters = g == 700 ? "QXZDEP" : "QXZDIR";
  for (const auto& [c, w] : b.axes) {
    // (LinuxCNC's U and W shift the contour, on a machine with U and W axes.)
    if (c == 'U' || c == 'W') fail(w->pos, std::string(1, c) + ": secondary linear axes (U, V, W) are not supported");
    if (letters.find(c) == std::string_view::npos) fail(w->pos, std::string(1, c) + " is not a word of " + code);
  }
  const auto q = b.axes.find('Q');
  if (q == b.axes.end()) fail(where, code + " needs Q, the number of the subroutine that holds the contour");
  if (m_.plane != 180) fail(where, code + " works in the plane G18 (Z, X) only, as in LinuxCNC");
  fix_lattice();
  const Axes here = to_program(pos_);
  const double unit = double(kNmPerMm) * (m_.inch ? 25.4 : 1.0);
  const double cur_x = double(here[0]) / unit, cur_z = double(here[2]) / unit;
  turning::CycleWords words;
  const auto read = [&](char c, double& v) {
    if (const auto it = b.axes.find(c); it != b.axes.end()) v = word_number(*it->second);
  };
  words.x = cur_x;  // (a radius: in G7 LinuxCNC halves an X word as it reads it)
  words.z = cur_z;
  read('X', words.x);
  read('Z', words.z);
  if (m_.diameter && b.axes.count('X')) words.x /= 2;
  const Pt rapid_to(words.z, words.x);  // the first rapid's (the words as absolute, in G91 too)
  if (m_.incremental) {
    words.x = cur_x + (b.axes.count('X') ? words.x : 0);
    words.z = cur_z + (b.axes.count('Z') ? words.z : 0);
  }
  read('D', words.d);
  read('E', words.e);
  read('P', words.p);
  read('I', words.i);
  read('R', words.r);
  if (g == 700 && words.p > 1000) fail(b.axes.at('P')->pos, "P (the number of finishing passes) is at most 1000");
  turning_pass(b, where, {turning::Pass::Rapid, rapid_to, {}});
  Contour contour;
  contour.at = Pt(words.z, words.x);
  contour.motion = 0;
  contour.incremental = m_.incremental;
  contour.ijk_absolute = m_.ijk_absolute;
  contour_ = &contour;
  try {
    run_sub(std::to_string(std::lround(word_number(*q->second))), {}, q->second->pos, 1);
  } catch (...) {
    contour_ = nullptr;
    throw;
  }
  contour_ = nullptr;
  m_.motion = contour.motion;
  sync_position();  // (#<_x> and #<_z> followed the contour)
  // (LinuxCNC cuts nothing then, and takes the contour's end for its position without
  // moving there: a jump the reader refuses.)
  if (contour.segs.size() <= 1 || (g == 700 && words.p < 1)) {
    fail(where, code + " Q" + q->second->text +
                    (g == 700 && words.p < 1 ? ": P (the number of finishing passes) must be at least 1"
                                             : ": the contour needs at least two moves (the approach and a cut)"));
  }
  if (g != 700 && !(words.i > 0)) fail(where, code + ": I (the depth of each cut) must be positive");
  const turning::Sink sink = [&](const turning::Pass& p) { turning_pass(b, where, p); };
  try {
    if (g == 700) {
      turning::finish(std::move(contour.segs), words, sink);
    } else {
      turning::rough(std::move(contour.segs), words, g % 10, g >= 720, sink);
    }
  } catch (const turning::CycleError& e) {
    fail(where, code + " Q" + q->second->text + ": " + e.what());
  }
}

// A words line of the contour: its parameters set, and its X, Z (or U, W), I, K, R and
// the corner words A (rounding) and C (chamfer) into a segment.
void Reader::contour_line(const Line& l) {
  std::vector<Word> words;
  words.reserve(l.words.size());
  for (const Word& w : l.words) words.push_back(macro_.value_word(l, w));
  if (!l.assigns.empty()) macro_.assign_all(l);
  Contour& c = *contour_;
  std::map<char, double> v;
  int g = -1;
  for (const Word& w : words) {
    if (w.letter == 'G') {
      const int t = tenths(w);
      if (t == 0 || t == 10 || t == 20 || t == 30 || other_motion(t)) g = t;
    } else if (std::string_view("XZUWIKRAC").find(w.letter) != std::string_view::npos) {
      v[w.letter] = word_number(w);
    }
  }
  const SourcePos where{l.number, 1};
  Pt end = c.incremental ? Pt(0, 0) : c.at;
  if (v.count('U')) {
    if (c.incremental) fail(where, "U in a contour read in G91 (LinuxCNC refuses it)");
    if (v.count('X')) fail(where, "U and X in one contour block");
    end.imag(end.imag() + (m_.diameter ? v['U'] / 2 : v['U']));
  } else if (v.count('X')) {
    end.imag(m_.diameter ? v['X'] / 2 : v['X']);
  }
  if (v.count('W')) {
    if (c.incremental) fail(where, "W in a contour read in G91 (LinuxCNC refuses it)");
    if (v.count('Z')) fail(where, "W and Z in one contour block");
    end.real(end.real() + v['W']);
  } else if (v.count('Z')) {
    end.real(v['Z']);
  }
  if (c.incremental) end += c.at;
  if (g >= 0) c.motion = g;
  if (end == c.at) return;
  contour_segment(c, v, end, where);
  c.at = end;
  const double unit_x = end.imag(), unit_z = end.real();
  macro_.set(5420, unit_x);
  macro_.set(5422, unit_z);
  macro_.set_named("_x", unit_x);
  macro_.set_named("_z", unit_z);
}

void Reader::contour_segment(Contour& c, const std::map<char, double>& v, Pt end, const SourcePos& where) {
  const auto has = [&](char k) { return v.count(k) != 0; };
  if (c.motion == 0 || c.motion == 10) {
    c.segs.push_back({false, false, c.at, end, {}, 0});
  } else if (c.motion == 20 || c.motion == 30) {
    Pt centre(has('K') ? v.at('K') : 0, has('I') ? v.at('I') : 0);
    if (has('R')) {  // the centre on the side of the turn, as LinuxCNC places it
      if (has('I') || has('K')) fail(where, "an arc of the contour takes a centre (I, K) or a radius R, not both");
      const double r = v.at('R');
      const Pt d = Pt(0, 1) * std::sqrt((r * r - std::norm(end - c.at) / 4) / std::norm(end - c.at)) * (end - c.at);
      centre = (c.at + end) / 2.0 + (c.motion == 30 ? d : -d);
    } else {
      if (!has('I') && !has('K')) fail(where, "an arc of the contour needs its centre (I, K) or a radius R");
      if (!c.ijk_absolute) centre += c.at;
    }
    c.segs.push_back({true, c.motion == 30, c.at, end, centre, 0});
  } else {
    return;
  }
  if (has('A') && has('C')) fail(where, "A (a rounding) and C (a chamfer) on one corner");
  if (has('A')) c.segs.push_back({true, false, end, end, end, v.at('A')});
  if (has('C')) c.segs.push_back({false, false, end, end, {}, v.at('C')});
}

// One pass as a block: X and Z (and the arc's centre I, K, absolute), in program units;
// an arc that ends where the tool is (within 0.0001) is left out, as LinuxCNC leaves it.
void Reader::turning_pass(const Block& cycle, const SourcePos& where, const turning::Pass& p) {
  const bool arc = p.kind == turning::Pass::ArcCw || p.kind == turning::Pass::ArcCcw;
  if (arc) {
    const Axes here = to_program(pos_);
    const double unit = double(kNmPerMm) * (m_.inch ? 25.4 : 1.0);
    if (std::fabs(double(here[2]) / unit - p.end.real()) < 1e-4 &&
        std::fabs(double(here[0]) / unit - p.end.imag()) < 1e-4) {
      return;
    }
  }
  std::array<Word, 4> w;
  Block b;
  b.n = cycle.n;
  const auto set = [&](std::size_t n, char c, double v) {
    if (!(std::fabs(v) < 1e7)) fail(where, "a pass of the turning cycle leaves the range the reader holds");
    w[n] = computed_word(c, v, where);
    b.axes[c] = &w[n];
  };
  set(0, 'X', m_.diameter ? 2 * p.end.imag() : p.end.imag());  // (the geometry's X is a radius)
  set(1, 'Z', p.end.real());
  if (arc) {
    set(2, 'I', p.centre.imag());
    set(3, 'K', p.centre.real());
  }
  static constexpr int kMotion[] = {0, 10, 20, 30};  // by Pass::Kind
  m_.motion = kMotion[p.kind];
  const bool incremental = m_.incremental, ijk_absolute = m_.ijk_absolute;
  m_.incremental = false;
  m_.ijk_absolute = true;
  motion(b, where, false);
  m_.incremental = incremental;
  m_.ijk_absolute = ijk_absolute;
}

}  // namespace dda::program::detail
