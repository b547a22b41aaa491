// Compute dispatches checked against a CPU computation; binding mismatches named on both sides.
#include <algorithm>
#include <cstring>
#include <string>

#include <glm/glm.hpp>

#include "backends.hpp"
#include "data.hpp"
#include "shaders/hal_test_box_entry.hpp"
#include "shaders/hal_test_image.hpp"
#include "shaders/hal_test_ray_query.rayquery.hpp"
#include "shaders/hal_test_scale.hpp"
#include "shaders/hal_test_uniforms.hpp"

using namespace conformance;
using hal::State;

namespace {

std::vector<float> random_floats(std::size_t count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> dist(-100.0f, 100.0f);
  std::vector<float> v(count);
  for (auto& x : v) x = dist(rng);
  return v;
}

}  // namespace

TEST_CASE("conformance: hal_test_scale dispatches match the CPU, each with its own uniforms") {
  for_each_backend([](hal::Device& device) {
    const hal::ShaderInfo& shader = asvgf::shaders::hal_test_scale;
    constexpr std::uint32_t count = 1000;  // not a multiple of the workgroup size
    const auto input = random_floats(count, 3);
    const auto src = device.create_buffer({"scale src", count * 4, hal::BufferUsage::Storage | hal::BufferUsage::CopyDst});
    hal::BufferHandle dst[2];
    for (int i = 0; i < 2; ++i)
      dst[i] = device.create_buffer(
          {"scale dst " + std::to_string(i), count * 4, hal::BufferUsage::Storage | hal::BufferUsage::CopySrc});
    device.upload_buffer(src, 0, as_bytes(input));

    const auto pipeline = device.create_pipeline({"scale", &shader});
    hal::BindingSetHandle sets[2];
    for (int i = 0; i < 2; ++i)
      sets[i] = device.create_binding_set({"scale set " + std::to_string(i), pipeline, {{"src", src}, {"dst", dst[i]}}});

    // Multiplying by a power of two is exact, so fused and unfused multiply-add agree bit for bit.
    const float scales[2] = {2.0f, -0.25f}, offsets[2] = {0.5f, 3.0f};
    auto cmd = device.create_command_list("scale");
    cmd->begin_label("scale");
    cmd->barrier({src, State::CopyDst, State::ShaderRead});
    for (int i = 0; i < 2; ++i) {
      cmd->barrier({dst[i], State::Undefined, State::ShaderWrite});
      Uniforms uniforms(shader);
      uniforms.set("count", count).set("scale", scales[i]).set("offset", offsets[i]);
      const std::uint32_t groups = (count + shader.workgroup_size[0] - 1) / shader.workgroup_size[0];
      cmd->dispatch({pipeline, sets[i], uniforms.bytes(), groups, 1, 1});
      cmd->barrier({dst[i], State::ShaderWrite, State::CopySrc});
    }
    cmd->end_label();
    device.submit(*cmd);
    device.wait();

    for (int i = 0; i < 2; ++i) {
      std::vector<float> out(count);
      device.read_buffer(dst[i], 0, as_writable(out));
      int wrong = 0;
      for (std::uint32_t k = 0; k < count; ++k)
        if (out[k] != input[k] * scales[i] + offsets[i]) ++wrong;
      CHECK_MESSAGE(wrong == 0, "dispatch " << i << ": " << wrong << " wrong values");
    }
  });
}

TEST_CASE("conformance: hal_test_image dispatch matches the CPU") {
  for_each_backend([](hal::Device& device) {
    const hal::ShaderInfo& shader = asvgf::shaders::hal_test_image;
    constexpr std::uint32_t w = 37, h = 23;
    const auto input = random_floats(std::size_t{w} * h * 4, 4);
    const auto src = device.create_image(
        {"image src", w, h, hal::Format::RGBA32F, hal::ImageUsage::Sampled | hal::ImageUsage::CopyDst});
    const auto dst = device.create_image(
        {"image dst", w, h, hal::Format::RGBA32F, hal::ImageUsage::Storage | hal::ImageUsage::CopySrc});
    device.upload_image(src, as_bytes(input));
    const auto pipeline = device.create_pipeline({"image", &shader});
    const auto set = device.create_binding_set({"image set", pipeline, {{"src_image", src}, {"dst_image", dst}}});

    auto cmd = device.create_command_list("image");
    cmd->barrier({src, State::CopyDst, State::ShaderRead});
    cmd->barrier({dst, State::Undefined, State::ShaderWrite});
    Uniforms uniforms(shader);
    uniforms.set("width", w).set("height", h).set("scale", 4.0f).set("offset", -1.0f);
    cmd->dispatch({pipeline, set, uniforms.bytes(), (w + 7) / 8, (h + 7) / 8, 1});
    cmd->barrier({dst, State::ShaderWrite, State::CopySrc});
    device.submit(*cmd);
    device.wait();

    std::vector<float> out(input.size());
    device.read_image(dst, as_writable(out));
    int wrong = 0;
    for (std::size_t k = 0; k < out.size(); ++k)
      if (out[k] != input[k] * 4.0f - 1.0f) ++wrong;
    CHECK(wrong == 0);
  });
}

TEST_CASE("conformance: the BVH ray/box test reports a miss at every tmax, also 1e30 where tmax + 1 == tmax") {
  // Rays along +z from the origin; each case: (tmin, tmax, box min, box max, expected entry or -1).
  struct Case {
    float tmin, tmax;
    glm::vec3 lo, hi;
    float expected;
  };
  std::vector<Case> cases;
  for (float tmax : {10.0f, 1e6f, 1e30f, 3.0e38f}) {
    cases.push_back({0.0f, tmax, {5, 0, 2}, {6, 1, 3}, -1.0f});      // beside the ray
    cases.push_back({0.0f, tmax, {-1, -1, -3}, {1, 1, -2}, -1.0f});  // behind the origin
    cases.push_back({0.0f, tmax, {-1, -1, 2}, {1, 1, 3}, 2.0f});     // ahead: entered at z = 2
    cases.push_back({0.0f, tmax, {-1, -1, -1}, {1, 1, 1}, 0.0f});    // around the origin: entered at tmin
  }
  cases.push_back({0.0f, 1.5f, {-1, -1, 2}, {1, 1, 3}, -1.0f});   // ahead but past tmax
  cases.push_back({0.0f, 2.0f, {-1, -1, 2}, {1, 1, 3}, 2.0f});    // entered exactly at tmax: kept (ties)
  cases.push_back({2.5f, 1e30f, {-1, -1, 2}, {1, 1, 3}, 2.5f});   // tmin inside the box
  cases.push_back({3.5f, 1e30f, {-1, -1, 2}, {1, 1, 3}, -1.0f});  // tmin past the box

  std::vector<float> input;
  for (const Case& c : cases) {
    const float v[16] = {0, 0, 0, c.tmin, 0, 0, 1, c.tmax, c.lo.x, c.lo.y, c.lo.z, 0, c.hi.x, c.hi.y, c.hi.z, 0};
    input.insert(input.end(), v, v + 16);
  }
  for_each_backend([&](hal::Device& device) {
    const hal::ShaderInfo& shader = asvgf::shaders::hal_test_box_entry;
    const auto count = static_cast<std::uint32_t>(cases.size());
    const auto src =
        device.create_buffer({"box cases", input.size() * 4, hal::BufferUsage::Storage | hal::BufferUsage::CopyDst});
    const auto dst =
        device.create_buffer({"box entries", count * 4, hal::BufferUsage::Storage | hal::BufferUsage::CopySrc});
    device.upload_buffer(src, 0, as_bytes(input));
    const auto pipeline = device.create_pipeline({"box entry", &shader});
    const auto set = device.create_binding_set({"box entry set", pipeline, {{"cases", src}, {"entries", dst}}});
    auto cmd = device.create_command_list("box entry");
    cmd->barrier({src, State::CopyDst, State::ShaderRead});
    cmd->barrier({dst, State::Undefined, State::ShaderWrite});
    Uniforms uniforms(shader);
    uniforms.set("count", count);
    cmd->dispatch({pipeline, set, uniforms.bytes(), 1, 1, 1});
    cmd->barrier({dst, State::ShaderWrite, State::CopySrc});
    device.submit(*cmd);
    device.wait();
    std::vector<float> out(count);
    device.read_buffer(dst, 0, as_writable(out));
    for (std::uint32_t i = 0; i < count; ++i) {
      const Case& c = cases[i];
      // traverse() enters a box when box_entry is >= 0: a miss must stay negative.
      if (c.expected < 0.0f)
        CHECK_MESSAGE(out[i] < 0.0f, "case " << i << " (tmax " << c.tmax << "): a missed box gave entry " << out[i]);
      else
        CHECK_MESSAGE(out[i] == c.expected, "case " << i << " (tmax " << c.tmax << "): entry " << out[i]);
    }
  });
}

TEST_CASE("conformance: a ray-query pipeline needs ray queries") {
  for_each_backend([](hal::Device& device) {
    const hal::ShaderInfo& shader = asvgf::shaders::hal_test_ray_query_rayquery;
    REQUIRE(shader.uses_ray_query);
    if (device.capabilities().ray_query) {
      device.destroy(device.create_pipeline({"ray query pipeline", &shader}));
    } else {
      try {
        device.create_pipeline({"ray query pipeline", &shader});
        FAIL_CHECK("expected Unsupported on a device without ray queries");
      } catch (const hal::Error& e) {
        CHECK(e.kind() == hal::ErrorKind::Unsupported);
        CHECK(e.object() == "ray query pipeline");
      }
    }
  });
}

TEST_CASE("conformance: the generated uniform struct fills a block with gaps, vectors and nested structs") {
  for_each_backend([](hal::Device& device) {
    const hal::ShaderInfo& shader = asvgf::shaders::hal_test_uniforms;
    using Params = asvgf::shaders::hal_test_uniforms_uniforms::Params;
    Params p;
    p.weight = 2.0f;
    p.tint = {1.0f, 2.0f, 3.0f, 4.0f};
    p.current = {{10.0f, 20.0f, 30.0f, 40.0f}, {5u, 6u}};
    p.previous = {{1.0f, 2.0f, 3.0f, 4.0f}, {7u, 8u}};
    p.axis = {0.5f, 0.25f, 0.125f};
    p.jitter = {-1.0f, 9.0f};
    p.offset = {-3, 4, -5};
    p.count = 3;
    // What the shader computes, from the GLSL: tint*weight + current.origin - previous.origin +
    // vec4(axis, jitter.x) + vec4(offset, current.size.x + previous.size.y).
    const std::array<float, 4> expected = {2 + 10 - 1 + 0.5f - 3, 4 + 20 - 2 + 0.25f + 4, 6 + 30 - 3 + 0.125f - 5,
                                           8 + 40 - 4 - 1.0f + 13};
    const auto dst = device.create_buffer({"uniforms dst", 4 * 16, hal::BufferUsage::Storage | hal::BufferUsage::CopySrc});
    const auto pipeline = device.create_pipeline({"uniforms", &shader});
    const auto set = device.create_binding_set({"uniforms set", pipeline, {{"dst", dst}}});
    auto cmd = device.create_command_list("uniforms");
    cmd->barrier({dst, State::Undefined, State::ShaderWrite});
    cmd->dispatch({pipeline, set, std::as_bytes(std::span(&p, 1)), 1, 1, 1});
    cmd->barrier({dst, State::ShaderWrite, State::CopySrc});
    device.submit(*cmd);
    device.wait();
    std::vector<float> out(4 * 4);
    device.read_buffer(dst, 0, as_writable(out));
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 4; ++c) CHECK_MESSAGE(out[i * 4 + c] == expected[c], "value " << i << "." << c);
  });
}
