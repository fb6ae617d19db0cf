// SPDX-License-Identifier: Apache-2.0
// The macro language of the program reader (docs/programs.md, "Macros" and "Dialects"):
// variables (numbered, LinuxCNC's named ones and its calls' own #1-#30), expressions in
// IEEE double with the deterministic sines (det_math.hpp) in the dialect's angle unit.
// The programs' structure is host/program/macro/structure.cpp's.
#include "host/program/macro/macro.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "host/geometry/det_math.hpp"

namespace dda::program::detail {

Macro::Macro(const std::string& file) : file_(file) {}

void Macro::fail(const SourcePos& p, const std::string& msg) const { throw ProgramError(file_, p.line, p.column, msg); }

std::int64_t Macro::var_number(const Line& l, int index, const SourcePos& at) {
  const double v = eval(l, index);
  const std::int64_t most = dialect_ == Dialect::Hnc ? kMaxVariable : kMaxParameter;
  // (LinuxCNC rounds a parameter number to the nearest whole number.)
  const double k = dialect_ == Dialect::Hnc ? v : std::round(v);
  if (!(k >= 0 && k <= double(most)) || k != std::floor(k)) {
    fail(at, fmt::format("#{}: a variable number is a whole number from 0 to {}", fmt_value(v), most));
  }
  return std::int64_t(k);
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
    case Op::Named:
      return named(l, n);
    case Op::Exists: {  // a named parameter with a value, or a numbered one in range
      const Node& v = l.nodes[std::size_t(n.a)];
      if (v.op == Op::Var) {
        const double k = std::round(eval(l, v.a));
        return k >= 1 && k <= double(kMaxParameter) ? 1 : 0;
      }
      const std::string& name = l.names[std::size_t(v.name)];
      return named_scope(name)->count(name) ? 1 : 0;
    }
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
    case Op::Xor:
      return condition(l, n);  // 0 or 1: nothing to overflow
    case Op::Add:
    case Op::Sub:
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
    case Op::Pow:
      r = arithmetic(l, n);
      break;
    default:
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
  const bool local = dialect_ == Dialect::LinuxCnc && k >= 1 && k <= kCallArgs;
  const auto& table = local ? frames_.back().args : vars_;
  const auto it = table.find(k);
  if (it != table.end()) return it->second;
  if (dialect_ != Dialect::Hnc) return 0;  // LinuxCNC's and Fanuc's parameters start at 0
  fail(n.pos, fmt::format("#{} is undefined: no value was assigned to it", k));
}

// LinuxCNC's named parameters: #<_name> global, others local to the call.
const std::map<std::string, double>* Macro::named_scope(const std::string& name) const {
  return !name.empty() && name[0] == '_' ? &globals_ : &frames_.back().named;
}

double Macro::named(const Line& l, const Node& n) const {
  const std::string& name = l.names[std::size_t(n.name)];
  const auto* scope = named_scope(name);
  const auto it = scope->find(name);
  if (it == scope->end()) fail(n.pos, "#<" + name + "> is undefined: no value was assigned to it");
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
    case Op::Xor: {
      const double a = arg(n.a), b = arg(n.b);
      return (a != 0) != (b != 0);
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
    case Op::Mod: {  // LinuxCNC's: a - b * floor(a / b), of the divisor's sign (-7 MOD 3 = 2)
      const double num = arg(n.a), den = arg(n.b);
      if (den == 0) fail(n.pos, "MOD by zero");
      const double m = std::fmod(num, den);
      return m != 0 && (m < 0) != (den < 0) ? m + den : m;
    }
    case Op::Pow: {
      const double base = arg(n.a), e = arg(n.b);
      if (base < 0 && e != std::floor(e)) fail(n.pos, "** of a negative number to a power that is not whole");
      if (base == 0 && e < 0) fail(n.pos, "** of 0 to a negative power");
      return std::pow(base, e);
    }
    default:
      return 0;
  }
}

// The angle functions: radians in HNC, degrees in LinuxCNC and Fanuc (SIN[30] = 0.5).
double Macro::angle_function(Op op, double a, double b, const Node& n) const {
  const bool degrees = dialect_ != Dialect::Hnc;
  const double to_rad = degrees ? det::kPi / 180 : 1, to_unit = degrees ? 180 / det::kPi : 1;
  switch (op) {
    case Op::Sin:
      return det::sin(a * to_rad);
    case Op::Cos:
      return det::cos(a * to_rad);
    case Op::Tan:  // (near an odd multiple of a right angle the value overflows: refused by eval)
      return det::tan(a * to_rad);
    case Op::Atan:
      if (dialect_ == Dialect::LinuxCnc) fail(n.pos, "LinuxCNC's ATAN takes two arguments: ATAN[y]/[x]");
      return det::atan(a) * to_unit;
    case Op::Atan2:
      return det::atan2(a, b) * to_unit;
    case Op::Asin:
    case Op::Acos: {
      if (!(a >= -1 && a <= 1))
        fail(n.pos, fmt::format("{} of {}: outside [-1, 1]", op == Op::Asin ? "ASIN" : "ACOS", fmt_value(a)));
      const double c = std::sqrt((1 - a) * (1 + a));
      return (op == Op::Asin ? det::atan2(a, c) : det::atan2(c, a)) * to_unit;
    }
    default:
      return 0;
  }
}

double Macro::function(const Line& l, const Node& n) {
  const double a = eval(l, n.a);
  switch (n.op) {
    case Op::Sin:
    case Op::Cos:
    case Op::Tan:
    case Op::Atan:
    case Op::Asin:
    case Op::Acos:
      return angle_function(n.op, a, 0, n);
    case Op::Atan2:
      return angle_function(n.op, a, eval(l, n.b), n);
    case Op::Fix:
      return std::floor(a);
    case Op::Fup:
      return std::ceil(a);
    case Op::Round:
      return std::round(a);
    case Op::Exp:
      return std::exp(a);
    case Op::Ln:
      if (a <= 0) fail(n.pos, fmt::format("LN of {}: not positive", fmt_value(a)));
      return std::log(a);
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

// Every value first, then the settings in order: a setting takes effect after the
// line's reads (LinuxCNC: "#1=5 #2=#1" gives #2 the old #1).
void Macro::assign_all(const Line& l) {
  std::vector<double> values;
  values.reserve(l.assigns.size());
  for (const Assign& a : l.assigns) values.push_back(eval(l, a.value));
  for (std::size_t i = 0; i < l.assigns.size(); ++i) store(l, l.assigns[i].target, values[i], l.assigns[i].pos);
}

void Macro::store(const Line& l, int target, double v, const SourcePos& at) {
  const Node& t = l.nodes[std::size_t(target)];
  if (t.op == Op::Named) {
    const std::string& name = l.names[std::size_t(t.name)];
    (name[0] == '_' ? globals_ : frames_.back().named)[name] = v;
    return;
  }
  const std::int64_t k = var_number(l, t.a, at);
  if (dialect_ == Dialect::LinuxCnc && k >= 1 && k <= kCallArgs) {
    frames_.back().args[k] = v;
  } else {
    vars_[k] = v;
  }
}

void Macro::set(std::int64_t k, double v) { vars_[k] = v; }

double Macro::param(std::int64_t k) const {
  const auto it = vars_.find(k);
  return it == vars_.end() ? 0 : it->second;
}

void Macro::set_named(const std::string& name, double v) {
  (name[0] == '_' ? globals_ : frames_.back().named)[name] = v;
}

void Macro::push_frame(const std::vector<double>& args) {
  Frame f;
  for (std::size_t i = 0; i < args.size(); ++i) f.args[std::int64_t(i) + 1] = args[i];
  frames_.push_back(std::move(f));
}

void Macro::pop_frame() { frames_.pop_back(); }

Word Macro::value_word(const Line& l, const Word& w) {
  if (w.expr < 0) return w;
  const double v = eval(l, w.expr);
  if (std::fabs(v) > 1e9) fail(w.pos, fmt::format("{}{} = {}: beyond what a word holds", w.letter, w.text, v));
  return computed_word(w.letter, v, w.pos);
}

double word_number(const Word& w) { return double(w.mantissa) / std::pow(10.0, w.decimals); }

Word computed_word(char letter, double v, const SourcePos& pos) {
  Word r;
  r.letter = letter;
  r.mantissa = std::llround(v * 1e9);
  r.decimals = 9;
  r.text = fmt_value(double(r.mantissa) / 1e9);
  r.pos = pos;
  return r;
}

std::string fmt_value(double v) {
  std::string s = fmt::format("{:.6f}", v);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

}  // namespace dda::program::detail
