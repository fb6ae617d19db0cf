// SPDX-License-Identifier: Apache-2.0
// The engines' names, apart from the engines: the option parsing (dda_options) links
// without the SystemC model and the RTL.
#include <string>

#include "cli/options/engine_names.hpp"

namespace dda::cli {

bool known_engine(const std::string& name) {
  for (const char* n : kEngineNames) {
    if (name == n) return true;
  }
  return false;
}

std::string engine_names() {
  std::string s;
  for (const char* n : kEngineNames) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

}  // namespace dda::cli
