#include "engines.hpp"

#include <utility>

namespace dda::cli {

namespace {

std::vector<Iteration> golden_engine(const Plan& plan, const EngineOptions&) {
  return run_records(plan);
}

constexpr std::pair<const char*, EngineFn> kEngines[] = {
    {"golden", &golden_engine},
};

}  // namespace

EngineFn find_engine(const std::string& name) {
  for (const auto& [n, fn] : kEngines) {
    if (name == n) return fn;
  }
  return nullptr;
}

std::string engine_names() {
  std::string s;
  for (const auto& [n, fn] : kEngines) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

}  // namespace dda::cli
