// SPDX-License-Identifier: Apache-2.0
// SVG picture of a paced run's speed against the path length (dda plot --speed).
#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "host/speed/pace_plan.hpp"
#include "tb/measure/pace_report.hpp"

namespace dda {

namespace {

// The run's iterations thinned to at most 2 x kBuckets stretches of the path, each with
// its lowest and highest speeds: memory bounded whatever the run's length. The path
// grows monotonically, so a stretch is full once the path leaves it; when there are too
// many, neighbours merge and the width doubles.
constexpr std::size_t kBuckets = 600;
struct Stretch {
  double lo_cmd = 0, hi_cmd = 0, lo_path = 0, hi_path = 0;
  bool used = false;
};
class Profile {
 public:
  void add(double s, double cmd, double path) {
    auto i = std::size_t(s / width_);
    while (i >= 2 * kBuckets) {
      merge();
      i = std::size_t(s / width_);
    }
    if (i >= st_.size()) st_.resize(i + 1);
    Stretch& b = st_[i];
    if (!b.used) b = Stretch{cmd, cmd, path, path, true};
    b.lo_cmd = std::min(b.lo_cmd, cmd);
    b.hi_cmd = std::max(b.hi_cmd, cmd);
    b.lo_path = std::min(b.lo_path, path);
    b.hi_path = std::max(b.hi_path, path);
  }
  // A polyline's points (x = path, y = speed) through each stretch's low and high.
  std::vector<std::pair<double, double>> line(bool commanded) const {
    std::vector<std::pair<double, double>> pts;
    for (std::size_t i = 0; i < st_.size(); ++i) {
      const Stretch& b = st_[i];
      if (!b.used) continue;
      const double x = (double(i) + 0.5) * width_;
      const double lo = commanded ? b.lo_cmd : b.lo_path, hi = commanded ? b.hi_cmd : b.hi_path;
      pts.emplace_back(x, lo);
      if (hi != lo) pts.emplace_back(x, hi);
    }
    return pts;
  }

 private:
  void merge() {
    std::vector<Stretch> m((st_.size() + 1) / 2);
    for (std::size_t i = 0; i < st_.size(); ++i) {
      const Stretch& b = st_[i];
      if (!b.used) continue;
      Stretch& t = m[i / 2];
      if (!t.used) {
        t = b;
        continue;
      }
      t.lo_cmd = std::min(t.lo_cmd, b.lo_cmd);
      t.hi_cmd = std::max(t.hi_cmd, b.hi_cmd);
      t.lo_path = std::min(t.lo_path, b.lo_path);
      t.hi_path = std::max(t.hi_path, b.hi_path);
    }
    st_ = std::move(m);
    width_ *= 2;
  }
  double width_ = 1.0 / 64;  // steps of path per stretch
  std::vector<Stretch> st_;
};

double tick(double span) {
  const double raw = span / 8;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0}) {
    if (raw <= m * mag) return m * mag;
  }
  return 10 * mag;
}

// The plot area: 70..900 x 50..470 px for 0..length steps and 0..top steps/s.
struct Frame {
  double length, top;
  double x(double s) const { return 70 + s / length * 830; }
  double y(double v) const { return 470 - v / top * 420; }
  std::string polyline(const std::vector<std::pair<double, double>>& pts) const {
    std::string out;
    for (const auto& [s, v] : pts) out += fmt::format("{:.1f},{:.1f} ", x(s), y(v));
    return out;
  }
};

void write_frame(std::ostream& os, const Frame& f, const std::string& title,
                 const char* x_label = "path length (steps)", const char* y_label = "speed (steps/s)") {
  fmt::print(os,
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"960\" height=\"620\" viewBox=\"0 0 960 620\" "
             "font-family=\"sans-serif\" font-size=\"12\">\n"
             "<title>{}</title>\n<rect width=\"960\" height=\"620\" fill=\"white\"/>\n"
             "<text x=\"70\" y=\"30\" font-size=\"14\">{}</text>\n",
             title, title);
  const double ts = tick(f.length), tv = tick(f.top);
  for (double s = 0; s <= f.length * 1.0001; s += ts) {
    fmt::print(os,
               "<line x1=\"{0:.1f}\" y1=\"50\" x2=\"{0:.1f}\" y2=\"470\" stroke=\"#eeeeee\"/>"
               "<text x=\"{0:.1f}\" y=\"488\" text-anchor=\"middle\">{1:g}</text>\n",
               f.x(s), s);
  }
  for (double v = 0; v <= f.top * 1.0001; v += tv) {
    fmt::print(os,
               "<line x1=\"70\" y1=\"{0:.1f}\" x2=\"900\" y2=\"{0:.1f}\" stroke=\"#eeeeee\"/>"
               "<text x=\"64\" y=\"{1:.1f}\" text-anchor=\"end\">{2:g}</text>\n",
               f.y(v), f.y(v) + 4, v);
  }
  fmt::print(os,
             "<rect x=\"70\" y=\"50\" width=\"830\" height=\"420\" fill=\"none\" stroke=\"#333333\"/>\n"
             "<text x=\"485\" y=\"512\" text-anchor=\"middle\">{}</text>\n"
             "<text x=\"18\" y=\"260\" text-anchor=\"middle\" transform=\"rotate(-90 18 260)\">{}</text>\n",
             x_label, y_label);
}

// The legend below the plot, in two columns of three.
void legend_item(std::ostream& os, int k, const char* colour, const std::string& text) {
  const int x = k < 3 ? 70 : 500, y = 538 + 18 * (k % 3);
  fmt::print(os,
             "<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"{3}\" stroke-width=\"3\"/>"
             "<text x=\"{4}\" y=\"{5}\">{6}</text>\n",
             x, y, x + 30, colour, x + 36, y + 4, text);
}

}  // namespace

void write_speed_svg(std::ostream& os, const Plan& plan, const PaceOptions& o, const std::string& title) {
  Profile prof;
  PaceHooks h;
  h.row = [&](const PaceRow& r) { prof.add(r.path, r.commanded, r.path_speed); };
  const PaceResult res = pace_plan(plan, o, h);
  const double length = std::max(res.path, 1.0);
  const Frame f{length, 1.15 * std::max(o.feed, res.monitor.peak_speed())};
  write_frame(os, f, title);
  // The limits: the feed, the minimum speed, and the ideal trapezoid (from rest up to the
  // feed at the acceleration, down to the minimum speed at the end).
  std::vector<std::pair<double, double>> ideal;
  for (int k = 0; k <= 1000; ++k) {
    const double s = length * k / 1000;
    const double up = o.accel > 0 ? std::sqrt(2 * o.accel * s) : o.feed;
    const double end = std::min(o.vmin, o.feed);
    const double down = o.accel > 0 ? std::sqrt(end * end + 2 * o.accel * (length - s)) : o.feed;
    ideal.emplace_back(s, std::min({o.feed, up, down}));
  }
  fmt::print(os,
             "<polyline class=\"ideal\" fill=\"none\" stroke=\"#9bd19b\" stroke-width=\"5\" points=\"{0}\"/>\n"
             "<line class=\"feed\" x1=\"70\" y1=\"{1:.1f}\" x2=\"900\" y2=\"{1:.1f}\" stroke=\"#d7191c\" "
             "stroke-dasharray=\"6,4\"/>\n"
             "<line class=\"vmin\" x1=\"70\" y1=\"{2:.1f}\" x2=\"900\" y2=\"{2:.1f}\" stroke=\"#888888\" "
             "stroke-dasharray=\"2,3\"/>\n",
             f.polyline(ideal), f.y(o.feed), f.y(o.vmin));
  fmt::print(os,
             "<polyline class=\"path-speed\" fill=\"none\" stroke=\"#333333\" stroke-width=\"1\" points=\"{}\"/>\n"
             "<polyline class=\"commanded\" fill=\"none\" stroke=\"#2c7bb6\" stroke-width=\"1.5\" points=\"{}\"/>\n",
             f.polyline(prof.line(false)), f.polyline(prof.line(true)));
  // The legend, with the run's figures.
  const auto item = [&](int k, const char* colour, const std::string& text) { legend_item(os, k, colour, text); };
  item(0, "#2c7bb6", "commanded speed (the pacer's v)");
  item(1, "#333333", "path speed (v x the DDA's velocity / d)");
  item(2, "#9bd19b", fmt::format("ideal trapezoid, A = {:g} steps/s^2", o.accel));
  item(3, "#d7191c", fmt::format("feed {:g} steps/s", o.feed));
  item(4, "#888888", fmt::format("minimum speed {:g} steps/s", o.vmin));
  fmt::print(os,
             "<text x=\"536\" y=\"578\">feed error at cruise {:.2e}; time {:.6f} s (ideal {:.6f} s)</text>\n"
             "</svg>\n",
             res.worst_cruise_error, res.seconds(), res.ideal_seconds);
}

PaceResult pace_program(const speed::PlannedProgram& pp, const speed::PaceSetup& setup, const speed::PlannerLimits& pl,
                        const speed::MachineLimits& lim, PaceHooks hooks) {
  speed::check_clock(pp, pl, setup.step_mm, setup.clock_hz);
  const std::vector<motion::PaceEntry> entries = speed::program_entries(pp, setup);
  double top = 0;
  for (const speed::PlannedSegment& p : pp.segments) top = std::max(top, p.peak);
  PaceOptions o;
  o.clock_hz = setup.clock_hz;
  o.feed = top / setup.step_mm;
  o.accel = pl.accel / setup.step_mm;
  o.vmin = std::min(o.feed, lim.min_speed / 60 / setup.step_mm);
  hooks.entries = &entries;
  return pace_plan(pp.plan, o, hooks);
}

PaceResult write_program_speed_svg(std::ostream& os, const speed::PlannedProgram& pp, const speed::PaceSetup& setup,
                                   const speed::PlannerLimits& pl, const speed::MachineLimits& lim,
                                   const std::string& title) {
  const double mm = setup.step_mm;
  Profile prof;
  PaceHooks h;
  h.row = [&](const PaceRow& r) { prof.add(r.path * mm, r.commanded * mm * 60, r.path_speed * mm * 60); };
  const PaceResult res = pace_program(pp, setup, pl, lim, h);
  // The plan: each piece's ramps and cruise; the feed asked and the speed allowed, piece by piece.
  std::vector<std::pair<double, double>> plan, feed, cap;
  double s = 0, top = 0;
  for (const speed::PlannedSegment& g : pp.segments) {
    const double a = pl.accel, len = g.seg.length;
    const double up = (g.peak * g.peak - g.entry * g.entry) / (2 * a),
                 down = (g.peak * g.peak - g.exit * g.exit) / (2 * a);
    // (Ramps at constant acceleration: v = sqrt(v0^2 + 2 a x), drawn through 9 points each.)
    for (int k = 0; k <= 8; ++k) {
      const double x = up * k / 8;
      plan.emplace_back(s + x, std::sqrt(g.entry * g.entry + 2 * a * x) * 60);
    }
    for (int k = 0; k <= 8; ++k) {
      const double x = down * (8 - k) / 8;
      plan.emplace_back(s + len - x, std::sqrt(g.exit * g.exit + 2 * a * x) * 60);
    }
    feed.insert(feed.end(), {{s, g.seg.feed * 60}, {s + len, g.seg.feed * 60}});
    cap.insert(cap.end(), {{s, g.cap * 60}, {s + len, g.cap * 60}});
    top = std::max({top, g.seg.feed * 60, g.cap * 60});
    s += len;
  }
  const Frame f{std::max(s, 1e-3), 1.15 * top};
  write_frame(os, f, title, "path length (mm)", "speed (mm/min)");
  // (A cap far above the feed, a piece the curvature does not hold, is drawn at the top.)
  for (auto& p : cap) p.second = std::min(p.second, 1.1 * top);
  fmt::print(os,
             "<polyline class=\"plan\" fill=\"none\" stroke=\"#9bd19b\" stroke-width=\"5\" points=\"{}\"/>\n"
             "<polyline class=\"feed\" fill=\"none\" stroke=\"#d7191c\" stroke-dasharray=\"6,4\" points=\"{}\"/>\n"
             "<polyline class=\"limit\" fill=\"none\" stroke=\"#fdae61\" stroke-dasharray=\"2,3\" points=\"{}\"/>\n"
             "<polyline class=\"path-speed\" fill=\"none\" stroke=\"#333333\" stroke-width=\"1\" points=\"{}\"/>\n"
             "<polyline class=\"commanded\" fill=\"none\" stroke=\"#2c7bb6\" stroke-width=\"1.5\" points=\"{}\"/>\n",
             f.polyline(plan), f.polyline(feed), f.polyline(cap), f.polyline(prof.line(false)),
             f.polyline(prof.line(true)));
  legend_item(os, 0, "#2c7bb6", "commanded speed (the pacer's v)");
  legend_item(os, 1, "#333333", "path speed (v x the DDA's velocity / d)");
  legend_item(os, 2, "#9bd19b", fmt::format("plan, ramps at {:g} mm/s^2", pl.accel));
  legend_item(os, 3, "#d7191c", "programmed feed (rapid rate on G00)");
  legend_item(os, 4, "#fdae61", "speed allowed: axes' vmax, curvature");
  fmt::print(os, "<text x=\"536\" y=\"578\">{} pieces; pacer {:.4f} s, plan {:.4f} s</text>\n</svg>\n",
             pp.segments.size(), res.seconds(), pp.totals.time - pp.totals.dwell);
  return res;
}

}  // namespace dda
