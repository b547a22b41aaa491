// Half-float stores: common/color.glsl's round_to_half makes an RGBA16F store round to nearest
// (ties to even) on every backend, whatever rounding the device's own conversion uses, and so does
// round_to_half_clamped for normal halves (within a subnormal half's step below them); the test also
// reports that native rounding (Vulkan and GLSL leave it to the implementation).
#include <cfenv>
#include <cmath>
#include <cstdint>
#include <vector>

#include "backends.hpp"
#include "data.hpp"
#include "shaders/hal_test_half_store.hpp"

using namespace conformance;
using hal::State;

namespace {

float half_value(std::uint16_t h) {
  const int e = (h >> 10) & 0x1f, m = h & 0x3ff;
  const float v = e == 0 ? std::ldexp(float(m), -24) : std::ldexp(float(m | 0x400), e - 25);
  return (h & 0x8000) ? -v : v;
}

// The half float nearest to x (ties to even), or toward zero, by scaling to the half's ulp: a
// different computation from round_to_half's bit arithmetic. |x| below 65504 and finite.
float to_half(float x, bool toward_zero) {
  const double a = std::fabs(double(x));
  const int exponent = a < std::ldexp(1.0, -14) ? -14 : std::ilogb(a);
  const double ulp = std::ldexp(1.0, exponent - 10);
  const double steps = double(x) / ulp;
  return float((toward_zero ? std::trunc(steps) : std::nearbyint(steps)) * ulp);
}

std::vector<float> half_store_cases() {
  std::vector<float> v;
  // Around 1 (ulp 2^-10) in steps of 2^-13: below, at and above the half-ulp points, ties included.
  for (int k = -16; k <= 16; ++k) v.push_back(1.0f + float(k) * 0x1p-13f);
  // Ties to even at other exponents, and their neighbours one float away.
  for (float base : {0x1p-14f, 0.75f, 3.0f, 1000.0f, 60000.0f})
    for (int k : {1, 3, 5}) {
      const float tie = base + float(k) * std::ldexp(1.0f, std::ilogb(base) - 11);  // k half ulps above
      v.insert(v.end(), {tie, std::nextafter(tie, 0.0f), std::nextafter(tie, 1e9f)});
    }
  // Subnormal halves (multiples of 2^-24), a tie among them, and below the smallest.
  v.insert(v.end(), {2.5f * 0x1p-24f, 3.5f * 0x1p-24f, 0.4f * 0x1p-24f, 0.6f * 0x1p-24f, 1000.3f * 0x1p-24f, 0.0f,
                     -0.0f, 65504.0f, 65503.0f, 65490.0f, -65503.0f});
  // Random magnitudes over the normal range, both signs.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> log2_magnitude(-14.0f, 15.9f);
  while (v.size() % 4 != 0 || v.size() < 4 * 16 * 8) {
    const float m = std::exp2(log2_magnitude(rng));
    v.push_back(rng() & 1 ? -m : m);
  }
  return v;
}

}  // namespace

TEST_CASE(
    "conformance: round_to_half makes an RGBA16F store round to nearest, ties to even (native rounding reported)") {
  REQUIRE(std::fegetround() == FE_TONEAREST);
  const std::vector<float> values = half_store_cases();
  const std::uint32_t w = 16, h = static_cast<std::uint32_t>(values.size() / 4 / 16 + (values.size() % 64 != 0));
  std::vector<float> texels(std::size_t{w} * h * 4, 0.0f);
  std::copy(values.begin(), values.end(), texels.begin());
  for_each_backend([&](hal::Device& device) {
    const hal::ShaderInfo& shader = asvgf::shaders::hal_test_half_store;
    const auto usage = hal::ImageUsage::Storage | hal::ImageUsage::CopySrc;
    const auto src = device.create_image(
        {"half values", w, h, hal::Format::RGBA32F, hal::ImageUsage::Sampled | hal::ImageUsage::CopyDst});
    const auto rounded = device.create_image({"half rounded", w, h, hal::Format::RGBA16F, usage});
    const auto native = device.create_image({"half native", w, h, hal::Format::RGBA16F, usage});
    const auto clamped = device.create_image({"half rounded clamped", w, h, hal::Format::RGBA16F, usage});
    device.upload_image(src, as_bytes(texels));
    const auto pipeline = device.create_pipeline({"half store", &shader});
    const auto set = device.create_binding_set(
        {"half store set",
         pipeline,
         {{"values", src}, {"rounded", rounded}, {"native", native}, {"rounded_clamped", clamped}}});
    auto cmd = device.create_command_list("half store");
    cmd->barrier({src, State::CopyDst, State::ShaderRead});
    cmd->barrier({rounded, State::Undefined, State::ShaderWrite});
    cmd->barrier({native, State::Undefined, State::ShaderWrite});
    cmd->barrier({clamped, State::Undefined, State::ShaderWrite});
    Uniforms uniforms(shader);
    uniforms.set("width", w).set("height", h);
    cmd->dispatch({pipeline, set, uniforms.bytes(), (w + 7) / 8, (h + 7) / 8, 1});
    cmd->barrier({rounded, State::ShaderWrite, State::CopySrc});
    cmd->barrier({native, State::ShaderWrite, State::CopySrc});
    cmd->barrier({clamped, State::ShaderWrite, State::CopySrc});
    device.submit(*cmd);
    device.wait();
    std::vector<std::uint16_t> got(texels.size()), got_native(texels.size()), got_clamped(texels.size());
    device.read_image(rounded, as_writable(got));
    device.read_image(native, as_writable(got_native));
    device.read_image(clamped, as_writable(got_clamped));
    int wrong = 0, wrong_clamped = 0, native_nearest = 0, native_toward_zero = 0, inexact = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
      const float x = values[i], want = to_half(x, false);
      if (half_value(got[i]) != want) {
        if (++wrong <= 8) MESSAGE("value " << x << " stored as " << half_value(got[i]) << ", nearest half " << want);
      }
      const bool subnormal = std::fabs(want) < 0x1p-14f;
      if (subnormal ? std::fabs(half_value(got_clamped[i]) - want) > 0x1p-24f : half_value(got_clamped[i]) != want) {
        if (++wrong_clamped <= 8)
          MESSAGE("value " << x << " stored by round_to_half_clamped as " << half_value(got_clamped[i])
                           << ", nearest half " << want);
      }
      if (to_half(x, false) == to_half(x, true)) continue;  // both roundings agree
      ++inexact;
      native_nearest += half_value(got_native[i]) == want;
      native_toward_zero += half_value(got_native[i]) == to_half(x, true);
    }
    CHECK(wrong == 0);
    CHECK(wrong_clamped == 0);
    CHECK(inexact > 100);  // the cases tell the two roundings apart
    MESSAGE("the device's own RGBA16F store, on " << inexact << " values where the roundings differ: nearest "
                                                  << native_nearest << ", toward zero " << native_toward_zero);
  });
}
