// SPDX-License-Identifier: Apache-2.0
// The speed plan of a part program (dda stats --program --speeds): one row per block as
// the lookahead passes it (its length, the feed asked, its entry, cruise and exit
// speeds in mm/min, its time (ramps and cruise) and the dwell before it, whether it
// starts at rest, what limit held it below the feed), then the totals (the time with
// every dwell); text (no dwell column), CSV or JSON.
#pragma once

#include <ostream>
#include <string>

#include "host/report/program_report.hpp"
#include "host/speed/speed_run.hpp"

namespace dda::speed {

class SpeedReport {
 public:
  SpeedReport(std::ostream& os, program::BlockStatsFormat fmt, const MachineLimits& lim, program::Machine m);
  void block(const BlockSpeeds& b);
  void finish(const SpeedTotals& t);

 private:
  void header();
  std::ostream& os_;
  program::BlockStatsFormat fmt_;
  MachineLimits lim_;
  program::Machine machine_;
  bool started_ = false;
  std::size_t rows_ = 0;
};

}  // namespace dda::speed
