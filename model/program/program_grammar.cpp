// SPDX-License-Identifier: Apache-2.0
// The grammar of a part program, in PEGTL: a line is blanks, words (a letter and a
// number or a macro expression, blanks allowed between them), comments in parentheses
// that close on the line, and an optional ';' comment to the end of the line; or a macro
// statement (#n = expression, WHILE, ENDW, IF, ELSE, ENDIF: HNC-21T's). A line starting
// with '%' marks a program's start and may give its number (%2). The lines are read from
// a stream one at a time (LineStream), as often as the interpreter runs them.
#include <tao/pegtl.hpp>

#include <cctype>
#include <limits>
#include <string>
#include <string_view>

#include "program_detail.hpp"

namespace dda::program::detail {

namespace {

namespace pg = tao::pegtl;

struct blank : pg::one<' ', '\t'> {};
struct ws : pg::star<blank> {};
struct paren_open : pg::one<'('> {};
struct comment_body : pg::until<pg::one<')'>, pg::not_one<'\r', '\n'>> {};
struct paren_comment : pg::if_must<paren_open, comment_body> {};
struct semi_comment : pg::seq<pg::one<';'>, pg::star<pg::not_one<'\r', '\n'>>> {};
struct digits : pg::plus<pg::digit> {};
struct unsigned_number
    : pg::sor<pg::seq<digits, pg::opt<pg::one<'.'>, pg::opt<digits>>>, pg::seq<pg::one<'.'>, digits>> {};
struct number : pg::seq<pg::opt<pg::one<'+', '-'>>, unsigned_number> {};

// Macro expressions. Keywords are whole words in any case.
template <typename Kw>
struct keyword : pg::seq<Kw, pg::not_at<pg::alnum>> {};
struct kw_pi : keyword<TAO_PEGTL_ISTRING("PI")> {};
struct kw_not : keyword<TAO_PEGTL_ISTRING("NOT")> {};
struct kw_and : keyword<TAO_PEGTL_ISTRING("AND")> {};
struct kw_or : keyword<TAO_PEGTL_ISTRING("OR")> {};
struct func_name
    : pg::sor<TAO_PEGTL_ISTRING("SIN"), TAO_PEGTL_ISTRING("COS"), TAO_PEGTL_ISTRING("TAN"), TAO_PEGTL_ISTRING("ATAN"),
              TAO_PEGTL_ISTRING("SQRT"), TAO_PEGTL_ISTRING("ABS"), TAO_PEGTL_ISTRING("INT")> {};
struct cmp_op : pg::seq<pg::sor<TAO_PEGTL_ISTRING("EQ"), TAO_PEGTL_ISTRING("NE"), TAO_PEGTL_ISTRING("GT"),
                                TAO_PEGTL_ISTRING("GE"), TAO_PEGTL_ISTRING("LT"), TAO_PEGTL_ISTRING("LE")>,
                        pg::not_at<pg::alpha>> {};
struct add_op : pg::one<'+', '-'> {};
struct mul_op : pg::one<'*', '/'> {};

struct expr;
struct expr_number : unsigned_number {};
struct bracket_close : pg::one<']'> {};
struct bracket : pg::if_must<pg::one<'['>, ws, expr, ws, bracket_close> {};
struct var;
struct var_index : pg::sor<expr_number, bracket, var> {};
struct var : pg::if_must<pg::one<'#'>, var_index> {};
struct func : pg::if_must<func_name, ws, bracket> {};
struct primary : pg::sor<expr_number, var, bracket, kw_pi, func> {};
struct unary;
struct negate : pg::if_must<pg::one<'-'>, ws, unary> {};
struct unary : pg::sor<negate, pg::seq<pg::one<'+'>, ws, unary>, primary> {};
struct mul_tail : pg::if_must<mul_op, ws, unary> {};
struct product : pg::seq<unary, pg::star<ws, mul_tail>> {};
struct add_tail : pg::if_must<add_op, ws, product> {};
struct sum : pg::seq<product, pg::star<ws, add_tail>> {};
struct cmp_tail : pg::if_must<cmp_op, ws, sum> {};
struct comparison : pg::seq<sum, pg::opt<ws, cmp_tail>> {};
struct negation;
struct not_expr : pg::sor<negation, comparison> {};
struct negation : pg::if_must<kw_not, ws, not_expr> {};
struct and_tail : pg::if_must<kw_and, ws, not_expr> {};
struct conjunction : pg::seq<not_expr, pg::star<ws, and_tail>> {};
struct or_tail : pg::if_must<kw_or, ws, conjunction> {};
struct expr : pg::seq<conjunction, pg::star<ws, or_tail>> {};

// Words: a letter, then a number or an expression (#n, [..], -#n, -[..], a function).
struct letter : pg::alpha {};
struct word_expr : pg::sor<var, bracket, negate, func> {};
struct word_value : pg::sor<number, word_expr> {};
struct word : pg::if_must<letter, ws, word_value> {};
struct end_of_line : pg::eolf {};
struct tail : pg::seq<pg::star<pg::sor<blank, paren_comment>>, pg::opt<semi_comment>, pg::must<end_of_line>> {};

// Statements.
struct assign_eq : pg::one<'='> {};
struct assignment : pg::if_must<pg::one<'#'>, var_index, ws, assign_eq, ws, expr> {};
struct kw_while : keyword<TAO_PEGTL_ISTRING("WHILE")> {};
struct kw_endw : keyword<TAO_PEGTL_ISTRING("ENDW")> {};
struct kw_if : keyword<TAO_PEGTL_ISTRING("IF")> {};
struct kw_else : keyword<TAO_PEGTL_ISTRING("ELSE")> {};
struct kw_endif : keyword<TAO_PEGTL_ISTRING("ENDIF")> {};
struct while_stmt : pg::if_must<kw_while, ws, expr> {};
struct if_stmt : pg::if_must<kw_if, ws, expr> {};
struct statement : pg::sor<assignment, while_stmt, kw_endw, if_stmt, kw_else, kw_endif> {};
struct n_word : pg::seq<pg::at<pg::one<'N', 'n'>>, word> {};
// A statement line is recognised by looking ahead (actions are off inside at<>), so that
// no action of a line read as words has run when it turns out to be a statement.
struct statement_start : pg::sor<pg::one<'#'>, kw_while, kw_endw, kw_if, kw_else, kw_endif> {};
struct n_raw : pg::seq<pg::one<'N', 'n'>, ws, number> {};
struct lead : pg::star<pg::sor<blank, paren_comment>> {};  // blanks and comments before a statement
struct statement_line
    : pg::seq<pg::at<lead, pg::opt<n_raw, lead>, statement_start>, lead, pg::opt<n_word, lead>, statement, tail> {};
struct words_line : pg::seq<pg::star<pg::sor<blank, paren_comment, word>>, tail> {};
struct line : pg::sor<statement_line, words_line> {};

// A character as a user reads it: printable ASCII in quotes, a UTF-8 sequence as the
// character and its code point, a control character or a byte that is not UTF-8 text
// by its value.
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
  } else if constexpr (std::is_same_v<Rule, assign_eq>) {
    return "'=' expected: a macro variable at the start of a line is assigned (#n = expression)";
  } else if constexpr (std::is_same_v<Rule, expr> || std::is_same_v<Rule, unary> || std::is_same_v<Rule, product> ||
                       std::is_same_v<Rule, sum> || std::is_same_v<Rule, not_expr> ||
                       std::is_same_v<Rule, conjunction> || std::is_same_v<Rule, var_index> ||
                       std::is_same_v<Rule, bracket>) {
    return "an expression expected (a number, #n, [..], PI or a function)";
  } else {
    if (c == ')') return "')' closes no comment";
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

struct State {
  std::vector<Word> words;
  Word cur;
  std::size_t line = 0;
  std::vector<Node> nodes;
  std::vector<int> values;  // the expression stack (node indices)
  std::vector<Node> ops;    // pending operators (op and position)
  Stmt stmt = Stmt::None;
  int target = -1, value = -1;
  SourcePos stmt_pos;

  template <typename Input>
  SourcePos at(const Input& in) const {
    return SourcePos{line, in.position().column};
  }
  int push(Node n) {
    nodes.push_back(n);
    values.push_back(int(nodes.size()) - 1);
    return values.back();
  }
  int pop() {
    const int v = values.back();
    values.pop_back();
    return v;
  }
  // Pops the pending operator and its operands (one or two) into a node.
  void reduce(int arity) {
    Node n = ops.back();
    ops.pop_back();
    if (arity == 2) n.b = pop();
    n.a = pop();
    push(n);
  }
};

template <typename Rule>
struct action : pg::nothing<Rule> {};

template <>
struct action<letter> {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    s.cur = Word{};
    s.cur.letter = char(std::toupper(static_cast<unsigned char>(in.peek_char())));
    s.cur.pos = s.at(in);
  }
};

// Digits of a number read exactly: at most 15, as a decimal mantissa and exponent.
template <typename Input>
void read_decimal(const Input& in, const std::string& text, std::int64_t& mantissa, int& decimals) {
  bool neg = false, point = false;
  std::int64_t m = 0;
  int digits_seen = 0;
  decimals = 0;
  for (const char c : text) {
    if (c == '-') neg = true;
    if (c == '.') point = true;
    if (std::isdigit(static_cast<unsigned char>(c))) {
      if (++digits_seen > 15) throw pg::parse_error("a number of more than 15 digits", in);
      m = 10 * m + (c - '0');
      if (point) ++decimals;
    }
  }
  mantissa = neg ? -m : m;
}

template <>
struct action<number> {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    s.cur.text = in.string();
    read_decimal(in, s.cur.text, s.cur.mantissa, s.cur.decimals);
    s.words.push_back(s.cur);
  }
};

template <>
struct action<word_expr> {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    s.cur.text = in.string();
    s.cur.expr = s.pop();
    s.words.push_back(s.cur);
  }
};

template <>
struct action<expr_number> {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    std::int64_t m = 0;
    int d = 0;
    read_decimal(in, in.string(), m, d);
    Node n;
    n.op = Op::Num;
    // One division of two exact doubles (m < 10^15 < 2^53, 10^d <= 10^15): the correctly
    // rounded value of the decimal, as IEEE 754 reads it.
    double p = 1;
    for (int i = 0; i < d; ++i) p *= 10;
    n.value = double(m) / p;
    n.pos = s.at(in);
    s.push(n);
  }
};

// An operator's position and kind, pushed when it is read and reduced with its operands.
template <typename Input>
void pending(State& s, const Input& in, Op op) {
  Node n;
  n.op = op;
  n.pos = s.at(in);
  s.ops.push_back(n);
}
Op binary_op(const std::string& t) {
  std::string u;
  for (const char c : t) u += char(std::toupper(static_cast<unsigned char>(c)));
  if (u == "+") return Op::Add;
  if (u == "-") return Op::Sub;
  if (u == "*") return Op::Mul;
  if (u == "/") return Op::Div;
  if (u == "EQ") return Op::Eq;
  if (u == "NE") return Op::Ne;
  if (u == "GT") return Op::Gt;
  if (u == "GE") return Op::Ge;
  if (u == "LT") return Op::Lt;
  if (u == "LE") return Op::Le;
  if (u == "AND") return Op::And;
  if (u == "OR") return Op::Or;
  if (u == "SIN") return Op::Sin;
  if (u == "COS") return Op::Cos;
  if (u == "TAN") return Op::Tan;
  if (u == "ATAN") return Op::Atan;
  if (u == "SQRT") return Op::Sqrt;
  if (u == "ABS") return Op::Abs;
  return Op::Int;
}

template <typename Rule>
struct op_action {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    pending(s, in, binary_op(in.string()));
  }
};
template <>
struct action<add_op> : op_action<add_op> {};
template <>
struct action<mul_op> : op_action<mul_op> {};
template <>
struct action<cmp_op> : op_action<cmp_op> {};
template <>
struct action<kw_and> : op_action<kw_and> {};
template <>
struct action<kw_or> : op_action<kw_or> {};
template <>
struct action<func_name> : op_action<func_name> {};

template <int Arity>
struct reduce_action {
  template <typename Input>
  static void apply(const Input& /*in*/, State& s) {
    s.reduce(Arity);
  }
};
template <>
struct action<add_tail> : reduce_action<2> {};
template <>
struct action<mul_tail> : reduce_action<2> {};
template <>
struct action<cmp_tail> : reduce_action<2> {};
template <>
struct action<and_tail> : reduce_action<2> {};
template <>
struct action<or_tail> : reduce_action<2> {};
template <>
struct action<func> : reduce_action<1> {};

template <>
struct action<kw_pi> {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    Node n;
    n.op = Op::Pi;
    n.pos = s.at(in);
    s.push(n);
  }
};

// Unary operators and variables, reduced once their operand is read.
template <>
struct action<negate> {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    Node n;
    n.op = Op::Neg;
    n.pos = s.at(in);
    n.a = s.pop();
    s.push(n);
  }
};
template <>
struct action<negation> {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    Node n;
    n.op = Op::Not;
    n.pos = s.at(in);
    n.a = s.pop();
    s.push(n);
  }
};
template <>
struct action<var> {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    Node n;
    n.op = Op::Var;
    n.pos = s.at(in);
    n.a = s.pop();
    s.push(n);
  }
};

template <>
struct action<assignment> {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    s.stmt = Stmt::Assign;
    s.value = s.pop();
    s.target = s.pop();
    s.stmt_pos = s.at(in);
  }
};
template <Stmt K>
struct stmt_action {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    s.stmt = K;
    if (K == Stmt::While || K == Stmt::If) s.value = s.pop();
    s.stmt_pos = s.at(in);
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

// One line's text (not a '%' header, at most kMaxLineLength characters) parsed into its
// words or its statement.
Line parse_line(std::string_view raw, std::size_t number, const std::string& file) {
  State s;
  s.line = number;
  pg::memory_input<> in(raw.data(), raw.size(), file);
  try {
    pg::parse<line, action, control>(in, s);
  } catch (const pg::parse_error& e) {
    const auto& p = e.positions().front();
    throw ProgramError(file, number, p.column, std::string(e.message()));
  }
  Line l;
  l.number = number;
  l.words = std::move(s.words);
  l.nodes = std::move(s.nodes);
  l.stmt = s.stmt;
  l.target = s.target;
  l.value = s.value;
  l.stmt_pos = s.stmt_pos;
  return l;
}

bool is_end(std::char_traits<char>::int_type c) {
  return std::char_traits<char>::eq_int_type(c, std::char_traits<char>::eof());
}

}  // namespace

LineStream::LineStream(std::istream& in, const std::string& file) : sb_(in.rdbuf()), file_(file) {
  const std::streampos bad(std::streamoff(-1));
  base_ = sb_ ? sb_->pubseekoff(0, std::ios::cur, std::ios::in) : bad;
  if (base_ == bad) throw InputError(file + ": the program's stream cannot seek");
  char bom[3];
  pos_ = std::uint64_t(sb_->sgetn(bom, 3));
  if (pos_ == 3 && std::string_view(bom, 3) == "\xEF\xBB\xBF") first_.offset = 3;  // a UTF-8 byte-order mark
  text_.reserve(kMaxLineLength + 1);
}

void LineStream::seek(std::uint64_t offset) {
  if (offset == pos_) return;
  if (sb_->pubseekpos(base_ + std::streamoff(offset), std::ios::in) == std::streampos(std::streamoff(-1))) {
    throw InputError(file_ + ": the program's stream cannot seek");
  }
  pos_ = offset;
}

void LineStream::take(char c) {
  if (text_.size() <= kMaxLineLength) text_ += c;
  ++length_;
  if (lead_ == Lead::Blanks && c != ' ' && c != '\t') {
    lead_ = c == '%' ? Lead::Header : Lead::Other;
    digits_ = lead_ == Lead::Header;
  } else if (digits_) {
    // The rest of a '%' line names the program: its number, if digits follow (read
    // while the number is below 10^8).
    const std::int64_t n = program_ < 0 ? 0 : program_;
    digits_ = std::isdigit(static_cast<unsigned char>(c)) && n < 100000000;
    if (digits_) program_ = 10 * n + (c - '0');
  }
}

LinePos LineStream::read(const LinePos& at, Line& out) {
  seek(at.offset);
  text_.clear();
  length_ = 0;
  lead_ = Lead::Blanks;
  digits_ = false;
  program_ = -1;
  bool cr = false;  // a '\r' held back: dropped if the line ends after it
  for (;;) {
    const auto c = sb_->sbumpc();
    at_end_ = is_end(c);
    if (at_end_) break;
    ++pos_;
    const char ch = std::char_traits<char>::to_char_type(c);
    if (ch == '\n') break;
    if (cr) take('\r');
    cr = ch == '\r';
    if (!cr) take(ch);
  }
  if (lead_ == Lead::Header) {
    out = Line{};
    out.number = at.number;
    out.header = true;
    out.program = program_;
  } else if (length_ > kMaxLineLength) {
    // (Bounds the grammar's and the evaluator's recursion: brackets and signs nest.)
    throw ProgramError(file_, at.number, kMaxLineLength + 1,
                       "a line of more than " + std::to_string(kMaxLineLength) + " characters");
  } else {
    out = parse_line(text_, at.number, file_);
  }
  return LinePos{pos_, at.number + 1};
}

}  // namespace dda::program::detail
