#pragma once
// Reading back the PNGs of tools/trajectory_plot: a pixel's colour, and pixel points just inside or
// outside a drawn polygon.

#include <cairo.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cyber/plot/world_view.hpp"

namespace cyber::plot::pixels {

using planner::Point2;

inline std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / (name + "_" + std::to_string(getpid()) + ".png")).string();
}

class Image {
 public:
  explicit Image(const std::string& path) : surface_(cairo_image_surface_create_from_png(path.c_str())) {}
  ~Image() { cairo_surface_destroy(surface_); }
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;
  [[nodiscard]] bool ok() const { return cairo_surface_status(surface_) == CAIRO_STATUS_SUCCESS; }
  // RGB of the pixel containing (x, y).
  [[nodiscard]] std::array<int, 3> at(double x, double y) const {
    const int ix = static_cast<int>(std::floor(x)), iy = static_cast<int>(std::floor(y));
    const unsigned char* row = cairo_image_surface_get_data(surface_) + iy * cairo_image_surface_get_stride(surface_);
    uint32_t argb = 0;
    std::memcpy(&argb, row + 4 * ix, 4);
    return {static_cast<int>((argb >> 16) & 0xff), static_cast<int>((argb >> 8) & 0xff), static_cast<int>(argb & 0xff)};
  }

 private:
  cairo_surface_t* surface_;
};

inline bool near(const std::array<int, 3>& got, const uint8_t (&want)[3]) {
  for (int i = 0; i < 3; ++i) {
    if (std::abs(got[i] - want[i]) > 4) return false;
  }
  return true;
}

// The pixel point `px` pixels from world point p toward (or, negative, away from) `toward`.
inline Point2 inset(const WorldCanvas& c, const Point2& p, const Point2& toward, double px) {
  const Point2 a(c.px(p.x()), c.py(p.y())), b(c.px(toward.x()), c.py(toward.y()));
  return a + px * (b - a).normalized();
}

// The pixel point `px` pixels inside both edges at corner `i` of a convex polygon (world
// vertices), or `px` pixels outside it along the corner's bisector when px < 0.
inline Point2 corner(const WorldCanvas& c, const std::vector<Point2>& world, size_t i, double px) {
  auto pixel = [&](const Point2& p) { return Point2(c.px(p.x()), c.py(p.y())); };
  const size_t n = world.size();
  const Point2 a = pixel(world[i]);
  const Point2 u1 = (pixel(world[(i + n - 1) % n]) - a).normalized(), u2 = (pixel(world[(i + 1) % n]) - a).normalized();
  const Point2 bisector = (u1 + u2).normalized();
  const double sin_half = std::sqrt(std::max(1e-6, (1 - u1.dot(u2)) / 2));
  return px > 0 ? a + bisector * (px / sin_half) : a + bisector * px;
}

inline Point2 centroid(const std::vector<Point2>& vertices) {
  Point2 sum = Point2::Zero();
  for (const Point2& v : vertices) sum += v;
  return sum / static_cast<double>(vertices.size());
}

}  // namespace cyber::plot::pixels
