// SPDX-License-Identifier: Apache-2.0
// The macro language of the program reader (docs/programs.md, "Macros"): variables,
// expressions in IEEE double with the deterministic sines (det_math.hpp), and the
// programs' structure (WHILE/ENDW and IF/ELSE/ENDIF matched, subprograms by number).
#include "program_macro.hpp"

#include <fmt/format.h>

#include <cmath>

#include "dda/det_math.hpp"

namespace dda::program::detail {

Macro::Macro(const std::string& file) : file_(file) {}

void Macro::fail(const SourcePos& p, const std::string& msg) const { throw ProgramError(file_, p.line, p.column, msg); }

std::int64_t Macro::var_number(const Line& l, int index, const SourcePos& at) {
  const double v = eval(l, index);
  if (!(v >= 0 && v <= double(kMaxVariable)) || v != std::floor(v)) {
    fail(at, fmt::format("#{}: a variable number is a whole number from 0 to {}", fmt_value(v), kMaxVariable));
  }
  return std::int64_t(v);
}

double Macro::eval(const Line& l, int node) {
  const Node& n = l.nodes[std::size_t(node)];
  const auto arg = [&](int i) { return eval(l, i); };
  double r = 0;
  switch (n.op) {
    case Op::Num:
      return n.value;
    case Op::Pi:
      return det::kPi;
    case Op::Var: {
      const std::int64_t k = var_number(l, n.a, n.pos);
      const auto it = vars_.find(k);
      if (it == vars_.end()) fail(n.pos, fmt::format("#{} is undefined: no value was assigned to it", k));
      return it->second;
    }
    case Op::Neg:
      return -arg(n.a);
    case Op::Not:
      return arg(n.a) == 0 ? 1 : 0;
    case Op::Add:
      r = arg(n.a) + arg(n.b);
      break;
    case Op::Sub:
      r = arg(n.a) - arg(n.b);
      break;
    case Op::Mul:
      r = arg(n.a) * arg(n.b);
      break;
    case Op::Div: {
      const double num = arg(n.a), den = arg(n.b);
      if (den == 0) fail(n.pos, "division by zero");
      r = num / den;
      break;
    }
    case Op::Eq:
      return arg(n.a) == arg(n.b);
    case Op::Ne:
      return arg(n.a) != arg(n.b);
    case Op::Gt:
      return arg(n.a) > arg(n.b);
    case Op::Ge:
      return arg(n.a) >= arg(n.b);
    case Op::Lt:
      return arg(n.a) < arg(n.b);
    case Op::Le:
      return arg(n.a) <= arg(n.b);
    case Op::And: {
      const double a = arg(n.a), b = arg(n.b);
      return a != 0 && b != 0;
    }
    case Op::Or: {
      const double a = arg(n.a), b = arg(n.b);
      return a != 0 || b != 0;
    }
    case Op::Sin:
      r = det::sin(arg(n.a));
      break;
    case Op::Cos:
      r = det::cos(arg(n.a));
      break;
    case Op::Tan:  // (near an odd multiple of pi/2 the value overflows: refused below)
      r = det::tan(arg(n.a));
      break;
    case Op::Atan:
      r = det::atan(arg(n.a));
      break;
    case Op::Sqrt: {
      const double a = arg(n.a);
      if (a < 0) fail(n.pos, fmt::format("SQRT of a negative number ({})", fmt_value(a)));
      r = std::sqrt(a);  // IEEE 754 rounds it correctly: the same bits everywhere
      break;
    }
    case Op::Abs:
      r = std::fabs(arg(n.a));
      break;
    case Op::Int:
      r = std::trunc(arg(n.a));
      break;
  }
  if (!std::isfinite(r) || std::fabs(r) > kMaxValue) {
    fail(n.pos, fmt::format("a value beyond {:g}: the macro arithmetic overflows", kMaxValue));
  }
  return r;
}

bool Macro::truth(const Line& l) { return eval(l, l.value) != 0; }

void Macro::assign(const Line& l) {
  const std::int64_t k = var_number(l, l.target, l.stmt_pos);
  vars_[k] = eval(l, l.value);
}

void Macro::set(std::int64_t k, double v) { vars_[k] = v; }

Word Macro::value_word(const Line& l, const Word& w) {
  if (w.expr < 0) return w;
  const double v = eval(l, w.expr);
  if (std::fabs(v) > 1e9) fail(w.pos, fmt::format("{}{} = {}: beyond what a word holds", w.letter, w.text, v));
  Word r = w;
  r.expr = -1;
  r.mantissa = std::llround(v * 1e6);  // the value to the millionth, as a number of 6 decimals
  r.decimals = 6;
  r.text = fmt_value(double(r.mantissa) / 1e6);
  return r;
}

std::string fmt_value(double v) {
  std::string s = fmt::format("{:.6f}", v);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

Structure structure(const std::vector<Line>& lines, const std::string& file) {
  Structure st;
  st.jump.assign(lines.size(), 0);
  const auto fail = [&](const SourcePos& p, const std::string& msg) {
    throw ProgramError(file, p.line, p.column, msg);
  };
  // Programs: cut at '%' lines; text before the first is a program without a number.
  std::size_t begin = 0;
  std::int64_t number = -1;
  const auto close = [&](std::size_t end) {
    bool content = false;
    for (std::size_t i = begin; i < end; ++i)
      content = content || !lines[i].words.empty() || lines[i].stmt != Stmt::None;
    if (number >= 0) {
      for (const ProgramText& p : st.programs) {
        if (p.number == number) {
          fail(SourcePos{lines[begin - 1].number, 1},
               fmt::format("program %{} is defined twice (first at line {})", number, lines[p.begin - 1].number));
        }
      }
    }
    if (content || number >= 0) st.programs.push_back(ProgramText{number, begin, end, content});
  };
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (!lines[i].header) continue;
    close(i);
    begin = i + 1;
    number = lines[i].program;
  }
  close(lines.size());
  // Matching WHILE/ENDW and IF/ELSE/ENDIF inside each program.
  for (const ProgramText& p : st.programs) {
    std::vector<std::size_t> open;  // WHILE and IF lines (an IF's ELSE replaces it)
    for (std::size_t i = p.begin; i < p.end; ++i) {
      const Line& l = lines[i];
      const auto top_is = [&](Stmt k) { return !open.empty() && lines[open.back()].stmt == k; };
      switch (l.stmt) {
        case Stmt::While:
        case Stmt::If:
          open.push_back(i);
          break;
        case Stmt::EndW:
          if (!top_is(Stmt::While)) fail(l.stmt_pos, open.empty() ? "ENDW without WHILE" : "ENDW inside an open IF");
          st.jump[i] = open.back();
          st.jump[open.back()] = i;
          open.pop_back();
          break;
        case Stmt::Else:
          if (!top_is(Stmt::If))
            fail(l.stmt_pos, open.empty() ? "ELSE without IF" : "ELSE inside an open WHILE or ELSE");
          st.jump[open.back()] = i;  // a false condition goes past the ELSE
          open.back() = i;
          break;
        case Stmt::EndIf:
          if (!top_is(Stmt::If) && !top_is(Stmt::Else)) {
            fail(l.stmt_pos, open.empty() ? "ENDIF without IF" : "ENDIF inside an open WHILE");
          }
          st.jump[open.back()] = i;
          open.pop_back();
          break;
        default:
          break;
      }
    }
    if (!open.empty()) {
      const Line& l = lines[open.back()];
      fail(l.stmt_pos, l.stmt == Stmt::While ? "WHILE without ENDW in its program" : "IF without ENDIF in its program");
    }
  }
  return st;
}

}  // namespace dda::program::detail
