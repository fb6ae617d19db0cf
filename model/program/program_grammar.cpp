// SPDX-License-Identifier: Apache-2.0
// A part program line parsed (program_rules.hpp): the actions that collect its words,
// parameter settings and statement, and build each expression's tree with the
// dialect's precedence (docs/programs.md, "Dialects"); the messages of the rules that
// must match.
#include <cctype>
#include <limits>
#include <string>
#include <string_view>

#include "program_detail.hpp"
#include "program_rules.hpp"

namespace dda::program::detail {

namespace rules {

// The binary operators' precedence by dialect, loosest first (docs/programs.md):
// HNC OR, AND, NOT, comparisons, + -, * /; LinuxCNC AND OR XOR, comparisons, + -,
// * / MOD, **; Fanuc comparisons, + - OR XOR, * / AND MOD, **. Unary minus binds
// tightest; operators of one level group from the left.
int precedence(Dialect d, Op op) {
  const bool lcnc = d == Dialect::LinuxCnc, fanuc = d == Dialect::Fanuc;
  switch (op) {
    case Op::Or:
    case Op::Xor:
      return lcnc ? 1 : fanuc ? 2 : 1;
    case Op::And:
      return lcnc ? 1 : fanuc ? 3 : 2;
    case Op::Not:
      return 3;
    case Op::Eq:
    case Op::Ne:
    case Op::Gt:
    case Op::Ge:
    case Op::Lt:
    case Op::Le:
      return lcnc ? 2 : fanuc ? 1 : 4;
    case Op::Add:
    case Op::Sub:
      return lcnc ? 3 : fanuc ? 2 : 5;
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
      return lcnc ? 4 : fanuc ? 3 : 6;
    case Op::Pow:
      return 7;
    default:
      return 8;  // a sentinel's: an open expression
  }
}

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

bool dialect_is(const ParseState& s, Dialect d) { return s.dialect == d; }

}  // namespace rules

namespace {

namespace pg = tao::pegtl;
using namespace rules;

std::string describe_char(std::string_view rest) {
  const auto hex = [](unsigned v, int digits) {
    static const char* kDigits = "0123456789ABCDEF";
    std::string h;
    for (int k = digits - 1; k >= 0; --k) h += kDigits[(v >> (4 * k)) & 0xF];
    return h;
  };
  const unsigned char c0 = rest.empty() ? 0 : static_cast<unsigned char>(rest[0]);
  if (c0 < 0x80) {
    if (std::isprint(c0) != 0) return std::string("'") + char(c0) + "'";
    return "control character 0x" + hex(c0, 2);
  }
  const std::size_t len = c0 >= 0xF0 && c0 < 0xF5 ? 4 : c0 >= 0xE0 && c0 < 0xF0 ? 3 : c0 >= 0xC2 && c0 < 0xE0 ? 2 : 0;
  unsigned cp = len == 4 ? c0 & 0x07u : len == 3 ? c0 & 0x0Fu : c0 & 0x1Fu;
  bool ok = len != 0 && rest.size() >= len;
  for (std::size_t k = 1; ok && k < len; ++k) {
    const unsigned char ck = static_cast<unsigned char>(rest[k]);
    ok = (ck & 0xC0u) == 0x80u;
    cp = (cp << 6) | (ck & 0x3Fu);
  }
  ok = ok && !(len == 3 && cp < 0x800) && !(len == 4 && (cp < 0x10000 || cp > 0x10FFFF)) &&
       !(cp >= 0xD800 && cp <= 0xDFFF);
  if (!ok) return "byte 0x" + hex(c0, 2) + " (not UTF-8 text)";
  return "character '" + std::string(rest.substr(0, len)) + "' (U+" + hex(cp, cp > 0xFFFF ? 6 : 4) + ")";
}

// The message of each rule that must match; `rest` is the input from where it failed.
template <typename Rule>
std::string message(std::string_view rest) {
  const char c = rest.empty() ? '\0' : rest[0];
  if constexpr (std::is_same_v<Rule, word_value>) {
    return "a number must follow the letter";
  } else if constexpr (std::is_same_v<Rule, comment_body>) {
    return "a comment opened with '(' must close on its line";
  } else if constexpr (std::is_same_v<Rule, bracket_close>) {
    return "']' expected: an expression's bracket must close";
  } else if constexpr (std::is_same_v<Rule, name_close> || std::is_same_v<Rule, name_text> ||
                       std::is_same_v<Rule, o_name_text>) {
    return "'>' expected: a name in angle brackets must close on its line";
  } else if constexpr (std::is_same_v<Rule, exists_close> || std::is_same_v<Rule, var_ref>) {
    return "EXISTS takes one parameter: EXISTS[#<name>]";
  } else if constexpr (std::is_same_v<Rule, assign_eq>) {
    return "'=' expected: a macro variable at the start of a line is assigned (#n = expression)";
  } else if constexpr (std::is_same_v<Rule, set_eq>) {
    return "'=' expected: a parameter among the words is set (#n = expression, #<name> = expression)";
  } else if constexpr (std::is_same_v<Rule, o_keyword_expected>) {
    return "an O-word keyword expected (sub, endsub, call, return, if, elseif, else, endif, while, endwhile, do, "
           "repeat, endrepeat, break, continue)";
  } else if constexpr (std::is_same_v<Rule, o_condition>) {
    return "a bracketed expression expected after the O-word keyword";
  } else if constexpr (std::is_same_v<Rule, expr> || std::is_same_v<Rule, unary> || std::is_same_v<Rule, operand> ||
                       std::is_same_v<Rule, var_index> || std::is_same_v<Rule, bracket> ||
                       std::is_same_v<Rule, func_arg>) {
    return "an expression expected (a number, #n, [..], PI or a function)";
  } else {
    if (c == ')') return "')' closes no comment";
    if (c == '(') return "a comment inside a comment: LinuxCNC refuses nested comments";
    if (c == '@' || c == '^') return "polar coordinates (@ and ^ words) are not supported";
    return "unexpected " + describe_char(rest);
  }
}

template <typename Rule>
struct control : pg::normal<Rule> {
  template <typename Input, typename... States>
  [[noreturn]] static void raise(const Input& in, States&&... /*unused*/) {
    throw pg::parse_error(message<Rule>(std::string_view(in.current(), in.size(4))), in);
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

Op op_named(const std::string& t) {
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
    if (name[0] != '<') {
      const auto nz = name.find_first_not_of('0');
      name = nz == std::string::npos ? "0" : name.substr(nz);
    }
    s.line.oname = name;
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

// A Grbl '$' line or a Fanuc macro statement, which the grammar does not read: their
// message, or empty.
std::string foreign_line(std::string_view raw, Dialect d) {
  std::size_t i = raw.find_first_not_of(" \t");
  if (i == std::string_view::npos) return {};
  if (raw[i] == '$') {
    return "a '$' line is a command to a Grbl controller (settings, homing, jogging) sent by a G-code sender, "
           "not G-code: remove it from the program";
  }
  if (d != Dialect::Fanuc) return {};
  std::string head;
  for (; i < raw.size() && head.size() < 5 && std::isalpha(static_cast<unsigned char>(raw[i])) != 0; ++i) {
    head += char(std::toupper(static_cast<unsigned char>(raw[i])));
  }
  if (head == "WHILE" || head == "IF" || head == "GOTO" || (head == "END" && i < raw.size() && raw[i] != 'I')) {
    return "Fanuc macro B flow control (IF, GOTO, WHILE .. DO, END) is not supported: write the loop out, or use "
           "--dialect linuxcnc with O-words";
  }
  return {};
}

}  // namespace

// One line's text (not a '%' header, at most kMaxLineLength characters) parsed in the
// dialect into its words, parameter settings or its statement.
Line parse_line(std::string_view raw, std::size_t number, const std::string& file, Dialect dialect) {
  if (const std::string why = foreign_line(raw, dialect); !why.empty()) {
    throw ProgramError(file, number, raw.find_first_not_of(" \t") + 1, why);
  }
  ParseState s;
  s.dialect = dialect;
  s.line.number = number;
  pg::memory_input<> in(raw.data(), raw.size(), file);
  try {
    pg::parse<line, action, control>(in, s);
  } catch (const pg::parse_error& e) {
    const auto& p = e.positions().front();
    throw ProgramError(file, number, p.column, std::string(e.message()));
  }
  return std::move(s.line);
}

}  // namespace dda::program::detail
