// SPDX-License-Identifier: Apache-2.0
#include "tb/random/dda_random.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "model/datapath/hw_command.hpp"

namespace dda {

ArcSpec paper_example() {
  ArcSpec s;
  s.a = 10;
  s.b = 6;
  s.bits = 4;
  s.preload = Preload::Zero;
  return s;
}

std::uint64_t test_seed(std::uint64_t default_seed) {
  if (const char* s = std::getenv("DDA_SEED"); s && *s) return std::strtoull(s, nullptr, 0);
  return default_seed;
}

std::uint64_t case_seed(std::uint64_t seed, std::uint64_t index) {
  // SplitMix64 of the pair: well mixed, and independent of how the cases are sharded.
  std::uint64_t z = seed * 0x9e3779b97f4a7c15ULL + index + 0x632be59bd9b4e019ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  const auto bad = [&] { return std::invalid_argument("shard '" + text + "' is invalid: use I/N with 0 <= I < N"); };
  if (slash == std::string::npos) throw bad();
  char* end = nullptr;
  const std::string i = text.substr(0, slash), n = text.substr(slash + 1);
  Shard s;
  s.index = std::strtoull(i.c_str(), &end, 10);
  if (i.empty() || *end != '\0') throw bad();
  s.count = std::strtoull(n.c_str(), &end, 10);
  if (n.empty() || *end != '\0' || s.count == 0 || s.index >= s.count) throw bad();
  return s;
}

// The widths bound every draw: the largest semi-axis whose capacity fits AccWidth at the
// widest n drawn (program arcs use the default n, smallest + 4) and whose steps fit
// CntWidth (hw::max_semi_axis). At the default widths that is 16384 (+8) and 32768 (+4),
// above what the tests ask for; a build at smaller widths draws smaller ellipses.
RandomArcs::RandomArcs(std::uint64_t seed, std::int64_t max_axis, int extra_bits_max, ArcKind kind)
    : rng_(seed),
      max_axis_(std::min(max_axis, hw::max_semi_axis(kind == ArcKind::Program ? 4 : extra_bits_max))),
      extra_bits_max_(extra_bits_max),
      kind_(kind) {}

namespace {

// The dda options of a drawn configuration (before the planner resolves it).
std::string options_of(const ArcSpec& s) {
  std::ostringstream o;
  o << "--a " << s.a << " --b " << s.b;
  if (s.bits != 0) o << " --bits " << s.bits;
  o << " --preload " << to_string(s.preload) << " --center " << s.center.x << ',' << s.center.y << " --angle "
    << format_degrees(s.angle) << " --dir " << to_string(s.dir);
  if (s.from) o << " --from " << s.from->x << ',' << s.from->y;
  if (s.to) o << " --to " << s.to->x << ',' << s.to->y;
  if (s.from_theta) o << " --from-theta " << format_degrees(*s.from_theta);
  if (s.to_theta) o << " --to-theta " << format_degrees(*s.to_theta);
  return o.str();
}

}  // namespace

std::optional<Plan> RandomArcs::next_program() {
  const auto uni = [&](std::uint64_t n) { return rng_() % n; };
  const auto log_axis = [&]() {
    const double u = double(uni(1u << 30)) / double(1u << 30);
    const double v = std::exp(u * std::log(double(max_axis_)));
    return std::max<std::int64_t>(1, std::min<std::int64_t>(max_axis_, std::int64_t(v + 0.5)));
  };
  const Preload pre = uni(2) ? Preload::Half : Preload::Zero;
  const Point center{std::int64_t(uni(2001)) - 1000, std::int64_t(uni(2001)) - 1000};
  try {
    if (uni(8) == 0) {  // a line of any length up to the largest axis, any direction
      drawn_ = Drawn::Line;
      const std::int64_t m = log_axis();
      Point to{center.x + std::int64_t(uni(std::uint64_t(2 * m + 1))) - m,
               center.y + std::int64_t(uni(std::uint64_t(2 * m + 1))) - m};
      if (to == center) to.x += 1;
      drawn_options_ = "--line --from " + std::to_string(center.x) + "," + std::to_string(center.y) + " --to " +
                       std::to_string(to.x) + "," + std::to_string(to.y) + " --preload " + to_string(pre);
      return plan_line(center, to, pre);
    }
    ArcSpec s;
    s.a = log_axis();
    s.b = log_axis();
    while (std::max(s.a, s.b) > 1000 * std::min(s.a, s.b)) {  // aspect ratio at most 1000
      (s.a > s.b ? s.b : s.a) *= 2;
    }
    s.preload = pre;
    s.center = center;
    s.dir = uni(2) ? Direction::Cw : Direction::Ccw;
    const bool rotated = uni(2) != 0;
    s.angle = rotated ? std::int64_t(uni(std::uint64_t(kFullTurn))) : kQuarterTurn * std::int64_t(uni(4));
    if (rotated && s.angle % kQuarterTurn == 0) s.angle += 1;
    drawn_ = rotated ? Drawn::Rotated : Drawn::AxisAligned;
    drawn_thin_ = std::max(s.a, s.b) > 4 * std::min(s.a, s.b);
    // Start and end: lattice points rounded from random points of the curve (the
    // nearest lattice point to the fixed-point curve point); one in eight a full turn by
    // point, one in eight a full turn by angle.
    const auto theta = [&]() { return std::int64_t(uni(std::uint64_t(kFullTurn))); };
    const auto rounded = [&](std::int64_t t) {
      const FixedPoint f = theta_ideal(s, t);
      const auto r = [](std::int64_t v) {
        const std::int64_t half = std::int64_t{1} << (kPosFrac - 1);
        return v < 0 ? -((-v + half) >> kPosFrac) : (v + half) >> kPosFrac;
      };
      return Point{s.center.x + r(f.x), s.center.y + r(f.y)};
    };
    const unsigned shape = unsigned(uni(8));
    if (shape == 0) {
      s.from_theta = s.to_theta = theta();
    } else {
      s.from = rounded(theta());
      s.to = shape == 1 ? *s.from : rounded(theta());
    }
    drawn_options_ = options_of(s);
    return plan_arc(s);
  } catch (const InputError& e) {
    ++rejected_;
    last_refusal_ = e.what();
    return std::nullopt;
  }
}

std::optional<Plan> RandomArcs::next_spatial() {
  const auto uni = [&](std::uint64_t n) { return rng_() % n; };
  const auto span = [&](std::int64_t m) { return std::int64_t(uni(std::uint64_t(2 * m + 1))) - m; };
  const Preload pre = uni(2) ? Preload::Half : Preload::Zero;
  const Point from{span(1000), span(1000), span(1000)};
  const unsigned what = unsigned(uni(4));
  try {
    if (what <= 1) {  // a 3-D line (what 0) or a move of the third axis alone (what 1)
      drawn_ = Drawn::Line;
      const std::int64_t m = 1 + std::int64_t(uni(std::uint64_t(max_axis_)));
      Point to{from.x, from.y, from.z + span(m)};
      if (what == 0) to.x += span(m), to.y += span(m);
      if (to.z == from.z) to.z += 1;
      drawn_options_ = "--line --from " + std::to_string(from.x) + "," + std::to_string(from.y) + "," +
                       std::to_string(from.z) + " --to " + std::to_string(to.x) + "," + std::to_string(to.y) + "," +
                       std::to_string(to.z) + " --preload " + to_string(pre);
      return plan_line(from, to, pre);
    }
    Plan arc;
    for (;;) {
      std::optional<Plan> drawn = next_program();
      if (drawn && !drawn->is_line()) {
        arc = std::move(*drawn);
        break;
      }
    }
    // A rise of either sign up to the path's iterations (about twice its steps): halved
    // until the third axis can follow it.
    std::uint64_t steps = 0;
    for (const Piece& pc : arc.pieces) steps += std::uint64_t(pc.cmd.cnt_x + pc.cmd.cnt_y);
    std::int64_t rise = span(std::int64_t(std::max<std::uint64_t>(steps, 1)));
    for (;;) {
      try {
        lift(arc, from.z, from.z + rise, arc.preload());
        break;
      } catch (const InputError&) {
        rise /= 2;
      }
    }
    drawn_options_ += " (a helix rising " + std::to_string(rise) + " from z " + std::to_string(from.z) + ")";
    return arc;
  } catch (const InputError& e) {
    ++rejected_;
    last_refusal_ = e.what();
    return std::nullopt;
  }
}

std::optional<Plan> RandomArcs::next() {
  if (kind_ == ArcKind::Program) return next_program();
  if (kind_ == ArcKind::Spatial) return next_spatial();
  // Floating point only shapes the draw (axis lengths, angles); what is drawn is an exact
  // integer configuration and describe() prints it, so a failure is reproducible from its
  // printed options even where another libm would round a draw differently.
  const auto uni = [&](std::uint64_t n) { return rng_() % n; };  // n << 2^64: bias negligible
  const auto log_axis = [&]() {
    const double u = double(uni(1u << 30)) / double(1u << 30);
    const double v = std::exp(u * std::log(double(max_axis_)));
    return std::max<std::int64_t>(1, std::min<std::int64_t>(max_axis_, std::int64_t(v + 0.5)));
  };
  ArcSpec s;
  s.a = log_axis();
  s.b = log_axis();
  s.bits = smallest_valid_bits(s.a, s.b) + int(uni(std::uint64_t(extra_bits_max_) + 1));
  s.preload = uni(2) ? Preload::Half : Preload::Zero;
  if (kind_ == ArcKind::Whole) {
    if (uni(16) == 0) s.b = s.a;  // circles
    s.bits = smallest_valid_bits(s.a, s.b) + int(uni(std::uint64_t(extra_bits_max_) + 1));
    s.center = Point{std::int64_t(uni(2001)) - 1000, std::int64_t(uni(2001)) - 1000};
    s.dir = uni(2) ? Direction::Cw : Direction::Ccw;
    // Half the ellipses are turned by a uniform angle (micro-degrees), half by quarter turns.
    s.angle = uni(2) ? std::int64_t(uni(std::uint64_t(kFullTurn))) : kQuarterTurn * std::int64_t(uni(4));
    const auto theta = [&]() { return std::int64_t(uni(std::uint64_t(kFullTurn))); };
    s.from_theta = theta();
    // One in eight is a full turn, one in eight starts on a vertex (parametric 0, 90, 180
    // or 270 degrees), one in eight starts at a lattice point (the DDA follows the curve
    // through it).
    const unsigned shape = unsigned(uni(8));
    if (shape == 1) s.from_theta = kQuarterTurn * std::int64_t(uni(4));
    s.to_theta = shape == 0 ? *s.from_theta : theta();
    if (shape == 2) {
      s.from = theta_point(s, *s.from_theta);
      s.from_theta.reset();
    }
  } else if (uni(8) != 0) {  // one in eight keeps the default quarter arc
    const double kQuarter = std::acos(0.0);
    double t0 = kQuarter * double(uni(1u << 20)) / double(1u << 20);
    double t1 = kQuarter * double(uni(1u << 20)) / double(1u << 20);
    if (t0 > t1) std::swap(t0, t1);
    s.from = Point{std::llround(double(s.a) * std::cos(t0)), std::llround(double(s.b) * std::sin(t0))};
    s.to = Point{std::llround(double(s.a) * std::cos(t1)), std::llround(double(s.b) * std::sin(t1))};
  }
  drawn_options_ = options_of(s);
  try {
    return plan_arc(s);
  } catch (const InputError& e) {
    ++rejected_;
    last_refusal_ = e.what();
    return std::nullopt;
  }
}

}  // namespace dda
