// SPDX-License-Identifier: Apache-2.0
// The live run's words for the user (its exit statuses, a position in millimetres) and
// the lattice step a machine's drives give.
#include <fmt/format.h>

#include <array>
#include <cmath>

#include "host/run/live_run.hpp"
#include "host/speed/segments.hpp"
#include "model/datapath/errors.hpp"

namespace dda::live {

std::string exit_table() {
  return "  0  the program ran to its end, every step counted\n"
         "  1  a run-time failure (an I/O error, a guard, the block refused an entry)\n"
         "  2  bad usage or input (refused before the machine moved)\n"
         "  3  E-stop\n"
         "  4  a limit switch\n"
         "  5  the block's watchdog ran out (the host stopped writing)\n"
         "  6  the link failed (a bad status byte, a frame count that did not advance)\n"
         "  7  the operator stopped the run (soft or hard stop)\n";
}

program::Length live_step(const speed::MachineLimits& lim, program::Machine m, program::Length fallback) {
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  double spm = 0;
  int first = -1;
  for (int a = 0; a < 3; ++a) {
    if (m == program::Machine::Lathe && a == 1) continue;
    const double s = lim.live.axes[std::size_t(a)].steps_per_mm;
    if (s == 0) continue;
    if (first >= 0 && s != spm) {
      throw InputError(fmt::format(
          "machine config: axes.{}.steps_per_mm = {} and axes.{}.steps_per_mm = {} differ: the block runs every "
          "axis on one lattice (one step size); give the drives the same steps per mm (microstepping or gearing)",
          kAxis[first], spm, kAxis[a], s));
    }
    spm = s;
    first = first < 0 ? a : first;
  }
  if (spm == 0) return fallback;
  const double nm = 1e6 / spm;
  if (std::abs(nm - std::round(nm)) > 1e-6 || nm < 1)
    throw InputError(
        fmt::format("machine config: {} steps per mm is a step of {} nm: the lattice takes a whole number "
                    "of nanometres (e.g. 1000, 800, 500, 400, 250, 200 or 100 steps per mm)",
                    spm, nm));
  return program::Length(std::llround(nm));
}

std::string position_mm(const Point& p, int plane, double step_mm, program::Machine machine, int axes) {
  static constexpr const char* kName[] = {"X", "Y", "Z"};
  const std::array<std::size_t, 3> to = speed::machine_axes(plane);
  const std::array<std::int64_t, 3> v{p.x, p.y, p.z};
  std::array<double, 3> m{};
  for (std::size_t a = 0; a < 3; ++a) m[to[a]] = double(v[a]) * step_mm;
  std::string out;
  for (std::size_t a = 0; a < 3; ++a) {
    if (machine == program::Machine::Lathe && a == 1) continue;
    if (axes == 2 && to[2] == a) continue;
    // (A lathe's X as its programs give it: a diameter.)
    const bool dia = machine == program::Machine::Lathe && a == 0;
    out += fmt::format("{}{} {:.3f}{}", out.empty() ? "" : " ", kName[a], dia ? 2 * m[a] : m[a], dia ? " (dia.)" : "");
  }
  return out + " mm";
}

}  // namespace dda::live
