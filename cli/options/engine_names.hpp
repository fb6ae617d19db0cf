// SPDX-License-Identifier: Apache-2.0
// The engines the `dda` command can run, by name: the option parsing needs the names, not
// the engines (engine_names.cpp). The engines themselves are cli/engines.hpp's.
#pragma once

#include <string>

namespace dda::cli {

inline constexpr const char* kEngineNames[] = {"golden", "systemc", "rtl"};
bool known_engine(const std::string& name);
std::string engine_names();

}  // namespace dda::cli
