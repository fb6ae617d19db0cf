// SPDX-License-Identifier: Apache-2.0
// Running a part program live on a motion block (`dda run`; docs/programs.md, "Running a
// program live"): the program planned as a stream (host/speed/entry_stream.hpp), the
// block configured from the machine description, its queue kept filled while it runs,
// its watchdog written, the operator's controls applied, a status line, and every stop
// said with its cause and an exit status of its own.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>

#include "host/driver/motion_driver.hpp"
#include "host/pipeline/pipeline.hpp"
#include "host/port/bus_master.hpp"
#include "host/speed/entry_stream.hpp"
#include "host/speed/machine_limits.hpp"

namespace dda::live {

// The exit statuses of `dda run` (README, `dda run --help`): 0, 1 and 2 as every
// subcommand's, one per cause of a stop above them.
enum Exit : int {
  kDone = 0,      // the program ran to its end, every step counted
  kFailure = 1,   // a run-time failure (a guard, an I/O error, the block refusing an entry)
  kBadInput = 2,  // bad usage or input (the program refused before it moved)
  kEstop = 3,     // the E-stop input
  kLimit = 4,     // a limit switch
  kWatchdog = 5,  // the block's watchdog ran out (the host stopped writing)
  kLink = 6,      // the link failed: a bad status byte, a frame count that did not advance
  kOperator = 7,  // the operator stopped the run (soft or hard stop)
};
// The table of them, a line each ("N  meaning"), for --help and the README.
std::string exit_table();

// The port can no longer reach the block at all (the sim port's host that was made to
// die): the run ends there, with what it knew.
class PortGone : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How the run reaches the block: a bus master on it and the block's clock as time.
class Port {
 public:
  virtual ~Port() = default;
  virtual motion::BusMaster& bus() = 0;
  // The block's clocks since the port opened (the machine's time).
  virtual std::uint64_t clocks() const = 0;
  // The host leaves the link idle for this many of the block's clocks.
  virtual void wait(std::uint64_t clocks) = 0;
  // Whether the link shows the block's interrupt, and what it showed last (the SPI
  // status byte's irq bit).
  virtual bool has_irq() const { return false; }
  virtual bool irq() const { return false; }
  // After the run, what the port itself saw of the motion, a line (the sim port: the
  // steps counted at the pins), and whether it agrees with the block's position
  // registers (`pos`, steps).
  virtual std::string pins_report(const Point& pos, bool& agree) const {
    agree = true;
    (void)pos;
    return "";
  }
};

// What the operator asks.
enum class Control { Hold, Resume, OverrideUp, OverrideDown, Override, SoftStop, HardStop };
struct ControlRequest {
  Control what = Control::Hold;
  double percent = 100;  // Control::Override's value
};
// Where the operator's requests come from (a terminal's keys, signals, a control file):
// polled by the run between its accesses, at the machine's time `seconds`.
class Controls {
 public:
  virtual ~Controls() = default;
  virtual std::optional<ControlRequest> poll(double seconds) = 0;
};

struct LiveOptions {
  double status_every = 0;   // s of the machine's time between status lines (0: none)
  bool status_line = false;  // one line rewritten in place (a terminal) rather than lines
  double poll_ms = 1;        // how long the host waits when the queue is full, ms of machine time
  // The plan of the whole program (a first pass), for the progress and the time left.
  std::optional<speed::SpeedTotals> totals;
};

struct LiveResult {
  int exit = kDone;
  std::string message;          // the cause, one line ("" when the program ran to its end)
  Point position;               // the block's position registers at the end, steps
  bool position_known = false;  // read back (not after a link failure)
  double seconds = 0;           // the machine's time
  std::uint64_t entries = 0;
  int plane = 170;  // the run's plane (position_mm)
  int axes = 3;     // the block's (CONFIG.axes)
};

// Runs the program read from `in` on the block behind `port`. Status lines go to
// `status`. Throws ProgramError and InputError when the program or the setup is
// refused before anything moved; once the machine moves, every failure stops it and
// comes back as a result.
LiveResult run_live(std::istream& in, const ProgramRun& run, const speed::MachineLimits& lim, Port& port,
                    Controls& controls, std::ostream& status, const LiveOptions& opt);

// A position of the block's axes (steps) in millimetres on the machine's axes, "X 1.000 Y
// 2.000 Z 0.000 mm": the block's axes are the run's plane's u, v and normal (plane 170,
// 180, 190), a lathe has no Y and its X is a diameter ("X 60.000 (dia.)"), a block of two
// axes has no third.
std::string position_mm(const Point& p, int plane, double step_mm, program::Machine m, int axes);

// The block's setup for a machine at its clock, from the description (LiveSettings):
// the step in nanometres the drives' steps per mm give (InputError when the axes
// disagree or a step is not a whole number of nanometres; `fallback` when none gives
// it), and each register's value.
program::Length live_step(const speed::MachineLimits& lim, program::Machine m, program::Length fallback);

}  // namespace dda::live
