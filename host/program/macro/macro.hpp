// SPDX-License-Identifier: Apache-2.0
// Inside the program reader: the macro language's state and the programs' structure
// (host/program/macro/macro.cpp; docs/programs.md, "Macros").
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "host/program/program.hpp"

#include "host/program/grammar/line.hpp"

namespace dda::program::detail {

// Variables #0 to #kMaxVariable (HNC) or #kMaxParameter (LinuxCNC, Fanuc); a value
// beyond kMaxValue is an error (overflow).
inline constexpr std::int64_t kMaxVariable = 999;
inline constexpr std::int64_t kMaxParameter = 5602;
// LinuxCNC's subroutine arguments and locals: #1 to #kCallArgs in each call.
inline constexpr std::int64_t kCallArgs = 30;
inline constexpr double kMaxValue = 1e15;
// Execution limit: subprogram calls nested (recursion); the lines executed in all are
// ReadOptions::max_lines.
inline constexpr int kMaxCallDepth = 8;

// A value as the shortest decimal of at most 6 places ("0.25", "-3", "12.5").
std::string fmt_value(double v);

class Macro {
 public:
  explicit Macro(const std::string& file);
  void set_dialect(Dialect d) { dialect_ = d; }
  void set_file(const std::string& file) { file_ = file; }  // the file whose lines run
  // The value of a line's expression; an undefined variable, a division by zero, the
  // square root of a negative number or an overflow is a ProgramError at the operator.
  double eval(const Line& l, int node);
  bool truth(const Line& l);  // a WHILE's or IF's condition: not 0
  void assign(const Line& l);
  // A words line's parameter settings (LinuxCNC, Fanuc), after its words were read.
  void assign_all(const Line& l);
  void set(std::int64_t var, double v);
  // A numbered parameter's value (0 if never set: LinuxCNC's and Fanuc's rule).
  double param(std::int64_t var) const;
  void set_named(const std::string& name, double v);
  // LinuxCNC's calls: a frame of #1-#30 (the arguments) and the named locals.
  void push_frame(const std::vector<double>& args);
  void pop_frame();
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
  double angle_function(Op op, double a, double b, const Node& n) const;
  double named(const Line& l, const Node& n) const;
  const std::map<std::string, double>* named_scope(const std::string& name) const;
  void store(const Line& l, int target, double v, const SourcePos& at);
  std::string file_;
  Dialect dialect_ = Dialect::Hnc;
  std::map<std::int64_t, double> vars_;
  struct Frame {
    std::map<std::int64_t, double> args;
    std::map<std::string, double> named;
  };
  std::vector<Frame> frames_{1};           // the main program's, then one per call
  std::map<std::string, double> globals_;  // #<_name>
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
// LinuxCNC's O-words: sub its endsub and endsub its sub; if, elseif its next elseif,
// else or endif, else its endif; a loop's head (while, do, repeat) its end (endwhile,
// the do's closing while, endrepeat) and the end its head; break, continue and return
// the loop or sub they leave. `end` of an if chain's marks: its endif.
struct StmtMark {
  LinePos at, next;
  Stmt stmt = Stmt::None;
  SourcePos pos;  // the statement's
  std::size_t jump = 0;
  std::size_t end = 0;
  bool do_tail = false;  // an o.. while that closes a do loop
};
struct Structure {
  std::vector<ProgramText> programs;
  std::vector<StmtMark> marks;              // in the order of the file
  std::map<std::string, std::size_t> subs;  // LinuxCNC's subroutines: name, its sub mark
  bool closed = false;                      // LinuxCNC, Fanuc: the text ends at a closing '%'
  std::size_t last_line = 1;                // the number of the text's last line
  // The mark of the statement line at `offset`.
  const StmtMark& mark(std::uint64_t offset) const;
};
// Reads every line of the stream (pass 1 of a read: every syntax error is thrown here),
// cuts the lines into programs and matches their statements. Then, as a program number
// defined twice or an unmatched WHILE, ENDW, IF, ELSE or ENDIF is a ProgramError at it,
// throws the first of them (a program defined twice before any unmatched statement).
Structure structure(LineStream& lines, const std::string& file, Dialect dialect);

}  // namespace dda::program::detail
