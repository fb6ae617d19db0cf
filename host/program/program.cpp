// SPDX-License-Identifier: Apache-2.0
// The program reader's entry points (program.hpp): a text or a stream through the
// interpreter (reader.hpp), and the files it reads, standard input through a
// temporary file.
#include "host/program/program.hpp"

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include "host/program/reader.hpp"

namespace dda::program {

namespace {

using detail::Output;
using detail::Reader;

[[noreturn]] void cannot_read(const std::string& path, int err) {
  throw InputError("program = '" + path + "' is invalid: cannot read it (" + std::strerror(err) + ")");
}

// A read-only stream buffer over a C file (of the program `path`), which it closes;
// seekable, and a seek within what it holds (a loop's jump back to its WHILE, most
// often) costs no system call. A read error is an InputError.
class FileBuf : public std::streambuf {
 public:
  FileBuf(std::FILE* f, const std::string& path) : f_(f), path_(path) {}
  ~FileBuf() override { std::fclose(f_); }
  FileBuf(const FileBuf&) = delete;
  FileBuf& operator=(const FileBuf&) = delete;

 protected:
  int_type underflow() override {
    start_ += egptr() - eback();
    const std::size_t n = std::fread(buf_.data(), 1, buf_.size(), f_);
    if (n == 0 && std::ferror(f_)) cannot_read(path_, errno);
    setg(buf_.data(), buf_.data(), buf_.data() + n);
    return n == 0 ? traits_type::eof() : traits_type::to_int_type(buf_[0]);
  }
  pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode which) override {
    if (dir == std::ios_base::cur) return seekpos(pos_type(start_ + (gptr() - eback()) + off), which);
    if (dir == std::ios_base::beg) return seekpos(pos_type(off), which);
    return pos_type(off_type(-1));  // (from the end: not needed)
  }
  pos_type seekpos(pos_type pos, std::ios_base::openmode /*which*/) override {
    const off_type p = pos;
    if (p >= start_ && p <= start_ + (egptr() - eback())) {
      setg(eback(), eback() + (p - start_), egptr());
      return pos;
    }
    if (p < 0 || fseeko(f_, p, SEEK_SET) != 0) return pos_type(off_type(-1));
    start_ = p;
    setg(buf_.data(), buf_.data(), buf_.data());
    return pos;
  }

 private:
  std::FILE* f_;
  std::string path_;
  std::array<char, 65536> buf_;
  off_type start_ = 0;  // the file's offset of eback()
};

class FileStream : public std::istream {
 public:
  FileStream(std::FILE* f, const std::string& path) : std::istream(nullptr), buf_(f, path) { rdbuf(&buf_); }

 private:
  FileBuf buf_;
};

// Standard input, which cannot seek, copied to an anonymous temporary file (removed by
// the system when it is closed).
std::FILE* copy_stdin() {
  std::FILE* f = std::tmpfile();
  if (!f) cannot_read("-", errno);
  const auto give_up = [f] {
    const int err = errno;
    std::fclose(f);
    cannot_read("-", err);
  };
  std::vector<char> chunk(65536);
  for (std::streamsize n; (n = std::cin.rdbuf()->sgetn(chunk.data(), std::streamsize(chunk.size()))) > 0;) {
    if (std::fwrite(chunk.data(), 1, std::size_t(n), f) != std::size_t(n)) give_up();
  }
  if (std::fflush(f) != 0 || std::fseek(f, 0, SEEK_SET) != 0) give_up();
  return f;
}

}  // namespace

Program read(std::string_view text, const std::string& file, const ReadOptions& opt) {
  std::istringstream in{std::string(text)};
  Program p;
  const std::function<void(const Move&)> keep = [&p](const Move& m) { p.moves.push_back(m); };
  ReadSummary s = Reader(in, file, opt, Output{keep, std::numeric_limits<std::size_t>::max()}).run();
  p.ignored = std::move(s.ignored);
  p.start = s.start;
  p.ended = s.ended;
  p.dialect = s.dialect;
  p.plane = s.plane;
  p.dwell_after = s.dwell_after;
  return p;
}

ReadSummary read_stream(std::istream& in, const std::string& file, const ReadOptions& opt,
                        const std::function<void(const Move&)>& on_move) {
  return Reader(in, file, opt, Output{on_move, kMaxIgnoredKept}).run();
}

std::unique_ptr<std::istream> open_program(const std::string& path) {
  if (path == "-") return std::make_unique<FileStream>(copy_stdin(), path);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError("program = '" + path + "' is invalid: it is a directory");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) cannot_read(path, errno);
  return std::make_unique<FileStream>(f, path);
}

}  // namespace dda::program
