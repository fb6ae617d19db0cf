// SPDX-License-Identifier: Apache-2.0
// The lexical grammar of a part program, in PEGTL: a line is blanks, words (a letter and
// a number, blanks allowed between them), comments in parentheses that close on the
// line, and an optional ';' comment to the end of the line. A line starting with '%'
// marks a program's start.
#include <tao/pegtl.hpp>

#include <cctype>
#include <limits>

#include "program_detail.hpp"

namespace dda::program::detail {

namespace {

namespace pg = tao::pegtl;

struct blank : pg::one<' ', '\t'> {};
struct paren_open : pg::one<'('> {};
struct paren_comment : pg::if_must<paren_open, pg::until<pg::one<')'>, pg::not_one<'\r', '\n'>>> {};
struct semi_comment : pg::seq<pg::one<';'>, pg::star<pg::not_one<'\r', '\n'>>> {};
struct digits : pg::plus<pg::digit> {};
struct number
    : pg::seq<pg::opt<pg::one<'+', '-'>>,
              pg::sor<pg::seq<digits, pg::opt<pg::one<'.'>, pg::opt<digits>>>, pg::seq<pg::one<'.'>, digits>>> {};
struct letter : pg::alpha {};
struct word : pg::if_must<letter, pg::star<blank>, number> {};
struct end_of_line : pg::eolf {};
struct line : pg::seq<pg::star<pg::sor<blank, paren_comment, word>>, pg::opt<semi_comment>, pg::must<end_of_line>> {};

// The message of each rule that must match.
template <typename Rule>
std::string message(char c) {
  if constexpr (std::is_same_v<Rule, number>) {
    return "a number must follow the letter";
  } else if constexpr (std::is_same_v<Rule, pg::until<pg::one<')'>, pg::not_one<'\r', '\n'>>>) {
    return "a comment opened with '(' must close on its line";
  } else {
    if (c == ')') return "')' closes no comment";
    const bool print = std::isprint(static_cast<unsigned char>(c)) != 0;
    return print ? std::string("unexpected '") + c + "'"
                 : "unexpected character " + std::to_string(static_cast<unsigned char>(c));
  }
}

template <typename Rule>
struct control : pg::normal<Rule> {
  template <typename Input, typename... States>
  [[noreturn]] static void raise(const Input& in, States&&... /*unused*/) {
    throw pg::parse_error(message<Rule>(in.empty() ? '\0' : in.peek_char()), in);
  }
};

struct State {
  std::vector<Word> words;
  Word cur;
  std::size_t line = 0;
};

template <typename Rule>
struct action : pg::nothing<Rule> {};

template <>
struct action<letter> {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    s.cur = Word{};
    s.cur.letter = char(std::toupper(static_cast<unsigned char>(in.peek_char())));
    s.cur.pos = SourcePos{s.line, in.position().column};
  }
};

template <>
struct action<number> {
  template <typename Input>
  static void apply(const Input& in, State& s) {
    s.cur.text = in.string();
    bool neg = false, point = false;
    std::int64_t m = 0;
    int digits_seen = 0;
    for (const char c : s.cur.text) {
      if (c == '-') neg = true;
      if (c == '.') point = true;
      if (std::isdigit(static_cast<unsigned char>(c))) {
        if (++digits_seen > 15) throw pg::parse_error("a number of more than 15 digits", in);
        m = 10 * m + (c - '0');
        if (point) ++s.cur.decimals;
      }
    }
    s.cur.mantissa = neg ? -m : m;
    s.words.push_back(s.cur);
  }
};

}  // namespace

std::vector<Line> parse_lines(std::string_view text, const std::string& file) {
  std::vector<Line> out;
  std::size_t start = 0, number = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    const bool last = end == std::string_view::npos;
    if (last) end = text.size();
    std::string_view raw = text.substr(start, end - start);
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    ++number;
    Line l;
    l.number = number;
    const std::size_t first = raw.find_first_not_of(" \t");
    if (first != std::string_view::npos && raw[first] == '%') {
      l.header = true;  // the rest of a '%' line names the program
    } else {
      State s;
      s.line = number;
      pg::memory_input<> in(raw.data(), raw.size(), file);
      try {
        pg::parse<line, action, control>(in, s);
      } catch (const pg::parse_error& e) {
        const auto& p = e.positions().front();
        throw ProgramError(file, number, p.column, std::string(e.message()));
      }
      l.words = std::move(s.words);
    }
    out.push_back(std::move(l));
    if (last) break;
    start = end + 1;
  }
  return out;
}

}  // namespace dda::program::detail
