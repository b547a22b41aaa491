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
//   illumination  rgb   linear radiance of this frame divided by its albedo: radiance / max(albedo,
//                       1e-3) per channel (demodulated). Not demodulating: pass albedo = 1 and the
//                       radiance, and the filters blur texture detail. NaN/Inf samples are dropped
//                       before the histories and counted (sanitised()); values are clamped to
//                       [0, 65504].
//   albedo        rgb   what the output is multiplied by (the demodulation albedo).
//   normal        xyz   world-space surface normal at the primary hit, any length (0 = background).
//   depth         x     linear view depth (distance along the camera's forward axis, any unit),
//                       > 0; 0, negative or not finite = background (sky, miss).
//                 y     optional: max(|dz/dx|, |dz/dy|) in depth units per pixel
//                       (DenoiserConfig::depth_gradient_given); else estimated from the neighbours.
//   motion        xy    where this pixel's surface point was in the previous frame, minus where it is
//                       now, in pixels (previous - current; x right, y down). A point that was not on
//                       screen: any value that lands outside the image (e.g. -1e6).
//   gradient_samples    A-SVGF only, ceil(w/3) x ceil(h/3): per 3x3 stratum, x = the luminance of
//                       the previous frame's illumination at the sample, y = the sample's pixel in
//                       the stratum (0..8, row-major: pixel 3*s + (i%3, i/3)), -1 = no sample. The
//                       renderer must have shaded that pixel of `illumination` at last frame's surface
//                       point, forward-projected into this frame, with last frame's random numbers
//                       (Schied et al. 2018, section 4). A frame without gradient samples is treated
//                       as a frame where nothing moved (constant alpha). A renderer that cannot
//                       re-shade sets settings.gradient_source = GradientSource::Reprojected: the
//                       denoiser then estimates the gradient from this frame's noisy luminance
//                       against last frame's, reprojected, and ignores gradient_samples.
//   radiance      out   RGBA32F storage image: the denoised radiance (re-modulated by albedo); never
//                       NaN or Inf (non-finite pixels are written as 0 and counted).
//   display       out   optional RGBA8Unorm storage image: exposure, tone curve, sRGB encoding.
//
// Inputs are left in hal::State::ShaderRead, outputs in DenoiserOutputs::final_state.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "asvgf/denoise_settings.hpp"
#include "hal/command_list.hpp"
#include "hal/device.hpp"

namespace asvgf {

// Ema: temporal accumulation only; Svgf: + variance-guided a-trous filter (Schied et al. 2017);
// Asvgf: + the temporal gradient's adaptive blend factor (Schied, Peters, Dachsbacher 2018).
enum class DenoiseMethod { Ema, Svgf, Asvgf };

// An image of yours: its handle, its format, and the state it is in when the frame's commands run.
struct DenoiserImage {
  hal::ImageHandle image;
  hal::Format format = hal::Format::Undefined;
  hal::State state = hal::State::Undefined;
};

struct DenoiserInputs {
  DenoiserImage illumination, albedo, normal, depth, motion;
  std::optional<DenoiserImage> gradient_samples;  // A-SVGF; see the table above
  bool camera_cut = false;                        // true: forget every history before this frame
};

struct DenoiserOutputs {
  DenoiserImage radiance;                // RGBA32F
  std::optional<DenoiserImage> display;  // RGBA8Unorm
  hal::State final_state = hal::State::ShaderRead;
};

struct DenoiserConfig {
  std::uint32_t width = 0, height = 0;
  DenoiseMethod method = DenoiseMethod::Asvgf;
  DenoiseSettings settings;           // `adaptive` is set from the method
  bool depth_gradient_given = false;  // depth.y holds the depth gradient
  // Check every frame's inputs on the GPU against the conventions above (one extra pass that
  // counts with atomics); input_report() says what is wrong, in words.
  bool validate = false;
};

// What DenoiserConfig::validate found in the last frame's inputs (counts of pixels).
struct InputReport {
  std::uint32_t pixels = 0, surface_pixels = 0;  // surface: depth finite and > 0
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

  struct PassTime {
    std::string pass;
    std::optional<double> gpu_ms;  // empty when the device has no timestamps
  };
  // GPU time per pass of the last frame; call after the device finished it.
  std::vector<PassTime> timings();
  struct Sanitised {
    std::uint32_t nan_samples = 0, inf_samples = 0, clamped_samples = 0, zeroed_outputs = 0;
  };
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
