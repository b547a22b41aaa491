// report/canvas.hpp: a small CPU rasteriser into an RGBA8 buffer for the report's plots: filled
// rectangles, anti-aliased lines and markers, bitmap text (stb_easy_font), image blits, PNG out.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace asvgf::report {

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

enum class Marker { Circle, Square, Triangle, Diamond, Cross };

class Canvas {
 public:
  Canvas(std::uint32_t width, std::uint32_t height, Rgba background = {255, 255, 255, 255});

  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  std::span<const std::uint8_t> pixels() const { return pixels_; }

  // Blends `c` over the pixel with extra coverage in [0,1]; outside the canvas: nothing.
  void blend(int x, int y, Rgba c, double coverage = 1.0);
  // Pixels with x0 <= x < x1, y0 <= y < y1.
  void fill_rect(int x0, int y0, int x1, int y1, Rgba c);
  void rect_outline(int x0, int y0, int x1, int y1, Rgba c);
  // Anti-aliased segment of the given width (pixel centres at +0.5).
  void line(double x0, double y0, double x1, double y1, Rgba c, double width = 1.5);
  void marker(double x, double y, Marker shape, double size, Rgba c);
  // Text with its top-left corner at (x, y); `scale` multiplies the ~7 px high font. Returns the
  // width drawn. text_width() measures without drawing.
  int text(int x, int y, std::string_view text, Rgba c, int scale = 1);
  static int text_width(std::string_view text, int scale = 1);
  static int text_height(int scale = 1) { return 8 * scale; }
  // Copies an RGBA8 image (rows top to bottom), each pixel as a zoom x zoom block.
  void blit(std::span<const std::uint8_t> rgba, std::uint32_t w, std::uint32_t h, int x, int y, int zoom = 1);

  void write_png(const std::filesystem::path& path) const;

 private:
  std::uint32_t width_, height_;
  std::vector<std::uint8_t> pixels_;
};

}  // namespace asvgf::report
