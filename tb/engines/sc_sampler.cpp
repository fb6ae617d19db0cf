// SPDX-License-Identifier: Apache-2.0
#include "tb/engines/sc_sampler.hpp"

#include <systemc>

namespace dda::sc {

namespace {

template <typename T>
bool try_bind(sc_core::sc_object* o, int width, std::function<std::uint64_t()>& out, int& found_width) {
  auto* s = dynamic_cast<sc_core::sc_signal_in_if<T>*>(o);
  if (!s) return false;
  if constexpr (std::is_same_v<T, bool>) {
    found_width = 1;
    out = [s] { return std::uint64_t(s->read()); };
  } else {
    found_width = T().length();
    out = [s] { return std::uint64_t(s->read().to_uint64()); };
  }
  return found_width == width;
}

}  // namespace

ScSampler::ScSampler(const std::string& core, const hw::SignalTable& table) {
  for (const auto& r : table) {
    const std::string full = core + "." + std::string(r.name);
    sc_core::sc_object* o = sc_core::sc_find_object(full.c_str());
    if (!o) throw GuardError("register table: the SystemC model has no signal " + std::string(r.name));
    std::function<std::uint64_t()> f;
    int w = 0;
    const bool ok = try_bind<bool>(o, r.width, f, w) || try_bind<sc_dt::sc_uint<hw::kAccWidth>>(o, r.width, f, w) ||
                    try_bind<sc_dt::sc_uint<hw::kAccWidth + 1>>(o, r.width, f, w) ||
                    try_bind<sc_dt::sc_uint<hw::kCntWidth>>(o, r.width, f, w) ||
                    try_bind<sc_dt::sc_uint<hw::kStateWidth>>(o, r.width, f, w);
    if (!ok) {
      throw GuardError("register table: the SystemC model's " + std::string(r.name) + " is " +
                       (w ? std::to_string(w) + " bits wide" : std::string("of an unknown type")) +
                       ", the table says " + std::to_string(r.width));
    }
    readers_.push_back(std::move(f));
  }
}

Signals ScSampler::read() const {
  Signals s{};
  for (std::size_t i = 0; i < s.size() && i < readers_.size(); ++i) s[i] = readers_[i]();
  return s;
}

}  // namespace dda::sc
