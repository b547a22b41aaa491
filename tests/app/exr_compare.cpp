// exr_compare A_PATTERN B_PATTERN FIRST COUNT [MAX_RELMSE]: compares two EXR frame sequences
// (printf-style patterns, RGB) frame by frame. Prints per frame the relative MSE of B against A
// (as metrics.csv computes it), B's mean over A's minus 1 (the energy bias), the largest absolute
// difference and how many values differ at all;
// exits 0 when every frame's relMSE is at most MAX_RELMSE (default 0: bit-identical), 1 otherwise,
// 2 when a file cannot be read or the sizes differ.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "frame_pattern.hpp"
#include "io/image_io.hpp"
#include "report/metrics.hpp"

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: exr_compare A_PATTERN B_PATTERN FIRST COUNT [MAX_RELMSE]\n");
    return 2;
  }
  const int first = std::atoi(argv[3]), count = std::atoi(argv[4]);
  const double max_relmse = argc > 5 ? std::atof(argv[5]) : 0.0;
  bool ok = true;
  double worst = 0;
  try {
    for (int f = first; f < first + count; ++f) {
      const auto a = asvgf::render::read_exr(expand_frame_pattern(argv[1], f));
      const auto b = asvgf::render::read_exr(expand_frame_pattern(argv[2], f));
      if (a.width != b.width || a.height != b.height) {
        std::fprintf(stderr, "exr_compare: frame %d: %ux%u against %ux%u\n", f, a.width, a.height, b.width, b.height);
        return 2;
      }
      double max_abs = 0, sum_a = 0, sum_b = 0;
      std::size_t differ = 0;
      for (std::size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        sum_a += a.rgba[i], sum_b += b.rgba[i];
        if (a.rgba[i] != b.rgba[i]) {
          ++differ;
          max_abs = std::max(max_abs, double(std::fabs(a.rgba[i] - b.rgba[i])));
        }
      }
      const double relmse = asvgf::render::relative_mse(b.rgba, a.rgba);
      worst = std::max(worst, relmse);
      std::printf("frame %d: relMSE %.3g, energy bias %+.2f%%, max |difference| %.3g, %zu of %zu values differ\n", f,
                  relmse, sum_a > 0 ? 100.0 * (sum_b / sum_a - 1.0) : 0.0, max_abs, differ, a.rgba.size() / 4 * 3);
      ok = ok && (max_relmse > 0 ? relmse <= max_relmse : differ == 0);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exr_compare: %s\n", e.what());
    return 2;
  }
  std::printf("exr_compare: %s (worst relMSE %.3g, allowed %s)\n", ok ? "match" : "DIFFER", worst,
              max_relmse > 0 ? std::to_string(max_relmse).c_str() : "bit-identical");
  return ok ? 0 : 1;
}
