// SPDX-License-Identifier: Apache-2.0
// The operator's controls of a live run (docs/programs.md, "Running a program live"):
// a terminal's keys, signals, and a control file, each a source of requests the run
// polls between its accesses.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host/run/live_run.hpp"

namespace dda::live {

// Signals: SIGINT and SIGTERM a soft stop, a second one a hard stop; SIGUSR1 a feed
// hold, SIGUSR2 its end. Installs its handlers for its lifetime (one at a time).
class SignalControls : public Controls {
 public:
  SignalControls();
  ~SignalControls() override;
  std::optional<ControlRequest> poll(double seconds) override;

 private:
  int stops_seen_ = 0;
};

// A terminal's keys, the terminal in raw mode (no echo, a key at a time; Ctrl-C still a
// signal) for its lifetime: `!` or space a feed hold, `~` or `r` its end, `+` and `-`
// the override up and down by 10%, `s` a soft stop.
class TerminalControls : public Controls {
 public:
  explicit TerminalControls(int fd);
  ~TerminalControls() override;
  std::optional<ControlRequest> poll(double seconds) override;
  static const char* keys();  // the keys, one line, for the help

 private:
  int fd_;
  struct Saved;
  std::unique_ptr<Saved> saved_;
};

// A control file (or FIFO), read as it grows: a request a line, `hold`, `resume`,
// `override PERCENT`, `override +` or `override -`, `stop` (soft) or `hard-stop`,
// optionally after `@SECONDS` (it acts once the machine's time reaches it; the lines'
// times in order); `#` starts a comment. InputError naming the file and the line for
// anything else.
class ControlFile : public Controls {
 public:
  explicit ControlFile(const std::string& path);
  ~ControlFile() override;
  ControlFile(const ControlFile&) = delete;
  ControlFile& operator=(const ControlFile&) = delete;
  std::optional<ControlRequest> poll(double seconds) override;

 private:
  // The next whole line read so far (never waiting: the file is read without blocking).
  std::optional<std::string> next_line();
  std::string path_;
  int fd_ = -1;
  std::string partial_;
  std::size_t line_ = 0;
  std::optional<std::pair<double, ControlRequest>> waiting_;
};

// Every source in turn.
class AllControls : public Controls {
 public:
  void add(std::unique_ptr<Controls> c) { all_.push_back(std::move(c)); }
  std::optional<ControlRequest> poll(double seconds) override;

 private:
  std::vector<std::unique_ptr<Controls>> all_;
};

}  // namespace dda::live
