// Refactoring guard: the frames of every method, hashed to the bit. Structural changes (how passes
// are declared, how the graph compiles) must leave them identical; a change meant to alter the
// images updates the table below from this test's MESSAGE output and says why in its commit.
#include <doctest/doctest.h>

#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <string>

#include "renderer/renderer.hpp"
#include "renderer/scene/builtin.hpp"
#include "vulkan/validated_device.hpp"

using namespace asvgf;

namespace {

// FNV-1a, 64 bits.
std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t h = 0xcbf29ce484222325ull) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 0x100000001b3ull;
  return h;
}

// Frames 0..4 (3..4 move the box, so A-SVGF's gradient passes run): every HDR float and display byte.
std::uint64_t frames_hash(render::Renderer& r) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (int f = 0; f < 5; ++f) {
    const auto img = r.render(f);
    h = fnv1a(img.hdr.data(), img.hdr.size() * sizeof(float), h);
    h = fnv1a(img.display.data(), img.display.size(), h);
  }
  return h;
}

struct Expected {
  frame::Method method;
  const char* name;
  std::uint64_t hash;  // over frames 0..4: every HDR float and display byte
};

// Recorded on lavapipe (Mesa 25.0.7); ray queries and the software BVH give the same frames
// (frame_inputs_test), so one hash serves both. svgf and asvgf re-recorded when the local-mean
// correction became the default (k 5 here; with --local-mean 0 the frames are the earlier hashes'
// 0x5db946742115e956 and 0xcb611bb2b3717a4e, bit for bit); asvgf again when anti-lag 8 became the
// default (with --antilag 4: 0x412a6542e5699a97); svgf and asvgf when the B3 kernel lost its four
// corner taps (before: 0xa0c28d453cca35e8, 0xb08078e1f71ab664; 1080p error unchanged, 0.000564 ->
// 0.000563 on light-exit, docs/performance.md "Fewer taps"), and again when it kept only the 13 taps
// with |i| + |j| <= 2 (21 taps: 0x259c2f2b0acba4e4, 0x850da73e6e222ba1; 1080p light-exit over 24
// frames 0.000281 both, three seeds within 0.1%); asvgf when pathtrace began writing the gradient's
// candidates, each stratum's pick hashed with the frame that takes the sample instead of the frame
// that projects it (before: 0x10c5bc2c9a3cd83e, which the same code gives with the pick hashed with
// frame + 4096, the next frame's index; 64x64, light-exit and boxes-move, every scene, seeds 0 and
// 1: mean relMSE within -5.5%..+4.8%, geometric mean -0.8%: another draw of the same picks); svgf
// and asvgf when the composite began reading the last a-trous iteration's colour as RGB9E5 (before:
// 0x2347b47913dfdbd4, 0xd2b666d42f575e7e; 128x128 light-exit, 12 frames, asvgf relMSE 0.0133017 ->
// 0.0133018, docs/performance.md "The colour in four bytes"); ema, svgf and asvgf when their
// radiance became RGBA16F, rounded to the nearest half (before: 0xa14f6011c2143061,
// 0xc698a755b7d0357e, 0xc183b08951b9a3bf; the same report 0.0133018 -> 0.0133016), and ema again
// when that rounding took the clamped form, which leaves a subnormal half's last bit to the store
// (0x76f17d641236f87f before); svgf and asvgf when their colour history and temporal result became
// RGB9E5 words (before: 0x7a990fe14ebfe36b, 0x6713087334642fee; the same report 0.0133016 ->
// 0.0133086, at 1080p on an H100 0.0002805 -> 0.0002806, lag 2 both: docs/performance.md, "The
// histories in four bytes"); svgf and asvgf when the moments became one word (before:
// 0x3b8e6725da87c6d1, 0xb6535a4f4ddff45e; the same report 0.0133086 -> 0.0133070, every built-in
// scene at 64x64 -0.03%..+0.00%: docs/performance.md, "The moments in one word"); every method
// when the G-buffer's albedo became RGB9E5 words that the path tracer divides by (before:
// 0x9e60626002f2596f, 0x3fc87b1d91a1c2f3, 0x016a25545f761c8b, 0xeaf886246ddefd74,
// 0x3e41802295162b54; 128x128 light-exit asvgf 0.013307 -> 0.013306, every built-in scene at 64x64
// -0.03%..+0.04%: docs/performance.md, "The albedo and the motion in four bytes"; the motion's
// halves in one word changed no bit).
const Expected kExpected[] = {
    {frame::Method::Raw, "raw", 0x5260bd541bd6bda9ull},
    {frame::Method::Ema, "ema", 0x43e1f2fd9ebafa1dull},
    {frame::Method::Svgf, "svgf", 0xa7efd13897614858ull},
    {frame::Method::Asvgf, "asvgf", 0x0604ec0f67a12846ull},
    {frame::Method::Reference, "reference", 0x819176378da0c042ull},
};

}  // namespace

TEST_CASE("frames of every method on boxes-move are bit-identical to the recorded ones, in both tracing variants") {
  ValidatedDevice device;
  const auto scene = scene::builtin_scene("cornell", "boxes-move");
  for (bool ray_query : {true, false}) {
    for (const Expected& e : kExpected) {
      CAPTURE(ray_query);
      const std::string name = e.name;
      CAPTURE(name);
      render::RenderSettings s;
      s.method = e.method;
      s.width = 32;
      s.height = 24;
      s.seed = 5;
      s.spp = e.method == frame::Method::Reference ? 2 : 1;
      s.ray_query = ray_query;
      render::Renderer r(*device, scene, s);
      const std::uint64_t h = frames_hash(r);
      char text[32];
      std::snprintf(text, sizeof text, "0x%016" PRIx64 "ull", h);
      MESSAGE(std::string(e.name) << ": " << text);
      CHECK(h == e.hash);
    }
  }
}

// The radiance image follows the method (frame::hdr_format): switched from svgf (RGBA16F) to the
// reference (RGBA32F, unclamped) and back, a renderer gives each method's recorded frames.
TEST_CASE("a renderer switched between methods gives each method's recorded frames") {
  ValidatedDevice device;
  const auto scene = scene::builtin_scene("cornell", "boxes-move");
  render::RenderSettings s;
  s.method = frame::Method::Svgf;
  s.width = 32;
  s.height = 24;
  s.seed = 5;
  render::Renderer r(*device, scene, s);
  r.render(0);
  for (const Expected& e : {kExpected[4], kExpected[2]}) {
    CAPTURE(e.name);
    s.method = e.method;
    s.spp = e.method == frame::Method::Reference ? 2 : 1;
    r.set_settings(s);
    CHECK(frames_hash(r) == e.hash);
  }
}
