// SPDX-License-Identifier: Apache-2.0
// The reader's error type and the names of its motion kinds and dialects (program.hpp).
#include <fmt/format.h>

#include "host/program/program.hpp"

namespace dda::program {

ProgramError::ProgramError(const std::string& file, std::size_t line, std::size_t column, const std::string& message)
    : InputError(fmt::format("{}:{}:{}: {}", file, line, column, message)), line_(line), column_(column) {}

std::string_view kind_name(MoveKind k) {
  switch (k) {
    case MoveKind::Rapid:
      return "rapid";
    case MoveKind::Line:
      return "line";
    case MoveKind::ArcCw:
      return "arc cw";
    case MoveKind::ArcCcw:
      return "arc ccw";
    case MoveKind::EllipseCw:
      return "ellipse cw";
    case MoveKind::EllipseCcw:
      return "ellipse ccw";
  }
  return "?";
}

std::string_view dialect_name(Dialect d) {
  switch (d) {
    case Dialect::LinuxCnc:
      return "linuxcnc";
    case Dialect::Hnc:
      return "hnc";
    case Dialect::Fanuc:
      return "fanuc";
  }
  return "?";
}

}  // namespace dda::program
