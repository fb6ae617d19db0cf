// SPDX-License-Identifier: Apache-2.0
// Inside the program reader's grammar (host/program/grammar/rules.hpp): the state a line's parse
// fills in and the actions that fill it (its words, parameter settings, statement and
// expression trees, built with the dialect's precedence). Included by
// host/program/grammar/grammar.cpp only, where the parse runs.
#pragma once

#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include "host/program/grammar/line.hpp"
#include "host/program/grammar/rules.hpp"

namespace dda::program::detail::rules {

// The binary operators' precedence in the dialect (host/program/grammar/grammar.cpp): higher binds
// tighter.
int precedence(Dialect d, Op op);

struct ParseState {
  Dialect dialect = Dialect::LinuxCnc;
  Line line;
  Word cur;
  std::vector<int> values;  // the expression stack (node indices)
  std::vector<Node> ops;    // pending operators (op and position); Op::Num: an expression's start

  template <typename Input>
  SourcePos at(const Input& in) const {
    return SourcePos{line.number, in.position().column};
  }
  int push(Node n) {
    line.nodes.push_back(n);
    values.push_back(int(line.nodes.size()) - 1);
    return values.back();
  }
  int pop() {
    const int v = values.back();
    values.pop_back();
    return v;
  }
  // Pops the pending operator and its operands (one for NOT, else two) into a node.
  void reduce() {
    Node n = ops.back();
    ops.pop_back();
    if (n.op != Op::Not) n.b = pop();
    n.a = pop();
    push(n);
  }
  bool pending_binds(int prec) const {
    return !ops.empty() && ops.back().op != Op::Num && precedence(dialect, ops.back().op) >= prec;
  }
};

template <typename Rule>
struct action : pg::nothing<Rule> {};

template <>
struct action<nested_open> {
  template <typename Input>
  static void apply(const Input& in, ParseState& /*s*/) {
    throw pg::parse_error("a comment inside a comment: LinuxCNC refuses nested comments", in);
  }
};

template <>
struct action<block_delete> {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    s.line.block_delete = true;
  }
};

template <>
struct action<letter> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.cur = Word{};
    s.cur.letter = char(std::toupper(static_cast<unsigned char>(in.peek_char())));
    s.cur.pos = s.at(in);
  }
};

// A number read exactly as a decimal mantissa and exponent: up to 18 significant digits;
// digits after the point beyond them are rounded off (a length is kept to the nanometre
// anyway), more before the point are refused.
template <typename Input>
void read_decimal(const Input& in, const std::string& text, std::int64_t& mantissa, int& decimals) {
  bool neg = false, point = false, rounded = false;
  std::int64_t m = 0;
  int digits_seen = 0;
  decimals = 0;
  for (const char c : text) {
    if (c == '-') neg = true;
    if (c == '.') point = true;
    if (!std::isdigit(static_cast<unsigned char>(c))) continue;
    if (m == 0 && c == '0' && !point) continue;  // leading zeros
    if (digits_seen >= 18) {
      if (!point) throw pg::parse_error("a number of more than 18 digits before its point", in);
      if (!rounded && c >= '5') ++m;  // (the first digit dropped rounds the rest)
      rounded = true;
      continue;
    }
    if (m != 0 || c != '0' || point) ++digits_seen;
    m = 10 * m + (c - '0');
    if (point) ++decimals;
  }
  mantissa = neg ? -m : m;
}

template <>
struct action<number> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.cur.text = in.string();
    read_decimal(in, s.cur.text, s.cur.mantissa, s.cur.decimals);
    s.line.words.push_back(s.cur);
  }
};

template <>
struct action<word_expr> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.cur.text = in.string();
    s.cur.expr = s.pop();
    s.line.words.push_back(s.cur);
  }
};

template <>
struct action<expr_number> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    std::int64_t m = 0;
    int d = 0;
    read_decimal(in, in.string(), m, d);
    Node n;
    n.op = Op::Num;
    // One division of two exact doubles (m < 10^15 < 2^53, 10^d <= 10^15): the correctly
    // rounded value of the decimal, as IEEE 754 reads it (longer numbers: within an ulp).
    double p = 1;
    for (int i = 0; i < d; ++i) p *= 10;
    n.value = double(m) / p;
    n.pos = s.at(in);
    s.push(n);
  }
};

inline Op op_named(const std::string& t) {
  std::string u;
  for (const char c : t) u += char(std::toupper(static_cast<unsigned char>(c)));
  static const std::pair<const char*, Op> kOps[] = {
      {"+", Op::Add},     {"-", Op::Sub},       {"*", Op::Mul},   {"/", Op::Div},     {"**", Op::Pow},
      {"MOD", Op::Mod},   {"EQ", Op::Eq},       {"NE", Op::Ne},   {"GT", Op::Gt},     {"GE", Op::Ge},
      {"LT", Op::Lt},     {"LE", Op::Le},       {"AND", Op::And}, {"OR", Op::Or},     {"XOR", Op::Xor},
      {"SIN", Op::Sin},   {"COS", Op::Cos},     {"TAN", Op::Tan}, {"ATAN", Op::Atan}, {"ASIN", Op::Asin},
      {"ACOS", Op::Acos}, {"SQRT", Op::Sqrt},   {"ABS", Op::Abs}, {"INT", Op::Int},   {"FIX", Op::Fix},
      {"FUP", Op::Fup},   {"ROUND", Op::Round}, {"EXP", Op::Exp}, {"LN", Op::Ln},
  };
  for (const auto& [name, op] : kOps)
    if (u == name) return op;
  return Op::Num;
}

// An expression's start: a sentinel below its operators.
template <>
struct action<expr_open> {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    s.ops.push_back(Node{});
  }
};
// Its end: every pending operator reduced, the sentinel removed.
template <>
struct action<expr> {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    while (s.ops.back().op != Op::Num) s.reduce();
    s.ops.pop_back();
  }
};
template <>
struct action<binary_op> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    Node n;
    n.op = op_named(in.string());
    n.pos = s.at(in);
    while (s.pending_binds(precedence(s.dialect, n.op))) s.reduce();
    s.ops.push_back(n);
  }
};
template <>
struct action<not_prefix> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    Node n;
    n.op = Op::Not;
    n.pos = s.at(in);
    s.ops.push_back(n);
  }
};

// A function: its name held until its argument is read.
template <>
struct action<func_name> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    Node n;
    n.op = op_named(in.string());
    n.pos = s.at(in);
    s.ops.push_back(n);
  }
};
template <>
struct action<atan_name> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    Node n;
    n.op = Op::Atan;
    n.pos = s.at(in);
    s.ops.push_back(n);
  }
};
template <>
struct action<func> {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    Node n = s.ops.back();
    s.ops.pop_back();
    if (n.op == Op::Atan2) n.b = s.pop();
    n.a = s.pop();
    s.push(n);
  }
};
template <>
struct action<atan2_tail> {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    s.ops.back().op = Op::Atan2;
  }
};

template <>
struct action<kw_pi> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    Node n;
    n.op = Op::Pi;
    n.pos = s.at(in);
    s.push(n);
  }
};

// Unary operators and variables, reduced once their operand is read.
template <Op K>
struct unary_action {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    Node n;
    n.op = K;
    n.pos = s.at(in);
    n.a = s.pop();
    s.push(n);
  }
};
template <>
struct action<negate> : unary_action<Op::Neg> {};
template <>
struct action<var> : unary_action<Op::Var> {};
template <>
struct action<exists> : unary_action<Op::Exists> {};

// A named parameter: its name without blanks, in lower case (as LinuxCNC reads it).
template <>
struct action<named_var> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    std::string name;
    for (const char c : in.string().substr(2)) {
      if (c != ' ' && c != '\t' && c != '>') name += char(std::tolower(static_cast<unsigned char>(c)));
    }
    Node n;
    n.op = Op::Named;
    n.pos = s.at(in);
    n.name = int(s.line.names.size());
    s.line.names.push_back(name);
    s.push(n);
  }
};

template <>
struct action<param_set> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    Assign a;
    a.value = s.pop();
    a.target = s.pop();
    a.pos = s.at(in);
    s.line.assigns.push_back(a);
  }
};

template <>
struct action<assignment> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.line.stmt = Stmt::Assign;
    s.line.value = s.pop();
    s.line.target = s.pop();
    s.line.stmt_pos = s.at(in);
  }
};
template <Stmt K>
struct stmt_action {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.line.stmt = K;
    if (K == Stmt::While || K == Stmt::If) s.line.value = s.pop();
    s.line.stmt_pos = s.at(in);
  }
};
template <>
struct action<while_stmt> : stmt_action<Stmt::While> {};
template <>
struct action<if_stmt> : stmt_action<Stmt::If> {};
template <>
struct action<kw_endw> : stmt_action<Stmt::EndW> {};
template <>
struct action<kw_else> : stmt_action<Stmt::Else> {};
template <>
struct action<kw_endif> : stmt_action<Stmt::EndIf> {};

// O-words: the name (a number without its leading zeros, or "<name>" in lower case
// without blanks), the keyword, the condition or value and a call's arguments.
template <>
struct action<o_letter> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    s.line.stmt_pos = s.at(in);
  }
};
template <>
struct action<o_name> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    std::string name;
    for (const char c : in.string()) {
      if (c != ' ' && c != '\t') name += char(std::tolower(static_cast<unsigned char>(c)));
    }
    if (name[0] == '#') {
      name = "#";  // computed when the call runs (Line::target)
    } else if (name[0] != '<') {
      const auto nz = name.find_first_not_of('0');
      name = nz == std::string::npos ? "0" : name.substr(nz);
    }
    s.line.oname = name;
  }
};
template <>
struct action<o_computed> {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    s.line.target = s.pop();
  }
};
template <typename R>
struct o_kw_action {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    s.line.stmt = R::kind;
  }
};
template <>
struct action<o_sub> : o_kw_action<o_sub> {};
template <>
struct action<o_endsub> : o_kw_action<o_endsub> {};
template <>
struct action<o_call> : o_kw_action<o_call> {};
template <>
struct action<o_return> : o_kw_action<o_return> {};
template <>
struct action<o_if> : o_kw_action<o_if> {};
template <>
struct action<o_elseif> : o_kw_action<o_elseif> {};
template <>
struct action<o_else> : o_kw_action<o_else> {};
template <>
struct action<o_endif> : o_kw_action<o_endif> {};
template <>
struct action<o_while> : o_kw_action<o_while> {};
template <>
struct action<o_endwhile> : o_kw_action<o_endwhile> {};
template <>
struct action<o_do> : o_kw_action<o_do> {};
template <>
struct action<o_repeat> : o_kw_action<o_repeat> {};
template <>
struct action<o_endrepeat> : o_kw_action<o_endrepeat> {};
template <>
struct action<o_break> : o_kw_action<o_break> {};
template <>
struct action<o_continue> : o_kw_action<o_continue> {};
template <>
struct action<o_condition> {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    s.line.value = s.pop();
  }
};
template <>
struct action<o_arg> {
  template <typename Input>
  static void apply(const Input& /*in*/, ParseState& s) {
    s.line.args.push_back(s.pop());
  }
};

template <>
struct action<fanuc_number> {
  template <typename Input>
  static void apply(const Input& in, ParseState& s) {
    const std::string t = in.string();
    if (t.size() > 8) throw pg::parse_error("a program number of more than 8 digits", in);
    s.line.header = true;
    s.line.program = std::stoll(t);
  }
};

}  // namespace dda::program::detail::rules
