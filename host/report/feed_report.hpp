// SPDX-License-Identifier: Apache-2.0
// dda feed: what the DDA does to the feed (docs/results.md, "Feed"): at a constant
// increment the core iterates at a constant rate, and its speed along the path per
// iteration is the integrands' length |(jv_x, jv_y)| / cap, which changes along an
// ellipse. Per piece and for the whole arc: that speed's smallest, mean and largest
// value, its ripple (largest / smallest) and the feed error of a constant-feed scheme.
#pragma once

#include <ostream>
#include <string>

#include "host/planner/plan.hpp"

namespace dda {

// One row per piece and a row for the arc (summary: the arc's row only, labelled).
void write_feed_report(std::ostream& os, const Plan& plan, bool summary, const std::string& label);

}  // namespace dda
