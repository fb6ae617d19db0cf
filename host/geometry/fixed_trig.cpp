// SPDX-License-Identifier: Apache-2.0
// Deterministic fixed-point trigonometry (see fixed_trig.hpp).
#include "host/geometry/fixed_trig.hpp"

#include <array>

#include <cctype>
#include <cstdlib>

#include "model/datapath/errors.hpp"

namespace dda {

namespace {

using i128 = __int128;
constexpr int kWork = 60;  // working precision: Q60
// pi * 2^60, rounded to nearest (from 60 exact decimal digits of pi).
constexpr i128 kPiQ60 = i128(3622009729038561421LL);

// sin and cos of x radians in Q60, 0 <= x <= pi/4 (x in Q60). Taylor series; every
// term is rounded down (>> floors) before its division truncates, about 58 bits are kept; the series stops when a term
// is 0 (after about 12 terms at pi/4).
void taylor(i128 x, i128& c, i128& s) {
  const i128 one = i128(1) << kWork;
  const i128 x2 = (x * x) >> kWork;
  i128 ts = x, tc = one;
  s = x;
  c = one;
  for (int k = 1; ts != 0 || tc != 0; ++k) {
    ts = -((ts * x2) >> kWork) / ((2 * k) * (2 * k + 1));
    tc = -((tc * x2) >> kWork) / ((2 * k - 1) * (2 * k));
    s += ts;
    c += tc;
  }
}

// Q60 to Q(kTrigFrac), rounded half up.
std::int64_t to_trig(i128 v) {
  constexpr int sh = kWork - kTrigFrac;
  return static_cast<std::int64_t>((v + (i128(1) << (sh - 1))) >> sh);
}

}  // namespace

std::int64_t normalize_udeg(std::int64_t udeg) {
  const std::int64_t m = udeg % kFullTurn;
  return m < 0 ? m + kFullTurn : m;
}

namespace {

SinCos sincos_uncached(std::int64_t t);

}  // namespace

// The planners ask for the same angles again and again (an ellipse's own angle beside
// every point's, the same 1440 sample angles for every arc): a direct-mapped memo of the
// pure function, per thread, returns the bits the series gives.
SinCos sincos_udeg(std::int64_t udeg) {
  struct Entry {
    std::int64_t t = -1;
    SinCos v;
  };
  constexpr int kBits = 12;
  thread_local std::array<Entry, std::size_t{1} << kBits> memo;
  const std::int64_t t = normalize_udeg(udeg);
  Entry& e = memo[(std::uint64_t(t) * 0x9E3779B97F4A7C15ull) >> (64 - kBits)];
  if (e.t != t) e = Entry{t, sincos_uncached(t)};
  return e.v;
}

namespace {

SinCos sincos_uncached(std::int64_t t) {
  const int quadrant = static_cast<int>(t / kQuarterTurn);
  std::int64_t r = t % kQuarterTurn;  // [0, 90 degrees)
  const bool complement = r > kQuarterTurn / 2;
  if (complement) r = kQuarterTurn - r;  // [0, 45 degrees]
  std::int64_t c = std::int64_t{1} << kTrigFrac, s = 0;
  if (r != 0) {
    // x = r * pi / 180e6 in Q60, rounded to nearest: r * pi_Q60 < 45e6 * 2^62 < 2^88.
    const i128 den = i128(180) * kMicroDeg;
    const i128 x = (i128(r) * kPiQ60 + den / 2) / den;
    i128 cq = 0, sq = 0;
    taylor(x, cq, sq);
    c = to_trig(cq);
    s = to_trig(sq);
  }
  if (complement) std::swap(c, s);
  switch (quadrant) {
    case 1:
      return SinCos{-s, c};
    case 2:
      return SinCos{-c, -s};
    case 3:
      return SinCos{s, -c};
    default:
      return SinCos{c, s};
  }
}

}  // namespace

std::int64_t parse_degrees(const std::string& name, const std::string& text) {
  const auto bad = [&](const std::string& rule) { return InputError(name + " = '" + text + "' is invalid: " + rule); };
  const std::string rule = "an angle in degrees, a decimal with at most 6 decimals and below 10^9";
  std::size_t i = 0;
  bool neg = false;
  if (i < text.size() && (text[i] == '-' || text[i] == '+')) neg = text[i++] == '-';
  std::int64_t whole = 0, frac = 0;
  int int_digits = 0, frac_digits = 0;
  for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i, ++int_digits) {
    whole = whole * 10 + (text[i] - '0');
    if (whole >= 1'000'000'000) throw bad(rule);  // leading zeros are fine
  }
  if (i < text.size() && text[i] == '.') {
    for (++i; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i, ++frac_digits) {
      if (frac_digits >= 6) throw bad(rule);
      frac = frac * 10 + (text[i] - '0');
    }
  }
  if (i != text.size() || int_digits + frac_digits == 0) throw bad(rule);
  for (int k = frac_digits; k < 6; ++k) frac *= 10;
  const std::int64_t v = whole * kMicroDeg + frac;
  return neg ? -v : v;
}

std::string format_degrees(std::int64_t udeg) {
  const bool neg = udeg < 0;
  const std::uint64_t m = neg ? std::uint64_t(-(udeg + 1)) + 1 : std::uint64_t(udeg);
  std::string s = (neg ? "-" : "") + std::to_string(m / kMicroDeg);
  std::uint64_t f = m % kMicroDeg;
  if (f != 0) {
    std::string d = std::to_string(f);
    d.insert(0, 6 - d.size(), '0');
    while (d.back() == '0') d.pop_back();
    s += "." + d;
  }
  return s;
}

}  // namespace dda
