// SPDX-License-Identifier: Apache-2.0
// Writing a JSON document as a stream, in exactly the text nlohmann's dump(1) prints for
// the whole document, so a report can write its rows as they come.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace dda::json_stream {

// `j` as dump(1) prints it as a value at nesting depth `depth` (its first line not indented).
inline std::string nested(const nlohmann::ordered_json& j, int depth) {
  std::string text = j.dump(1), out;
  for (const char ch : text) {
    out += ch;
    if (ch == '\n') out.append(std::size_t(depth), ' ');
  }
  return out;
}

// `j` as an element of an array at nesting depth `depth` (indented).
inline std::string element(const nlohmann::ordered_json& j, int depth) {
  return std::string(std::size_t(depth), ' ') + nested(j, depth);
}

// An object's text as dump(1) prints it, without its closing "\n}": members follow.
inline std::string open_object(const nlohmann::ordered_json& j) {
  const std::string text = j.dump(1);
  return text.substr(0, text.size() - 2);
}

}  // namespace dda::json_stream
