// SPDX-License-Identifier: Apache-2.0
// Rotated ellipses: deterministic trigonometry, pinned fixed-point coefficients, the
// lathe paper's oblique ellipse, and the rules of angles.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "host/accuracy/golden.hpp"

using namespace dda;

namespace {
constexpr std::int64_t kOne = std::int64_t{1} << kTrigFrac;

ArcSpec lathe(Preload preload) {
  ArcSpec s;
  s.a = 25000;
  s.b = 15000;
  s.angle = parse_degrees("angle", "330");
  s.center = Point{-30000, 5000};
  s.from_theta = 60 * kMicroDeg;
  s.to_theta = 136 * kMicroDeg;
  s.preload = preload;
  return s;
}
}  // namespace

TEST_CASE("rotated: sines and cosines are pinned to correctly rounded Q40 values", "[golden][rotated]") {
  // Reference values: 50-digit decimal Taylor series of the exact angle, rounded half up
  // to Q40 (computed outside this project).
  struct Pin {
    const char* deg;
    std::int64_t c, s;
  };
  const Pin pins[] = {{"30", 952205001410, 549755813888},         {"45", 777472127994, 777472127994},
                      {"60", 549755813888, 952205001410},         {"330", 952205001410, -549755813888},
                      {"12.345678", 1074085893542, 235085756499}, {"136", -790922474794, 763784955652}};
  for (const auto& p : pins) {
    INFO(p.deg);
    const SinCos r = sincos_udeg(parse_degrees("angle", p.deg));
    CHECK(r.c == p.c);
    CHECK(r.s == p.s);
  }
  for (int k = -8; k <= 8; ++k) {  // multiples of 90 degrees are exact
    const SinCos r = sincos_udeg(k * kQuarterTurn);
    const int q = ((k % 4) + 4) % 4;
    CHECK(r.c == (q == 0 ? kOne : q == 2 ? -kOne : 0));
    CHECK(r.s == (q == 1 ? kOne : q == 3 ? -kOne : 0));
  }
}

TEST_CASE("rotated: sines and cosines are within one Q40 unit everywhere", "[golden][rotated]") {
  std::mt19937_64 rng(20261122);
  for (int i = 0; i < 20000; ++i) {
    const std::int64_t u = std::int64_t(rng() % std::uint64_t(kFullTurn)) - kFullTurn / 2;
    const long double rad = (long double)u / kMicroDeg * 3.14159265358979323846264338327950288L / 180;
    const SinCos r = sincos_udeg(u);
    INFO("micro-degrees " << u);
    CHECK(std::fabs((long double)r.c - std::ldexp(std::cos(rad), kTrigFrac)) <= 1.0L);
    CHECK(std::fabs((long double)r.s - std::ldexp(std::sin(rad), kTrigFrac)) <= 1.0L);
  }
}

TEST_CASE("rotated: angles parse exactly and print back", "[golden][rotated]") {
  CHECK(parse_degrees("angle", "330") == 330 * kMicroDeg);
  CHECK(parse_degrees("angle", "-30") == -30 * kMicroDeg);
  CHECK(parse_degrees("angle", "+0.000001") == 1);
  CHECK(parse_degrees("angle", "12.5") == 12'500'000);
  CHECK(parse_degrees("angle", ".5") == 500'000);
  for (const char* bad : {"", "-", ".", "1.2345678", "1e3", "12,5", "0x10", "1000000000", " 1"}) {
    INFO(bad);
    CHECK_THROWS_AS(parse_degrees("angle", bad), InputError);
  }
  for (const std::int64_t v : {std::int64_t{0}, std::int64_t{1}, std::int64_t{-1}, std::int64_t{12'500'000},
                               std::int64_t{359'999'999}, std::int64_t{-90'000'000}}) {
    CHECK(parse_degrees("angle", format_degrees(v)) == v);
  }
  CHECK(format_degrees(330 * kMicroDeg) == "330");
  CHECK(format_degrees(-1) == "-0.000001");
}

TEST_CASE("rotated: the lathe example's coefficients are pinned", "[golden][rotated][default-widths]") {
  const Plan p = plan_arc(lathe(Preload::Half));
  REQUIRE(p.arc().rotated);
  REQUIRE(p.arc().spec.bits == 19);  // smallest valid (15) + 4
  // P = cs (a^2 - b^2), Qx = a^2 c^2 + b^2 s^2, Qy = a^2 s^2 + b^2 c^2 times
  // 2^(49 - 19) / (a b), with c = cos 330, s = sin 330 (exactly: P = -sqrt(3)/4 *
  // 4e8, Qx = 5.25e8, Qy = 3.25e8); the pinned integers are those reals rounded, the
  // trigonometry's last-bit rounding does not reach them.
  const long double scale = std::ldexp(1.0L, 30) / (25000.0L * 15000.0L);
  CHECK(std::fabs((long double)p.arc().coef.p - (-std::sqrt(3.0L) / 4 * 4e8L) * scale) <= 0.5L);
  CHECK(std::fabs((long double)p.arc().coef.qx - 5.25e8L * scale) <= 0.5L);
  CHECK(std::fabs((long double)p.arc().coef.qy - 3.25e8L * scale) <= 0.5L);
  CHECK(p.arc().coef.p == -495940105);   // -sqrt(3) 2^30 / 3.75 = -495940104.90
  CHECK(p.arc().coef.qx == 1503238554);  // 1.4 * 2^30 = 1503238553.6
  CHECK(p.arc().coef.qy == 930576247);   // 13/15 * 2^30 = 930576247.47
  CHECK(p.pieces.front().cmd.cap == (std::int64_t{1} << kRotCapBits));
}

TEST_CASE("rotated: the lathe example ends on its end point within a step of the curve",
          "[golden][rotated][default-widths]") {
  for (const Preload pre : {Preload::Zero, Preload::Half}) {
    const Plan p = plan_arc(lathe(pre));
    INFO(to_string(pre));
    double worst = 0;
    Point prev = p.from;
    const RunSummary r = run(p, [&](const Iteration& it) {
      CHECK(std::llabs(it.pos.x - prev.x) <= 1);
      CHECK(std::llabs(it.pos.y - prev.y) <= 1);
      prev = it.pos;
      worst = std::max(worst, plan_distance(p, double(it.pos.x), double(it.pos.y)));
    });
    CHECK(r.end == p.to);
    // The end lies on the ray from the centre through the ideal point of 136 degrees.
    const FixedPoint e = theta_ideal(p.arc().spec, 136 * kMicroDeg);
    const long double ex = std::ldexp((long double)e.x, -kPosFrac), ey = std::ldexp((long double)e.y, -kPosFrac);
    const long double tx = p.to.x - p.arc().spec.center.x, ty = p.to.y - p.arc().spec.center.y;
    CHECK(std::fabs(std::atan2(ty, tx) - std::atan2(ey, ex)) < 1.5L / std::hypot(tx, ty));
    CHECK(worst <= (pre == Preload::Half ? 1.0 : 2.0));
    CHECK(p.pieces.size() >= 2);  // the arc passes the turn where X (the Z axis) reverses
  }
}

TEST_CASE("rotated: half preload starts on the ideal curve point", "[golden][rotated]") {
  const Plan p = plan_arc(lathe(Preload::Half));
  const FixedPoint f = theta_ideal(p.arc().spec, 60 * kMicroDeg);
  CHECK(((p.from.x - p.arc().spec.center.x) << kPosFrac) + p.arc().frac_x == f.x);
  CHECK(((p.from.y - p.arc().spec.center.y) << kPosFrac) + p.arc().frac_y == f.y);
  CHECK(start_offset(p) < 1e-6);
  CHECK(std::llabs(p.arc().frac_x) <= (std::int64_t{1} << (kPosFrac - 1)));
  const Command& c = p.pieces.front().cmd;
  CHECK(c.jr_x != c.cap / 2);  // the fraction is in the preload
}

TEST_CASE("rotated: quarter-turn angles keep the exact integer datapath", "[golden][rotated]") {
  ArcSpec s;
  s.a = 10;
  s.b = 6;
  s.bits = 4;
  s.angle = 360 * kMicroDeg;  // a full turn is no turn
  const Plan p = plan_arc(s);
  CHECK_FALSE(p.arc().rotated);
  CHECK(p.pieces.front().cmd.cap == (std::int64_t{10 * 6} << 4));
  s.angle = 90 * kMicroDeg + 1;  // one micro-degree off: fixed point
  CHECK(plan_arc(s).arc().rotated);
}

TEST_CASE("parametric ends: the span is judged from the ideal start, not the rounded one", "[golden][rotated]") {
  // A start past the end's ray: (100,1), the start of 0.4 and of 0.6 degrees, lies past the ray of
  // 0.5 and before that of 0.59 degrees.
  ArcSpec s;
  s.a = s.b = 100;
  s.preload = Preload::Half;
  s.from_theta = 400'000;  // 0.4 degrees
  s.to_theta = 500'000;
  Plan p = plan_arc(s);
  CHECK(run(p).iterations > 0);
  CHECK(std::llabs(p.to.x - p.from.x) + std::llabs(p.to.y - p.from.y) <= 1);  // a tenth of a degree: one step
  s.from_theta = 600'000;
  s.to_theta = 590'000;  // almost a full turn, not one step
  p = plan_arc(s);
  std::uint64_t moves = 0;
  run(p, [&](const Iteration& it) { moves += it.step_x || it.step_y; });
  CHECK(moves > 700);  // about 8 * 100 steps around a circle of radius 100
  CHECK(plan_distance(p, double(p.to.x), double(p.to.y)) < 1.0);
}

TEST_CASE("reached: lattice ends the counted path cannot reach, and still refused: a start at the centre",
          "[golden][rotated][default-widths]") {
  // Far inside the curve the counted path stalls short of the vertex; the
  // planner ends the arc on the ray through the end's curve point and goes on to the end
  // with a line (zero preload), or starts from the start's nearest curve point after a
  // lead-in line (half preload), so the path starts and ends exactly on the given points.
  ArcSpec s;
  s.a = 2;
  s.b = 6;
  s.bits = 3;
  s.from = Point{1, 2};
  s.to = Point{-1, 6};
  for (const Preload pre : {Preload::Zero, Preload::Half}) {
    s.preload = pre;
    INFO("preload " << to_string(pre));
    const Plan p = plan_arc(s);
    CHECK(p.from == Point{1, 2});
    CHECK(p.to == Point{-1, 6});
    CHECK(run(p).end == Point{-1, 6});
    if (pre == Preload::Zero) {
      CHECK(p.pieces.back().kind == PieceKind::Line);  // the lead-out from the stall
    } else {
      CHECK(p.pieces.front().kind == PieceKind::Line);  // the lead-in to the start's curve point
      CHECK(p.pieces.front().to != p.from);
    }
  }
  ArcSpec c;
  c.a = c.b = 1;
  c.from = Point{0, 0};
  c.to = Point{0, 1};
  CHECK_THROWS_WITH(plan_arc(c), Catch::Contains("is the centre of the ellipse"));
}

TEST_CASE("rotated: tips sharper than the lattice are followed, full turns close within a step",
          "[golden][rotated][default-widths]") {
  // Tips of radius of curvature min(a,b)^2 / max(a,b) at most a quarter step: the planner
  // crosses such tips in short lines and re-anchors on the curve at every turn
  // (docs/golden-model.md, "Rotated ellipses").
  const struct {
    std::int64_t a, b, angle_udeg;
  } cases[] = {{2, 113, 280'613'133},  {100, 4, 30'000'000}, {1000, 1, 33'000'000},
               {7380, 8, 128'716'349}, {3, 23, 242'274'367}, {29097, 56, 100'521'436}};
  for (const auto& c : cases) {
    for (const Preload pre : {Preload::Half, Preload::Zero}) {
      for (const Direction dir : {Direction::Ccw, Direction::Cw}) {
        ArcSpec s;
        s.a = c.a;
        s.b = c.b;
        s.angle = c.angle_udeg;
        s.preload = pre;
        s.dir = dir;
        s.from_theta = s.to_theta = 17 * kMicroDeg;
        INFO("a " << c.a << " b " << c.b << " angle " << format_degrees(c.angle_udeg) << " preload " << to_string(pre)
                  << " dir " << to_string(dir));
        const Plan p = plan_arc(s);
        CHECK(p.arc().full);
        double worst = 0;
        std::uint64_t steps = 0, line_steps = 0;
        Point prev = p.from;
        const RunSummary r = run(p, [&](const Iteration& it) {
          CHECK(std::llabs(it.pos.x - prev.x) <= 1);
          CHECK(std::llabs(it.pos.y - prev.y) <= 1);
          if (it.pos != prev) {
            ++steps;
            line_steps += p.pieces[it.piece].kind == PieceKind::Line;
          }
          prev = it.pos;
          worst = std::max(worst, plan_distance(p, double(it.pos.x), double(it.pos.y)));
        });
        CHECK(r.end == p.from);  // closed
        if (pre == Preload::Half) {
          CHECK(worst <= 1.0);
          // The hardware interpolates the curve: lines only across the tips. An ellipse
          // whose minor semi-axis is 1 lies within a step of its major axis everywhere.
          if (std::min(c.a, c.b) > 1) CHECK(double(line_steps) < 0.2 * double(steps));
        }
      }
    }
  }
}
