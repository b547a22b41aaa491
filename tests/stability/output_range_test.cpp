// What we write never holds NaN or Inf, and what the denoiser had to clamp is counted: radiance
// above half float's 65504 reaches the EXR exactly (32-bit float), the fp16 histories clamp it and
// say how often, and composite zeroes (and counts) non-finite radiance.
#include <doctest/doctest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>

#include "io/image_io.hpp"
#include "renderer/renderer.hpp"
#include "renderer/scene/scene.hpp"
#include "vulkan/validated_device.hpp"

using namespace asvgf;

namespace {

// Two emissive 4x4 squares facing each other 3 apart, both of the largest valid emission; the
// camera between them sees only the one at z = -1, whose radiance is its emission plus what it
// reflects of the other: above 65504 wherever a sample finds the other square.
scene::Scene facing_emitters() {
  scene::Scene s;
  s.name = "facing emitters";
  s.materials = {{"emitter", glm::vec3(0.5f), glm::vec3(scene::kMaxEmission), -1}};
  scene::Mesh m;
  m.name = "squares";
  for (float z : {-1.0f, 2.0f})
    for (int i = 0; i < 4; ++i) m.positions.push_back({i & 1 ? 2.0f : -2.0f, i & 2 ? 2.0f : -2.0f, z});
  m.indices = {0, 1, 3, 0, 3, 2, 4, 5, 7, 4, 7, 6};
  m.materials.assign(4, 0);
  s.meshes = {m};
  s.instances = {{"squares", 0, {{0.0f, scene::Transform{}}}}};
  s.camera = {{0.0f, {glm::vec3(0.0f, 0.0f, 1.5f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f), 40.0f}}};
  scene::validate(s, "facing emitters");
  return s;
}

}  // namespace

TEST_CASE(
    "radiance above the half-float range is written to the EXR exactly, finite, and counted where the denoiser clamps "
    "it") {
  ValidatedDevice device;
  const auto scene = facing_emitters();
  render::RenderSettings s;
  s.width = s.height = 16;
  const auto dir = std::filesystem::temp_directory_path() / ("asvgf_output_range_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (frame::Method method : {frame::Method::Raw, frame::Method::Reference, frame::Method::Svgf}) {
    CAPTURE(static_cast<int>(method));
    s.method = method;
    s.spp = method == frame::Method::Reference ? 4 : 1;
    render::Renderer r(*device, scene, s);
    for (int f = 0; f < 3; ++f) {
      const auto img = r.render(f);
      float largest = 0;
      std::size_t not_finite = 0;
      for (float v : img.hdr) {
        not_finite += !std::isfinite(v);
        largest = std::max(largest, v);
      }
      CHECK(not_finite == 0);
      const auto path = dir / "frame.exr";
      render::write_exr(path, img.width, img.height, img.hdr);
      const auto back = render::read_exr(path);
      REQUIRE(back.width == img.width);
      REQUIRE(back.height == img.height);
      std::size_t differ = 0;
      for (std::size_t p = 0; p < std::size_t(img.width) * img.height; ++p)
        for (int c = 0; c < 3; ++c) differ += back.rgba[4 * p + c] != img.hdr[4 * p + c];
      CHECK(differ == 0);
      MESSAGE("largest radiance " << largest);
      if (method != frame::Method::Svgf) {
        CHECK(largest > 65504.0f);  // the case this test is about
      } else {
        // The clamped samples keep the histories' largest value (RGB9E5 words: 65408) to the output:
        // neither dropped nor darkened by the clamp, and not beyond what the histories hold.
        CHECK(largest >= 65000.0f);
        CHECK(largest <= 65408.0f);
      }
    }
    const auto counts = r.dropped_samples();
    MESSAGE("clamped " << counts.clamped_samples << ", zeroed " << counts.zeroed_outputs);
    CHECK(counts.nan_samples == 0);
    CHECK(counts.inf_samples == 0);
    CHECK(counts.zeroed_outputs == 0);
    // Only the filtering methods store samples in fp16 histories; there every clamp is counted.
    if (method == frame::Method::Svgf)
      CHECK(counts.clamped_samples > 0);
    else
      CHECK(counts.clamped_samples == 0);
  }
  std::filesystem::remove_all(dir);
}
