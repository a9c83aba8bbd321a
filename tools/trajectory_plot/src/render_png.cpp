#include <fmt/format.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "cyber/plot/trajectory_plot.hpp"
#include "drawing.hpp"

namespace cyber::plot {
namespace {

constexpr int kWidth = 1600;
constexpr int kHeight = 1000;

using detail::Rgb;
using detail::setColor;
using detail::text;
constexpr Rgb kJoint0Color{0.10, 0.35, 0.75};
constexpr Rgb kJoint1Color{0.85, 0.35, 0.10};
constexpr Rgb kLimitColor{0.80, 0.10, 0.10};

struct Box {
  double x, y, w, h;
};

// Maps data coordinates into a box on the page, with "nice" tick marks.
struct Axes {
  Box box;
  double x0, x1, y0, y1;
  [[nodiscard]] double px(double x) const { return box.x + (x - x0) / (x1 - x0) * box.w; }
  [[nodiscard]] double py(double y) const { return box.y + box.h - (y - y0) / (y1 - y0) * box.h; }
};

double niceStep(double span, int target_ticks) {
  const double raw = span / std::max(1, target_ticks);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (raw <= m * mag) return m * mag;
  }
  return 10.0 * mag;
}

std::string format(double v, double step) {
  if (std::abs(v) < 1e-9 * step) v = 0.0;  // a tick at zero reached by summing steps: no "-0"
  const int decimals = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step)));
  return fmt::format("{:.{}f}", v, std::clamp(decimals, 0, 4));
}

void drawFrame(cairo_t* cr, const Axes& ax, const std::string& title, const std::string& xlabel,
               const std::string& ylabel) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_rectangle(cr, ax.box.x, ax.box.y, ax.box.w, ax.box.h);
  cairo_fill(cr);
  cairo_set_line_width(cr, 1.0);
  const double xs = niceStep(ax.x1 - ax.x0, 8);
  const double ys = niceStep(ax.y1 - ax.y0, 5);
  for (double x = std::ceil(ax.x0 / xs) * xs; x <= ax.x1 + 1e-9; x += xs) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, ax.px(x), ax.box.y);
    cairo_line_to(cr, ax.px(x), ax.box.y + ax.box.h);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    text(cr, ax.px(x), ax.box.y + ax.box.h + 14, format(x, xs), 11, true);
  }
  for (double y = std::ceil(ax.y0 / ys) * ys; y <= ax.y1 + 1e-9; y += ys) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, ax.box.x, ax.py(y));
    cairo_line_to(cr, ax.box.x + ax.box.w, ax.py(y));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    text(cr, ax.box.x - 5, ax.py(y) + 4, format(y, ys), 11, false, true);
  }
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_rectangle(cr, ax.box.x, ax.box.y, ax.box.w, ax.box.h);
  cairo_stroke(cr);
  text(cr, ax.box.x + ax.box.w / 2, ax.box.y - 8, title, 14, true);
  text(cr, ax.box.x + ax.box.w / 2, ax.box.y + ax.box.h + 30, xlabel, 12, true);
  cairo_save(cr);
  cairo_translate(cr, ax.box.x - 48, ax.box.y + ax.box.h / 2);
  cairo_rotate(cr, -M_PI / 2);
  text(cr, 0, 0, ylabel, 12, true);
  cairo_restore(cr);
}

void polyline(cairo_t* cr, const Axes& ax, const std::vector<double>& x, const std::vector<double>& y, Rgb color,
              double width = 1.8) {
  const size_t n = std::min(x.size(), y.size());
  if (n == 0) return;
  cairo_save(cr);
  cairo_rectangle(cr, ax.box.x, ax.box.y, ax.box.w, ax.box.h);
  cairo_clip(cr);
  setColor(cr, color);
  cairo_set_line_width(cr, width);
  // Thin the samples to about one per pixel column; a 1 ms trajectory has thousands.
  const size_t stride = std::max<size_t>(1, n / static_cast<size_t>(ax.box.w * 2));
  cairo_move_to(cr, ax.px(x[0]), ax.py(y[0]));
  for (size_t i = stride; i < n; i += stride) cairo_line_to(cr, ax.px(x[i]), ax.py(y[i]));
  cairo_line_to(cr, ax.px(x[n - 1]), ax.py(y[n - 1]));
  cairo_stroke(cr);
  cairo_restore(cr);
}

void hline(cairo_t* cr, const Axes& ax, double y, Rgb color) {
  if (y < ax.y0 || y > ax.y1) return;
  setColor(cr, color);
  cairo_set_line_width(cr, 1.2);
  const double dash[] = {6.0, 4.0};
  cairo_set_dash(cr, dash, 2, 0);
  cairo_move_to(cr, ax.box.x, ax.py(y));
  cairo_line_to(cr, ax.box.x + ax.box.w, ax.py(y));
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
}

std::pair<double, double> rangeOf(std::initializer_list<const std::vector<double>*> series,
                                  std::initializer_list<double> extra) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const auto* s : series) {
    for (double v : *s) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  for (double v : extra) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (!std::isfinite(lo)) return {-1, 1};
  const double pad = std::max(1e-3, 0.06 * (hi - lo));
  return {lo - pad, hi + pad};
}

void legend(cairo_t* cr, const Box& box, const std::array<std::string, 2>& labels) {
  const double x = box.x + box.w - 170;
  const double y = box.y + 14;
  for (int i = 0; i < 2; ++i) {
    setColor(cr, i == 0 ? kJoint0Color : kJoint1Color);
    cairo_set_line_width(cr, 2.5);
    cairo_move_to(cr, x, y + 16 * i - 4);
    cairo_line_to(cr, x + 22, y + 16 * i - 4);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text(cr, x + 28, y + 16 * i, labels[static_cast<size_t>(i)], 11);
  }
}

// The map's frame and blocked cells: joint 1 on x, joint 0 on y, so a cascade's carried joint reads
// across (for an elevator carrying an arm, the robot's side view).
Axes drawCSpaceMap(cairo_t* cr, const CSpaceMap& m, const Box& box) {
  Axes ax{box, m.range[1].min, m.range[1].max, m.range[0].min, m.range[0].max};
  if (!(ax.x1 > ax.x0) || !(ax.y1 > ax.y0)) ax = Axes{box, 0, 1, 0, 1};
  drawFrame(cr, ax, "configuration space (grey: closer than the clearance)", m.names[1] + " [" + m.units[1] + "]",
            m.names[0] + " [" + m.units[0] + "]");
  if (m.cells[0] > 0 && m.cells[1] > 0 && m.blocked.size() == static_cast<size_t>(m.cells[0] * m.cells[1])) {
    const double cw = box.w / m.cells[1];
    const double ch = box.h / m.cells[0];
    cairo_set_source_rgba(cr, 0.35, 0.35, 0.40, 0.75);
    for (int i = 0; i < m.cells[0]; ++i) {
      for (int j = 0; j < m.cells[1]; ++j) {
        if (m.blocked[static_cast<size_t>(i * m.cells[1] + j)] != 0) {
          cairo_rectangle(cr, box.x + j * cw, box.y + box.h - (i + 1) * ch, cw + 0.5, ch + 0.5);
        }
      }
    }
    cairo_fill(cr);
  }
  return ax;
}

void marker(cairo_t* cr, const Axes& ax, double q1, double q0, const std::string& label) {
  cairo_set_source_rgb(cr, 0.05, 0.4, 0.1);
  cairo_arc(cr, ax.px(q1), ax.py(q0), 6, 0, 2 * M_PI);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, ax.px(q1) + 9, ax.py(q0) - 8, label, 13);
}

void drawCSpace(cairo_t* cr, const TrajectoryPlotData& d, const Box& box) {
  const Axes ax = drawCSpaceMap(cr, d.cspace, box);
  const auto& e = d.joints[0].position;
  const auto& a = d.joints[1].position;
  polyline(cr, ax, a, e, Rgb{0.05, 0.55, 0.15}, 3.0);
  if (!e.empty()) {
    for (auto [idx, label] : {std::pair{size_t{0}, "start"}, std::pair{e.size() - 1, "goal"}})
      marker(cr, ax, a[idx], e[idx], label);
  }
}

void drawSignal(cairo_t* cr, const TrajectoryPlotData& d, const Box& box, const std::string& title,
                const std::string& ylabel, const std::function<const std::vector<double>&(const JointSeries&)>& pick,
                const std::array<double, 2>* limits, const std::array<std::string, 2>& labels, bool with_xlabel) {
  const auto& s0 = pick(d.joints[0]);
  const auto& s1 = pick(d.joints[1]);
  // Both joints' limits stay in view (zero when there are none).
  const double l0 = limits != nullptr ? (*limits)[0] : 0.0;
  const double l1 = limits != nullptr ? (*limits)[1] : 0.0;
  auto [lo, hi] = rangeOf({&s0, &s1}, {-l0, l0, -l1, l1});
  const double t1 = d.time_s.empty() ? 1.0 : std::max(1e-3, d.time_s.back());
  Axes ax{box, 0.0, t1, lo, hi};
  drawFrame(cr, ax, title, with_xlabel ? "time [s]" : "", ylabel);
  if (limits != nullptr) {
    hline(cr, ax, (*limits)[0], kLimitColor);
    hline(cr, ax, -(*limits)[0], kLimitColor);
    if ((*limits)[1] != (*limits)[0]) {
      hline(cr, ax, (*limits)[1], Rgb{0.6, 0.2, 0.6});
      hline(cr, ax, -(*limits)[1], Rgb{0.6, 0.2, 0.6});
    }
  }
  polyline(cr, ax, d.time_s, s0, kJoint0Color);
  polyline(cr, ax, d.time_s, s1, kJoint1Color);
  legend(cr, box, labels);
}

}  // namespace

void detail::drawCSpaceWithPoses(cairo_t* cr, const CSpaceMap& map, const std::vector<NamedJointPose>& poses, double x,
                                 double y, double w, double h) {
  const Axes ax = drawCSpaceMap(cr, map, Box{x, y, w, h});
  for (const NamedJointPose& p : poses) marker(cr, ax, p.q[1], p.q[0], p.name);
}

Result<Done, PlotStatus> renderTrajectoryPng(const TrajectoryPlotData& d, const std::string& path) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kWidth, kHeight);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 0.96, 0.96, 0.97);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, kWidth / 2.0, 30, d.title, 18, true);

  drawCSpace(cr, d, Box{80, 70, 640, 860});
  const double x = 860, w = 700, h = 170, gap = 62;
  double y = 70;
  // Each joint's signal labelled with its name and unit (per second for velocity).
  const auto labels = [&](const std::string& unit0, const std::string& unit1) {
    return std::array<std::string, 2>{d.cspace.names[0] + " [" + unit0 + "]", d.cspace.names[1] + " [" + unit1 + "]"};
  };
  const std::array<std::string, 2>& units = d.cspace.units;
  drawSignal(
      cr, d, Box{x, y, w, h}, "position", units[0] + " | " + units[1],
      [](const JointSeries& s) -> const std::vector<double>& { return s.position; }, nullptr,
      labels(units[0], units[1]), false);
  y += h + gap;
  drawSignal(
      cr, d, Box{x, y, w, h}, "velocity", units[0] + "/s | " + units[1] + "/s",
      [](const JointSeries& s) -> const std::vector<double>& { return s.velocity; }, nullptr,
      labels(units[0] + "/s", units[1] + "/s"), false);
  y += h + gap;
  drawSignal(
      cr, d, Box{x, y, w, h}, "feedforward voltage (dashed: limits)", "V",
      [](const JointSeries& s) -> const std::vector<double>& { return s.volts; }, &d.voltage_limit_volts,
      labels("V", "V"), false);
  y += h + gap;
  drawSignal(
      cr, d, Box{x, y, w, h}, "current per motor (dashed: limits)", "A",
      [](const JointSeries& s) -> const std::vector<double>& { return s.amps; }, &d.current_limit_amps,
      labels("A", "A"), true);

  cairo_destroy(cr);
  auto written = detail::writePng(surface, path);
  cairo_surface_destroy(surface);
  return written;
}

}  // namespace cyber::plot
