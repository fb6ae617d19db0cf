// SPDX-License-Identifier: Apache-2.0
// Inside the program reader: the macro language's state and the programs' structure
// (program_macro.cpp; docs/programs.md, "Macros").
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "program_detail.hpp"

namespace dda::program::detail {

// Variables #0 to #kMaxVariable; a value beyond kMaxValue is an error (overflow).
inline constexpr std::int64_t kMaxVariable = 999;
inline constexpr double kMaxValue = 1e15;
// Execution limit: subprogram calls nested (recursion); the lines executed in all are
// ReadOptions::max_lines.
inline constexpr int kMaxCallDepth = 8;

// A value as the shortest decimal of at most 6 places ("0.25", "-3", "12.5").
std::string fmt_value(double v);

class Macro {
 public:
  explicit Macro(const std::string& file);
  // The value of a line's expression; an undefined variable, a division by zero, the
  // square root of a negative number or an overflow is a ProgramError at the operator.
  double eval(const Line& l, int node);
  bool truth(const Line& l);  // a WHILE's or IF's condition: not 0
  void assign(const Line& l);
  void set(std::int64_t var, double v);
  // A word whose value is an expression, evaluated to the millionth (6 decimals).
  Word value_word(const Line& l, const Word& w);

 private:
  [[noreturn]] void fail(const SourcePos& p, const std::string& msg) const;
  std::int64_t var_number(const Line& l, int index, const SourcePos& at);
  // The parts of eval, by the kind of node: a variable's value; a comparison, AND or OR
  // (0 or 1); + - * /; a function (SIN .. INT). eval checks the last two for overflow.
  double variable(const Line& l, const Node& n);
  double condition(const Line& l, const Node& n);
  double arithmetic(const Line& l, const Node& n);
  double function(const Line& l, const Node& n);
  std::string file_;
  std::map<std::int64_t, double> vars_;
};

// A program of the file: the lines after its '%' header, from `begin` to the line
// before line `end` (number -1 for text before the first header or a header without a
// number).
struct ProgramText {
  std::int64_t number = -1;
  LinePos begin;
  std::size_t end = 0;
  bool content = false;  // any word or statement
};
// A WHILE, ENDW, IF, ELSE or ENDIF line: where it is, where the line after it starts,
// and its match (an index in Structure::marks): for WHILE its ENDW, ENDW its WHILE, IF
// its ELSE or ENDIF, ELSE its ENDIF.
struct StmtMark {
  LinePos at, next;
  Stmt stmt = Stmt::None;
  SourcePos pos;  // the statement's
  std::size_t jump = 0;
};
struct Structure {
  std::vector<ProgramText> programs;
  std::vector<StmtMark> marks;  // in the order of the file
  // The mark of the statement line at `offset`.
  const StmtMark& mark(std::uint64_t offset) const;
};
// Reads every line of the stream (pass 1 of a read: every syntax error is thrown here),
// cuts the lines into programs and matches their statements. Then, as a program number
// defined twice or an unmatched WHILE, ENDW, IF, ELSE or ENDIF is a ProgramError at it,
// throws the first of them (a program defined twice before any unmatched statement).
Structure structure(LineStream& lines, const std::string& file);

}  // namespace dda::program::detail
