#pragma once
// Small cairo helpers shared by the trajectory plot, the world view and the APNG writer.

#include <cairo.h>

#include <string>
#include <vector>

#include "cyber/plot/plot_status.hpp"
#include "cyber/plot/world_view.hpp"
#include "cyber/result.hpp"

namespace cyber::plot::detail {

struct Rgb {
  double r, g, b;
};

inline void setColor(cairo_t* cr, Rgb c, double alpha = 1.0) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

// Text at (x, y) (baseline), left-aligned, centred or right-aligned on x.
inline void text(cairo_t* cr, double x, double y, const std::string& s, double size, bool center = false,
                 bool right = false) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, s.c_str(), &ext);
  double dx = 0;
  if (center) dx = -ext.width / 2 - ext.x_bearing;
  if (right) dx = -ext.width - ext.x_bearing;
  cairo_move_to(cr, x + dx, y);
  cairo_show_text(cr, s.c_str());
}

// The error of a picture at `path`: its message is "PATH: what".
inline Error<PlotStatus> pictureError(PlotStatus status, const std::string& path, const std::string& what) {
  return {status, path + ": " + what};
}

// Writes a surface to a PNG file; kCannotWrite with cairo's reason when cairo cannot.
inline Result<Done, PlotStatus> writePng(cairo_surface_t* surface, const std::string& path) {
  const cairo_status_t status = cairo_surface_write_to_png(surface, path.c_str());
  if (status != CAIRO_STATUS_SUCCESS)
    return pictureError(PlotStatus::kCannotWrite, path, cairo_status_to_string(status));
  return Done{};
}

// The C-space view in a box with the poses marked (render_png.cpp draws it as cyber-plan --plot):
// one joint's strip, two joints' plane, or the first of three joints' maps.
void drawCSpaceWithPoses(cairo_t* cr, const CSpaceView& view, const std::vector<NamedJointPose>& poses, double x,
                         double y, double w, double h);

}  // namespace cyber::plot::detail
