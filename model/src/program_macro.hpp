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
  std::string file_;
  std::map<std::int64_t, double> vars_;
};

// A program of the file: the lines after its '%' header (number -1 for text before the
// first header or a header without a number).
struct ProgramText {
  std::int64_t number = -1;
  std::size_t begin = 0, end = 0;
  bool content = false;  // any word or statement
};
struct Structure {
  std::vector<ProgramText> programs;
  // For WHILE: its ENDW; ENDW: its WHILE; IF: its ELSE or ENDIF; ELSE: its ENDIF.
  std::vector<std::size_t> jump;
};
// Cuts the lines into programs and matches their statements; an unmatched WHILE, ENDW,
// IF, ELSE or ENDIF is a ProgramError at it.
Structure structure(const std::vector<Line>& lines, const std::string& file);

}  // namespace dda::program::detail
