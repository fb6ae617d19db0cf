// SPDX-License-Identifier: Apache-2.0
// Inside the program reader: the words, macro statements and expressions of each line
// (program_grammar.cpp, PEGTL) that the interpreter (program.cpp, program_macro.cpp)
// turns into motion blocks.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dda/program.hpp"

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

// Splits the text into lines and each line into words or a macro statement; throws
// ProgramError at the first character that does not fit.
std::vector<Line> parse_lines(std::string_view text, const std::string& file);

}  // namespace dda::program::detail
