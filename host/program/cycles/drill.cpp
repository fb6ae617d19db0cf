// SPDX-License-Identifier: Apache-2.0
// LinuxCNC's drilling cycles in the reader (docs/programs.md, "Canned cycles"): G81
// (drill), G82 (drill, dwell), G83 (peck), G73 (chip break), G85 (bore, feed out) and
// G89 (bore, dwell, feed out), with G98/G99 and L repeats, expanded into rapids and
// feeds along the axis normal to the plane in force, move for move as LinuxCNC's
// interpreter expands them (interp_cycles.cc of the LinuxCNC Debian ships).
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>

#include "host/program/reader.hpp"

namespace dda::program::detail {

namespace {

const char kAxisLetter[] = {'X', 'Y', 'Z'};

}  // namespace

bool drill_code(int g) { return g == 730 || g == 810 || g == 820 || g == 830 || g == 850 || g == 890; }

// A block while a drilling cycle is in force: the cycle runs on an axis word (with or
// without its code); any other word of the cycle's alone is refused, as in LinuxCNC.
void Reader::drill_block(const Block& b, const SourcePos& first, int before, bool machine) {
  const Word* code = b.group[kMotion];
  if (machine) fail(b.group[kNonModal]->pos, "G53 goes with G00 or G01 only (LinuxCNC refuses it in a canned cycle)");
  const bool axis = b.axes.count('X') || b.axes.count('Y') || b.axes.count('Z');
  if (axis) return drill_cycle(b, code ? code->pos : first, before);
  if (code)
    fail(code->pos, name(*code) + " needs an axis word (X, Y or Z): LinuxCNC refuses a motion code without one");
  if (!b.axes.empty()) {
    const Word& w = *b.axes.begin()->second;
    fail(w.pos, std::string(1, w.letter) + " with no code that reads it: a canned cycle in force runs on X, Y or Z");
  }
}

// The cycle's block (`before`: the motion mode before it): where the holes are, R the
// retract plane, the bottom along the normal axis, and each hole's moves.
void Reader::drill_cycle(const Block& b, const SourcePos& where, int before) {
  const int g = m_.motion;
  const std::string code = fmt::format("G{}", g / 10);
  const bool dwell = g == 820 || g == 890, peck = g == 730 || g == 830;
  for (const auto& [c, w] : b.axes) {
    const bool ok =
        c == 'X' || c == 'Y' || c == 'Z' || c == 'R' || c == 'L' || (c == 'P' && dwell) || (c == 'Q' && peck);
    if (!ok) fail(w->pos, std::string(1, c) + " is not a word of " + code);
  }
  if (m_.inverse_time) fail(where, code + ": a canned cycle cannot feed in inverse time (G93), as in LinuxCNC");
  if (m_.feed <= 0)
    fail(where, code + " with no feed rate in force: give F (LinuxCNC refuses a feed move at zero feed)");
  fix_lattice();
  const PlaneAxes pa = plane_axes(m_.plane);
  const auto value = [&](char c) -> std::optional<double> {
    const auto it = b.axes.find(c);
    if (it == b.axes.end()) return std::nullopt;
    return c == 'X' && m_.diameter ? word_number(*it->second) / 2 : word_number(*it->second);
  };
  const char normal = kAxisLetter[pa.w];
  if (before != g && !value(normal))
    fail(where, code + " needs " + normal + ", the bottom of the hole, when it starts");
  if (before != g && !value('R')) fail(where, code + " needs R, the retract plane, when it starts");
  if (dwell && before != g && !value('P')) fail(where, code + " needs P, the dwell in seconds, when it starts");
  if (peck && before != g && !value('Q')) fail(where, code + " needs Q, the depth of each peck, when it starts");
  std::int64_t repeats = 1;
  if (const auto l = b.axes.find('L'); l != b.axes.end()) {
    repeats = integer(*l->second);
    if (repeats < 1 || repeats > 1000000)
      fail(l->second->pos, "L (the repeats of a canned cycle) must be from 1 to 1000000");
  }
  const double bottom_word = value(normal).value_or(cycle_.bottom), r_word = value('R').value_or(cycle_.r);
  if (peck) cycle_.q = value('Q').value_or(cycle_.q);
  if (peck && !(cycle_.q > 0)) fail(where, code + ": Q (the depth of each peck) must be positive");

  const Axes here = to_program(pos_);
  const double unit = double(kNmPerMm) * (m_.inch ? 25.4 : 1.0);
  const double cur_u = double(here[std::size_t(pa.u)]) / unit, cur_v = double(here[std::size_t(pa.v)]) / unit;
  double current_w = double(here[std::size_t(pa.w)]) / unit;
  if (!cycle_.initial) cycle_.initial = current_w;  // the level the cycles started from (G98)
  double old_w = *cycle_.initial;
  Hole h;
  double du = 0, dv = 0;
  if (m_.incremental) {
    du = value(kAxisLetter[pa.u]).value_or(0);
    dv = value(kAxisLetter[pa.v]).value_or(0);
    h.r = r_word + old_w;
    h.bottom = h.r + bottom_word;
    h.u = cur_u;
    h.v = cur_v;
  } else {
    h.r = r_word;
    h.bottom = bottom_word;
    h.u = value(kAxisLetter[pa.u]).value_or(cur_u);
    h.v = value(kAxisLetter[pa.v]).value_or(cur_v);
  }
  if (h.r < h.bottom) fail(where, code + ": the retract plane R lies below the bottom " + std::string(1, normal));
  if (old_w < h.r) {  // below the R plane: straight up to it first
    drill_move(b, where, false, cur_u, cur_v, h.r);
    old_w = current_w = h.r;
  }
  h.clear = m_.retract_old_z ? old_w : h.r;
  for (std::int64_t k = repeats; k > 0; --k) {
    h.u += du;
    h.v += dv;
    if (k == repeats && current_w > h.r) {
      drill_move(b, where, false, h.u, h.v, current_w);
      drill_move(b, where, false, h.u, h.v, h.r);
    } else {
      drill_move(b, where, false, h.u, h.v, h.clear);
      if (h.clear > h.r) drill_move(b, where, false, h.u, h.v, h.r);
    }
    drill_hole(b, where, g, h);
  }
  cycle_.bottom = bottom_word;
  cycle_.r = r_word;
}

// One hole's moves from the R plane (LinuxCNC's convert_cycle_g81 .. g89).
void Reader::drill_hole(const Block& b, const SourcePos& where, int g, const Hole& h) {
  const auto feed = [&](double w) { drill_move(b, where, true, h.u, h.v, w); };
  const auto rapid = [&](double w) { drill_move(b, where, false, h.u, h.v, w); };
  // A peck backs off 0.010 inch (0.254 mm) above the depth it reached.
  const double back_off = m_.inch ? 0.010 : 0.254;
  if (g == 730 || g == 830) {
    for (double depth = h.r - cycle_.q; depth > h.bottom; depth -= cycle_.q) {
      feed(depth);
      if (g == 830) rapid(h.r);
      rapid(depth + back_off);
    }
  }
  feed(h.bottom);
  if (g == 850) feed(h.r);
  if (g == 890) {
    feed(h.clear);
  } else {
    rapid(h.clear);
  }
}

// A rapid or a feed to (u, v, w) of the plane in force, in absolute program coordinates.
void Reader::drill_move(const Block& cycle, const SourcePos& where, bool feed, double u, double v, double w) {
  const PlaneAxes pa = plane_axes(m_.plane);
  std::array<Word, 3> words;
  Block b;
  b.n = cycle.n;
  const double at[] = {u, v, w};
  const int axis[] = {pa.u, pa.v, pa.w};
  for (std::size_t k = 0; k < 3; ++k) {
    double value = at[k];
    if (axis[k] == 0 && m_.diameter) value *= 2;  // (the geometry's X is a radius)
    if (!(std::fabs(value) < 1e7)) fail(where, "a move of the canned cycle leaves the range the reader holds");
    words[k] = computed_word(kAxisLetter[axis[k]], value, where);
    b.axes[words[k].letter] = &words[k];
  }
  const int mode = m_.motion;
  const bool incremental = m_.incremental;
  m_.motion = feed ? 10 : 0;
  m_.incremental = false;
  motion(b, where, false);
  m_.motion = mode;
  m_.incremental = incremental;
}

}  // namespace dda::program::detail
