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
// By joint index, as the world view colours the links (world_view.hpp, WorldColors).
constexpr Rgb kJointColors[planner::kMaxJoints] = {{0.10, 0.35, 0.75}, {0.85, 0.35, 0.10}, {0.49, 0.33, 0.76}};
// A joint's limit lines, in the colour of the first joint with that limit.
constexpr Rgb kLimitColors[planner::kMaxJoints] = {{0.80, 0.10, 0.10}, {0.6, 0.2, 0.6}, {0.10, 0.50, 0.50}};
constexpr Rgb kPathColor{0.05, 0.55, 0.15};

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

// x_ticks false: the x axis means nothing (the strip of one joint in a preview).
void drawFrame(cairo_t* cr, const Axes& ax, const std::string& title, const std::string& xlabel,
               const std::string& ylabel, bool x_ticks = true) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_rectangle(cr, ax.box.x, ax.box.y, ax.box.w, ax.box.h);
  cairo_fill(cr);
  cairo_set_line_width(cr, 1.0);
  const double xs = niceStep(ax.x1 - ax.x0, 8);
  const double ys = niceStep(ax.y1 - ax.y0, 5);
  for (double x = std::ceil(ax.x0 / xs) * xs; x_ticks && x <= ax.x1 + 1e-9; x += xs) {
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

std::pair<double, double> rangeOf(const std::vector<const std::vector<double>*>& series,
                                  const std::vector<double>& extra) {
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

void legend(cairo_t* cr, const Box& box, const std::vector<std::string>& labels) {
  const double x = box.x + box.w - 170;
  const double y = box.y + 14;
  for (int i = 0; i < static_cast<int>(labels.size()); ++i) {
    setColor(cr, kJointColors[i]);
    cairo_set_line_width(cr, 2.5);
    cairo_move_to(cr, x, y + 16 * i - 4);
    cairo_line_to(cr, x + 22, y + 16 * i - 4);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text(cr, x + 28, y + 16 * i, labels[static_cast<size_t>(i)], 11);
  }
}

// Where a map goes in its box and what its frame says.
struct MapFrame {
  Axes ax;
  std::string title, xlabel, ylabel;
  bool x_ticks = true;
};

std::string axisLabel(const JointAxis& joint) { return joint.name + " [" + joint.unit + "]"; }

// A map of two joints: joints[1] on x, joints[0] on y, so a cascade's carried joint reads across
// (for an elevator carrying an arm, the robot's side view).
MapFrame planeFrame(const CSpaceView& v, const CSpaceMap& m, const Box& box) {
  const JointAxis& y = v.joints[static_cast<size_t>(m.joints[0])];
  const JointAxis& x = v.joints[static_cast<size_t>(m.joints[1])];
  std::string title = "configuration space (grey: closer than the clearance)";
  if (m.projected_joint >= 0) {
    title = "configuration space, " + m.caption;
  } else if (!m.caption.empty()) {
    title = "slice at " + m.caption + " (grey: closer than the clearance)";
  }
  return MapFrame{Axes{box, x.range.min, x.range.max, y.range.min, y.range.max}, title, axisLabel(x), axisLabel(y)};
}

// A projection's two greys, named on one line under its frame's x label.
void projectionLegend(cairo_t* cr, const CSpaceView& v, const CSpaceMap& m, const Box& box) {
  const std::string& projected = v.joints[static_cast<size_t>(m.projected_joint)].name;
  const std::string lines[2] = {"closer than the clearance at every " + projected + " value",
                                "at some " + projected + " values, not at others"};
  const double alphas[2] = {0.75, 0.3};
  double x = box.x;
  const double y = box.y + box.h + 50;
  for (int i = 0; i < 2; ++i) {
    cairo_set_source_rgba(cr, 0.35, 0.35, 0.40, alphas[i]);
    cairo_rectangle(cr, x, y - 10, 16, 12);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text(cr, x + 22, y, lines[i], 12);
    cairo_text_extents_t ext;
    cairo_text_extents(cr, lines[i].c_str(), &ext);
    x += 22 + ext.x_advance + 24;
  }
}

// The map's frame and blocked cells (for a projection, the some-blocked ones lighter).
Axes drawCSpaceMap(cairo_t* cr, const CSpaceView& v, const CSpaceMap& m, MapFrame f) {
  const Box& box = f.ax.box;
  if (!(f.ax.x1 > f.ax.x0) || !(f.ax.y1 > f.ax.y0)) f.ax = Axes{box, 0, 1, 0, 1};
  drawFrame(cr, f.ax, f.title, f.xlabel, f.ylabel, f.x_ticks);
  if (m.cells[0] > 0 && m.cells[1] > 0 && m.blocked.size() == static_cast<size_t>(m.cells[0] * m.cells[1])) {
    const double cw = box.w / m.cells[1];
    const double ch = box.h / m.cells[0];
    for (const auto& [value, alpha] : {std::pair{kBlocked, 0.75}, std::pair{kSomeBlocked, 0.3}}) {
      if (std::find(m.blocked.begin(), m.blocked.end(), value) == m.blocked.end()) continue;
      cairo_set_source_rgba(cr, 0.35, 0.35, 0.40, alpha);
      for (int i = 0; i < m.cells[0]; ++i) {
        for (int j = 0; j < m.cells[1]; ++j) {
          if (m.blocked[static_cast<size_t>(i * m.cells[1] + j)] == value) {
            cairo_rectangle(cr, box.x + j * cw, box.y + box.h - (i + 1) * ch, cw + 0.5, ch + 0.5);
          }
        }
      }
      cairo_fill(cr);
    }
  }
  if (m.projected_joint >= 0) projectionLegend(cr, v, m, box);
  return f.ax;
}

// filled false: a ring, for an end of the move that lies in another slice than the one drawn.
void marker(cairo_t* cr, const Axes& ax, double x, double y, const std::string& label, bool filled = true) {
  cairo_set_source_rgb(cr, 0.05, 0.4, 0.1);
  if (filled) {
    cairo_arc(cr, ax.px(x), ax.py(y), 6, 0, 2 * M_PI);
    cairo_fill(cr);
  } else {
    cairo_set_line_width(cr, 2.0);
    cairo_new_sub_path(cr);  // no line from where the previous label's text ended
    cairo_arc(cr, ax.px(x), ax.py(y), 5, 0, 2 * M_PI);
    cairo_stroke(cr);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, ax.px(x) + 9, ax.py(y) - 8, label, 13);
}

// One joint: its range against time, the blocked intervals as bands, and the move.
void drawCSpaceStrip(cairo_t* cr, const TrajectoryPlotData& d, const Box& box) {
  const JointAxis& joint = d.cspace.joints.front();
  const double t1 = d.time_s.empty() ? 1.0 : std::max(1e-3, d.time_s.back());
  const Axes ax = drawCSpaceMap(
      cr, d.cspace, d.cspace.maps.front(),
      MapFrame{Axes{box, 0.0, t1, joint.range.min, joint.range.max},
               "configuration space over time (grey: closer than the clearance)", "time [s]", axisLabel(joint)});
  const auto& q = d.joints[0].position;
  polyline(cr, ax, d.time_s, q, kPathColor, 3.0);
  if (!q.empty()) {
    marker(cr, ax, d.time_s.front(), q.front(), "start");
    marker(cr, ax, d.time_s.back(), q.back(), "goal");
  }
}

// Two or three joints: each map of the first two with the path (projected, for three joints) and
// its ends, an end filled where the map holds the third joint at that end's value.
void drawCSpacePlanes(cairo_t* cr, const TrajectoryPlotData& d, const Box& box) {
  const auto& e = d.joints[0].position;
  const auto& a = d.joints[1].position;
  const size_t count = d.cspace.maps.size();
  constexpr double kGap = 70;
  const double h = (box.h - kGap * static_cast<double>(count - 1)) / static_cast<double>(count);
  for (size_t k = 0; k < count; ++k) {
    const CSpaceMap& m = d.cspace.maps[k];
    const Box mbox{box.x, box.y + static_cast<double>(k) * (h + kGap), box.w, h};
    const Axes ax = drawCSpaceMap(cr, d.cspace, m, planeFrame(d.cspace, m, mbox));
    polyline(cr, ax, a, e, kPathColor, 3.0);
    if (e.empty()) continue;
    for (auto [idx, label] : {std::pair{size_t{0}, "start"}, std::pair{e.size() - 1, "goal"}}) {
      const bool in_map = d.joints.size() < 3 || m.projected_joint >= 0 || d.joints[2].position[idx] == m.held[2];
      marker(cr, ax, a[idx], e[idx], label, in_map);
    }
  }
}

// Every joint's series picked by `pick` against time, with the joints' limits picked by `limit`
// when it is given (each value drawn once, in the colour of the first joint that has it).
void drawSignal(cairo_t* cr, const TrajectoryPlotData& d, const Box& box, const std::string& title,
                const std::string& ylabel, const std::function<const std::vector<double>&(const JointSeries&)>& pick,
                const std::function<double(const JointAxis&)>& limit, const std::vector<std::string>& labels,
                bool with_xlabel) {
  std::vector<const std::vector<double>*> series;
  std::vector<double> limits;
  std::vector<double> extra;
  for (size_t j = 0; j < d.joints.size(); ++j) {
    series.push_back(&pick(d.joints[j]));
    // Every joint's limits stay in view (zero when there are none).
    limits.push_back(limit ? limit(d.cspace.joints[j]) : 0.0);
    extra.push_back(-limits.back());
    extra.push_back(limits.back());
  }
  auto [lo, hi] = rangeOf(series, extra);
  const double t1 = d.time_s.empty() ? 1.0 : std::max(1e-3, d.time_s.back());
  Axes ax{box, 0.0, t1, lo, hi};
  drawFrame(cr, ax, title, with_xlabel ? "time [s]" : "", ylabel);
  for (size_t j = 0; limit && j < limits.size(); ++j) {
    const auto earlier = limits.begin() + static_cast<std::ptrdiff_t>(j);
    if (std::find(limits.begin(), earlier, limits[j]) != earlier) continue;
    hline(cr, ax, limits[j], kLimitColors[j]);
    hline(cr, ax, -limits[j], kLimitColors[j]);
  }
  for (size_t j = 0; j < series.size(); ++j) polyline(cr, ax, d.time_s, *series[j], kJointColors[j]);
  legend(cr, box, labels);
}

// Whether the data can be drawn: one series per joint of the view (1 to kMaxJoints), each as long
// as the times, and at least one map.
bool drawable(const TrajectoryPlotData& d) {
  const size_t n = d.cspace.joints.size();
  if (n < 1 || n > static_cast<size_t>(planner::kMaxJoints) || d.joints.size() != n || d.cspace.maps.empty()) {
    return false;
  }
  for (const JointSeries& s : d.joints) {
    for (const auto* v : {&s.position, &s.velocity, &s.volts, &s.amps}) {
      if (v->size() != d.time_s.size()) return false;
    }
  }
  for (const CSpaceMap& m : d.cspace.maps) {
    for (int joint : m.joints) {
      if (joint >= static_cast<int>(n)) return false;
    }
    if (m.joints[0] < 0 || (n >= 2 && m.joints[1] < 0) || (n >= 3 && m.held.size() != static_cast<Eigen::Index>(n)))
      return false;
  }
  return true;
}

}  // namespace

void detail::drawCSpaceWithPoses(cairo_t* cr, const CSpaceView& view, const std::vector<NamedJointPose>& poses,
                                 double x, double y, double w, double h) {
  if (view.joints.empty() || view.maps.empty()) return;
  const CSpaceMap& map = view.maps.front();
  if (view.joints.size() == 1) {
    // One joint: a strip of its range, each pose a tick across it named on its right.
    const JointAxis& joint = view.joints.front();
    const Box box{x, y, std::min(w, 160.0), h};
    const Axes ax = drawCSpaceMap(cr, view, map,
                                  MapFrame{Axes{box, 0, 1, joint.range.min, joint.range.max}, "configuration space", "",
                                           axisLabel(joint), false});
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text(cr, box.x, box.y + box.h + 30, "grey: closer than the clearance", 12);
    for (const NamedJointPose& p : poses) {
      cairo_set_source_rgb(cr, 0.05, 0.4, 0.1);
      cairo_set_line_width(cr, 3.0);
      cairo_move_to(cr, ax.px(0), ax.py(p.q[0]));
      cairo_line_to(cr, ax.px(1), ax.py(p.q[0]));
      cairo_stroke(cr);
      cairo_set_source_rgb(cr, 0, 0, 0);
      text(cr, ax.px(1) + 9, ax.py(p.q[0]) + 4, p.name, 13);
    }
    return;
  }
  // Two joints: the plane; three: the first two with the third projected out (sampleCSpace), each
  // pose where it projects.
  const Axes ax = drawCSpaceMap(cr, view, map, planeFrame(view, map, Box{x, y, w, h}));
  for (const NamedJointPose& p : poses) marker(cr, ax, p.q[1], p.q[0], p.name);
}

Result<Done, PlotStatus> renderTrajectoryPng(const TrajectoryPlotData& d, const std::string& path) {
  if (!drawable(d)) {
    return detail::pictureError(PlotStatus::kNothingToDraw, path,
                                fmt::format("{} joint series of {} samples for {} joints: not one per joint",
                                            d.joints.size(), d.time_s.size(), d.cspace.joints.size()));
  }
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kWidth, kHeight);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 0.96, 0.96, 0.97);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, kWidth / 2.0, 30, d.title, 18, true);

  const Box cspace_box{80, 70, 640, 860};
  if (d.cspace.joints.size() == 1) {
    drawCSpaceStrip(cr, d, cspace_box);
  } else {
    drawCSpacePlanes(cr, d, cspace_box);
  }
  const double x = 860, w = 700, h = 170, gap = 62;
  double y = 70;
  // Each joint's signal labelled with its name and unit (per second for velocity); the axis
  // names the units in chain order.
  const auto labels = [&](const std::string& suffix, const std::string& unit) {
    std::vector<std::string> out;
    for (const JointAxis& j : d.cspace.joints)
      out.push_back(j.name + " [" + (unit.empty() ? j.unit + suffix : unit) + "]");
    return out;
  };
  const auto units = [&](const std::string& suffix) {
    std::string out;
    for (const JointAxis& j : d.cspace.joints) out += (out.empty() ? "" : " | ") + j.unit + suffix;
    return out;
  };
  drawSignal(
      cr, d, Box{x, y, w, h}, "position", units(""),
      [](const JointSeries& s) -> const std::vector<double>& { return s.position; }, nullptr, labels("", ""), false);
  y += h + gap;
  drawSignal(
      cr, d, Box{x, y, w, h}, "velocity", units("/s"),
      [](const JointSeries& s) -> const std::vector<double>& { return s.velocity; }, nullptr, labels("/s", ""), false);
  y += h + gap;
  drawSignal(
      cr, d, Box{x, y, w, h}, "feedforward voltage (dashed: limits)", "V",
      [](const JointSeries& s) -> const std::vector<double>& { return s.volts; },
      [](const JointAxis& j) { return j.voltage_limit_volts; }, labels("", "V"), false);
  y += h + gap;
  drawSignal(
      cr, d, Box{x, y, w, h}, "current per motor (dashed: limits)", "A",
      [](const JointSeries& s) -> const std::vector<double>& { return s.amps; },
      [](const JointAxis& j) { return j.current_limit_amps; }, labels("", "A"), true);

  cairo_destroy(cr);
  auto written = detail::writePng(surface, path);
  cairo_surface_destroy(surface);
  return written;
}

}  // namespace cyber::plot
