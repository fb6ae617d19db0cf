// SPDX-License-Identifier: Apache-2.0
// The two kinds of failure every component reports (the CLI maps them to exit codes).
#pragma once

#include <stdexcept>
#include <string>

namespace dda {

// Bad input: a parameter breaks a documented rule. The CLI exits with status 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
// A run-time guard tripped (iteration bound, stall, mismatch). The CLI exits with 1.
class GuardError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The input's fault as a value, for a caller that may go on: a way of planning that
// cannot plan the input says why, and its caller either reports it (an InputError with
// that text) or tries another way.
struct Refusal {
  std::string why;
};

}  // namespace dda
