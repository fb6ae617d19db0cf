// SPDX-License-Identifier: Apache-2.0
// A part program line parsed (host/program/grammar/rules.hpp): the actions that collect its words,
// parameter settings and statement, and build each expression's tree with the
// dialect's precedence (docs/programs.md, "Dialects"); the messages of the rules that
// must match.
#include <cctype>
#include <limits>
#include <string>
#include <string_view>

#include "host/program/grammar/actions.hpp"
#include "host/program/grammar/line.hpp"
#include "host/program/grammar/rules.hpp"

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

// A Grbl '$' line or a Fanuc macro statement, which the grammar does not read: their
// message, or empty.
std::string foreign_line(std::string_view raw, Dialect d) {
  std::size_t i = raw.find_first_not_of(" \t");
  if (i == std::string_view::npos) return {};
  if (raw[i] == '$') {
    return "a '$' line is a command to a Grbl controller (settings, homing, jogging) sent by a G-code sender, "
           "not G-code: remove it from the program";
  }
  if (d != Dialect::LinuxCnc && (raw[i] == 'o' || raw[i] == 'O')) {
    // An O-word statement (o100 sub, o<name> call): a name, blanks, then a letter.
    std::size_t j = i + 1;
    if (j < raw.size() && raw[j] == '<') j = raw.find('>', j);
    while (j != std::string_view::npos && j < raw.size() && std::isdigit(static_cast<unsigned char>(raw[j])) != 0) ++j;
    if (j != std::string_view::npos && j > i + 1 && j < raw.size() && raw[j] == '>') ++j;
    const std::size_t k = j == std::string_view::npos ? j : raw.find_first_not_of(" \t", j);
    if (k != std::string_view::npos && k > j && std::isalpha(static_cast<unsigned char>(raw[k])) != 0) {
      return "an O-word statement is LinuxCNC's (o100 sub, o<name> call, o101 while ...): read it with --dialect "
             "linuxcnc";
    }
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
