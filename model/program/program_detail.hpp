// SPDX-License-Identifier: Apache-2.0
// Inside the program reader: the lines of a stream, one at a time, and the words, macro
// statements and expressions of each (program_grammar.cpp, PEGTL) that the interpreter
// (program.cpp, program_macro.cpp) turns into motion blocks.
#pragma once

#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "program/program.hpp"

namespace dda::program::detail {

// A node of a macro expression (docs/programs.md, "Macros"); a line's nodes form trees
// in Line::nodes, operands by index.
enum class Op {
  Num,  // value
  Var,  // #a: the variable whose number is expression a
  Pi,   // PI
  Neg,  // -a
  Not,  // NOT a
  Add,  // a + b, and so on
  Sub,
  Mul,
  Div,
  Eq,
  Ne,
  Gt,
  Ge,
  Lt,
  Le,
  And,
  Or,
  Sin,  // functions of a, radians
  Cos,
  Tan,
  Atan,
  Sqrt,
  Abs,
  Int,
};
struct Node {
  Op op = Op::Num;
  double value = 0;
  int a = -1, b = -1;
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

enum class Stmt { None, Assign, While, EndW, If, Else, EndIf };

struct Line {
  std::size_t number = 0;     // 1-based
  bool header = false;        // a '%' line: a program's start
  std::int64_t program = -1;  // its number (%2: 2), -1 if it has none
  std::vector<Word> words;
  std::vector<Node> nodes;
  Stmt stmt = Stmt::None;
  int target = -1, value = -1;  // Assign: #target = value; While, If: the condition in value
  SourcePos stmt_pos;
};

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
  LinePos first() const { return first_; }
  // Reads the line at `at` (seeking there unless it is the one after the last read) into
  // `out`: a '%' header, or its words or macro statement; throws ProgramError at the
  // first character that does not fit. Returns where the next line starts.
  LinePos read(const LinePos& at, Line& out);
  // Whether the line read last ended at the end of the stream (it was the last line).
  bool at_end() const { return at_end_; }

 private:
  void seek(std::uint64_t offset);
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
  std::int64_t program_ = -1;
};

}  // namespace dda::program::detail
