// The public API (include/asvgf/denoiser.hpp) on the validated Vulkan device: the validate option
// finds nothing in inputs that follow the conventions and names each kind of mistake in words, and
// bad images and settings are refused naming the input or setting.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "asvgf/denoiser.hpp"
#include "cpu_oracle/rgb9e5.hpp"
#include "hal/error.hpp"
#include "io/half_float.hpp"
#include "vulkan/validated_device.hpp"

namespace {

constexpr std::uint32_t kW = 48, kH = 16;

// A scene sliding right by 3 pixels a frame: a staircase of depths (1, 2, ..., changing every 4
// columns), normals facing the camera, radiance 1.
struct Inputs {
  std::vector<float> illumination, albedo, normal, depth, motion;
};
Inputs sliding_frame(int frame) {
  Inputs in;
  const std::size_t n = std::size_t(kW) * kH * 4;
  in.illumination.assign(n, 1.0f);
  in.albedo.assign(n, 1.0f);
  in.normal.assign(n, 0.0f);
  in.depth.assign(n, 0.0f);
  in.motion.assign(n, 0.0f);
  for (std::uint32_t y = 0; y < kH; ++y)
    for (std::uint32_t x = 0; x < kW; ++x) {
      const std::size_t i = (std::size_t(y) * kW + x) * 4;
      const int source = static_cast<int>(x) - 3 * frame;  // what is at x came from x - 3 last frame
      in.depth[i] = 1.0f + static_cast<float>(((source % 40) + 40) % 40 / 4);
      in.normal[i + 2] = -1.0f;
      in.motion[i] = -3.0f;  // previous minus current
    }
  return in;
}

struct Rig {
  ValidatedDevice device;
  std::vector<hal::ImageHandle> images;  // illumination, albedo, normal, depth, motion, radiance
  asvgf::Denoiser denoiser;
  int frame = 0;
  hal::Format radiance_format;

  explicit Rig(asvgf::DenoiserConfig config, hal::Format radiance = hal::Format::RGBA32F)
      : denoiser(*device, config), radiance_format(radiance) {
    const auto usage =
        hal::ImageUsage::Sampled | hal::ImageUsage::Storage | hal::ImageUsage::CopySrc | hal::ImageUsage::CopyDst;
    for (const char* name : {"illumination", "albedo", "normal", "depth", "motion"})
      images.push_back(device->create_image({name, kW, kH, hal::Format::RGBA32F, usage}));
    images.push_back(device->create_image({"radiance", kW, kH, radiance_format, usage}));
  }
  ~Rig() {
    for (auto h : images) device->destroy(h);
  }
  void run(const Inputs& in, hal::State final_state = hal::State::ShaderRead) {
    const std::vector<float>* data[] = {&in.illumination, &in.albedo, &in.normal, &in.depth, &in.motion};
    for (int i = 0; i < 5; ++i) device->upload_image(images[i], std::as_bytes(std::span(*data[i])));
    const auto F = hal::Format::RGBA32F;
    const auto up = hal::State::CopyDst;
    denoiser.denoise(
        {{images[0], F, up}, {images[1], F, up}, {images[2], F, up}, {images[3], F, up}, {images[4], F, up}},
        {{images[5], radiance_format, frame == 0 ? hal::State::Undefined : hal::State::ShaderRead},
         std::nullopt,
         final_state});
    ++frame;
  }
};

bool mentions(const asvgf::InputReport& r, const std::string& text) {
  return std::any_of(r.problems.begin(), r.problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

}  // namespace

TEST_CASE("denoiser API: validate finds nothing wrong with inputs that follow the conventions") {
  Rig rig({.width = kW, .height = kH, .method = asvgf::DenoiseMethod::Svgf, .validate = true});
  for (int f = 0; f < 3; ++f) rig.run(sliding_frame(f));
  const asvgf::InputReport r = rig.denoiser.input_report();
  for (const auto& p : r.problems) MESSAGE(p);
  CHECK(r.problems.empty());
  CHECK(r.pixels == kW * kH);
  CHECK(r.surface_pixels == kW * kH);
  CHECK(r.moving_pixels == kW * kH);
  CHECK(r.moving_consistent > 0.8 * r.moving_pixels);
  CHECK(rig.device.messages.empty());
}

TEST_CASE("denoiser API: validate names negated motion, encoded normals, NaN radiance and negative depth") {
  Rig rig({.width = kW, .height = kH, .method = asvgf::DenoiseMethod::Svgf, .validate = true});
  rig.run(sliding_frame(0));
  Inputs bad = sliding_frame(1);
  for (std::size_t i = 0; i < bad.motion.size(); i += 4) bad.motion[i] = -bad.motion[i];  // current minus previous
  for (std::size_t i = 0; i < bad.normal.size(); i += 4) bad.normal[i + 2] = 0.5f;        // (n + 1) / 2 encoding
  bad.illumination[0] = std::numeric_limits<float>::quiet_NaN();
  bad.depth[4 * 5] = -1.0f;
  rig.run(bad);
  const asvgf::InputReport r = rig.denoiser.input_report();
  for (const auto& p : r.problems) MESSAGE(p);
  CHECK(mentions(r, "motion vectors look negated"));
  CHECK(mentions(r, "normals are not unit length at 100.0% of surface pixels"));
  CHECK(mentions(r, "illumination is NaN or Inf at 1 pixel"));
  CHECK(mentions(r, "depth is negative at 1 pixel"));
  CHECK(r.moving_consistent_negated > r.moving_consistent);
  CHECK(rig.device.messages.empty());
}

TEST_CASE("denoiser API: images and settings it cannot use are refused naming them") {
  ValidatedDevice device;
  auto settings_error = [&](asvgf::DenoiserConfig config) {
    try {
      asvgf::Denoiser d(*device, config);
    } catch (const hal::Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(settings_error({.width = 0, .height = 4}).find("denoiser size") != std::string::npos);
  asvgf::DenoiserConfig alpha{.width = 4, .height = 4};
  alpha.settings.alpha = 0.0f;
  CHECK(settings_error(alpha).find("alpha") != std::string::npos);
  asvgf::DenoiserConfig tap{.width = 4, .height = 4};
  tap.settings.history_tap = 7;
  CHECK(settings_error(tap).find("history_tap") != std::string::npos);
  asvgf::DenoiserConfig sigma{.width = 4, .height = 4};
  sigma.settings.sigma_n = std::numeric_limits<float>::infinity();
  CHECK(settings_error(sigma).find("sigma_n (--sigma-n) is inf, valid: [0, inf), finite") != std::string::npos);

  asvgf::Denoiser denoiser(*device, {.width = 4, .height = 4, .method = asvgf::DenoiseMethod::Ema});
  const hal::ImageHandle f32 = device->create_image({"f32", 4, 4, hal::Format::RGBA32F});
  const hal::ImageHandle u8 = device->create_image({"u8", 4, 4, hal::Format::RGBA8Unorm});
  const auto F = hal::Format::RGBA32F;
  auto record_error = [&](asvgf::DenoiserInputs in, asvgf::DenoiserOutputs out) {
    auto commands = device->create_command_list("refused");
    try {
      denoiser.record(*commands, in, out);
    } catch (const hal::Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const asvgf::DenoiserImage good{f32, F, hal::State::Undefined};
  CHECK(record_error({good, {u8, hal::Format::RGBA8Unorm}, good, good, good}, {good}).find("denoiser input albedo") !=
        std::string::npos);
  CHECK(record_error({good, good, good, good, {}}, {good}).find("denoiser input motion") != std::string::npos);
  const std::string wrong_format = record_error({good, good, good, good, good}, {{u8, hal::Format::RGBA8Unorm}});
  MESSAGE(wrong_format);
  CHECK(wrong_format.find("denoiser output radiance") != std::string::npos);
  CHECK(wrong_format.find("rgba32f or rgba16f needed") != std::string::npos);
  CHECK(record_error({good, good, good, good, good}, {good}).find("is also an output") != std::string::npos);
  CHECK_THROWS_AS(denoiser.input_report(), hal::Error);  // validate is off
  device->destroy(f32);
  device->destroy(u8);
  CHECK(device.messages.empty());
}

namespace {

// Runs `frames` frames of `make(f)` through a denoiser of `config` and returns the last radiance.
std::vector<float> denoise_frames(asvgf::DenoiserConfig config, int frames, const std::function<Inputs(int)>& make) {
  Rig rig(config);
  for (int f = 0; f < frames; ++f) rig.run(make(f), f + 1 == frames ? hal::State::CopySrc : hal::State::ShaderRead);
  std::vector<float> out(std::size_t(kW) * kH * 4);
  rig.device->read_image(rig.images[5], std::as_writable_bytes(std::span(out)));
  CHECK(rig.device.messages.empty());
  return out;
}

// A textured, noisy version of the sliding frame: albedo varies per pixel (some below 1e-3, some
// emitters above 1), illumination is noisy.
Inputs textured_frame(int f) {
  Inputs in = sliding_frame(f);
  for (std::uint32_t p = 0; p < kW * kH; ++p)
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t hash = (p * 2654435761u + std::uint32_t(c) * 40503u + std::uint32_t(f) * 9973u) >> 8;
      in.illumination[4 * p + std::size_t(c)] = 0.25f + float(hash % 1000) / 500.0f;
      const std::uint32_t x = p % kW;
      in.albedo[4 * p + std::size_t(c)] = x % 7 == 0 ? 0.0f : x % 11 == 0 ? 4.0f : 0.1f + 0.1f * float((x + c) % 8);
    }
  return in;
}

}  // namespace

TEST_CASE("denoiser API: radiance in equals the same frames given demodulated, albedo 0 passes the radiance through") {
  auto radiance = [](int f) {
    Inputs in = textured_frame(f);
    for (std::size_t i = 0; i < in.illumination.size(); ++i)
      if (i % 4 < 3 && in.albedo[i] >= 1e-3f) in.illumination[i] *= in.albedo[i];
    return in;
  };
  // Demodulated by hand as the denoiser does it: a = the albedo where it is >= 1e-3, else 1, as its
  // RGB9E5 word holds it; illumination = radiance / max(a, 1e-3).
  auto by_hand = [&](int f) {
    Inputs in = radiance(f);
    for (std::size_t p = 0; p < in.albedo.size(); p += 4) {
      double a[3];
      for (std::size_t c = 0; c < 3; ++c) a[c] = in.albedo[p + c] >= 1e-3f ? in.albedo[p + c] : 1.0;
      const auto held = asvgf::reference::unpack_rgb9e5(asvgf::reference::pack_rgb9e5(a[0], a[1], a[2]));
      for (std::size_t c = 0; c < 3; ++c) {
        in.albedo[p + c] = static_cast<float>(held[c]);
        in.illumination[p + c] = static_cast<float>(in.illumination[p + c] / std::max(held[c], 1e-3));
      }
    }
    return in;
  };
  const auto want = denoise_frames(
      {.width = kW, .height = kH, .method = asvgf::DenoiseMethod::Svgf, .color_input = asvgf::ColorInput::Demodulated},
      4, by_hand);
  const auto got = denoise_frames({.width = kW, .height = kH, .method = asvgf::DenoiseMethod::Svgf}, 4, radiance);
  double worst = 0;
  for (std::size_t i = 0; i < want.size(); ++i)
    if (i % 4 < 3)
      worst = std::max(worst, std::abs(double(got[i]) - want[i]) / std::max(1.0, std::abs(double(want[i]))));
  MESSAGE("worst relative difference " << worst);
  // radiance / a is the same fp32 division on both sides, within an ulp or two; through the chain that can
  // flip an fp16 rounding of a history or filter store (2^-11 relative, measured 5.1e-4): four fp16
  // ulps, as the backend parity tests allow.
  CHECK(worst < 4.0 / 2048.0);
}

TEST_CASE("denoiser API: motion in Cycles' and NRD's conventions gives the frames of ours") {
  // Textured frames (every pixel its own value) moving 3 px left and half a pixel up a frame.
  auto ours = [](int f) {
    Inputs in = textured_frame(f);
    for (std::size_t i = 0; i < in.motion.size(); i += 4) in.motion[i + 1] = -0.5f;
    return in;
  };
  auto cycles = [&](int f) {  // y up
    Inputs in = ours(f);
    for (std::size_t i = 0; i < in.motion.size(); i += 4) in.motion[i + 1] = -in.motion[i + 1];
    return in;
  };
  auto nrd = [&](int f) {  // UV units (exact: kW and kH are powers of two times small integers)
    Inputs in = ours(f);
    for (std::size_t i = 0; i < in.motion.size(); i += 4) in.motion[i] /= float(kW), in.motion[i + 1] /= float(kH);
    return in;
  };
  const asvgf::DenoiserConfig base{
      .width = kW, .height = kH, .method = asvgf::DenoiseMethod::Svgf, .color_input = asvgf::ColorInput::Demodulated};
  auto with = [&](asvgf::MotionConvention m) {
    auto c = base;
    c.motion = m;
    return c;
  };
  const auto want = denoise_frames(base, 3, ours);
  CHECK(denoise_frames(with(asvgf::MotionConvention::cycles()), 3, cycles) == want);
  CHECK(denoise_frames(with(asvgf::MotionConvention::nrd()), 3, nrd) == want);
  // The conversion matters: our vectors read as Cycles' take the history from elsewhere.
  CHECK(denoise_frames(with(asvgf::MotionConvention::cycles()), 3, ours) != want);
}

TEST_CASE("denoiser API: an RGBA16F radiance holds the RGBA32F radiance rounded to the nearest half") {
  for (const auto method : {asvgf::DenoiseMethod::Ema, asvgf::DenoiseMethod::Svgf}) {
    CAPTURE(static_cast<int>(method));
    Rig full({.width = kW, .height = kH, .method = method});
    Rig half({.width = kW, .height = kH, .method = method}, hal::Format::RGBA16F);
    for (int f = 0; f < 3; ++f) {
      const hal::State after = f == 2 ? hal::State::CopySrc : hal::State::ShaderRead;
      full.run(textured_frame(f), after);
      half.run(textured_frame(f), after);
    }
    std::vector<float> want(std::size_t(kW) * kH * 4);
    std::vector<std::uint16_t> got(want.size());
    full.device->read_image(full.images[5], std::as_writable_bytes(std::span(want)));
    half.device->read_image(half.images[5], std::as_writable_bytes(std::span(got)));
    int differ = 0;
    for (std::size_t i = 0; i < want.size(); ++i) differ += got[i] != asvgf::io::float_to_half(want[i]);
    CHECK(differ == 0);
    CHECK(std::any_of(want.begin(), want.end(), [](float v) { return v > 0.0f && v != 1.0f; }));
    CHECK(full.device.messages.empty());
    CHECK(half.device.messages.empty());
  }
}
