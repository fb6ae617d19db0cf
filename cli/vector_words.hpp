// SPDX-License-Identifier: Apache-2.0
// The words of the vector sets (the core's and the bus-level one): fields, a word built
// field by field and printed in hex for $readmemh, and a word's layout for a manifest.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace dda::vec {

// One field of a vector word: name, width, meaning, and (expected words) the Verilog
// expression the bench compares it with, relative to the instance `dut`.
struct Field {
  std::string name;
  int width;
  std::string meaning;
  std::string verilog;
};

inline int total_width(const std::vector<Field>& fs) {
  int w = 0;
  for (const auto& f : fs) w += f.width;
  return w;
}

// A wide word built field by field, most significant first, printed in hex.
class Word {
 public:
  explicit Word(int width) : bits_(std::size_t(width), 0) {}
  void put(std::uint64_t v, int width) {
    for (int k = width - 1; k >= 0; --k) bits_[pos_++] = (v >> k) & 1;
  }
  std::string hex() const {
    const int w = int(bits_.size()), digits = (w + 3) / 4;
    std::string s(std::size_t(digits), '0');
    for (int d = 0; d < digits; ++d) {
      int v = 0;
      for (int k = 0; k < 4; ++k) {
        const int bit = w - 1 - (4 * (digits - 1 - d) + (3 - k));  // index from the MSB
        v = v * 2 + (bit >= 0 && bit < w ? bits_[std::size_t(bit)] : 0);
      }
      s[std::size_t(d)] = "0123456789abcdef"[v];
    }
    return s;
  }

 private:
  std::vector<char> bits_;
  std::size_t pos_ = 0;
};

// The word of `fields` holding `values` (one each, in order), in hex.
inline std::string hex_word(const std::vector<Field>& fields, const std::vector<std::uint64_t>& values) {
  Word w(total_width(fields));
  for (std::size_t i = 0; i < fields.size(); ++i) w.put(values[i], fields[i].width);
  return w.hex();
}

// A word layout for a manifest: each field's name, bits (most significant first), width
// and meaning.
inline nlohmann::ordered_json field_layout(const std::vector<Field>& fs) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  int msb = total_width(fs) - 1;
  for (const auto& f : fs) {
    a.push_back(
        {{"name", f.name}, {"msb", msb}, {"lsb", msb - f.width + 1}, {"width", f.width}, {"meaning", f.meaning}});
    msb -= f.width;
  }
  return a;
}

}  // namespace dda::vec
