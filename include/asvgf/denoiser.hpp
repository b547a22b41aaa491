// asvgf/denoiser.hpp: A-SVGF (or SVGF, or a temporal moving average) over your renderer's own
// buffers, on any hal::Device (hal/hal.hpp; hal_vulkan/vulkan.hpp opens a Vulkan one).
//
//   asvgf::Denoiser denoiser(device, {.width = w, .height = h});
//   per frame, after your renderer wrote its buffers:
//     denoiser.record(commands, inputs, outputs);   // then submit `commands`
//   or, for the simple case, denoiser.denoise(inputs, outputs) (records, submits, waits).
//
// Conventions (README "Use it in your renderer" has the same table). Every input is read with
// texelFetch, so any float format with enough channels works (RGBA32F, RGBA16F, RG16F, R32F, ...);
// integer and 8-bit formats are refused. Pixel (0,0) is the top-left; sizes are the denoiser's.
//
//   color         rgb   this frame's noisy linear radiance (DenoiserConfig::color_input Radiance,
//                       the default): the denoiser divides it by the albedo itself, per channel where
//                       the albedo is at least 1e-3 (elsewhere the radiance passes through), filters
//                       and multiplies back. With ColorInput::Demodulated: radiance already divided by
//                       the albedo. NaN/Inf samples are dropped before the histories and counted
//                       (sanitised()); values are clamped to [0, 65504].
//   albedo        rgb   the surface's albedo (for emitters, whatever the renderer divides by: Cycles'
//                       Denoising Albedo holds their emission, which is then filtered as 1 and
//                       multiplied back). Albedo 1 everywhere: no demodulation, and the filters blur
//                       texture detail.
//   normal        xyz   world-space surface normal at the primary hit, any length (0 = background).
//   depth         x     linear view depth (distance along the camera's forward axis, any unit),
//                       > 0. Background (sky, miss): 0, negative, not finite or >= kBackgroundDepth
//                       (1e9: Cycles writes 1e10), or a zero normal; is_background() decides.
//                 y     optional: max(|dz/dx|, |dz/dy|) in depth units per pixel
//                       (DenoiserConfig::depth_gradient_given); else estimated from the neighbours.
//   motion        xy    where this pixel's surface point was in the previous frame, minus where it is
//                       now, in pixels (previous - current; x right, y down): MotionConvention::ours().
//                       Other conventions (sign, UV or NDC units, y up) are converted when
//                       DenoiserConfig::motion says so (presets: cycles(), nrd()). A point that was not
//                       on screen: any value that lands outside the image (e.g. -1e6).
//   gradient_samples    A-SVGF only, ceil(w/3) x ceil(h/3): per 3x3 stratum, x = the luminance of
//                       the previous frame's illumination at the sample, y = the sample's pixel in
//                       the stratum (0..8, row-major: pixel 3*s + (i%3, i/3)), -1 = no sample. The
//                       renderer re-shades the sample at last frame's surface point, forward-projected
//                       into this frame, with last frame's random numbers (Schied et al. 2018,
//                       section 4), either apart (recommended; DenoiserConfig::gradient_current_given):
//                       z = its luminance, in x's units (negative or not finite: missing), and
//                       every pixel of `illumination` is a fresh sample; or as that pixel of
//                       `illumination` itself, which then repeats a sample its history already
//                       holds (1 pixel in 9 gets nothing new). A frame without gradient samples is treated
//                       as a frame where nothing moved (constant alpha). A renderer that cannot
//                       re-shade sets settings.gradient_source = GradientSource::Reprojected: the
//                       denoiser then estimates the gradient from this frame's noisy luminance
//                       against last frame's, reprojected, and ignores gradient_samples.
//   radiance      out   RGBA32F or RGBA16F storage image: the denoised radiance (re-modulated by
//                       albedo); never NaN or Inf (non-finite pixels are written as 0 and counted).
//                       RGBA16F: rounded to the nearest half (below 2^-14 the last bit is the
//                       store's), at most 65504: 8 bytes a pixel less written, and the filter's
//                       histories are half floats already.
//   display       out   optional RGBA8Unorm storage image: exposure, tone curve, sRGB encoding.
//
// Inputs are left in hal::State::ShaderRead, outputs in DenoiserOutputs::final_state.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "asvgf/denoise_settings.hpp"
#include "asvgf/denoiser_stats.hpp"
#include "hal/command_list.hpp"
#include "hal/device.hpp"

namespace asvgf {

// The one definition of background (no surface at the pixel), used by the denoiser's passes
// (shaders/common/surface.glsl), its input validation and the command line's checks.
inline constexpr double kBackgroundDepth = 1e9;
inline bool is_background_depth(double depth) {
  return !std::isfinite(depth) || depth <= 0 || depth >= kBackgroundDepth;
}
inline bool is_background(double depth, const std::array<double, 3>& normal) {
  const double l1 = std::abs(normal[0]) + std::abs(normal[1]) + std::abs(normal[2]);
  return is_background_depth(depth) || !std::isfinite(l1) || !(l1 >= 1e-30);
}

// An image of yours: its handle, its format, and the state it is in when the frame's commands run.
struct DenoiserImage {
  hal::ImageHandle image;
  hal::Format format = hal::Format::Undefined;
  hal::State state = hal::State::Undefined;
};

struct DenoiserInputs {
  DenoiserImage illumination, albedo, normal, depth, motion;  // illumination: the `color` above
  std::optional<DenoiserImage> gradient_samples;              // A-SVGF; see the table above
  bool camera_cut = false;                                    // true: forget every history before this frame
};

struct DenoiserOutputs {
  DenoiserImage radiance;                // RGBA32F or RGBA16F
  std::optional<DenoiserImage> display;  // RGBA8Unorm
  hal::State final_state = hal::State::ShaderRead;
};

// What DenoiserInputs::illumination holds.
enum class ColorInput {
  Radiance,     // the renderer's radiance: the denoiser demodulates by the albedo and re-modulates
  Demodulated,  // radiance already divided by the albedo (asvgf render --aovs writes this)
};

// How a renderer's motion vectors are written; the denoiser converts them to ours().
enum class MotionUnits {
  Pixels,  // one unit = one pixel
  Uv,      // one unit = the image's width (x) or height (y)
  Ndc,     // one unit = half the image's width or height (NDC spans [-1, 1])
};
struct MotionConvention {
  bool previous_minus_current = true;  // false: current minus previous (the vector points forward)
  MotionUnits units = MotionUnits::Pixels;
  bool y_up = false;  // true: +y points up the image
  static constexpr MotionConvention ours() { return {}; }
  // Blender Cycles' Vector pass, X and Y: previous minus current, in pixels, y up.
  static constexpr MotionConvention cycles() { return {true, MotionUnits::Pixels, true}; }
  // NVIDIA NRD's screen-space motion (IN_MV): previous minus current UV, y down.
  static constexpr MotionConvention nrd() { return {true, MotionUnits::Uv, false}; }
  bool operator==(const MotionConvention&) const = default;
};
// What the denoiser multiplies a vector in convention `c` by, per axis, to get ours() (pixels,
// previous minus current, y down) on a width x height image; the GPU applies the same factors.
inline std::array<float, 2> motion_scale(const MotionConvention& c, std::uint32_t width, std::uint32_t height) {
  const float unit_x = c.units == MotionUnits::Pixels ? 1.0f
                       : c.units == MotionUnits::Uv   ? float(width)
                                                      : 0.5f * float(width);
  const float unit_y = c.units == MotionUnits::Pixels ? 1.0f
                       : c.units == MotionUnits::Uv   ? float(height)
                                                      : 0.5f * float(height);
  const float sign = c.previous_minus_current ? 1.0f : -1.0f;
  return {sign * unit_x, sign * (c.y_up ? -unit_y : unit_y)};
}

struct DenoiserConfig {
  std::uint32_t width = 0, height = 0;
  DenoiseMethod method = DenoiseMethod::Asvgf;
  DenoiseSettings settings;
  bool depth_gradient_given = false;  // depth.y holds the depth gradient
  // gradient_samples.z holds this frame's luminance of each re-shaded sample, shaded apart from
  // `illumination` (see gradient_samples above).
  bool gradient_current_given = false;
  ColorInput color_input = ColorInput::Radiance;
  MotionConvention motion;
  // Check every frame's inputs on the GPU against the conventions above (one extra pass that
  // counts with atomics); input_report() says what is wrong, in words.
  bool validate = false;
};

// What DenoiserConfig::validate found in the last frame's inputs (counts of pixels).
struct InputReport {
  std::uint32_t pixels = 0, surface_pixels = 0;  // surface: not background (is_background), a non-finite normal aside
  std::uint32_t illumination_not_finite = 0, illumination_negative = 0, illumination_above_fp16 = 0;
  std::uint32_t albedo_invalid = 0;                          // NaN, Inf or negative
  std::uint32_t normal_not_unit = 0, normal_not_finite = 0;  // on surface pixels; unit: length within 0.1 of 1
  std::uint32_t depth_not_finite = 0, depth_negative = 0;
  std::uint32_t motion_not_finite = 0;
  // Surface pixels moving by 0.5 px or more (previous frame available), and how many of them land
  // on the same surface in the previous frame (depth within 5%) following the vectors as given and
  // negated.
  std::uint32_t moving_pixels = 0, moving_consistent = 0, moving_consistent_negated = 0;
  std::vector<std::string> problems;  // in words, e.g. "normals are not unit length at 12% of surface pixels"
};

class Denoiser {
 public:
  // Throws hal::Error (InvalidDescriptor) naming the setting for a size outside 1..max image
  // dimension or settings out of range.
  Denoiser(hal::Device& device, const DenoiserConfig& config);
  ~Denoiser();
  Denoiser(const Denoiser&) = delete;
  Denoiser& operator=(const Denoiser&) = delete;

  // Records this frame into `commands` (the caller submits it, before recording the next frame).
  // Throws hal::Error (InvalidUsage) naming the input for a missing image or a format the
  // denoiser cannot read or write.
  void record(hal::CommandList& commands, const DenoiserInputs& inputs, const DenoiserOutputs& outputs);
  // Records, submits and waits for the device.
  void denoise(const DenoiserInputs& inputs, const DenoiserOutputs& outputs);
  // Forgets every history: the next frame starts afresh (as DenoiserInputs::camera_cut).
  void reset();

  using PassTime = asvgf::PassTime;
  // GPU time per pass of the last frame; call after the device finished it.
  std::vector<PassTime> timings();
  using Sanitised = SanitisedCounts;
  // Samples dropped (NaN, Inf) or clamped before the histories and output pixels written as 0,
  // since creation; waits for the device.
  Sanitised sanitised();
  // With DenoiserConfig::validate: what the last frame's inputs got wrong; waits for the device.
  // Throws hal::Error (InvalidUsage) without it.
  InputReport input_report();
  const DenoiserConfig& config() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace asvgf
