// Test helper: a few frames of one method rendered on a device (software BVH), and their per-pixel
// luminance comparison at the rounding of what they store, for the backend parity tests (OpenGL, WGSL in
// Dawn).
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "renderer/renderer.hpp"
#include "renderer/scene/builtin.hpp"

namespace frame_parity {

using namespace asvgf;

struct Difference {
  int over = 0;      // pixels whose luminance differs by more than the tolerance
  double worst = 0;  // largest relative luminance difference
  double mean = 0;   // mean relative luminance difference
};

// Histories and filter outputs are fp16: a value rounds to 2^-11 relative at each store, and the
// chain stores a pixel a handful of times, so four ulps bound what rounding alone explains.
constexpr double kUlps = 4.0 / 2048.0;
// svgf's and asvgf's colour histories and temporal results are RGB9E5 words (shaders/common/color.glsl),
// which round to steps of up to 2^-8 of the largest channel: where the backends' last bits flip one
// such rounding, the pixel moves by that step, and the next frames carry it on.
inline double pixel_tolerance(frame::Method method) {
  return method == frame::Method::Svgf || method == frame::Method::Asvgf ? kUlps + 1.0 / 256.0 : kUlps;
}

inline Difference compare(const std::vector<float>& a, const std::vector<float>& b, double tolerance) {
  Difference d;
  const std::size_t pixels = a.size() / 4;
  for (std::size_t p = 0; p < pixels; ++p) {
    auto lum = [p](const std::vector<float>& v) {
      return 0.2126 * v[4 * p] + 0.7152 * v[4 * p + 1] + 0.0722 * v[4 * p + 2];
    };
    const double la = lum(a), lb = lum(b);
    const double rel = std::fabs(la - lb) / std::max({std::fabs(la), std::fabs(lb), 1e-3});
    if (rel > tolerance) ++d.over;
    d.worst = std::max(d.worst, rel);
    d.mean += rel / static_cast<double>(pixels);
  }
  return d;
}

inline std::vector<std::vector<float>> frames(hal::Device& device, frame::Method method, int count) {
  render::RenderSettings s;
  s.method = method;
  s.width = 32;
  s.height = 24;
  s.seed = 5;
  s.spp = method == frame::Method::Reference ? 2 : 1;
  s.ray_query = false;
  const scene::Scene scene = scene::builtin_scene("cornell", "boxes-move");  // the renderer keeps a reference
  render::Renderer r(device, scene, s);
  std::vector<std::vector<float>> out;
  for (int f = 0; f < count; ++f) out.push_back(r.render(f).hdr);
  return out;
}

}  // namespace frame_parity
