// SPDX-License-Identifier: Apache-2.0
#include "model/motion/build.hpp"

#include <fmt/format.h>

#include <charconv>
#include <stdexcept>

#include "model/datapath/errors.hpp"

namespace dda::motion {

namespace {

// Each kBuildParams key and its member of Build.
int get(const Build& b, std::string_view key) {
  if (key == "depth_log2") return b.depth_log2;
  if (key == "inputs") return b.inputs ? 1 : 0;
  if (key == "axes") return b.axes;
  if (key == "pacer") return b.pacer ? 1 : 0;
  throw std::logic_error(fmt::format("build: no member for '{}'", key));
}
void set(Build& b, std::string_view key, int v) {
  if (key == "depth_log2")
    b.depth_log2 = v;
  else if (key == "inputs")
    b.inputs = v != 0;
  else if (key == "axes")
    b.axes = v;
  else if (key == "pacer")
    b.pacer = v != 0;
  else
    throw std::logic_error(fmt::format("build: no member for '{}'", key));
}

}  // namespace

std::vector<int> build_values(const Build& b) {
  std::vector<int> v;
  for (const auto& p : kBuildParams) v.push_back(get(b, p.key));
  return v;
}

Build parse_build(std::string_view spec) {
  Build b;
  std::vector<std::string_view> seen;
  bool more = !spec.empty();
  while (more) {
    const auto comma = spec.find(',');
    const std::string_view item = spec.substr(0, comma);
    more = comma != std::string_view::npos;  // (a comma at the end leaves an empty item: refused)
    spec = more ? spec.substr(comma + 1) : std::string_view{};
    const auto eq = item.find('=');
    if (eq == std::string_view::npos) throw InputError(fmt::format("build: '{}' is not key=value", item));
    const std::string_view key = item.substr(0, eq), text = item.substr(eq + 1);
    const BuildParam* param = nullptr;
    for (const auto& p : kBuildParams)
      if (p.key == key) param = &p;
    if (param == nullptr) {
      std::string keys;
      for (const auto& p : kBuildParams) keys += (keys.empty() ? "" : ", ") + std::string(p.key);
      throw InputError(fmt::format("build: no choice '{}' (the choices: {})", key, keys));
    }
    for (const auto s : seen)
      if (s == key) throw InputError(fmt::format("build: '{}' given twice", key));
    seen.push_back(key);
    int v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc{} || end != text.data() + text.size() || v < param->min || v > param->max)
      throw InputError(
          fmt::format("build: {}={} is not a whole number in {} .. {}", key, text, param->min, param->max));
    set(b, key, v);
  }
  return b;
}

std::string build_spec(const Build& b) {
  std::string s;
  const auto v = build_values(b);
  for (std::size_t i = 0; i < kBuildParams.size(); ++i)
    s += fmt::format("{}{}={}", s.empty() ? "" : ",", kBuildParams[i].key, v[i]);
  return s;
}

std::vector<std::pair<std::string, int>> rtl_params(const Build& b) {
  std::vector<std::pair<std::string, int>> r;
  const auto v = build_values(b);
  for (std::size_t i = 0; i < kBuildParams.size(); ++i) r.emplace_back(std::string(kBuildParams[i].rtl), v[i]);
  return r;
}

bool input_built(const Input& in, const Build& b) {
  return b.inputs && (b.axes == 3 || in.name.find("_z") == std::string_view::npos);
}

CmdFields idle_linear_axis(CmdFields c) {
  for (std::size_t i = 0; i < hw::kCmdFields.size(); ++i) {
    const std::string_view n = hw::kCmdFields[i].name;
    if (n.size() > 2 && n.substr(n.size() - 2) == "_z") c[i] = n == "cap_z" ? 1 : 0;
  }
  return c;
}

}  // namespace dda::motion
