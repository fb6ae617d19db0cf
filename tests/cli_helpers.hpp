// SPDX-License-Identifier: Apache-2.0
// Running the `dda` command from a test as a user would: a scratch directory, the
// command's exit status, standard output and standard error (DDA_BIN names it).
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

struct Result {
  int status = -1;
  std::string out, err;
};

// A scratch directory per test case, removed afterwards.
struct Scratch {
  fs::path dir;
  Scratch() {
    dir = fs::temp_directory_path() / ("dda_cli_test_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
  // Files in the directory other than the captured stdout/stderr.
  int user_files() const {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
      const auto name = e.path().filename().string();
      n += name != "stdout" && name != "stderr";
    }
    return n;
  }
};

Result run_dda(const Scratch& s, const std::string& args) {
  const std::string cmd =
      std::string(DDA_BIN) + " " + args + " >" + (s.dir / "stdout").string() + " 2>" + (s.dir / "stderr").string();
  const int rc = std::system(cmd.c_str());
  Result r;
  r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  r.out = slurp(s.dir / "stdout");
  r.err = slurp(s.dir / "stderr");
  return r;
}

}  // namespace
