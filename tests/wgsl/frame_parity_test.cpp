// The whole frame from WGSL in Dawn against the Vulkan backend's software-BVH variant: every
// method (so gradient_clear/select/resolve and accumulate run too, which have no CPU reference),
// frames where the box moves, HDR output compared per pixel at fp16 rounding.
#include <doctest/doctest.h>

#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "dawn_device.hpp"
#include "hal/validate.hpp"
#include "pipeline/frame_parity.hpp"
#include "vulkan/validated_device.hpp"

using namespace asvgf;
using namespace frame_parity;

namespace {

// The Dawn device of the build's shaders; its validation errors go to `messages`.
std::unique_ptr<hal::Device> open_dawn(std::vector<std::string>& messages) {
  return hal::validate::wrap(hal::dawn_node::create_device(
      hal::dawn_node::build_options([&messages](const std::string& m) { messages.push_back(m); })));
}

}  // namespace

TEST_CASE(
    "every method's frames from WGSL in Dawn match Vulkan's software-BVH frames to the rounding of what they store") {
  ValidatedDevice vulkan;
  std::vector<std::string> messages;
  const auto dawn = open_dawn(messages);
  for (const frame::Method method :
       {frame::Method::Raw, frame::Method::Ema, frame::Method::Svgf, frame::Method::Asvgf, frame::Method::Reference}) {
    const std::string name(frame::to_string(method));
    CAPTURE(name);
    const auto expected = frames(*vulkan, method, 5);
    const auto got = frames(*dawn, method, 5);
    for (std::size_t f = 0; f < expected.size(); ++f) {
      const Difference d = compare(got[f], expected[f], pixel_tolerance(method));
      MESSAGE("wgsl " << name << " frame " << f << ": " << d.over << " pixels over " << pixel_tolerance(method)
                      << ", worst " << d.worst << ", mean " << d.mean);
      CHECK(d.mean < kUlps / 4);
      CHECK(d.over <= static_cast<int>(expected[f].size() / 4 / 100));  // at most 1% of pixels
    }
  }
  for (const auto& m : messages) FAIL_CHECK("Dawn reported: " << m);
}

TEST_CASE("every debug view from WGSL in Dawn equals Vulkan's to one 8-bit step") {
  ValidatedDevice vulkan;
  std::vector<std::string> messages;
  const auto dawn = open_dawn(messages);
  const auto scene = scene::builtin_scene("cornell", "boxes-move");
  for (std::uint32_t v = 0; v <= static_cast<std::uint32_t>(passes::DebugView::HistoryLength); ++v) {
    CAPTURE(v);
    auto debug_frame = [&](hal::Device& device) {
      render::RenderSettings s;
      s.method = frame::Method::Asvgf;
      s.width = 32;
      s.height = 24;
      s.seed = 5;
      s.ray_query = false;
      s.debug_view = static_cast<passes::DebugView>(v);
      render::Renderer r(device, scene, s);
      std::vector<std::uint8_t> last;
      for (int f = 0; f < 3; ++f) last = r.render(f).debug;
      return last;
    };
    const auto expected = debug_frame(*vulkan), got = debug_frame(*dawn);
    REQUIRE(got.size() == expected.size());
    REQUIRE(got.size() == 32u * 24u * 4u);
    int worst = 0;
    for (std::size_t i = 0; i < got.size(); ++i) worst = std::max(worst, std::abs(int(got[i]) - int(expected[i])));
    MESSAGE("debug view " << v << ": worst difference " << worst << " steps");
    CHECK(worst <= 1);
  }
  for (const auto& m : messages) FAIL_CHECK("Dawn reported: " << m);
}
