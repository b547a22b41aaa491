// renderer/scene/builtin_many.cpp: a procedural field for tracing and BVH scale: 64 spheres (UV spheres of
// 1520 triangles, six colours) on an 8 x 8 grid 3 units apart, 40 boxes between them, a 60 x 60
// ground plane, four sphere lights 7 units up; about 98k triangles. Sizes, colours and box
// rotations come from a fixed hash, so the scene is the same on every run.
//
// Animations (kCornellFrameCount frames, like the room's):
//   static      nothing moves
//   light-exit  light 0 holds for frames 0..3, then leaves sideways, 54 units away by frame 9
//   orbit       the camera travels 60 degrees around the field at varying height (a path, one
//               keyframe a frame)
//   boxes-move  every eighth sphere rises 1.5 units between frames 3 and 7
#include "renderer/scene/builtin_many.hpp"

#include <cmath>
#include <numbers>

#include "renderer/scene/builtin.hpp"

namespace asvgf::scene {
namespace {

constexpr int kStacks = 20, kSlices = 40;  // 2 * 40 + 18 * 80 = 1520 triangles a sphere
constexpr int kGrid = 8;
constexpr float kSpacing = 3.0f;

// A deterministic value in [0, 1) for an integer (a 32-bit integer hash, "lowbias32").
float hash01(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return static_cast<float>(x >> 8) / 16777216.0f;
}

// Unit UV sphere, triangles facing outward, every triangle `material`.
Mesh sphere_mesh(const std::string& name, std::uint32_t material) {
  Mesh m;
  m.name = name;
  auto vertex = [](int stack, int slice) {
    const float theta = std::numbers::pi_v<float> * static_cast<float>(stack) / kStacks;
    // slice % kSlices: the seam's last column reuses the first's vertices exactly (no crack).
    const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(slice % kSlices) / kSlices;
    return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
  };
  for (int stack = 0; stack < kStacks; ++stack) {
    for (int slice = 0; slice < kSlices; ++slice) {
      const glm::vec3 a = vertex(stack, slice), b = vertex(stack, slice + 1), c = vertex(stack + 1, slice + 1),
                      d = vertex(stack + 1, slice);
      auto triangle = [&m, material](glm::vec3 p, glm::vec3 q, glm::vec3 r) {
        // Outward: the normal points away from the centre.
        if (glm::dot(glm::cross(q - p, r - p), p + q + r) < 0.0f) std::swap(q, r);
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        m.positions.insert(m.positions.end(), {p, q, r});
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
        m.materials.push_back(material);
      };
      if (stack != 0) triangle(a, b, c);  // the top cap's quads are triangles
      if (stack != kStacks - 1) triangle(a, c, d);
    }
  }
  return m;
}

Instance placed(std::string name, std::uint32_t mesh, glm::vec3 at, float scale, float yaw_degrees = 0.0f) {
  Transform t;
  t.translation = at;
  t.rotation = glm::angleAxis(glm::radians(yaw_degrees), glm::vec3(0.0f, 1.0f, 0.0f));
  t.scale = glm::vec3(scale);
  return Instance{std::move(name), mesh, {{0.0f, t}}};
}

}  // namespace

Scene many_scene(const std::string& animation) {
  Scene s;
  s.name = "many/" + animation;
  s.frame_count = kCornellFrameCount;
  const glm::vec3 colours[] = {{0.8f, 0.8f, 0.8f},  {0.75f, 0.2f, 0.15f}, {0.2f, 0.6f, 0.25f},
                               {0.2f, 0.3f, 0.75f}, {0.8f, 0.65f, 0.2f},  {0.55f, 0.3f, 0.6f}};
  for (const glm::vec3& c : colours) s.materials.push_back(Material{"colour" + std::to_string(s.materials.size()), c});
  const auto ground_material = static_cast<std::uint32_t>(s.materials.size());
  s.materials.push_back(Material{"ground", glm::vec3(0.5f)});

  Mesh ground;
  ground.name = "ground";
  const float g = 30.0f;
  ground.positions = {{-g, 0.0f, -g}, {-g, 0.0f, g}, {g, 0.0f, g}, {g, 0.0f, -g}};  // faces +y
  ground.indices = {0, 1, 2, 0, 2, 3};
  ground.materials = {ground_material, ground_material};
  s.meshes.push_back(ground);
  s.instances.push_back(placed("ground", 0, glm::vec3(0.0f), 1.0f));
  const auto first_sphere_mesh = static_cast<std::uint32_t>(s.meshes.size());
  for (std::uint32_t c = 0; c < std::size(colours); ++c)
    s.meshes.push_back(sphere_mesh("sphere" + std::to_string(c), c));
  const auto box_index = static_cast<std::uint32_t>(s.meshes.size());
  s.meshes.push_back(box_mesh("box", 0));

  const float origin = -0.5f * kSpacing * (kGrid - 1);
  for (int i = 0; i < kManySpheres; ++i) {
    const float radius = 0.6f + 0.5f * hash01(2u * i + 1u);  // <= 1.1: neighbours 3 apart never touch
    const glm::vec3 at{origin + kSpacing * (i % kGrid), radius, origin + kSpacing * (i / kGrid)};
    const auto mesh = first_sphere_mesh + static_cast<std::uint32_t>(i % std::size(colours));
    s.instances.push_back(placed("sphere" + std::to_string(i), mesh, at, radius));
  }
  // Boxes on the first 40 of the 7 x 7 cell corners: 2.1 from every sphere centre, at most 0.57
  // across half a diagonal, so they touch no sphere.
  for (int i = 0; i < kManyBoxes; ++i) {
    const float size = 0.5f + 0.3f * hash01(2u * i + 1000u);
    const glm::vec3 at{origin + kSpacing * (0.5f + i % (kGrid - 1)), 0.5f * size,
                       origin + kSpacing * (0.5f + i / (kGrid - 1))};
    s.instances.push_back(placed("box" + std::to_string(i), box_index, at, size, 90.0f * hash01(2u * i + 2000u)));
  }
  for (int l = 0; l < kManyLights; ++l) {
    const glm::vec3 at{l % 2 == 0 ? -6.0f : 6.0f, 7.0f, l / 2 == 0 ? -6.0f : 6.0f};
    s.sphere_lights.push_back(SphereLight{"light" + std::to_string(l), {{0.0f, {at, 0.6f, glm::vec3(40.0f)}}}});
  }
  const CameraState start{{0.0f, 6.0f, 18.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 50.0f};
  s.camera = {{0.0f, start}};

  if (animation == "light-exit") {
    SphereLightState gone = s.sphere_lights[0].state[0].value;
    const SphereLightState rest = gone;
    gone.position.x -= 54.0f;
    s.sphere_lights[0].state = {{0.0f, rest}, {3.0f, rest}, {9.0f, gone}};
  } else if (animation == "orbit") {
    s.camera.clear();
    for (int f = 0; f <= s.frame_count; ++f) {
      const float t = static_cast<float>(f) / static_cast<float>(s.frame_count);
      const float angle = glm::radians(60.0f) * t;
      CameraState c = start;
      c.position = glm::vec3(18.0f * std::sin(angle), 6.0f - 2.0f * std::sin(std::numbers::pi_v<float> * t),
                             18.0f * std::cos(angle));
      s.camera.push_back({static_cast<float>(f), c});
    }
  } else if (animation == "boxes-move") {
    for (int i = 0; i < kManySpheres; i += 8) {
      Instance& sphere = s.instances[1 + static_cast<std::size_t>(i)];
      Transform up = sphere.transform[0].value;
      const Transform rest = up;
      up.translation.y += 1.5f;
      sphere.transform = {{0.0f, rest}, {3.0f, rest}, {7.0f, up}};
    }
  } else if (animation != "static") {
    std::string valid;
    for (const std::string& a : builtin_animations()) valid += (valid.empty() ? "" : ", ") + a;
    throw SceneError("builtin scene 'many': unknown animation '" + animation + "' (valid: " + valid + ")");
  }
  validate(s, "builtin scene '" + s.name + "'");
  return s;
}

}  // namespace asvgf::scene
