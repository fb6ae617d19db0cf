// SPDX-License-Identifier: Apache-2.0
#include "host/speed/machine_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "model/datapath/errors.hpp"
#include "model/motion/motion_map.hpp"

namespace dda::speed {

namespace {

using program::Machine;

constexpr std::array<const char*, 3> kAxisNames{"x", "y", "z"};

bool has_axis(Machine m, std::size_t i) { return m == Machine::Mill || i != 1; }

[[noreturn]] void bad(const std::string& name, const std::string& what) {
  throw InputError("machine config '" + name + "': " + what);
}

double number(const nlohmann::json& v, const std::string& name, const std::string& key) {
  if (!v.is_number()) bad(name, key + " must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x) || x <= 0) bad(name, fmt::format("{} = {} must be positive", key, x));
  return x;
}

double non_negative(const nlohmann::json& v, const std::string& name, const std::string& key) {
  if (!v.is_number()) bad(name, key + " must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < 0) bad(name, fmt::format("{} = {} must be 0 or more", key, x));
  return x;
}

double finite(const nlohmann::json& v, const std::string& name, const std::string& key) {
  if (!v.is_number() || !std::isfinite(v.get<double>())) bad(name, key + " must be a number");
  return v.get<double>();
}

bool boolean(const nlohmann::json& v, const std::string& name, const std::string& key) {
  if (!v.is_boolean()) bad(name, key + " must be true or false");
  return v.get<bool>();
}

// An axis' live keys (AxisDrive); false for a key that is not one.
bool read_drive(const std::string& key, const nlohmann::json& x, const std::string& name, const std::string& where,
                AxisDrive& d) {
  if (key == "steps_per_mm") {
    d.steps_per_mm = number(x, name, where);
  } else if (key == "step_len_ns") {
    d.step_len_ns = non_negative(x, name, where);
  } else if (key == "step_space_ns") {
    d.step_space_ns = non_negative(x, name, where);
  } else if (key == "dir_setup_ns") {
    d.dir_setup_ns = non_negative(x, name, where);
  } else if (key == "dir_hold_ns") {
    d.dir_hold_ns = non_negative(x, name, where);
  } else if (key == "invert_step") {
    d.invert_step = boolean(x, name, where);
  } else if (key == "invert_dir") {
    d.invert_dir = boolean(x, name, where);
  } else if (key == "limit_neg_mm") {
    d.limit_neg_mm = finite(x, name, where);
  } else if (key == "limit_pos_mm") {
    d.limit_pos_mm = finite(x, name, where);
  } else {
    return false;
  }
  return true;
}

void read_inputs(const nlohmann::json& v, const std::string& name, LiveSettings& live) {
  if (!v.is_object()) bad(name, "inputs must be an object");
  for (const auto& [key, x] : v.items()) {
    const std::string where = "inputs." + key;
    if (key == "invert") {
      if (!x.is_array()) bad(name, where + " must be a list of input names");
      live.invert_inputs = 0;
      for (const auto& n : x) {
        const auto it = n.is_string()
                            ? std::find_if(motion::kInputs.begin(), motion::kInputs.end(),
                                           [&](const motion::Input& i) { return i.name == n.get<std::string>(); })
                            : motion::kInputs.end();
        if (it == motion::kInputs.end()) {
          std::string names;
          for (const auto& i : motion::kInputs) names += (names.empty() ? "" : ", ") + std::string(i.name);
          bad(name, where + ": " + n.dump() + " is not an input (the inputs: " + names + ")");
        }
        live.invert_inputs |= 1u << it->bit;
      }
    } else if (key == "switch_filter_us") {
      live.switch_filter_us = non_negative(x, name, where);
    } else if (key == "probe_filter_us") {
      live.probe_filter_us = non_negative(x, name, where);
    } else if (key == "limit_decel") {
      live.limit_decel = boolean(x, name, where);
    } else {
      bad(name, "unknown key '" + where + "' (inputs has invert, switch_filter_us, probe_filter_us, limit_decel)");
    }
  }
}

void read_axes(const nlohmann::json& axes, const std::string& name, Machine m, MachineLimits& l) {
  if (!axes.is_object()) bad(name, "axes must be an object of x, y, z");
  for (const auto& [axis, v] : axes.items()) {
    const auto it = std::find(kAxisNames.begin(), kAxisNames.end(), axis);
    if (it == kAxisNames.end()) bad(name, "unknown axis '" + axis + "' (the axes are x, y, z)");
    const std::size_t i = std::size_t(it - kAxisNames.begin());
    // An axis the machine has not: its limits would be read and never used.
    if (!has_axis(m, i)) bad(name, "axes." + axis + ": a lathe has no Y axis (its axes are x and z)");
    if (!v.is_object()) bad(name, "axes." + axis + " must be an object");
    AxisLimits& a = l.axes[i];
    for (const auto& [key, x] : v.items()) {
      const std::string where = "axes." + axis + "." + key;
      if (key == "vmax_mm_per_min") {
        a.vmax = number(x, name, where);
      } else if (key == "accel_mm_per_s2") {
        a.accel = number(x, name, where);
      } else if (!read_drive(key, x, name, where, l.live.axes[i])) {
        bad(name, "unknown key '" + where +
                      "' (an axis has vmax_mm_per_min, accel_mm_per_s2, steps_per_mm, step_len_ns, step_space_ns, "
                      "dir_setup_ns, dir_hold_ns, invert_step, invert_dir, limit_neg_mm, limit_pos_mm)");
      }
    }
  }
}

}  // namespace

MachineLimits default_limits(Machine m) {
  MachineLimits l;
  if (m == Machine::Mill) {
    l.axes = {AxisLimits{6000, 500}, AxisLimits{6000, 500}, AxisLimits{3000, 500}};
    l.rapid = 6000;
  } else {
    l.axes = {AxisLimits{4000, 500}, AxisLimits{}, AxisLimits{6000, 500}};
    l.rapid = 4000;
  }
  return l;
}

MachineLimits parse_machine_config(const std::string& text, const std::string& name, MachineLimits l, Machine m) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    bad(name, std::string("not JSON: ") + e.what());
  }
  if (!j.is_object()) bad(name, "the file must hold one JSON object");
  for (const auto& [key, v] : j.items()) {
    if (key == "axes") {
      read_axes(v, name, m, l);
    } else if (key == "rapid_mm_per_min") {
      l.rapid = number(v, name, key);
    } else if (key == "junction_deviation_mm") {
      l.junction_deviation = number(v, name, key);
    } else if (key == "min_speed_mm_per_min") {
      l.min_speed = number(v, name, key);
    } else if (key == "tangential_share") {
      l.tangential_share = number(v, name, key);
    } else if (key == "default_feed_mm_per_min") {
      l.default_feed = number(v, name, key);
    } else if (key == "window") {
      if (!v.is_number_integer() || v.get<std::int64_t>() < 2 || v.get<std::int64_t>() > 100000)
        bad(name, "window must be a whole number from 2 to 100000");
      l.window = v.get<std::size_t>();
    } else if (key == "clock_hz") {
      l.live.clock_hz = number(v, name, key);
      if (l.live.clock_hz > 1e9) bad(name, fmt::format("clock_hz = {} is above 1e9", l.live.clock_hz));
    } else if (key == "watchdog_ms") {
      l.live.watchdog_ms = number(v, name, key);
    } else if (key == "port") {
      if (!v.is_string() || v.get<std::string>().empty()) bad(name, "port must be a port's name, such as \"sim\"");
      l.live.port = v.get<std::string>();
    } else if (key == "inputs") {
      read_inputs(v, name, l.live);
    } else if (key != "comment") {
      bad(name, "unknown key '" + key +
                    "' (keys: axes, rapid_mm_per_min, junction_deviation_mm, min_speed_mm_per_min, "
                    "tangential_share, default_feed_mm_per_min, window, clock_hz, watchdog_ms, port, inputs, "
                    "comment)");
    }
  }
  return l;
}

MachineLimits read_machine_config(const std::string& path, MachineLimits base, Machine m) {
  std::ifstream in(path);
  if (!in) bad(path, "cannot read it");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) bad(path, "cannot read it");
  return parse_machine_config(text.str(), path, base, m);
}

void check(const MachineLimits& l, Machine m) {
  for (std::size_t i = 0; i < 3; ++i) {
    if (!has_axis(m, i)) continue;
    if (!(l.axes[i].vmax > 0) || !(l.axes[i].accel > 0))
      throw InputError(fmt::format("machine limits: axis {} needs a positive vmax and acceleration", kAxisNames[i]));
  }
  if (!(l.rapid > 0)) throw InputError("machine limits: the rapid rate must be positive");
  if (!(l.junction_deviation > 0)) throw InputError("machine limits: the junction deviation must be positive");
  if (!(l.min_speed > 0))
    throw InputError("machine limits: the minimum speed must be positive (a drive starts and stops at it)");
  if (!(l.tangential_share > 0 && l.tangential_share < 1))
    throw InputError("machine limits: tangential_share must be above 0 and below 1 (curves need the rest)");
  if (l.window < 2 || l.window > 100000) throw InputError("machine limits: the window must be 2 to 100000 pieces");
}

static double smallest_accel(const MachineLimits& l, Machine m) {
  double a = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    if (has_axis(m, i)) a = a == 0 ? l.axes[i].accel : std::min(a, l.axes[i].accel);
  }
  return a;
}

double path_accel(const MachineLimits& l, Machine m) { return l.tangential_share * smallest_accel(l, m); }

double normal_accel(const MachineLimits& l, Machine m) {
  const double a = smallest_accel(l, m), t = path_accel(l, m);
  return std::sqrt(a * a - t * t);
}

}  // namespace dda::speed
