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
  Builder(const std::string& file, const LinePos& first, Dialect d) : file_(file), dialect_(d) { cur_.begin = first; }
  // Returns false at the line that ends the text read (LinuxCNC's and Fanuc's closing '%').
  bool add(const Line& l, const LinePos& at, const LinePos& next);
  Structure finish(std::size_t end);  // end: the last line's number + 1

 private:
  void close(std::size_t end);  // the program being read ends before line `end`
  void match(const Line& l, const LinePos& at, const LinePos& next);
  void o_match(const Line& l, std::size_t i);
  void o_close(const Line& l, std::size_t i, std::initializer_list<Stmt> opens, const char* what);
  std::optional<std::size_t> o_enclosing(const Line& l, bool sub) const;
  void defer(std::optional<ProgramError>& first, const SourcePos& p, const std::string& msg) const {
    if (!first) first.emplace(file_, p.line, p.column, msg);
  }
  std::string file_;
  Dialect dialect_;
  Structure st_;
  ProgramText cur_;                              // the program being read
  std::map<std::int64_t, std::size_t> headers_;  // a program's number: its header's line
  std::vector<std::size_t> open_;                // its open WHILE and IF marks (an IF's ELSE replaces it)
  struct OOpen {
    std::size_t mark;
    std::string name;
    std::vector<std::size_t> chain;  // an if's marks so far
  };
  std::vector<OOpen> o_open_;                      // open O-word blocks
  std::optional<ProgramError> twice_, unmatched_;  // a program defined twice; a statement unmatched
};

bool Builder::add(const Line& l, const LinePos& at, const LinePos& next) {
  if (l.header && l.header_text && dialect_ == Dialect::LinuxCnc) {
    defer(unmatched_, SourcePos{l.number, 1}, "a '%' line holds nothing but the '%' (LinuxCNC's rule)");
  }
  if (l.header && l.program < 0 && dialect_ != Dialect::Hnc) {
    // LinuxCNC and Fanuc: a '%' before anything else opens the text, one after it ends
    // the text (what follows is not read).
    if (cur_.content) return false;
    cur_.begin = next;
    return true;
  }
  if (l.header) {  // programs are cut at headers; text before the first is a program without a number
    close(at.number);
    cur_ = ProgramText{l.program, next, 0, false};
    return true;
  }
  cur_.content = cur_.content || !l.words.empty() || l.stmt != Stmt::None || !l.assigns.empty();
  if (l.stmt != Stmt::None && l.stmt != Stmt::Assign) match(l, at, next);
  return true;
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
  if (!o_open_.empty()) {
    const StmtMark& m = st_.marks[o_open_.back().mark];
    defer(unmatched_, m.pos,
          "o" + o_open_.back().name + ": a block opened here is not closed (sub, if, while, do or repeat)");
    o_open_.clear();
  }
  if (cur_.content || cur_.number >= 0) st_.programs.push_back(cur_);
}

// Matches WHILE/ENDW and IF/ELSE/ENDIF inside the program being read.
void Builder::match(const Line& l, const LinePos& at, const LinePos& next) {
  const std::size_t i = st_.marks.size();
  st_.marks.push_back(StmtMark{at, next, l.stmt, l.stmt_pos, 0, 0, false});
  if (is_oword(l.stmt)) return o_match(l, i);
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

// The O-word statements: each closing one matches the innermost open block, which must
// carry the same name (LinuxCNC's rule).
void Builder::o_match(const Line& l, std::size_t i) {
  const auto top_is = [&](std::initializer_list<Stmt> ks) {
    if (o_open_.empty() || o_open_.back().name != l.oname) return false;
    for (const Stmt k : ks)
      if (st_.marks[o_open_.back().mark].stmt == k) return true;
    return false;
  };
  switch (l.stmt) {
    case Stmt::OSub:
      if (!o_open_.empty())
        return defer(unmatched_, l.stmt_pos,
                     "o" + l.oname + " sub inside another block: subroutines are defined at the top level");
      if (st_.subs.count(l.oname)) return defer(unmatched_, l.stmt_pos, "o" + l.oname + " sub: defined twice");
      st_.subs[l.oname] = i;
      o_open_.push_back({i, l.oname, {}});
      return;
    case Stmt::OIf:
    case Stmt::ORepeat:
    case Stmt::ODo:
      o_open_.push_back({i, l.oname, {i}});
      return;
    case Stmt::OWhile:
      if (top_is({Stmt::ODo})) {  // the tail of a do loop
        st_.marks[i].do_tail = true;
        st_.marks[i].jump = o_open_.back().mark;
        st_.marks[o_open_.back().mark].jump = i;
        o_open_.pop_back();
        return;
      }
      o_open_.push_back({i, l.oname, {i}});
      return;
    case Stmt::OElseIf:
    case Stmt::OElse:
      if (!top_is({Stmt::OIf, Stmt::OElseIf}))
        return defer(
            unmatched_, l.stmt_pos,
            "o" + l.oname + (l.stmt == Stmt::OElse ? " else" : " elseif") + " without its o" + l.oname + " if");
      st_.marks[o_open_.back().mark].jump = i;
      o_open_.back().mark = i;
      o_open_.back().chain.push_back(i);
      return;
    case Stmt::OEndIf:
      return o_close(l, i, {Stmt::OIf, Stmt::OElseIf, Stmt::OElse}, " endif without its if");
    case Stmt::OEndSub:
      return o_close(l, i, {Stmt::OSub}, " endsub without its sub");
    case Stmt::OEndWhile:
      return o_close(l, i, {Stmt::OWhile}, " endwhile without its while");
    case Stmt::OEndRepeat:
      return o_close(l, i, {Stmt::ORepeat}, " endrepeat without its repeat");
    case Stmt::OBreak:
    case Stmt::OContinue:
    case Stmt::OReturn: {
      const std::optional<std::size_t> in = o_enclosing(l, l.stmt == Stmt::OReturn);
      if (!in)
        return defer(unmatched_, l.stmt_pos,
                     "o" + l.oname +
                         (l.stmt == Stmt::OReturn ? " return outside its o" + l.oname + " sub"
                                                  : " break or continue outside an o" + l.oname + " loop"));
      st_.marks[i].jump = *in;
      return;
    }
    default:
      return;
  }
}

void Builder::o_close(const Line& l, std::size_t i, std::initializer_list<Stmt> opens, const char* what) {
  bool ok = false;
  if (!o_open_.empty() && o_open_.back().name == l.oname) {
    for (const Stmt k : opens) ok = ok || st_.marks[o_open_.back().mark].stmt == k;
  }
  if (!ok) return defer(unmatched_, l.stmt_pos, "o" + l.oname + what);
  const OOpen& o = o_open_.back();
  st_.marks[o.mark].jump = i;
  st_.marks[i].jump = o.chain.empty() ? o.mark : o.chain.front();
  for (const std::size_t k : o.chain) st_.marks[k].end = i;
  o_open_.pop_back();
}

// The loop (or, for return, the sub) of the same name that a break, continue or return
// leaves: its head's mark.
std::optional<std::size_t> Builder::o_enclosing(const Line& l, bool sub) const {
  for (auto it = o_open_.rbegin(); it != o_open_.rend(); ++it) {
    if (it->name != l.oname) continue;
    const Stmt k = st_.marks[it->chain.empty() ? it->mark : it->chain.front()].stmt;
    if (sub ? k == Stmt::OSub : (k == Stmt::OWhile || k == Stmt::ODo || k == Stmt::ORepeat)) {
      return it->chain.empty() ? it->mark : it->chain.front();
    }
  }
  return std::nullopt;
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

Structure structure(LineStream& lines, const std::string& file, Dialect dialect) {
  Builder b(file, lines.first(), dialect);
  Line l;
  for (LinePos at = lines.first();;) {
    const LinePos next = lines.read(at, l);
    if (!b.add(l, at, next)) {
      Structure st = b.finish(at.number);
      st.closed = true;
      st.last_line = at.number;
      return st;
    }
    if (lines.at_end()) {
      Structure st = b.finish(next.number);
      st.last_line = at.number;
      return st;
    }
    at = next;
  }
}

}  // namespace dda::program::detail
