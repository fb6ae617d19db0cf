// SPDX-License-Identifier: Apache-2.0
// The program reader's coordinate systems (docs/programs.md, "Offsets"), as LinuxCNC
// keeps them: a program position is the machine position less the work offset in force
// (G54-G59.3, set by G10 L2 and L20), the G92 offset (G92, G52, G92.1-G92.3) and, on Z,
// the tool length offset (G43); G53 moves in machine coordinates; G28 and G30 go, by an
// optional point between, to the positions G28.1 and G30.1 stored.
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "host/geometry/det_math.hpp"
#include "host/program/reader.hpp"

namespace dda::program::detail {

namespace {

int axis_of(char c) { return c == 'X' ? 0 : c == 'Y' ? 1 : c == 'Z' ? 2 : -1; }
bool other_axis(char c) { return std::string_view("ABCUVW").find(c) != std::string_view::npos; }

}  // namespace

Length Reader::offset(int axis) const {
  return work_[std::size_t(m_.cs)][std::size_t(axis)] + g92_[std::size_t(axis)] + (axis == 2 ? tool_length_ : 0);
}

// (x, y) turned by the rotation in force (sign -1: back), with the deterministic sines.
std::pair<double, double> Reader::turn(double x, double y, double sign) const {
  const double a = sign * rotation_[std::size_t(m_.cs)] * det::kPi / 180;
  const double c = det::cos(a), s = det::sin(a);
  return {c * x - s * y, s * x + c * y};
}

Axes Reader::to_program(const Axes& machine) const {
  Axes p;
  for (int a = 0; a < 3; ++a) p[std::size_t(a)] = machine[std::size_t(a)] - offset(a);
  if (rotation_[std::size_t(m_.cs)] == 0) return p;
  const Axes& w = work_[std::size_t(m_.cs)];
  const auto [x, y] = turn(double(machine[0] - w[0]), double(machine[1] - w[1]), -1);
  p[0] = std::llround(x) - g92_[0];
  p[1] = std::llround(y) - g92_[1];
  return p;
}

Axes Reader::to_machine(const Axes& program) const {
  Axes m;
  for (int a = 0; a < 3; ++a) m[std::size_t(a)] = program[std::size_t(a)] + offset(a);
  if (rotation_[std::size_t(m_.cs)] == 0) return m;
  const Axes& w = work_[std::size_t(m_.cs)];
  const auto [x, y] = turn(double(program[0] + g92_[0]), double(program[1] + g92_[1]), 1);
  m[0] = std::llround(x) + w[0];
  m[1] = std::llround(y) + w[1];
  return m;
}

// The machine position the block's X, Y and Z words (and on HNC's and Fanuc's lathes U
// and W, incremental X and Z) give, starting from `base` for the axes they leave;
// `machine`: G53's machine coordinates.
Axes Reader::word_axes(const Block& b, bool machine, Axes base) const {
  const bool lathe_uw = opt_.machine == Machine::Lathe && dialect_ != Dialect::LinuxCnc;
  Axes prog = machine ? base : to_program(base);
  bool xy = false;
  for (const auto& [c, w] : b.axes) {
    int a = axis_of(c);
    bool incremental = m_.incremental && !machine;
    if (lathe_uw && (c == 'U' || c == 'W')) {
      a = c == 'U' ? 0 : 2;
      const char abs = c == 'U' ? 'X' : 'Z';
      if (b.axes.count(abs)) fail(w->pos, std::string("both ") + abs + " and " + c);
      incremental = true;
    }
    if (a < 0) continue;
    Length v = length(*w);
    if (a == 0 && m_.diameter) v /= 2;
    const std::size_t i = std::size_t(a);
    prog[i] = incremental ? prog[i] + v : v;
    if (std::llabs(prog[i]) > kMaxLength) fail(w->pos, "the move leaves the 1000000 mm the reader holds");
    xy = xy || a < 2;
  }
  if (machine) return prog;
  Axes to = to_machine(prog);
  if (!xy) to[0] = base[0], to[1] = base[1];  // (untouched axes stay exactly where they are)
  for (const Length c : to) {
    if (std::llabs(c) > kMaxLength)
      fail(b.axes.begin()->second->pos, "the move leaves the 1000000 mm the reader holds");
  }
  return to;
}

// G10, G28, G30, G52 and G92: offsets set and stored positions reached.
void Reader::non_modal(const Block& b) {
  const int g = tenths(*b.group[kNonModal]);
  fix_lattice();
  switch (g) {
    case 100:
      set_offsets(b);
      break;
    case 280:
    case 300:
      home(b, g);
      break;
    case 281:
      g28_ = pos_;
      break;
    case 301:
      g30_ = pos_;
      break;
    case 520:  // G52: the local offset, LinuxCNC's G92 offset given directly
    case 920:
      for (const auto& [c, w] : b.axes) {
        const int a = axis_of(c);
        if (a < 0 && other_axis(c)) {
          ignore(*w);  // (an offset of an axis the machine does not have: recorded)
          continue;
        }
        if (a < 0) fail(w->pos, std::string(1, c) + " in a " + (g == 520 ? "G52" : "G92") + " block");
        Length v = length(*w);
        if (a == 0 && m_.diameter) v /= 2;
        const std::size_t i = std::size_t(a);
        // G92: the offset that makes the tool's program position read v.
        g92_[i] = g == 520 ? v : g92_[i] + to_program(pos_)[i] - v;
      }
      g92_stored_ = g92_;
      break;
    case 921:
      g92_ = g92_stored_ = Axes{};
      break;
    case 922:
      g92_ = Axes{};
      break;
    case 923:
      g92_ = g92_stored_;
      break;
    default:
      break;
  }
  sync_params();
}

// G10 L2 (the offsets given) and L20 (the offsets that make the tool's position read
// the values given) of coordinate system P (0: the one in force, 1-9: G54-G59.3);
// G10 L1, L10 and L11 set the tool table, which is recorded.
void Reader::set_offsets(const Block& b) {
  const auto l = b.axes.find('L'), p = b.axes.find('P');
  if (l == b.axes.end()) fail(b.group[kNonModal]->pos, "G10 needs L (2 or 20: work offsets; 1, 10, 11: tools)");
  const std::int64_t lv = integer(*l->second);
  if (lv == 1 || lv == 10 || lv == 11) {
    for (const auto& [c, w] : b.axes) ignore(*w);
    return;
  }
  if (lv != 2 && lv != 20) fail(l->second->pos, fmt::format("G10 L{}: no such form (L2, L20; L1, L10, L11)", lv));
  const std::int64_t pv = p == b.axes.end() ? 0 : integer(*p->second);
  if (pv < 0 || pv > 9) fail(p->second->pos, "G10: P is the coordinate system, 0 (the one in force) to 9");
  const std::size_t cs = pv == 0 ? std::size_t(m_.cs) : std::size_t(pv - 1);
  if (const auto r = b.axes.find('R'); r != b.axes.end()) {
    if (lv != 2) fail(r->second->pos, "R (the rotation) is read with G10 L2 only");
    rotation_[cs] = double(r->second->mantissa) / double(pow10(r->second->decimals));
  }
  // L20: the offsets that make the tool's program position read the values given (the
  // other axes' program positions kept), in the system's own rotation.
  const int saved_cs = m_.cs;
  m_.cs = int(cs);
  Axes target = to_program(pos_);
  for (const auto& [c, w] : b.axes) {
    const int a = axis_of(c);
    if (a < 0) continue;
    Length v = length(*w);
    if (a == 0 && m_.diameter) v /= 2;
    target[std::size_t(a)] = v;
  }
  m_.cs = saved_cs;
  for (const auto& [c, w] : b.axes) {
    if (c == 'L' || c == 'P' || c == 'R') continue;
    const int a = axis_of(c);
    if (a < 0 && other_axis(c)) {
      ignore(*w);
      continue;
    }
    if (a < 0) fail(w->pos, std::string(1, c) + " in a G10 block");
    Length v = length(*w);
    if (a == 0 && m_.diameter) v /= 2;
    const std::size_t i = std::size_t(a);
    if (lv == 2) work_[cs][i] = v;
  }
  if (lv == 20) {
    // pos = turn(target + g92) + work: solve for work, X and Y together when turned.
    const std::array<double, 9> r = rotation_;
    const double rad = r[cs] * det::kPi / 180;
    const double c = det::cos(rad), s = det::sin(rad);
    const double px = double(target[0] + g92_[0]), py = double(target[1] + g92_[1]);
    const Length tx = r[cs] == 0 ? target[0] + g92_[0] : std::llround(c * px - s * py);
    const Length ty = r[cs] == 0 ? target[1] + g92_[1] : std::llround(s * px + c * py);
    work_[cs][0] = pos_[0] - tx;
    work_[cs][1] = pos_[1] - ty;
    work_[cs][2] = pos_[2] - target[2] - g92_[2] - tool_length_;
  }
}

// G28 / G30: a rapid to the point the axis words give (the tool's position without
// them), then to the stored position, on those axes only (all of them without axis
// words).
void Reader::home(const Block& b, int g) {
  const Axes& stored = g == 280 ? g28_ : g30_;
  Axes to = stored;
  bool words = false;
  for (const auto& [c, w] : b.axes) {
    if (axis_of(c) < 0) fail(w->pos, std::string(1, c) + " in a G" + std::to_string(g / 10) + " block");
    words = true;
  }
  const SourcePos where = b.group[kNonModal]->pos;
  // (LinuxCNC moves to the point between even without axis words: a move of length 0.)
  traverse(word_axes(b, false, pos_), b, where);
  if (words) {
    to = pos_;
    for (const auto& [c, w] : b.axes) to[std::size_t(axis_of(c))] = stored[std::size_t(axis_of(c))];
  }
  traverse(to, b, where);
}

// LinuxCNC's parameters of the position and offsets, for programs that read them: the
// current position (#5420-#5422, program coordinates), the coordinate system in force
// (#5220), the G92 offset (#5211-#5213), the work offsets (#5221 on, 20 per system) and
// the stored positions (#5161-#5163, #5181-#5183), in the program's unit.
void Reader::sync_params() {
  if (dialect_ != Dialect::LinuxCnc) return;
  sync_position();
  const double unit = double(kNmPerMm) * (m_.inch ? 25.4 : 1.0);
  for (int a = 0; a < 3; ++a) {
    const std::size_t i = std::size_t(a);
    macro_.set(5211 + a, double(g92_[i]) / unit);
    macro_.set(5161 + a, double(g28_[i]) / unit);
    macro_.set(5181 + a, double(g30_[i]) / unit);
    for (int cs = 0; cs < 9; ++cs) macro_.set(5221 + 20 * cs + a, double(work_[std::size_t(cs)][i]) / unit);
  }
  macro_.set(5220, m_.cs + 1);
}

void Reader::sync_position() {
  if (dialect_ != Dialect::LinuxCnc) return;
  const double unit = double(kNmPerMm) * (m_.inch ? 25.4 : 1.0);
  const Axes p = to_program(pos_);
  static const char* const kNamed[] = {"_x", "_y", "_z"};
  for (int a = 0; a < 3; ++a) {
    macro_.set(5420 + a, double(p[std::size_t(a)]) / unit);
    macro_.set_named(kNamed[a], double(p[std::size_t(a)]) / unit);
  }
}

}  // namespace dda::program::detail
