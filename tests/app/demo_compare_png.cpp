// demo_compare_png A.png B.png [MAX_DIFF [MAX_FRACTION]]: compares two 8-bit PNGs of the same size
// channel by channel (RGB; alpha ignored). Prints the largest and mean absolute difference in 8-bit
// steps and how many pixels differ; exits 0 when no channel differs by more than MAX_DIFF (default
// 0) and at most MAX_FRACTION of the pixels differ at all (default 1), 1 otherwise or when A is all
// black, 2 when a file cannot be read or the sizes differ.
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wuseless-cast"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
// Private copy (as pipeline/renderer/scene/image.cpp): Debian's libstb.so exports the same symbols.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace {

struct Png {
  int width = 0, height = 0;
  std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> pixels{nullptr, &stbi_image_free};
};

bool load(const char* path, Png& png) {
  int channels = 0;
  png.pixels.reset(stbi_load(path, &png.width, &png.height, &channels, 4));
  if (!png.pixels) std::fprintf(stderr, "demo_compare_png: %s: %s\n", path, stbi_failure_reason());
  return png.pixels != nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 5) {
    std::fprintf(stderr, "usage: demo_compare_png A.png B.png [MAX_DIFF [MAX_FRACTION]]\n");
    return 2;
  }
  const int allowed = argc >= 4 ? std::atoi(argv[3]) : 0;
  const double allowed_fraction = argc >= 5 ? std::atof(argv[4]) : 1.0;
  Png a, b;
  if (!load(argv[1], a) || !load(argv[2], b)) return 2;
  if (a.width != b.width || a.height != b.height) {
    std::fprintf(stderr, "demo_compare_png: sizes differ: %dx%d vs %dx%d\n", a.width, a.height, b.width, b.height);
    return 2;
  }
  int worst = 0, worst_x = 0, worst_y = 0;
  long long sum = 0, differing = 0, lit = 0;
  const int pixels = a.width * a.height;
  for (int i = 0; i < pixels; ++i) {
    bool differs = false;
    for (int c = 0; c < 3; ++c) {
      const int va = a.pixels.get()[4 * i + c], vb = b.pixels.get()[4 * i + c];
      const int d = std::abs(va - vb);
      sum += d;
      differs = differs || d > 0;
      if (va > 0) ++lit;
      if (d > worst) {
        worst = d;
        worst_x = i % a.width;
        worst_y = i / a.width;
      }
    }
    if (differs) ++differing;
  }
  std::printf("demo_compare_png: %dx%d, max difference %d at (%d,%d), mean %.4f, %lld of %d pixels differ, "
              "%lld non-zero channels; allowed: max %d, fraction %.4f\n",
              a.width, a.height, worst, worst_x, worst_y, static_cast<double>(sum) / (3.0 * pixels), differing, pixels,
              lit, allowed, allowed_fraction);
  if (lit == 0) {
    std::printf("demo_compare_png: FAIL: the first image is black\n");
    return 1;
  }
  const bool ok = worst <= allowed && static_cast<double>(differing) <= allowed_fraction * pixels;
  std::printf("demo_compare_png: %s\n", ok ? "match" : "FAIL");
  return ok ? 0 : 1;
}
