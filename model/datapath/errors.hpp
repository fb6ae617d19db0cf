// SPDX-License-Identifier: Apache-2.0
// The two kinds of failure every component reports (the CLI maps them to exit codes).
#pragma once

#include <stdexcept>

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

}  // namespace dda
