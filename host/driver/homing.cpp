// SPDX-License-Identifier: Apache-2.0
#include "host/driver/homing.hpp"

#include <cmath>
#include <string>

#include "host/driver/feed.hpp"
#include "host/planner/planner.hpp"
#include "model/datapath/errors.hpp"
#include "model/motion/pacer.hpp"

namespace dda::motion {

namespace {

std::string upper(char axis) { return std::string(1, char(axis - 'a' + 'A')); }

bool input_on(MotionDriver& d, std::string_view name) { return ((d.read("INPUTS") >> input_bit(name)) & 1u) != 0; }

// Polls until TRIP shows `name` (true) or the block rests without it (false).
bool wait_trip(MotionDriver& d, std::string_view name) {
  const std::uint32_t want = 1u << input_bit(name);
  for (;;) {
    const std::uint32_t trip = d.read("TRIP");
    if (trip & ~want) {
      throw GuardError("motion driver: the move stopped on another input (TRIP 0x" + std::to_string(trip) + ")");
    }
    if (trip & want) {
      d.wait_rest();
      return true;
    }
    const std::uint32_t st = d.read("STATUS");
    if (get_field("STATUS", "empty", st) && !get_field("STATUS", "busy", st)) return (d.read("TRIP") & want) != 0;
  }
}

Point along(char axis, std::int64_t steps) {
  Point p;
  (axis == 'x' ? p.x : axis == 'y' ? p.y : p.z) = steps;
  return p;
}

}  // namespace

void queue_move(MotionDriver& d, Point delta, std::uint32_t speed) {
  if (speed == 0) throw GuardError("motion driver: a move needs a cruise speed");
  const Plan plan = plan_line(Point{}, delta, Preload::Half);
  if (!d.pacer()) {  // each piece at its feed increment for the speed (steps per clock: a clock of 1 Hz)
    const double per_clock = std::ldexp(double(speed), -kSpeedFrac);
    for (const auto& piece : plan.pieces)
      d.queue(piece.cmd, feed::feed_increment(feed::piece_motion(piece.cmd), per_clock, 1.0), piece.rot);
    return;
  }
  std::vector<Command> cmds;
  for (const auto& piece : plan.pieces) cmds.push_back(piece.cmd);
  const std::vector<PaceEntry> pace = pace_entries(cmds, speed, d.read("VMIN"), d.read("ACCEL"));
  for (std::size_t i = 0; i < plan.pieces.size(); ++i) d.queue(plan.pieces[i].cmd, 0, plan.pieces[i].rot, pace[i]);
}

HomingResult home_axis(MotionDriver& d, const HomingParams& p) {
  if (p.axis < 'x' || p.axis > 'z') throw GuardError("homing: no axis " + std::string(1, p.axis));
  if (p.search_steps <= 0 || p.backoff_steps <= 0 || p.search_speed == 0 || p.latch_speed == 0)
    throw GuardError("homing: the search, the back-off and both speeds must be positive");
  const std::string home = std::string("home_") + p.axis, pos = "POS_" + upper(p.axis);
  const std::string latch = "LATCH_" + upper(p.axis);
  const std::int64_t toward = p.positive ? 1 : -1;
  const std::uint32_t mode = d.read("IN_MODE");
  d.wait_rest();
  if (input_on(d, home)) {  // on the switch already: off it first
    queue_move(d, along(p.axis, -toward * p.backoff_steps), p.search_speed);
    d.wait_rest();
    if (input_on(d, home)) throw GuardError("homing: still on the " + upper(p.axis) + " home switch after backing off");
  }
  d.write("IN_MODE", mode | field_bit("IN_MODE", home));
  d.clear();
  HomingResult r;
  queue_move(d, along(p.axis, toward * p.search_steps), p.search_speed);
  if (!wait_trip(d, home)) throw GuardError("homing: no " + upper(p.axis) + " home switch within the search");
  r.first_latch = std::int32_t(d.read(latch));
  d.clear();
  // Back off to backoff_steps from the first latch, off the switch.
  const std::int64_t here = std::int32_t(d.read(pos));
  queue_move(d, along(p.axis, r.first_latch - toward * p.backoff_steps - here), p.search_speed);
  d.wait_rest();
  if (input_on(d, home)) throw GuardError("homing: still on the " + upper(p.axis) + " home switch after backing off");
  d.clear();
  queue_move(d, along(p.axis, toward * 2 * p.backoff_steps), p.latch_speed);
  if (!wait_trip(d, home)) throw GuardError("homing: no " + upper(p.axis) + " home switch on the approach");
  r.second_latch = std::int32_t(d.read(latch));
  // At rest, no step on its way: a preset moves the axis' whole frame, exactly.
  const std::int32_t now = std::int32_t(d.read(pos));
  r.shift = p.home_position - r.second_latch;
  d.write(pos, std::uint32_t(now + r.shift));
  d.write("IN_MODE", mode);
  d.clear();
  return r;
}

Point probe_move(MotionDriver& d, Point delta, std::uint32_t speed) {
  const std::uint32_t mode = d.read("IN_MODE");
  d.wait_rest();
  d.write("IN_MODE", mode | field_bit("IN_MODE", "probe_stop"));
  d.arm_probe();
  queue_move(d, delta, speed);
  for (;;) {
    const std::uint32_t st = d.read("STATUS");
    if (get_field("STATUS", "probed", st)) break;
    if (get_field("STATUS", "empty", st) && !get_field("STATUS", "busy", st)) {
      if (get_field("STATUS", "probed", d.read("STATUS"))) break;
      d.write("IN_MODE", mode);
      throw GuardError("probing: no contact over the whole move");
    }
  }
  d.wait_rest();
  d.write("IN_MODE", mode);
  d.clear();  // (the soft stop's flush set STATUS.aborted)
  return d.positions("PROBE");
}

}  // namespace dda::motion
