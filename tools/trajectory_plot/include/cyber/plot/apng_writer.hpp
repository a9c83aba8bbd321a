#pragma once
// Animated PNG from cairo frames: cairo writes each frame as a PNG, whose image data becomes
// one APNG frame (acTL, fcTL, fdAT chunks of the APNG specification). Debian's libpng has no
// APNG support and GIF would need colour quantisation of the antialiased drawing, so the few
// chunks are written here, with zlib's CRC.

#include <cairo.h>

#include <string>
#include <vector>

#include "cyber/plot/plot_status.hpp"
#include "cyber/result.hpp"

namespace cyber::plot {

// All frames must be image surfaces of one size. Loops forever.
Result<Done, PlotStatus> writeApng(const std::vector<cairo_surface_t*>& frames, int delay_ms, const std::string& path);

}  // namespace cyber::plot
