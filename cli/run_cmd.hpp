// SPDX-License-Identifier: Apache-2.0
// `dda run PROGRAM --port PORT`: a part program run live on a motion block (docs/programs.md,
// "Running a program live"; host/run/live_run.hpp).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "cli/options/program_cmd.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace dda::cli {

struct RunCli {
  ProgramCli prog;
  std::string port, machine_config, control, vcd;
  double status_every = 0;
  bool quiet = false;
  CLI::Option* step_opt = nullptr;  // (--step given or not)
};
void add_run_options(CLI::App* sub, RunCli& r);
// Runs it; the exit status comes back in ExitStatus when it is not 0.
void run_run(const RunCli& r);

// A subcommand's exit status other than 0, 1 and 2's exceptions (the message already
// said).
class ExitStatus : public std::exception {
 public:
  explicit ExitStatus(int status) : status_(status) {}
  int status() const { return status_; }
  const char* what() const noexcept override { return "exit status"; }

 private:
  int status_;
};

}  // namespace dda::cli
