// SPDX-License-Identifier: Apache-2.0
// The lines of a program in a seekable stream, one at a time (host/program/grammar/line.hpp): read
// raw, or parsed in the program's dialect (host/program/grammar/grammar.cpp).
#include <cctype>
#include <string>

#include "host/program/grammar/line.hpp"

namespace dda::program::detail {

namespace {

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
  if (lead_ == Lead::Header && !digits_ && c != '%' && c != ' ' && c != '\t') header_text_ = true;
}

void LineStream::scan(const LinePos& at) {
  seek(at.offset);
  text_.clear();
  length_ = 0;
  lead_ = Lead::Blanks;
  digits_ = false;
  program_ = -1;
  header_text_ = false;
  std::size_t cr = 0;
  for (;;) {
    const auto c = sb_->sbumpc();
    at_end_ = is_end(c);
    if (at_end_) break;
    ++pos_;
    const char ch = std::char_traits<char>::to_char_type(c);
    if (ch == '\n') break;
    if (ch == '\r') {
      ++cr;  // held back: dropped if the line ends after them (CR LF, CR CR LF)
      continue;
    }
    for (; cr > 0; --cr) take('\r');
    take(ch);
  }
}

LinePos LineStream::read_raw(const LinePos& at, std::string& raw) {
  scan(at);
  raw = text_;
  return LinePos{pos_, at.number + 1};
}

LinePos LineStream::read(const LinePos& at, Line& out) {
  scan(at);
  if (lead_ == Lead::Header) {
    out = Line{};
    out.number = at.number;
    out.header = true;
    out.program = program_;
    out.header_text = header_text_;
  } else if (length_ > kMaxLineLength) {
    // (Bounds the grammar's and the evaluator's recursion: brackets and signs nest.)
    throw ProgramError(file_, at.number, kMaxLineLength + 1,
                       "a line of more than " + std::to_string(kMaxLineLength) + " characters");
  } else {
    out = parse_line(text_, at.number, file_, dialect_);
  }
  return LinePos{pos_, at.number + 1};
}

}  // namespace dda::program::detail
