#include "cyber/plot/apng_writer.hpp"

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <fstream>

#include "drawing.hpp"

namespace cyber::plot {
namespace {

constexpr uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

struct Chunk {
  std::string type;
  std::vector<uint8_t> data;
};

cairo_status_t appendBytes(void* closure, const unsigned char* data, unsigned int length) {
  auto* out = static_cast<std::vector<uint8_t>*>(closure);
  out->insert(out->end(), data, data + length);
  return CAIRO_STATUS_SUCCESS;
}

uint32_t be32(const uint8_t* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | uint32_t{p[3]};
}

void putBe32(std::vector<uint8_t>& out, uint32_t v) {
  const uint8_t bytes[4] = {static_cast<uint8_t>(v >> 24), static_cast<uint8_t>(v >> 16), static_cast<uint8_t>(v >> 8),
                            static_cast<uint8_t>(v)};
  out.insert(out.end(), bytes, bytes + 4);
}

// The chunks of a PNG that cairo wrote; false when the bytes are not a PNG.
bool chunksOf(const std::vector<uint8_t>& png, std::vector<Chunk>* chunks) {
  if (png.size() < 8 || std::memcmp(png.data(), kSignature, 8) != 0) return false;
  size_t at = 8;
  while (at + 12 <= png.size()) {
    const uint32_t length = be32(&png[at]);
    if (at + 12 + length > png.size()) return false;
    chunks->push_back(Chunk{std::string(reinterpret_cast<const char*>(&png[at + 4]), 4),
                            std::vector<uint8_t>(png.begin() + static_cast<long>(at + 8),
                                                 png.begin() + static_cast<long>(at + 8 + length))});
    at += 12 + length;
  }
  return at == png.size();
}

void putChunk(std::vector<uint8_t>& out, const std::string& type, const std::vector<uint8_t>& data) {
  putBe32(out, static_cast<uint32_t>(data.size()));
  const size_t type_at = out.size();
  out.insert(out.end(), type.begin(), type.end());
  out.insert(out.end(), data.begin(), data.end());
  const uLong crc = crc32(0L, &out[type_at], static_cast<uInt>(4 + data.size()));
  putBe32(out, static_cast<uint32_t>(crc));
}

}  // namespace

Result<Done, PlotStatus> writeApng(const std::vector<cairo_surface_t*>& frames, int delay_ms, const std::string& path) {
  auto fail = [&](PlotStatus status, const std::string& what) { return detail::pictureError(status, path, what); };
  if (frames.empty()) return fail(PlotStatus::kNothingToDraw, "no frames");
  std::vector<uint8_t> out(kSignature, kSignature + 8);
  uint32_t sequence = 0;
  std::vector<uint8_t> ihdr;
  for (size_t f = 0; f < frames.size(); ++f) {
    std::vector<uint8_t> png;
    if (cairo_surface_write_to_png_stream(frames[f], appendBytes, &png) != CAIRO_STATUS_SUCCESS)
      return fail(PlotStatus::kCannotEncode, "cairo cannot encode a frame");
    std::vector<Chunk> chunks;
    if (!chunksOf(png, &chunks) || chunks.empty() || chunks.front().type != "IHDR")
      return fail(PlotStatus::kCannotEncode, "cairo wrote no PNG");
    if (f == 0) {
      ihdr = chunks.front().data;
      putChunk(out, "IHDR", ihdr);
      std::vector<uint8_t> actl;
      putBe32(actl, static_cast<uint32_t>(frames.size()));
      putBe32(actl, 0);  // plays: forever
      putChunk(out, "acTL", actl);
    } else if (chunks.front().data != ihdr) {
      return fail(PlotStatus::kCannotEncode, "frames differ in size or format");
    }
    std::vector<uint8_t> fctl;
    putBe32(fctl, sequence++);
    fctl.insert(fctl.end(), ihdr.begin(), ihdr.begin() + 8);  // width, height
    putBe32(fctl, 0);                                         // x offset
    putBe32(fctl, 0);                                         // y offset
    fctl.push_back(static_cast<uint8_t>(delay_ms >> 8));
    fctl.push_back(static_cast<uint8_t>(delay_ms));
    fctl.push_back(0x03);  // delay denominator 1000: milliseconds
    fctl.push_back(0xe8);
    fctl.push_back(0);  // dispose: none
    fctl.push_back(0);  // blend: source
    putChunk(out, "fcTL", fctl);
    for (const Chunk& c : chunks) {
      if (c.type != "IDAT") continue;
      if (f == 0) {
        putChunk(out, "IDAT", c.data);
      } else {
        std::vector<uint8_t> fdat;
        putBe32(fdat, sequence++);
        fdat.insert(fdat.end(), c.data.begin(), c.data.end());
        putChunk(out, "fdAT", fdat);
      }
    }
  }
  putChunk(out, "IEND", {});
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()));
  file.close();
  if (!file) return fail(PlotStatus::kCannotWrite, "cannot write");
  return Done{};
}

}  // namespace cyber::plot
