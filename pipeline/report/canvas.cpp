#include "report/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "io/image_io.hpp"

// stb_easy_font is a header of static functions; some are unused here and it uses old-style casts.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace asvgf::report {

Canvas::Canvas(std::uint32_t width, std::uint32_t height, Rgba bg)
    : width_(width), height_(height), pixels_(std::size_t(width) * height * 4) {
  for (std::size_t i = 0; i < pixels_.size(); i += 4) {
    pixels_[i] = bg.r, pixels_[i + 1] = bg.g, pixels_[i + 2] = bg.b, pixels_[i + 3] = bg.a;
  }
}

void Canvas::blend(int x, int y, Rgba c, double coverage) {
  if (x < 0 || y < 0 || x >= int(width_) || y >= int(height_) || coverage <= 0.0) return;
  const double a = std::min(1.0, coverage) * c.a / 255.0;
  std::uint8_t* p = &pixels_[(std::size_t(y) * width_ + std::size_t(x)) * 4];
  const std::uint8_t src[3] = {c.r, c.g, c.b};
  for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(std::lround(p[k] * (1.0 - a) + src[k] * a));
  p[3] = 255;
}

void Canvas::fill_rect(int x0, int y0, int x1, int y1, Rgba c) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0);
  x1 = std::min(x1, int(width_)), y1 = std::min(y1, int(height_));
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) blend(x, y, c);
}

void Canvas::rect_outline(int x0, int y0, int x1, int y1, Rgba c) {
  fill_rect(x0, y0, x1, y0 + 1, c);
  fill_rect(x0, y1 - 1, x1, y1, c);
  fill_rect(x0, y0, x0 + 1, y1, c);
  fill_rect(x1 - 1, y0, x1, y1, c);
}

void Canvas::line(double x0, double y0, double x1, double y1, Rgba c, double width) {
  // Coverage from the distance of each pixel centre to the segment: cheap and smooth enough.
  const double r = width / 2.0;
  const int bx0 = int(std::floor(std::min(x0, x1) - r - 1)), bx1 = int(std::ceil(std::max(x0, x1) + r + 1));
  const int by0 = int(std::floor(std::min(y0, y1) - r - 1)), by1 = int(std::ceil(std::max(y0, y1) + r + 1));
  const double dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
  for (int y = std::max(by0, 0); y <= std::min(by1, int(height_) - 1); ++y)
    for (int x = std::max(bx0, 0); x <= std::min(bx1, int(width_) - 1); ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const double t = len2 > 0 ? std::clamp(((px - x0) * dx + (py - y0) * dy) / len2, 0.0, 1.0) : 0.0;
      const double d = std::hypot(px - (x0 + t * dx), py - (y0 + t * dy));
      blend(x, y, c, std::clamp(r + 0.5 - d, 0.0, 1.0));
    }
}

void Canvas::marker(double cx, double cy, Marker shape, double size, Rgba c) {
  const double h = size / 2.0;
  auto inside = [&](double px, double py) {
    const double u = px - cx, v = py - cy;
    switch (shape) {
      case Marker::Circle:
        return u * u + v * v <= h * h;
      case Marker::Square:
        return std::abs(u) <= h * 0.85 && std::abs(v) <= h * 0.85;
      case Marker::Diamond:
        return std::abs(u) + std::abs(v) <= h * 1.1;
      case Marker::Triangle:  // apex up at v = -h, base at v = +h
        return v >= -h && v <= h && std::abs(u) <= (v + h) / 2.0;
      case Marker::Cross:
        return (std::abs(u - v) <= h * 0.3 || std::abs(u + v) <= h * 0.3) && std::abs(u) <= h && std::abs(v) <= h;
    }
    return false;
  };
  // 4x4 supersampling gives the edges their coverage.
  for (int y = int(std::floor(cy - h - 1)); y <= int(std::ceil(cy + h + 1)); ++y)
    for (int x = int(std::floor(cx - h - 1)); x <= int(std::ceil(cx + h + 1)); ++x) {
      int hits = 0;
      for (int sy = 0; sy < 4; ++sy)
        for (int sx = 0; sx < 4; ++sx) hits += inside(x + (sx + 0.5) / 4.0, y + (sy + 0.5) / 4.0) ? 1 : 0;
      blend(x, y, c, hits / 16.0);
    }
}

int Canvas::text(int x, int y, std::string_view s, Rgba c, int scale) {
  std::string copy(s);
  // stb guesses ~270 bytes a character on average; a single glyph takes up to ~10 quads of 64 bytes.
  std::vector<char> quads(copy.size() * 1024 + 64);
  const int n = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, quads.data(), int(quads.size()));
  for (int q = 0; q < n; ++q) {
    float v[4][2];
    for (int k = 0; k < 4; ++k) {
      const char* vertex = quads.data() + (std::size_t(q) * 4 + std::size_t(k)) * 16;
      std::copy_n(vertex, sizeof v[k], reinterpret_cast<char*>(v[k]));
    }
    const float qx0 = std::min({v[0][0], v[1][0], v[2][0], v[3][0]}),
                qx1 = std::max({v[0][0], v[1][0], v[2][0], v[3][0]});
    const float qy0 = std::min({v[0][1], v[1][1], v[2][1], v[3][1]}),
                qy1 = std::max({v[0][1], v[1][1], v[2][1], v[3][1]});
    fill_rect(x + int(qx0 * float(scale)), y + int(qy0 * float(scale)), x + int(qx1 * float(scale)),
              y + int(qy1 * float(scale)), c);
  }
  return text_width(s, scale);
}

int Canvas::text_width(std::string_view s, int scale) {
  std::string copy(s);
  return stb_easy_font_width(copy.data()) * scale;
}

void Canvas::blit(std::span<const std::uint8_t> rgba, std::uint32_t w, std::uint32_t h, int x, int y, int zoom) {
  for (std::uint32_t sy = 0; sy < h; ++sy)
    for (std::uint32_t sx = 0; sx < w; ++sx) {
      const std::uint8_t* p = &rgba[(std::size_t(sy) * w + sx) * 4];
      fill_rect(x + int(sx) * zoom, y + int(sy) * zoom, x + int(sx + 1) * zoom, y + int(sy + 1) * zoom,
                Rgba{p[0], p[1], p[2], 255});
    }
}

void Canvas::write_png(const std::filesystem::path& path) const {
  render::write_png(path, width_, height_, pixels_);
}

}  // namespace asvgf::report
