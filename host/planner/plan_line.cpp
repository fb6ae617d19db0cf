// SPDX-License-Identifier: Apache-2.0
// Straight lines through the same core: Bresenham's line (half preload) cut into pieces
// the counters hold, and plan_line() for `--line`.
#include <algorithm>
#include <cstdlib>
#include <utility>

#include "host/planner/plan_detail.hpp"
#include "model/datapath/hw_params.hpp"

namespace dda {

using namespace detail;

std::vector<Piece> line_pieces(Point from, Point to, Preload preload) {
  const std::int64_t dx = to.x - from.x, dy = to.y - from.y, dz = to.z - from.z;
  const std::int64_t ax = std::llabs(dx), ay = std::llabs(dy), az = std::llabs(dz);
  const std::int64_t m = std::max({ax, ay, az});
  // Every axis adds its extent to an accumulator of capacity m, the longest extent: the
  // longest axis steps on every iteration (Bresenham's line in three axes, the third
  // axis on the core's linear integrator with the same capacity).
  const std::int64_t cap = m, jr0 = preload == Preload::Half ? cap / 2 : 0;
  // An axis' steps after k iterations: floor((jr0 + k extent) / cap), its accumulator's
  // carries; a piece starting at k0 takes the remainder as its preload.
  const auto carries = [&](std::int64_t k, std::int64_t e) { return std::int64_t((i128(jr0) + i128(k) * e) / cap); };
  const auto rest = [&](std::int64_t k, std::int64_t e) { return std::int64_t((i128(jr0) + i128(k) * e) % cap); };
  const auto at = [&](std::int64_t k) {
    return Point{from.x + (dx < 0 ? -1 : 1) * carries(k, ax), from.y + (dy < 0 ? -1 : 1) * carries(k, ay),
                 from.z + (dz < 0 ? -1 : 1) * carries(k, az)};
  };
  std::vector<Piece> v;
  const std::int64_t chunk = std::int64_t(hw::kCntMax);
  for (std::int64_t k0 = 0; k0 < m; k0 += chunk) {
    const std::int64_t k1 = std::min(m, k0 + chunk);
    Piece pc;
    pc.kind = PieceKind::Line;
    pc.from = at(k0);
    pc.to = at(k1);
    Command& c = pc.cmd;
    c.cap = cap;
    c.jv_x = ax;
    c.jv_y = ay;
    c.jr_x = rest(k0, ax);
    c.jr_y = rest(k0, ay);
    c.cnt_x = std::llabs(pc.to.x - pc.from.x);
    c.cnt_y = std::llabs(pc.to.y - pc.from.y);
    c.dir_x_neg = dx < 0;
    c.dir_y_neg = dy < 0;
    if (az != 0) {
      c.cap_z = cap;
      c.jv_z = az;
      c.jr_z = rest(k0, az);
      c.cnt_z = std::llabs(pc.to.z - pc.from.z);
      c.dir_z_neg = dz < 0;
    }
    pc.iteration_bound = std::uint64_t(k1 - k0) + 1;  // the longest axis steps every iteration
    pc.quadrant = dx >= 0 ? (dy >= 0 ? 1 : 4) : (dy >= 0 ? 2 : 3);
    v.push_back(pc);
  }
  return v;
}

Plan plan_line(Point from, Point to, Preload preload) {
  const std::int64_t lim = std::int64_t{1} << 40;
  for (const auto& [name, q] : {std::pair{"from", from}, std::pair{"to", to}}) {
    if (q.x < -lim || q.x > lim || q.y < -lim || q.y > lim || q.z < -lim || q.z > lim) {
      throw InputError(std::string(name) + " point " + pt(q) + " is out of range: coordinates must be within 2^40");
    }
  }
  if (from == to) {
    throw InputError("line from " + pt(from) + " to " + pt(to) + " has length 0: a line needs two different points");
  }
  const std::int64_t len = std::max({std::llabs(to.x - from.x), std::llabs(to.y - from.y), std::llabs(to.z - from.z)});
  if (len > kMaxLineSteps) {
    throw InputError("line from " + pt(from) + " to " + pt(to) + " is " + std::to_string(len) +
                     " steps long: at most 2^30 steps on its longer axis (cut it into several lines)");
  }
  Plan p;
  p.geometry = LineGeometry{preload};
  p.from = from;
  p.to = to;
  p.pieces = line_pieces(from, to, preload);
  for (const auto& pc : p.pieces) p.iteration_bound += pc.iteration_bound;
  // No run to check reachability: a line's pieces end on their points by construction
  // (one iteration per step of the longer axis; tested against the runner).
  return p;
}

}  // namespace dda
