// SPDX-License-Identifier: Apache-2.0
#include "host/report/feed_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "host/driver/feed.hpp"

namespace dda {

namespace {

// The feed error of a scheme that runs at `rate` iterations per second chosen for the
// mean speed: the speed is off by speed / mean - 1, worst of both ends, in percent.
double error_percent(double lo, double mean, double hi) {
  if (mean <= 0) return 0;
  return 100.0 * std::max(hi / mean - 1.0, 1.0 - lo / mean);
}

}  // namespace

void write_feed_report(std::ostream& os, const Plan& plan, bool summary, const std::string& label) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0, sum = 0, path = 0, worst_piece_err = 0;
  double worst_ripple = 1;
  std::uint64_t iters = 0;
  if (!summary) {
    os << "| piece | iterations | path (steps) | speed per iteration: min / mean / max (steps) | ripple (max/min) | "
          "feed "
          "error at the piece's own increment |\n|---|---|---|---|---|---|\n";
  }
  for (std::size_t i = 0; i < plan.pieces.size(); ++i) {
    const feed::PieceMotion m = feed::piece_motion(plan.pieces[i].cmd);
    if (m.iterations == 0) continue;
    // A piece's own increment sets its mean speed to the feed (feed_increment: its path
    // over its iterations is this mean).
    const double mean = m.speed_mean;
    const double ripple = m.speed_min > 0 ? m.speed_max / m.speed_min : std::numeric_limits<double>::infinity();
    const double err = error_percent(m.speed_min, mean, m.speed_max);
    lo = std::min(lo, m.speed_min);
    hi = std::max(hi, m.speed_max);
    sum += m.speed_mean * double(m.iterations);
    path += m.path;
    iters += m.iterations;
    worst_ripple = std::max(worst_ripple, ripple);
    worst_piece_err = std::max(worst_piece_err, err);
    if (!summary) {
      os << fmt::format("| {} | {} | {:.1f} | {:.4f} / {:.4f} / {:.4f} | {:.3f} | {:.1f}% |\n", i + 1, m.iterations,
                        m.path, m.speed_min, mean, m.speed_max, ripple, err);
    }
  }
  const double mean = iters ? sum / double(iters) : 0;
  const double arc_err = error_percent(lo, mean, hi);
  if (summary) {
    os << fmt::format("| {} | {} | {} | {:.0f} | {:.4f} / {:.4f} / {:.4f} | {:.3f} | {:.1f}% | {:.1f}% |\n", label,
                      plan.pieces.size(), iters, path, lo, mean, hi, worst_ripple, worst_piece_err, arc_err);
  } else {
    os << fmt::format(
        "| arc | {} | {:.1f} | {:.4f} / {:.4f} / {:.4f} | {:.3f} | {:.1f}% (one increment for the arc) |\n", iters,
        path, lo, mean, hi, hi / lo, arc_err);
  }
}

}  // namespace dda
