// SPDX-License-Identifier: Apache-2.0
// Where the `dda` command writes: files replaced atomically, or standard output.
#pragma once

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <ostream>
#include <string>

#include "cli/options/temp_files.hpp"
#include "model/datapath/errors.hpp"

namespace dda::cli {

// A file written atomically: a temporary file beside it, renamed over it only once all
// went well, and removed on any failure. A path naming an existing non-regular file (a
// device such as /dev/null or /dev/stdout, a FIFO) is written directly instead, and a
// symbolic link is followed, so neither is ever replaced by a regular file.
class AtomicFile {
 public:
  AtomicFile() = default;
  explicit AtomicFile(const std::string& path) : path_(path) {
    if (path_.empty()) return;
    std::error_code ec;
    const auto st = std::filesystem::status(path_, ec);
    if (!ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st)) {
      if (std::filesystem::is_directory(st)) throw GuardError("cannot write '" + path_ + "': it is a directory");
      direct_ = true;
      write_path_ = path_;
      return;
    }
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(path_, ec))) {
      target_ = std::filesystem::weakly_canonical(path_, ec).string();
      if (ec) throw GuardError("cannot resolve '" + path_ + "': " + ec.message());
    } else {
      target_ = path_;
    }
    remove_stale_temps(target_);
    write_path_ = target_ + ".tmp." + std::to_string(::getpid());
    register_temp(write_path_);
    std::ofstream probe(write_path_, std::ios::out | std::ios::trunc | std::ios::binary);
    if (!probe) {
      release_temp(write_path_);
      throw GuardError("cannot write '" + path_ + "': " + std::strerror(errno));
    }
  }
  ~AtomicFile() {
    if (!committed_ && !direct_ && !write_path_.empty()) {
      std::remove(write_path_.c_str());
      release_temp(write_path_);
    }
  }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  const std::string& write_path() const { return write_path_; }  // where to write now
  const std::string& path() const { return path_; }
  void commit() {
    if (write_path_.empty() || direct_) return;
    if (std::rename(write_path_.c_str(), target_.c_str()) != 0) {
      throw GuardError("cannot rename to '" + path_ + "': " + std::strerror(errno));
    }
    committed_ = true;
    release_temp(write_path_);
  }

 private:
  std::string path_, target_, write_path_;
  bool direct_ = false, committed_ = false;
};

// The command's text output: stdout (no path, or "-"), or an AtomicFile.
class Output {
 public:
  explicit Output(const std::string& path) : file_(path == "-" ? std::string() : path) {
    if (file_.path().empty()) return;
    stream_.open(file_.write_path(), std::ios::out | std::ios::trunc | std::ios::binary);
    if (!stream_) throw GuardError("cannot write '" + path + "': " + std::strerror(errno));
  }
  std::ostream& stream() { return file_.path().empty() ? std::cout : stream_; }
  void commit() {
    if (file_.path().empty()) {
      std::cout.flush();
      if (!std::cout) throw GuardError("error writing to standard output");
      return;
    }
    stream_.flush();
    stream_.close();
    if (stream_.fail()) throw GuardError("error writing '" + file_.path() + "'");
    file_.commit();
  }

 private:
  AtomicFile file_;
  std::ofstream stream_;
};

}  // namespace dda::cli
