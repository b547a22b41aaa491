// cpu_oracle/denoise_reference.hpp: CPU implementations, in double precision, of the denoiser passes
// (shaders/denoise/*.comp), used by tests. Each function mirrors its shader: same taps, weights,
// guards and clamps; only the precision differs (and fp16 stores, which the tests' tolerances cover).
// Images use the channel layouts of the GPU resources:
//   illumination 4 (rgb), depth_normal 4 (z, dz, oct normal: what the GPU's 8-byte texel holds,
//   cpu_oracle/depth_normal.hpp), motion 2, gradient_prev 2,
//   gradient 4 (delta, Delta, 0, 0), colour images 4 (rgb, variance), moments 4 (E[l], sqrt(Var[l]), n, 0),
//   albedo 4.
#pragma once

#include <cstdint>

#include "cpu_oracle/image.hpp"

namespace asvgf::reference {

// pack_surface.comp: depth (x linear depth, y its gradient when `depth_gradient_given`) and normal
// (xyz) as depth_normal (z, dz, octahedral normal, each rounded as the texel rounds it), all zero on
// background.
ImageD pack_surface(const ImageD& depth, const ImageD& normal, bool depth_gradient_given);

// convert_inputs.comp: a renderer's colour (radiance when `color_is_radiance`), albedo and motion
// as the denoiser's illumination, re-modulation albedo and motion (scale_x, scale_y:
// asvgf::motion_scale).
struct ConvertedInputs {
  // 4 channels each (rgb, rgb, xy); radiance in: the modulation's rgb as its RGB9E5 word holds it
  ImageD illumination, modulation, motion;
};
ConvertedInputs convert_inputs(const ImageD& color, const ImageD& albedo, const ImageD& motion, bool color_is_radiance,
                               double scale_x, double scale_y);

// gradient.comp: (delta, Delta) per 3x3 stratum, ceil(w/3) x ceil(h/3); `current_given`: l_cur is
// gradient_prev's third channel (the `given` variant), else the sample's pixel of `illumination`.
ImageD gradient(const ImageD& illumination, const ImageD& gradient_prev, bool current_given = false);

struct ReprojectedGradientInputs {
  const ImageD* illumination = nullptr;
  const ImageD* motion = nullptr;
  const ImageD* depth_normal = nullptr;
  const ImageD* prev_depth_normal = nullptr;
  const ImageD* prev_luminance = nullptr;  // 1 channel used
  bool history_valid = true;
};
struct ReprojectedGradientResult {
  ImageD gradient;   // (delta, Delta, 0, 0) per stratum
  ImageD luminance;  // this frame's, per pixel (channel 0)
};
// gradient_reprojected.comp
ReprojectedGradientResult gradient_reprojected(const ReprojectedGradientInputs& in);

struct GradientAtrousParams {
  int step = 1;
  double sigma_z = 1, sigma_n = 128;
};
// gradient_atrous.comp: one iteration at 1/3 resolution, guided by the full-resolution depth_normal.
ImageD gradient_atrous(const ImageD& gradient_in, const ImageD& depth_normal, const GradientAtrousParams& params);

struct TemporalParams {
  double alpha = 0.2, moments_alpha = 0.2, history_cap = 32;
  bool history_valid = true;
  double antilag = 8;  // DenoiseSettings::antilag
};
struct TemporalInputs {
  const ImageD* illumination = nullptr;
  const ImageD* motion = nullptr;
  const ImageD* depth_normal = nullptr;
  const ImageD* prev_depth_normal = nullptr;
  const ImageD* prev_color = nullptr;
  const ImageD* prev_moments = nullptr;
  const ImageD* gradient = nullptr;  // null: constant alpha
};
struct TemporalResult {
  ImageD integrated;  // rgb, temporal variance
  ImageD moments;     // E[l], sqrt(Var[l]), n, 0 (common/denoise.glsl: Moments)
  std::uint32_t nan_samples = 0, inf_samples = 0;
  std::uint32_t clamped_samples = 0;  // finite, a component at or above kFp16Max
};
// temporal.comp
TemporalResult temporal(const TemporalInputs& in, const TemporalParams& params);

struct VarianceParams {
  double sigma_z = 1, sigma_n = 128, sigma_l = 4, min_history = 4;
};
// variance.comp: rgb colour, a variance. `albedo`: what the signal is re-modulated by (rgb).
ImageD variance(const ImageD& integrated, const ImageD& moments, const ImageD& depth_normal, const ImageD& albedo,
                const VarianceParams& params);

struct AtrousParams {
  int step = 1;
  int kernel = 0;  // 0: B3 spline, its 13 taps with |i| + |j| <= 2 (atrous.comp), 1: 3x3 box
  double sigma_z = 1, sigma_n = 128, sigma_l = 4;
};
// atrous.comp: one iteration.
ImageD atrous(const ImageD& color_in, const ImageD& depth_normal, const AtrousParams& params);

struct CompositeResult {
  ImageD hdr;      // rgb radiance, a = 1
  ImageD display;  // sRGB-encoded in [0, 1] before the 8-bit store, a = 1
};
// composite.comp; tonemap 0: clamp, 1: ACES (Narkowicz).
CompositeResult composite(const ImageD& illumination, const ImageD& albedo, double exposure, int tonemap);

// local_mean.comp: the filtered colour (alpha kept) scaled toward the temporal result's local mean
// of luminance, by the gate or by the plain ratio. The mean: sums over blocks of `block` pixels, a
// box of (2 radius + 1)^2 blocks around each block (clamped to the image, weighted by the pixels in
// it), read between the four nearest blocks' centres bilinearly; block 1 is a plain box of
// 2 radius + 1 pixels a side.
ImageD local_mean(const ImageD& temporal, const ImageD& filtered, int block, int radius, bool gated);

}  // namespace asvgf::reference
