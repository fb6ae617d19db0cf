// SPDX-License-Identifier: Apache-2.0
// Inside the program reader: the words of each line (program_grammar.cpp, PEGTL) that
// the interpreter (program.cpp) turns into motion blocks.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dda/program.hpp"

namespace dda::program::detail {

// A word as written: its letter (upper case), its number as a decimal mantissa and the
// count of digits after the point (X-1.25: mantissa -125, decimals 2), and where it is.
struct Word {
  char letter = 0;
  std::string text;  // the number as written
  std::int64_t mantissa = 0;
  int decimals = 0;
  SourcePos pos;
};

struct Line {
  std::size_t number = 0;  // 1-based
  bool header = false;     // a '%' line: a program's start
  std::vector<Word> words;
};

// Splits the text into lines and each line into words; throws ProgramError at the first
// character that is not part of a word, a blank or a comment.
std::vector<Line> parse_lines(std::string_view text, const std::string& file);

}  // namespace dda::program::detail
