// SPDX-License-Identifier: Apache-2.0
// The macro language of the program reader (docs/programs.md, "Macros"): variables,
// expressions in IEEE double with the deterministic sines (det_math.hpp), and the
// programs' structure (WHILE/ENDW and IF/ELSE/ENDIF matched, subprograms by number),
// read from the stream in a first pass and kept as the offsets of headers and statements.
#include "program_macro.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "geometry/det_math.hpp"

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
  double r = 0;
  switch (n.op) {
    case Op::Num:
      return n.value;
    case Op::Pi:
      return det::kPi;
    case Op::Var:
      return variable(l, n);
    case Op::Neg:
      return -eval(l, n.a);
    case Op::Not:
      return eval(l, n.a) == 0 ? 1 : 0;
    case Op::Eq:
    case Op::Ne:
    case Op::Gt:
    case Op::Ge:
    case Op::Lt:
    case Op::Le:
    case Op::And:
    case Op::Or:
      return condition(l, n);  // 0 or 1: nothing to overflow
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
      r = arithmetic(l, n);
      break;
    case Op::Sin:
    case Op::Cos:
    case Op::Tan:
    case Op::Atan:
    case Op::Sqrt:
    case Op::Abs:
    case Op::Int:
      r = function(l, n);
      break;
  }
  if (!std::isfinite(r) || std::fabs(r) > kMaxValue) {
    fail(n.pos, fmt::format("a value beyond {:g}: the macro arithmetic overflows", kMaxValue));
  }
  return r;
}

double Macro::variable(const Line& l, const Node& n) {
  const std::int64_t k = var_number(l, n.a, n.pos);
  const auto it = vars_.find(k);
  if (it == vars_.end()) fail(n.pos, fmt::format("#{} is undefined: no value was assigned to it", k));
  return it->second;
}

double Macro::condition(const Line& l, const Node& n) {
  const auto arg = [&](int i) { return eval(l, i); };
  switch (n.op) {
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
    case Op::And: {  // both operands evaluated (and checked), as in the comparisons
      const double a = arg(n.a), b = arg(n.b);
      return a != 0 && b != 0;
    }
    case Op::Or: {
      const double a = arg(n.a), b = arg(n.b);
      return a != 0 || b != 0;
    }
    default:
      return 0;
  }
}

double Macro::arithmetic(const Line& l, const Node& n) {
  const auto arg = [&](int i) { return eval(l, i); };
  switch (n.op) {
    case Op::Add:
      return arg(n.a) + arg(n.b);
    case Op::Sub:
      return arg(n.a) - arg(n.b);
    case Op::Mul:
      return arg(n.a) * arg(n.b);
    case Op::Div: {
      const double num = arg(n.a), den = arg(n.b);
      if (den == 0) fail(n.pos, "division by zero");
      return num / den;
    }
    default:
      return 0;
  }
}

double Macro::function(const Line& l, const Node& n) {
  const double a = eval(l, n.a);
  switch (n.op) {
    case Op::Sin:
      return det::sin(a);
    case Op::Cos:
      return det::cos(a);
    case Op::Tan:  // (near an odd multiple of pi/2 the value overflows: refused by eval)
      return det::tan(a);
    case Op::Atan:
      return det::atan(a);
    case Op::Sqrt:
      if (a < 0) fail(n.pos, fmt::format("SQRT of a negative number ({})", fmt_value(a)));
      return std::sqrt(a);  // IEEE 754 rounds it correctly: the same bits everywhere
    case Op::Abs:
      return std::fabs(a);
    case Op::Int:
      return std::trunc(a);
    default:
      return 0;
  }
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

namespace {

// Builds the structure line by line; keeps the first error of each kind, thrown once
// every line has been parsed (a syntax error anywhere comes first).
class Builder {
 public:
  Builder(const std::string& file, const LinePos& first) : file_(file) { cur_.begin = first; }
  void add(const Line& l, const LinePos& at, const LinePos& next);
  Structure finish(std::size_t end);  // end: the last line's number + 1

 private:
  void close(std::size_t end);  // the program being read ends before line `end`
  void match(const Line& l, const LinePos& at, const LinePos& next);
  void defer(std::optional<ProgramError>& first, const SourcePos& p, const std::string& msg) const {
    if (!first) first.emplace(file_, p.line, p.column, msg);
  }
  std::string file_;
  Structure st_;
  ProgramText cur_;                                // the program being read
  std::map<std::int64_t, std::size_t> headers_;    // a program's number: its header's line
  std::vector<std::size_t> open_;                  // its open WHILE and IF marks (an IF's ELSE replaces it)
  std::optional<ProgramError> twice_, unmatched_;  // a program defined twice; a statement unmatched
};

void Builder::add(const Line& l, const LinePos& at, const LinePos& next) {
  if (l.header) {  // programs are cut at '%' lines; text before the first is a program without a number
    close(at.number);
    cur_ = ProgramText{l.program, next, 0, false};
    return;
  }
  cur_.content = cur_.content || !l.words.empty() || l.stmt != Stmt::None;
  if (l.stmt != Stmt::None && l.stmt != Stmt::Assign) match(l, at, next);
}

void Builder::close(std::size_t end) {
  cur_.end = end;
  if (cur_.number >= 0) {
    const std::size_t header = cur_.begin.number - 1;
    const auto [first, fresh] = headers_.emplace(cur_.number, header);
    if (!fresh) {
      defer(twice_, SourcePos{header, 1},
            fmt::format("program %{} is defined twice (first at line {})", cur_.number, first->second));
    }
  }
  if (!open_.empty()) {
    const StmtMark& m = st_.marks[open_.back()];
    defer(unmatched_, m.pos,
          m.stmt == Stmt::While ? "WHILE without ENDW in its program" : "IF without ENDIF in its program");
    open_.clear();
  }
  if (cur_.content || cur_.number >= 0) st_.programs.push_back(cur_);
}

// Matches WHILE/ENDW and IF/ELSE/ENDIF inside the program being read.
void Builder::match(const Line& l, const LinePos& at, const LinePos& next) {
  const std::size_t i = st_.marks.size();
  st_.marks.push_back(StmtMark{at, next, l.stmt, l.stmt_pos, 0});
  const auto top_is = [&](Stmt k) { return !open_.empty() && st_.marks[open_.back()].stmt == k; };
  switch (l.stmt) {
    case Stmt::While:
    case Stmt::If:
      open_.push_back(i);
      return;
    case Stmt::EndW:
      if (!top_is(Stmt::While)) {
        return defer(unmatched_, l.stmt_pos, open_.empty() ? "ENDW without WHILE" : "ENDW inside an open IF");
      }
      st_.marks[i].jump = open_.back();
      st_.marks[open_.back()].jump = i;
      open_.pop_back();
      return;
    case Stmt::Else:
      if (!top_is(Stmt::If)) {
        return defer(unmatched_, l.stmt_pos, open_.empty() ? "ELSE without IF" : "ELSE inside an open WHILE or ELSE");
      }
      st_.marks[open_.back()].jump = i;  // a false condition goes past the ELSE
      open_.back() = i;
      return;
    case Stmt::EndIf:
      if (!top_is(Stmt::If) && !top_is(Stmt::Else)) {
        return defer(unmatched_, l.stmt_pos, open_.empty() ? "ENDIF without IF" : "ENDIF inside an open WHILE");
      }
      st_.marks[open_.back()].jump = i;
      open_.pop_back();
      return;
    default:
      return;
  }
}

Structure Builder::finish(std::size_t end) {
  close(end);
  if (twice_) throw *twice_;
  if (unmatched_) throw *unmatched_;
  return std::move(st_);
}

}  // namespace

const StmtMark& Structure::mark(std::uint64_t offset) const {
  return *std::lower_bound(marks.begin(), marks.end(), offset,
                           [](const StmtMark& m, std::uint64_t o) { return m.at.offset < o; });
}

Structure structure(LineStream& lines, const std::string& file) {
  Builder b(file, lines.first());
  Line l;
  for (LinePos at = lines.first();;) {
    const LinePos next = lines.read(at, l);
    b.add(l, at, next);
    if (lines.at_end()) return b.finish(next.number);
    at = next;
  }
}

}  // namespace dda::program::detail
