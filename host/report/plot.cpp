// SPDX-License-Identifier: Apache-2.0
// SVG picture of a path over its ideal ellipse (dda plot).
#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "host/report/report.hpp"

namespace dda {

namespace {

// Colour of a distance on a 0..scale ramp: blue, cyan, green, yellow, red.
std::string ramp(double t) {
  t = std::clamp(t, 0.0, 1.0);
  static const double stops[5][3] = {{49, 54, 149}, {69, 167, 207}, {102, 189, 99}, {253, 216, 53}, {215, 25, 28}};
  const double x = t * 4.0;
  const int i = std::min(3, int(x));
  const double f = x - i;
  int c[3];
  for (int k = 0; k < 3; ++k) c[k] = int(std::lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k])));
  return fmt::format("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]);
}

// A "nice" tick step for a span.
double tick_step(double span, int target) {
  const double raw = span / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    if (raw <= m * mag) return m * mag;
  }
  return 10 * mag;
}

}  // namespace

void PathSample::add(Point p, double dist, bool keep) {
  const std::uint64_t seq = seen_++;
  const Kept k{seq, p, dist, keep && marked_ < budget_ / 4};
  if (!have_worst_ || dist > worst_.dist) worst_ = k, have_worst_ = true;
  if (seq % stride_ != 0 && !k.keep) return;
  marked_ += k.keep;
  kept_.push_back(k);
  if (kept_.size() >= budget_) thin();
}

// Every other sampled point goes (marked ones stay): the stride doubles.
void PathSample::thin() {
  stride_ *= 2;
  std::size_t n = 0;
  for (const Kept& k : kept_) {
    if (k.keep || k.seq % stride_ == 0) kept_[n++] = k;
  }
  kept_.resize(n);
}

void PathSample::take(std::vector<Point>& pts, std::vector<double>& dist) {
  // The farthest point in its place, if the stride left it out.
  if (have_worst_) {
    const auto at = std::lower_bound(kept_.begin(), kept_.end(), worst_.seq,
                                     [](const Kept& k, std::uint64_t seq) { return k.seq < seq; });
    if (at == kept_.end() || at->seq != worst_.seq) kept_.insert(at, worst_);
  }
  for (const Kept& k : kept_) {
    pts.push_back(k.p);
    dist.push_back(k.dist);
  }
  kept_.clear();
}

SvgSink::SvgSink(std::ostream& os, const Plan& plan, std::string title, View view)
    : os_(os), plan_(plan), title_(std::move(title)), view_(view) {
  sample_.add(project(plan.from, view), plan_distance(plan, double(plan.from.x), double(plan.from.y)));
}

void SvgSink::record(const Iteration& it) {
  // (The plane's view takes the plane's points; the others every step of any axis.)
  if (it.step_x || it.step_y || (view_ != View::XY && it.step_z)) {
    sample_.add(project(it.pos, view_), plan_distance(plan_, double(it.pos.x), double(it.pos.y)));
  }
}

void SvgSink::finish() {
  const Plan& plan = plan_;
  SvgPicture pic;
  if (sample_.stride() > 1) pic.sampled_from = sample_.seen(), pic.sample_stride = sample_.stride();
  sample_.take(pic.pts, pic.dist);
  pic.title = title_;
  pic.curve = "the ellipse";
  pic.projection = view_;
  // The ideal curve: the whole ellipse, sampled finely (a line: the line between its
  // ends); in the other views projected, the third axis along it from its start to its end.
  if (plan.is_line()) {
    const Point a = project(plan.from, view_), b = project(plan.to, view_);
    pic.ideal.push_back({{double(a.x), double(a.y)}, {double(b.x), double(b.y)}});
  } else {
    const ArcSpec& spec = plan.arc().spec;
    const EllipseDrawing e{center_x(spec), center_y(spec), a_steps(spec), b_steps(spec), spec.angle};
    std::vector<std::pair<double, double>> pts = ellipse_points(e, 0, 2 * M_PI, 4096);
    if (view_ != View::XY) {
      for (auto& [x, y] : pts) x = view_ == View::XZ ? x : y, y = double(plan.from.z);
    }
    pic.ideal.push_back(std::move(pts));
  }
  write_svg(os_, pic);
}

void write_svg(std::ostream& os, const Plan& plan, const std::vector<Iteration>& iters, const std::string& title) {
  SvgSink sink(os, plan, title);
  for (const Iteration& it : iters) sink.record(it);
  sink.finish();
}

namespace {

// Where the picture draws: the view (a box in steps) at one scale on both axes, inside
// margins for the axis labels (left, bottom) and the legend (right).
struct Frame {
  static constexpr double L = 90, T = 60, R = 180, B = 70;  // the margins
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;                    // the view, in steps
  double scale = 1;                                         // pixels per step
  double W = 0, H = 0;                                      // the plot area, in pixels

  double sx(double x) const { return L + (x - x0) * scale; }
  double sy(double y) const { return T + (y1 - y) * scale; }
  bool inside(const Point& p) const {
    return double(p.x) >= x0 && double(p.x) <= x1 && double(p.y) >= y0 && double(p.y) <= y1;
  }
  std::size_t count_inside(const std::vector<Point>& v) const {
    std::size_t n = 0;
    for (const Point& p : v) n += inside(p);
    return n;
  }
  // A path's polyline: the points in the view and their neighbours, at most about 8000
  // of them (every k-th beyond that: the picture's scale hides the rest).
  std::string polyline(const std::vector<Point>& v) const {
    std::vector<std::size_t> keep;
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (inside(v[i]) || (i > 0 && inside(v[i - 1])) || (i + 1 < v.size() && inside(v[i + 1]))) keep.push_back(i);
    }
    const std::size_t k = std::max<std::size_t>(1, (keep.size() + 7999) / 8000);
    std::string out;
    for (std::size_t j = 0; j < keep.size(); ++j) {
      if (j % k != 0 && j + 1 != keep.size()) continue;
      const Point& p = v[keep[j]];
      out += fmt::format("{:.2f},{:.2f} ", sx(double(p.x)), sy(double(p.y)));
    }
    return out;
  }
};

// The view: the path's bounding box with a margin of a tenth (at least one step), or the
// picture's own view.
Frame frame_of(const SvgPicture& pic) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Point& p : pic.pts) {
    x0 = std::min(x0, double(p.x));
    x1 = std::max(x1, double(p.x));
    y0 = std::min(y0, double(p.y));
    y1 = std::max(y1, double(p.y));
  }
  const double span = std::max({x1 - x0, y1 - y0, 2.0});
  const double pad = std::max(1.0, span / 10);
  x0 -= pad, x1 += pad, y0 -= pad, y1 += pad;
  if (pic.view.size() == 4) x0 = pic.view[0], y0 = pic.view[1], x1 = pic.view[2], y1 = pic.view[3];
  Frame f;
  f.x0 = x0, f.x1 = x1, f.y0 = y0, f.y1 = y1;
  f.scale = 600.0 / std::max(x1 - x0, y1 - y0);  // same scale on both axes
  f.W = (x1 - x0) * f.scale, f.H = (y1 - y0) * f.scale;
  return f;
}

// The document's start: its size, the white ground, the title and the plot area's clip.
void write_head(std::ostream& os, const Frame& f, const std::string& title) {
  const double L = Frame::L, T = Frame::T;
  fmt::print(os,
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" "
             "font-family=\"sans-serif\" font-size=\"13\">\n",
             L + f.W + Frame::R, T + f.H + Frame::B);
  fmt::print(os, "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
  fmt::print(os, "<text x=\"{:.1f}\" y=\"24\" font-size=\"15\">{}</text>\n", L, title);
  fmt::print(os,
             "<clipPath id=\"plot\"><rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\"/></clipPath>\n",
             L, T, f.W, f.H);
}

// The grid with its tick labels, the plot area's border and the axis labels.
void write_axes(std::ostream& os, const Frame& f, View view) {
  const auto [h, v] = view_axes(view);
  const double L = Frame::L, T = Frame::T, W = f.W, H = f.H;
  const double step = tick_step(std::max(f.x1 - f.x0, f.y1 - f.y0), 8);
  const auto tick = [&](double v) { return std::fabs(v) < step * 1e-9 ? 0.0 : v; };  // no "-0"
  fmt::print(os, "<g class=\"axes\" stroke=\"#dddddd\">\n");
  for (double x = std::ceil(f.x0 / step) * step; x <= f.x1; x += step) {
    fmt::print(os, "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\"/>", f.sx(x), T, T + H);
    fmt::print(os, "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\" stroke=\"none\" fill=\"black\">{}</text>\n",
               f.sx(x), T + H + 18, tick(x));
  }
  for (double y = std::ceil(f.y0 / step) * step; y <= f.y1; y += step) {
    fmt::print(os, "<line x1=\"{1:.1f}\" y1=\"{0:.1f}\" x2=\"{2:.1f}\" y2=\"{0:.1f}\"/>", f.sy(y), L, L + W);
    fmt::print(os, "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\" stroke=\"none\" fill=\"black\">{}</text>\n",
               L - 6, f.sy(y) + 4, tick(y));
  }
  fmt::print(
      os, "</g>\n<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" stroke=\"black\"/>\n",
      L, T, W, H);
  fmt::print(os, "<text class=\"axis-label\" x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{} (steps)</text>\n",
             L + W / 2, T + H + 44, h);
  fmt::print(os,
             "<text class=\"axis-label\" x=\"24\" y=\"{:.1f}\" text-anchor=\"middle\" "
             "transform=\"rotate(-90 24 {:.1f})\">{} (steps)</text>\n",
             T + H / 2, T + H / 2, v);
}

// The ideal geometry, clipped to the view.
void write_ideal(std::ostream& os, const Frame& f, const std::vector<std::vector<std::pair<double, double>>>& ideal) {
  for (const auto& line : ideal) {
    fmt::print(os,
               "<polyline class=\"ideal\" clip-path=\"url(#plot)\" fill=\"none\" stroke=\"#888888\" "
               "stroke-width=\"1.5\" points=\"");
    for (const auto& [x, y] : line) fmt::print(os, "{:.2f},{:.2f} ", f.sx(x), f.sy(y));
    fmt::print(os, "\"/>\n");
  }
}

// The second path (pic.other) and its square markers, r the marker size.
void write_other(std::ostream& os, const Frame& f, const SvgPicture& pic, double r) {
  fmt::print(os,
             "<polyline class=\"other\" clip-path=\"url(#plot)\" fill=\"none\" stroke=\"#e66101\" "
             "stroke-width=\"1.5\" points=\"");
  os << f.polyline(pic.other);
  fmt::print(os, "\"/>\n");
  const std::size_t other_shown = f.count_inside(pic.other);
  const std::size_t oe = std::max<std::size_t>(1, (other_shown + pic.max_markers - 1) / pic.max_markers);
  std::size_t k = 0;
  for (const Point& p : pic.other) {
    if (!f.inside(p) || k++ % oe != 0) continue;
    fmt::print(os,
               "<rect class=\"other-pt\" x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.1f}\" height=\"{:.1f}\" "
               "fill=\"#e66101\"/>\n",
               f.sx(double(p.x)) - r * 0.7, f.sy(double(p.y)) - r * 0.7, r * 1.4, r * 1.4);
  }
}

// The path's point markers in the view, coloured by distance on the 0..dscale ramp:
// every `every`-th of them, and always the worst one (imax).
void write_markers(std::ostream& os, const Frame& f, const SvgPicture& pic, std::size_t imax, std::size_t every,
                   double r, double dscale) {
  const std::vector<Point>& pts = pic.pts;
  const std::vector<double>& dist = pic.dist;
  std::size_t k_shown = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!f.inside(pts[i])) continue;
    if (k_shown++ % every != 0 && i != imax) continue;
    fmt::print(os,
               "<circle class=\"pt\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.1f}\" fill=\"{}\"><title>({},{}) "
               "{:.3f}</title></circle>\n",
               f.sx(double(pts[i].x)), f.sy(double(pts[i].y)), r, ramp(dist[i] / dscale), pts[i].x, pts[i].y, dist[i]);
  }
}

// The largest deviation d, at m, ringed and labelled (when it is in the view).
void write_max(std::ostream& os, const Frame& f, const Point& m, double d, double r) {
  if (!f.inside(m)) return;
  fmt::print(os,
             "<circle class=\"max\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.1f}\" fill=\"none\" stroke=\"black\" "
             "stroke-width=\"2\"/>\n",
             f.sx(double(m.x)), f.sy(double(m.y)), r + 5);
  const bool left = f.sx(double(m.x)) > Frame::L + f.W * 0.6;  // near the right edge: the label to the left
  fmt::print(os,
             "<text class=\"max-label\" x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"{}\" font-weight=\"bold\">max {:.2f} @ "
             "({},{})</text>\n",
             f.sx(double(m.x)) + (left ? -(r + 9) : r + 9), f.sy(double(m.y)) - (r + 6), left ? "end" : "start", d, m.x,
             m.y);
}

// Legend: the colour ramp with its scale, the key to the curves, and how the markers
// (every `every`-th of `shown`) and the path were thinned.
void write_legend(std::ostream& os, const Frame& f, const SvgPicture& pic, double dscale, std::size_t every,
                  std::size_t shown) {
  const double lx = Frame::L + f.W + 40, ly = Frame::T + 20, lh = 200;
  fmt::print(os,
             "<g class=\"legend\">\n<text x=\"{:.1f}\" y=\"{:.1f}\">distance from</text>\n"
             "<text x=\"{:.1f}\" y=\"{:.1f}\">{} (steps)</text>\n",
             lx - 10, ly - 4, lx - 10, ly + 12, pic.curve);
  fmt::print(os, "<linearGradient id=\"ramp\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">");
  for (int k = 0; k <= 4; ++k) fmt::print(os, "<stop offset=\"{}\" stop-color=\"{}\"/>", k / 4.0, ramp(k / 4.0));
  fmt::print(os,
             "</linearGradient>\n<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"18\" height=\"{:.1f}\" fill=\"url(#ramp)\" "
             "stroke=\"black\"/>\n",
             lx, ly + 24, lh);
  for (int k = 0; k <= 4; ++k) {
    fmt::print(os, "<text x=\"{:.1f}\" y=\"{:.1f}\">{:.2f}</text>\n", lx + 24, ly + 24 + lh - lh * k / 4.0 + 4,
               dscale * k / 4.0);
  }
  fmt::print(os, "<text x=\"{:.1f}\" y=\"{:.1f}\" fill=\"#888888\">grey: ideal curve</text>\n", lx - 10, ly + lh + 50);
  if (!pic.other.empty()) {
    fmt::print(os, "<text x=\"{:.1f}\" y=\"{:.1f}\" fill=\"#e66101\">orange: {}</text>\n", lx - 10, ly + lh + 104,
               pic.other_label);
  }
  if (every > 1) {
    fmt::print(os,
               "<text x=\"{:.1f}\" y=\"{:.1f}\">markers: every {}th</text>\n<text x=\"{:.1f}\" y=\"{:.1f}\">of {} "
               "points</text>\n",
               lx - 10, ly + lh + 70, every, lx - 10, ly + lh + 86, shown);
  }
  if (pic.sampled_from != 0) {
    fmt::print(os,
               "<text x=\"{:.1f}\" y=\"{:.1f}\">path: every {}th</text>\n<text x=\"{:.1f}\" y=\"{:.1f}\">of {} "
               "points</text>\n",
               lx - 10, ly + lh + 120, pic.sample_stride, lx - 10, ly + lh + 136, pic.sampled_from);
  }
  fmt::print(os, "</g>\n");
}

}  // namespace

void write_svg(std::ostream& os, const SvgPicture& pic) {
  const std::vector<Point>& pts = pic.pts;
  const std::vector<double>& dist = pic.dist;
  std::size_t imax = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (dist[i] > dist[imax]) imax = i;
  }
  const Frame f = frame_of(pic);
  const double dscale = std::max(1.0, dist[imax]);  // colour ramp 0..max(1, worst)
  write_head(os, f, pic.title);
  write_axes(os, f, pic.projection);
  write_ideal(os, f, pic.ideal);
  // The path and its point markers (at most max_markers: every k-th point beyond that,
  // always the worst one), the second path's drawn between them.
  fmt::print(os,
             "<polyline class=\"path\" clip-path=\"url(#plot)\" fill=\"none\" stroke=\"#333333\" "
             "stroke-width=\"1\" points=\"");
  os << f.polyline(pts);
  fmt::print(os, "\"/>\n");
  const std::size_t shown = f.count_inside(pts);
  const std::size_t every = std::max<std::size_t>(1, (shown + pic.max_markers - 1) / pic.max_markers);
  const double r = std::clamp(0.3 * f.scale, 1.5, 7.0);
  if (!pic.other.empty()) write_other(os, f, pic, r);
  write_markers(os, f, pic, imax, every, r, dscale);
  write_max(os, f, pts[imax], dist[imax], r);
  write_legend(os, f, pic, dscale, every, shown);
  fmt::print(os, "</svg>\n");
}

}  // namespace dda
