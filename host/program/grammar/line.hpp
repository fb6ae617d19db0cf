// SPDX-License-Identifier: Apache-2.0
// Inside the program reader: the lines of a stream, one at a time, and the words, macro
// statements and expressions of each (host/program/grammar/grammar.cpp, PEGTL) that the interpreter
// (program.cpp, host/program/macro/macro.cpp) turns into motion blocks.
#pragma once

#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "host/program/program.hpp"

namespace dda::program::detail {

// A node of a macro expression (docs/programs.md, "Macros"); a line's nodes form trees
// in Line::nodes, operands by index.
enum class Op {
  Num,    // value
  Var,    // #a: the variable whose number is expression a
  Named,  // #<name>: Line::names[name]
  Pi,     // PI
  Neg,    // -a
  Not,    // NOT a
  Add,    // a + b, and so on
  Sub,
  Mul,
  Div,
  Mod,
  Pow,
  Eq,
  Ne,
  Gt,
  Ge,
  Lt,
  Le,
  And,
  Or,
  Xor,
  Sin,  // functions of a: angles in radians (HNC) or degrees (LinuxCNC, Fanuc)
  Cos,
  Tan,
  Atan,
  Atan2,  // ATAN[a]/[b] (LinuxCNC, Fanuc)
  Asin,
  Acos,
  Sqrt,
  Abs,
  Int,
  Fix,
  Fup,
  Round,
  Exp,
  Ln,
  Exists,  // EXISTS[#<name>]: 1 if the named parameter a has a value
};
struct Node {
  Op op = Op::Num;
  double value = 0;
  int a = -1, b = -1;
  int name = -1;  // Named: its index in Line::names
  SourcePos pos;  // the operator's (or the operand's) position
};

// A word as written: its letter (upper case), its number as a decimal mantissa and the
// count of digits after the point (X-1.25: mantissa -125, decimals 2), and where it is;
// or (expr >= 0) an expression (X[2*#11], Z#12) evaluated when the block runs.
struct Word {
  char letter = 0;
  std::string text;  // the number as written
  std::int64_t mantissa = 0;
  int decimals = 0;
  int expr = -1;
  SourcePos pos;
};

// A word's value as a double (its mantissa over 10^decimals).
double word_number(const Word& w);
// A word of a computed value (|v| at most 1e9): 9 decimals, 1e-9 of the program's unit
// (an inch program's lengths keep the nanometre), its text the value's.
Word computed_word(char letter, double v, const SourcePos& pos);

// Statements: HNC's (Assign .. EndIf, a line of their own) and LinuxCNC's O-words.
enum class Stmt {
  None,
  Assign,
  While,
  EndW,
  If,
  Else,
  EndIf,
  OSub,  // o100 sub, o<name> sub
  OEndSub,
  OCall,
  OReturn,
  OIf,
  OElseIf,
  OElse,
  OEndIf,
  OWhile,  // a loop's head, or the tail of a do loop (matched in the structure)
  OEndWhile,
  ODo,
  ORepeat,
  OEndRepeat,
  OBreak,
  OContinue,
};
inline bool is_oword(Stmt s) { return s >= Stmt::OSub; }

// A parameter set on a words line (LinuxCNC, Fanuc): #target = value, where target is
// the node of the variable (Var or Named); applied after every word of the line is read.
struct Assign {
  int target = -1, value = -1;
  SourcePos pos;
};

struct Line {
  std::size_t number = 0;     // 1-based
  bool header = false;        // a '%' line, or a Fanuc 'O1234' line: a program's start
  std::int64_t program = -1;  // its number (%2: 2), -1 if it has none
  bool header_text = false;   // a '%' line with more than the '%' and a number
  bool block_delete = false;  // starts with '/'
  std::vector<Word> words;
  std::vector<Node> nodes;
  std::vector<std::string> names;  // of the named parameters in nodes
  std::vector<Assign> assigns;
  Stmt stmt = Stmt::None;
  int target = -1, value = -1;  // Assign: #target = value; While, If: the condition in value;
                                // O-words: the condition, count or returned value (-1: none)
  std::string oname;            // O-words: the number ("100") or the name ("<name>" lower case)
  std::vector<int> args;        // o.. call [a] [b]: the arguments
  SourcePos stmt_pos;
};

// One line's text parsed in the dialect (host/program/grammar/grammar.cpp); throws ProgramError.
Line parse_line(std::string_view raw, std::size_t number, const std::string& file, Dialect dialect);

// Lines longer than this are refused (RS274 allows 256 characters).
inline constexpr std::size_t kMaxLineLength = 4096;

// Where a line starts: its first byte's offset from the start of the stream and its
// number (1-based).
struct LinePos {
  std::uint64_t offset = 0;
  std::size_t number = 1;
};

// The lines of a program in a seekable stream, read one at a time. A line ends at '\n'
// (a '\r' before it, or before the end of the stream, is dropped) or at the end of the
// stream, so a text ending in '\n' has an empty last line; a UTF-8 byte-order mark at
// the start is skipped. Only the line being read is held, and at most kMaxLineLength + 1
// of its characters (a longer line is refused, a '%' line of any length is a header).
class LineStream {
 public:
  // Throws InputError if the stream cannot tell its position.
  LineStream(std::istream& in, const std::string& file);
  // The dialect the lines are parsed in (LinuxCNC until set).
  void set_dialect(Dialect d) { dialect_ = d; }
  // Reads the line at `at` as it is written, without parsing it, into `raw` (at most
  // kMaxLineLength + 1 characters; comments kept). Returns where the next line starts.
  LinePos read_raw(const LinePos& at, std::string& raw);
  LinePos first() const { return first_; }
  // Reads the line at `at` (seeking there unless it is the one after the last read) into
  // `out`: a '%' header, or its words or macro statement; throws ProgramError at the
  // first character that does not fit. Returns where the next line starts.
  LinePos read(const LinePos& at, Line& out);
  // Whether the line read last ended at the end of the stream (it was the last line).
  bool at_end() const { return at_end_; }

 private:
  void seek(std::uint64_t offset);
  void scan(const LinePos& at);  // reads the line at `at` into text_ (and its lead)
  Dialect dialect_ = Dialect::LinuxCnc;
  void take(char c);  // one character of the line being read
  std::streambuf* sb_;
  std::string file_;
  std::streampos base_;
  LinePos first_;
  std::uint64_t pos_ = 0;  // the offset sb_ reads next
  bool at_end_ = false;
  // The line being read: its first characters, its length, and whether its first
  // character other than a blank is '%' (then the digits after it: the program number).
  std::string text_;
  std::size_t length_ = 0;
  enum class Lead { Blanks, Header, Other } lead_ = Lead::Blanks;
  bool digits_ = false;  // in the header's digits
  bool header_text_ = false;
  std::int64_t program_ = -1;
};

}  // namespace dda::program::detail
