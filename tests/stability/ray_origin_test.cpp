// Where secondary rays start (shaders/renderer/pathtrace.comp, spawn_origin): the picture must not
// depend on the scene's scale, no light may pass through closed geometry at its edges and corners,
// and the offsets must not cut a light off from the walls of the box that holds it. Both tracing
// variants (ray queries and the software BVH) are checked.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "pipeline/frame_inputs.hpp"
#include "renderer/scene/builtin.hpp"
#include "vulkan/validated_device.hpp"

using namespace asvgf;

namespace {

// The scene with every length multiplied by s: geometry, light positions and radii, camera.
// Radiance is independent of scale, so the image must be the same.
scene::Scene scaled(scene::Scene s, float k) {
  for (auto& inst : s.instances)
    for (auto& key : inst.transform) {
      key.value.translation *= k;
      key.value.scale *= k;
    }
  for (auto& light : s.sphere_lights)
    for (auto& key : light.state) {
      key.value.position *= k;
      key.value.radius *= k;
    }
  for (auto& key : s.camera) {
    key.value.position *= k;
    key.value.target *= k;
  }
  scene::validate(s, "scaled scene");
  return s;
}

// Luminance of the demodulated illumination, one value per pixel.
std::vector<double> luminance(const FrameInputs& in) {
  std::vector<double> l(std::size_t(in.width) * in.height);
  for (std::size_t p = 0; p < l.size(); ++p)
    l[p] = 0.2126 * in.illumination[4 * p] + 0.7152 * in.illumination[4 * p + 1] + 0.0722 * in.illumination[4 * p + 2];
  return l;
}

// The closed cube [-1,1]^3 (12 triangles over 8 shared vertices, so its edges are exactly shared),
// white walls, one sphere light, and a camera at the centre with a 90 degree view.
scene::Scene closed_box(glm::vec3 light_position, float light_radius) {
  scene::Scene s;
  s.name = "closed box";
  s.materials = {{"white", glm::vec3(0.73f), glm::vec3(0.0f), -1}};
  scene::Mesh m;
  m.name = "cube";
  for (int i = 0; i < 8; ++i) m.positions.push_back({i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f});
  // Faces as vertex-index quads (x-, x+, y-, y+, z-, z+), each split along one diagonal.
  const std::uint32_t quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                     {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  for (const auto& q : quads) m.indices.insert(m.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  m.materials.assign(12, 0);
  s.meshes = {m};
  s.instances = {{"cube", 0, {{0.0f, scene::Transform{}}}}};
  s.sphere_lights = {{"light", {{0.0f, {light_position, light_radius, glm::vec3(50.0f)}}}}};
  s.camera = {{0.0f, {glm::vec3(0.0f), glm::vec3(1.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f), 90.0f}}};
  scene::validate(s, "closed box");
  return s;
}

// Views whose centre column of pixel-centre rays (odd image width) runs exactly along an inside edge
// (the camera's up vector is parallel to the edge, and the view target lies on it), or along a
// face's diagonal, and whose centre pixel looks into a corner: four from the cube's centre, then
// six from off-centre points, where the hit points' rounding is less symmetric (before the ray
// origins were made robust, these six leaked light at 4 to 14 pixels of 33x33 each).
const scene::CameraState kEdgeViews[] = {
    {glm::vec3(0.0f), glm::vec3(1.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f), 90.0f},
    {glm::vec3(0.0f), glm::vec3(1.0f, 1.0f, 1.0f), glm::vec3(0.0f, 0.0f, 1.0f), 90.0f},
    {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 1.0f), glm::vec3(0.0f, 1.0f, 0.0f), 90.0f},
    {glm::vec3(0.0f), glm::vec3(-1.0f, -1.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f), 90.0f},
    {{0.076f, 0.743f, 0.08f}, {1.0f, -0.368f, -1.0f}, {0.0f, 1.0f, 0.0f}, 60.0f},
    {{0.129f, -0.781f, 0.075f}, {1.0f, 0.309f, 1.0f}, {0.0f, 1.0f, 0.0f}, 60.0f},
    {{0.51f, -0.031f, -0.295f}, {1.0f, 0.368f, 1.0f}, {0.0f, 1.0f, 0.0f}, 60.0f},
    {{-0.232f, 0.04f, 0.441f}, {1.0f, 1.0f, 0.647f}, {0.0f, 0.0f, 1.0f}, 60.0f},
    {{0.736f, -0.535f, -0.534f}, {1.0f, 0.071f, -1.0f}, {0.0f, 1.0f, 0.0f}, 60.0f},
    {{0.666f, 0.425f, -0.545f}, {1.0f, -1.0f, 0.212f}, {0.0f, 0.0f, 1.0f}, 60.0f},
};

// Renders `s` from every edge view (33x33, frame 0) in both tracing variants and hands each
// frame's inputs to `check`.
void for_each_edge_view(hal::Device& device, scene::Scene s, std::uint32_t spp, std::uint32_t max_bounces,
                        const std::function<void(const FrameInputs&)>& check) {
  const std::uint32_t size = 33;
  for (bool ray_query : {true, false}) {
    for (std::size_t v = 0; v < std::size(kEdgeViews); ++v) {
      CAPTURE(ray_query);
      CAPTURE(v);
      s.camera = {{0.0f, kEdgeViews[v]}};
      check(render_frame_inputs(device, s, ray_query, size, size, 0, spp, max_bounces));
    }
  }
}

}  // namespace

TEST_CASE("the room scaled by 1e-4, 1e-3, 1e-2, 1, 1e2 and 1e4 renders the same image within Monte Carlo noise") {
  // Each image is the mean of N = 32 samples per pixel; two independent renders of the unscaled
  // room (seeds A, B) measure the noise: E[(A_p - B_p)^2] = 2 sigma_p^2 / N, which is also the
  // variance of S_p - A_p for an independent render S of a scaled room that is the same picture.
  // So a block b of n pixels has sd(mean_b(S) - mean_b(A)) = sqrt(sum_b (A_p - B_p)^2) / n, and
  // likewise the whole image. The test allows 5 of those standard deviations (two-sided 6e-7 per
  // comparison; 2 x 6 x 65 comparisons). Seeds are fixed, so the outcome is reproducible.
  ValidatedDevice device;
  const auto room = scene::builtin_scene("cornell", "static");
  const std::uint32_t size = 64, spp = 32, block = 8;
  const double z = 5.0;
  for (bool ray_query : {true, false}) {
    CAPTURE(ray_query);
    const auto a = luminance(render_frame_inputs(*device, room, ray_query, size, size, 0, spp, 4, 101));
    const auto b = luminance(render_frame_inputs(*device, room, ray_query, size, size, 0, spp, 4, 202));
    std::uint32_t seed = 303;
    for (float k : {1e-4f, 1e-3f, 1e-2f, 1.0f, 1e2f, 1e4f}) {
      CAPTURE(k);
      const auto s = luminance(render_frame_inputs(*device, scaled(room, k), ray_query, size, size, 0, spp, 4, seed++));
      double diff = 0, noise = 0, worst = 0;
      int failed_blocks = 0;
      for (std::uint32_t by = 0; by < size; by += block)
        for (std::uint32_t bx = 0; bx < size; bx += block) {
          double d = 0, v = 0;
          for (std::uint32_t y = by; y < by + block; ++y)
            for (std::uint32_t x = bx; x < bx + block; ++x) {
              const std::size_t p = std::size_t(y) * size + x;
              d += s[p] - a[p];
              v += (a[p] - b[p]) * (a[p] - b[p]);
            }
          diff += d;
          noise += v;
          const double sd = std::sqrt(v);  // both in units of the block's sum
          const double score = sd > 0 ? std::abs(d) / sd : (d == 0 ? 0.0 : 1e30);
          worst = std::max(worst, score);
          if (score > z) {
            ++failed_blocks;
            MESSAGE("block at (" << bx << ", " << by << "): mean differs by " << d / (block * block) << ", " << score
                                 << " standard deviations");
          }
        }
      const double n = double(size) * size;
      const double mean_a = [&] {
        double t = 0;
        for (double v : a) t += v;
        return t / n;
      }();
      MESSAGE("scale " << k << ": mean " << mean_a + diff / n << " vs " << mean_a << " ("
                       << std::abs(diff) / std::sqrt(noise) << " sd), worst block " << worst << " sd");
      CHECK(std::abs(diff) <= z * std::sqrt(noise));
      CHECK(failed_blocks == 0);
    }
  }
}

TEST_CASE(
    "no light passes through a closed box: cameras inside looking along its edges and into its corners see exactly 0") {
  // The light is outside; every wall faces it only from outside. Pixel-centre rays hit the inside
  // edges and corners exactly, where a ray leaving the hit point used to start on the neighbouring
  // face's plane and pass through it.
  ValidatedDevice device;
  for_each_edge_view(*device, closed_box({2.2f, 0.3f, 0.4f}, 0.5f), 4, 4, [](const FrameInputs& in) {
    int lit = 0;
    float brightest = 0;
    for (std::size_t p = 0; p < std::size_t(in.width) * in.height; ++p) {
      const float* rgb = &in.illumination[4 * p];
      brightest = std::max({brightest, rgb[0], rgb[1], rgb[2]});
      lit += rgb[0] != 0 || rgb[1] != 0 || rgb[2] != 0;
    }
    MESSAGE(lit << " lit pixels, brightest " << brightest);
    CHECK(lit == 0);
  });
}

TEST_CASE("a light inside a closed box lights every pixel of its walls, edges and corners included, at 1 spp") {
  // Every wall point sees the sphere (convex room, nothing in between), and next-event estimation
  // always samples it: a black pixel is a shadow ray stopped by the wall it starts from or by its
  // neighbour at an edge.
  ValidatedDevice device;
  for_each_edge_view(*device, closed_box({0.3f, -0.2f, 0.1f}, 0.15f), 1, 1, [](const FrameInputs& in) {
    int black = 0;
    for (std::size_t p = 0; p < std::size_t(in.width) * in.height; ++p)
      black += !(in.illumination[4 * p] > 0 && in.illumination[4 * p + 1] > 0 && in.illumination[4 * p + 2] > 0);
    CHECK(black == 0);
  });
}
