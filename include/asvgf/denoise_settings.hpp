// asvgf/denoise_settings.hpp: the denoiser's parameters with their defaults and sources (public:
// asvgf::Denoiser takes them, and so do the frame, the tests and the command line).
//
// Defaults and their sources (the papers and implementations named; README "Denoiser parameters"):
//   alpha 0.2, moments_alpha 0.2, atrous_iterations 5, sigma_z 1, sigma_n 128, B3-spline kernel (its
//   13 taps with |i| + |j| <= 2: 23% faster at 1080p than all 25 with the same error,
//   docs/performance.md "Fewer taps"),
//   history_tap 0, min_history 4: SVGF paper (Schied et al. 2017) and Falcor's SVGF pass.
//   sigma_l 0, by the image's size: the paper's 4 up to 256x256 pixels, 12 from 768x768 (measured;
//   see luminance_sigma).
//   gradient_iterations 3: Q2RTX (a-trous over the gradient at 1/3 resolution).
//   antilag 8: measured with the local-mean correction (the paper's is 1; Q2RTX's flt_antilag_hf 1
//   with a history shortened by (1 - alpha)^10).
//   history_cap 32: Falcor's SVGF (Q2RTX caps at 256 with alpha_min 0.02, moments alpha 0.01).
//   specular_atrous_iterations 4: measured on `glossy` at 1080p (Q2RTX 3; docs/performance.md).
//   specular_sigma_l 0, specular_alpha 0: the diffuse chain's.
//   local_mean -1, by the image's size: a sixteenth of its smaller side, odd, 5 to 255 (measured;
//   see local_mean_window).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace asvgf {

enum class AtrousKernel : std::uint32_t { B3Spline = 0, Box = 1 };  // values are the shader's `kernel`
enum class Tonemap : std::uint32_t { Clamp = 0, Aces = 1 };         // values are the shader's `tonemap`
// Where A-SVGF's temporal gradient comes from. Reshaded: the renderer re-shades forward-projected
// samples of last frame with last frame's random numbers (the A-SVGF paper; exact, needs the
// renderer's help). Reprojected: estimated from this frame's noisy luminance against last frame's,
// reprojected (Q2RTX's low-frequency gradient; no help needed, noisier).
enum class GradientSource : std::uint32_t { Reshaded = 0, Reprojected = 1 };

// Ema: temporal accumulation only; Svgf: + variance-guided a-trous filter (Schied et al. 2017);
// Asvgf: + the temporal gradient's adaptive blend factor (Schied, Peters, Dachsbacher 2018).
enum class DenoiseMethod { Ema, Svgf, Asvgf };

struct DenoiseSettings {
  float alpha = 0.2f;          // colour blend factor (SVGF; the seed's figures use 0.2)
  float moments_alpha = 0.2f;  // moments blend factor (SVGF)
  int atrous_iterations = 5;   // SVGF
  float sigma_z = 1.0f;        // depth edge-stopping (SVGF)
  float sigma_n = 128.0f;      // normal edge-stopping exponent (SVGF; Q2RTX 64)
  // Luminance edge-stopping (SVGF: 4; Q2RTX 16). 0: by the image's size (luminance_sigma).
  float sigma_l = 0.0f;
  AtrousKernel kernel = AtrousKernel::B3Spline;  // SVGF's 5x5 B3 spline, 13 taps (|i|+|j| <= 2); Box: seed's 3x3
  int gradient_iterations = 3;                   // a-trous iterations over the 1/3-res gradient (Q2RTX)
  float history_cap = 32.0f;                     // max history length (Falcor SVGF; Q2RTX 256)
  // The a-trous iteration whose output feeds the colour history (SVGF: 0, the first); -1: the
  // temporal pass's own result, unfiltered (docs/quality.md).
  int history_tap = 0;
  GradientSource gradient_source = GradientSource::Reshaded;  // A-SVGF's gradient (see above)
  // A-SVGF's anti-lag strength: lambda = min(1, antilag |delta^| / Delta^), the blend factor's and
  // the history length's response to the temporal gradient (the paper: 1; Q2RTX's flt_antilag_hf).
  // Above 1 because the gradient, filtered over strata, dilutes a local change with the unchanged
  // light around it (docs/quality.md, "Anti-lag strength"); 8 because the local-mean correction's
  // history keeps the light the filter used to drain, the light that left included: with it 8 is at
  // least as good as 4 on every built-in scene at 1080p (8-18% better on three) and better on three
  // of four at 64x64 (`many` +1.4%; docs/quality.md, "Anti-lag 8 by default"). With the reprojected
  // gradient on noisy light 1 is better: its noise alone then shortens the history.
  float antilag = 8.0f;
  float min_history = 4.0f;         // below this, variance is estimated spatially (SVGF)
  float exposure = 1.0f;            // composite: multiplier before the tone curve
  Tonemap tonemap = Tonemap::Aces;  // composite: ACES fit (Narkowicz 2015)
  // A-trous iterations over the specular signal, where diffuse and specular light are filtered
  // apart (--specular-split): Q2RTX filters its specular channel less than its diffuse one
  // (flt_atrous_spec 3 against flt_atrous_hf 4), as a reflection has detail that normals and depth
  // do not predict; 4 measured best of 2-5 at 1080p (3 at 128 and 256 px).
  int specular_atrous_iterations = 4;
  // The specular chain's luminance edge-stopping and blend factor (--specular-split); 0: the diffuse
  // chain's (sigma_l by the image's size, alpha). A reflection's light is several times noisier than
  // the diffuse bounce (docs/quality.md, "Glossy"): these let the specular signal be filtered and
  // accumulated harder than the diffuse one without touching it.
  float specular_sigma_l = 0.0f;
  float specular_alpha = 0.0f;
  // The local-mean correction's window k (odd 3..255; -1: by the image's size, local_mean_window; 0:
  // off, the paper's filter): the filtered colour scaled toward the temporal result's local mean of
  // luminance over about k x k pixels (exactly up to k 15; above, a box of blocks read bilinearly, 72
  // pixels wide at k 65), where that mean is known better than its difference from the filtered
  // one's, and the colour history the a-trous tap feeds scaled toward it always (else the filter's
  // loss feeds back through the history). It gives back the energy the a-trous gather drops at
  // bright pixels and the local contrast it blurs (one signal; the specular chain of
  // --specular-split is not corrected): docs/quality.md, "Energy: a correction of the displayed
  // frame's local mean", "The box over blocks" and "The local mean by the image's size".
  int local_mean = -1;
};

// The luminance edge-stopping a width x height image is filtered with: settings.sigma_l, or where it
// is 0, 4 up to 256x256 pixels, rising with sqrt(width x height) to 12 at 768x768 and above. The
// filter works in pixels, and the larger the image the less neighbouring pixels differ in signal
// against their noise: on cornell/static (lavapipe) 4 is best at 256x256 (8: +27% relMSE), 6 at
// 384x384, 8 at 512x512 (-13% against 4); at 1920x1080 (H200, H100) 8 is 36-42% better than 4 and
// 12 another 12-19% better than 8 on every built-in scene, lag unchanged; 16 gains a little more but
// lags on `textured` (docs/quality.md, "sigma_l by the image's size").
float luminance_sigma(const DenoiseSettings& settings, std::uint32_t width, std::uint32_t height);

// The local-mean correction's window for a width x height image: settings.local_mean, or where it is
// -1, a sixteenth of the smaller side rounded up to odd, from 5 to 255 (0: off). The bias it corrects
// follows the filter's footprint in pixels, and a small window puts the temporal result's noise back:
// at 64x64 (lavapipe, light-exit) k 5 has 8-40% less error than none on every built-in scene, k 9
// gains less and is 8% worse on `glossy`, k 13-17 worse everywhere; on the static room k 5 / 9 give
// 44% / 18% less error with 2.6 / 1.55 times the flicker; at 256x256 k 17 / 33 24% / 17% less, 1.79
// / 1.19 times the flicker; at 1080p k 65 (an H100) 14-32% less on every built-in scene but `many`
// (-1%), the flicker within 14%, where k 33 has more error and twice the flicker (docs/quality.md,
// "The local mean by the image's size").
int local_mean_window(const DenoiseSettings& settings, std::uint32_t width, std::uint32_t height);

// Whether `method` with `settings` reads gradient samples the renderer re-shaded (A-SVGF with
// GradientSource::Reshaded): the renderer then selects and re-shades them on frames where something moved.
inline bool reshades_gradients(DenoiseMethod method, const DenoiseSettings& settings) {
  return method == DenoiseMethod::Asvgf && settings.gradient_source == GradientSource::Reshaded;
}

// The one check of every setting, used by asvgf::Denoiser, the renderer and every command of the
// `asvgf` tool and the demo: a setting outside its range, NaN or infinite is refused naming the
// setting, its command-line option and its valid range.
struct SettingRange {
  const char* setting;  // the DenoiseSettings member
  const char* option;   // the command-line option that sets it, "" where none does
  const char* range;    // the valid values, as README and --help state them
};
// Every checked setting with its range, in declaration order.
const std::vector<SettingRange>& setting_ranges();
// The range text of `setting` (a DenoiseSettings member name), empty if unknown.
std::string_view setting_range(std::string_view setting);

struct SettingProblem {
  SettingRange setting;
  std::string value;            // the refused value as text
  std::string message() const;  // e.g. "alpha (--alpha) is nan, valid: (0, 1]"
};
// The first setting outside its range, or nothing.
std::optional<SettingProblem> check_settings(const DenoiseSettings& settings);

}  // namespace asvgf
