// SPDX-License-Identifier: Apache-2.0
#include "tb/engines/vl_sampler.hpp"

#include <verilated.h>
#include <verilated_syms.h>

#include <cstring>

namespace dda::rtl {

VlSampler::VlSampler(const VerilatedContext& ctx, const std::string& top, const hw::SignalTable& table) {
  for (const auto& r : table) {
    const std::string name(r.name);
    const auto dot = name.rfind('.');
    const std::string scope = dot == std::string::npos ? top : top + "." + name.substr(0, dot);
    const std::string var = dot == std::string::npos ? name : name.substr(dot + 1);
    const VerilatedScope* s = ctx.scopeFind(scope.c_str());
    VerilatedVar* v = s ? s->varFind(var.c_str()) : nullptr;
    if (!v) throw GuardError("register table: the RTL has no public signal " + name + " (scope " + scope + ")");
    const int width = v->dims() == 0 ? 1 : v->packed().elements();
    if (width != r.width) {
      throw GuardError("register table: the RTL's " + name + " is " + std::to_string(width) +
                       " bits wide, the table says " + std::to_string(r.width));
    }
    int bytes = 0;
    switch (v->vltype()) {
      case VLVT_UINT8:
        bytes = 1;
        break;
      case VLVT_UINT16:
        bytes = 2;
        break;
      case VLVT_UINT32:
        bytes = 4;
        break;
      case VLVT_UINT64:
        bytes = 8;
        break;
      default:
        throw GuardError("register table: the RTL's " + name + " is wider than 64 bits");
    }
    vars_.push_back(Var{v->datap(), bytes});
  }
}

Signals VlSampler::read() const {
  Signals s{};
  for (std::size_t i = 0; i < s.size() && i < vars_.size(); ++i) {
    std::uint64_t v = 0;
    switch (vars_[i].bytes) {
      case 1:
        v = *static_cast<const std::uint8_t*>(vars_[i].p);
        break;
      case 2:
        v = *static_cast<const std::uint16_t*>(vars_[i].p);
        break;
      case 4:
        v = *static_cast<const std::uint32_t*>(vars_[i].p);
        break;
      default:
        v = *static_cast<const std::uint64_t*>(vars_[i].p);
        break;
    }
    s[i] = v;
  }
  return s;
}

}  // namespace dda::rtl
