// Built-in scenes: the cornell room validates for every animation, and each animation moves what
// it says and nothing else.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "renderer/scene/builtin.hpp"

using namespace asvgf::scene;

namespace {

std::string error_of(const std::string& name, const std::string& animation) {
  try {
    builtin_scene(name, animation);
  } catch (const SceneError& e) {
    return e.what();
  }
  return {};
}

// Instances whose transform differs between frames a and b.
std::vector<std::size_t> moved_instances(const Scene& s, float a, float b) {
  const FrameState fa = evaluate(s, a), fb = evaluate(s, b);
  std::vector<std::size_t> moved;
  for (std::size_t i = 0; i < fa.instance_transforms.size(); ++i) {
    if (fa.instance_transforms[i] != fb.instance_transforms[i]) moved.push_back(i);
  }
  return moved;
}

}  // namespace

TEST_CASE("builtin cornell validates for every animation and has the room, two boxes and one light") {
  REQUIRE(builtin_scenes() == std::vector<std::string>{"cornell", "glossy", "textured", "many"});
  for (const std::string& animation : builtin_animations()) {
    CAPTURE(animation);
    Scene s;
    REQUIRE_NOTHROW(s = builtin_scene("cornell", animation));
    CHECK_NOTHROW(validate(s, s.name));
    CHECK(s.name == "cornell/" + animation);
    CHECK(s.frame_count == kCornellFrameCount);
    REQUIRE(s.instances.size() == 3);
    CHECK(s.meshes[s.instances[0].mesh].triangle_count() == 10);  // 5 walls, open front
    CHECK(s.meshes[s.instances[1].mesh].triangle_count() == 12);
    CHECK(s.meshes[s.instances[2].mesh].triangle_count() == 12);
    REQUIRE(s.sphere_lights.size() == 1);
    CHECK(s.materials.size() == 3);
    for (int f = 0; f < s.frame_count; ++f) CHECK(evaluate(s, static_cast<float>(f)).lights.size() == 1);
  }
}

TEST_CASE("builtin cornell walls face into the room and the walls are white, red (left) and green (right)") {
  const Scene s = builtin_scene("cornell", "static");
  const Mesh& room = s.meshes[s.instances[0].mesh];
  for (std::uint32_t t = 0; t < room.triangle_count(); ++t) {
    const glm::vec3 a = room.positions[room.indices[3 * t]], b = room.positions[room.indices[3 * t + 1]],
                    c = room.positions[room.indices[3 * t + 2]];
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    const glm::vec3 centre = (a + b + c) / 3.0f;
    CAPTURE(t);
    CHECK(glm::dot(n, -centre) > 0.0f);  // towards the room's centre
    const glm::vec3 albedo = s.materials[room.materials[t]].albedo;
    if (centre.x < -0.99f) CHECK(albedo.r > albedo.g);  // left: red
    if (centre.x > 0.99f) CHECK(albedo.g > albedo.r);   // right: green
    CHECK(centre.z < 0.99f);                            // nothing at the open front
  }
}

TEST_CASE("builtin cornell light sits inside the room near the ceiling, camera outside the open front") {
  const Scene s = builtin_scene("cornell", "static");
  const FrameState f = evaluate(s, 0.0f);
  const SphereLightState& l = f.lights[0];
  CHECK(l.radius >= 0.1f);
  CHECK(l.radius <= 0.15f);
  for (int axis = 0; axis < 3; ++axis) CHECK(std::abs(l.position[axis]) + l.radius < kCornellHalfExtent);
  CHECK(l.position.y > 0.5f);
  CHECK(l.emission.r > 0.0f);
  CHECK(f.camera.position.z > kCornellHalfExtent);
  CHECK(f.camera.target.z < f.camera.position.z);
}

TEST_CASE("builtin static animation: nothing moves over all frames") {
  const Scene s = builtin_scene("cornell", "static");
  const FrameState first = evaluate(s, 0.0f);
  for (int f = 1; f < s.frame_count; ++f) CHECK(same_state(first, evaluate(s, static_cast<float>(f))));
}

TEST_CASE(
    "builtin light-exit: the light is inside the room at frame 0 and beyond the right wall plus radius by frame 10") {
  const Scene s = builtin_scene("cornell", "light-exit");
  const SphereLightState start = evaluate(s, 0.0f).lights[0];
  CHECK(start.position.x + start.radius < kCornellHalfExtent);
  CHECK(same_state(evaluate(s, 0.0f), evaluate(s, 3.0f)));  // inside for the first frames
  for (int f = 10; f < s.frame_count; ++f) {
    const SphereLightState l = evaluate(s, static_cast<float>(f)).lights[0];
    CAPTURE(f);
    CHECK(l.position.x - l.radius > kCornellHalfExtent);
  }
  // Only the light moves; it moves monotonically to the right.
  float x = start.position.x;
  for (int f = 1; f < s.frame_count; ++f) {
    const FrameState st = evaluate(s, static_cast<float>(f));
    CHECK(st.lights[0].position.x >= x);
    x = st.lights[0].position.x;
    CHECK(moved_instances(s, 0.0f, static_cast<float>(f)).empty());
  }
}

TEST_CASE("builtin orbit: the camera keeps a constant distance from the room's centre, stays in front and moves") {
  const Scene s = builtin_scene("cornell", "orbit");
  const CameraState c0 = evaluate(s, 0.0f).camera;
  const float r0 = glm::length(c0.position - c0.target);
  bool moved = false;
  for (int f = 0; f <= s.frame_count; ++f) {
    const CameraState c = evaluate(s, static_cast<float>(f)).camera;
    CAPTURE(f);
    CHECK(glm::length(c.target) < 1e-6f);  // looks at the centre
    CHECK(glm::length(c.position - c.target) == doctest::Approx(r0).epsilon(1e-5));
    CHECK(std::abs(c.position.x) < kCornellHalfExtent);  // never sees the outside of a side wall
    CHECK(c.position.z > kCornellHalfExtent);
    moved = moved || !same_state(evaluate(s, 0.0f), evaluate(s, static_cast<float>(f)));
  }
  CHECK(moved);
  CHECK(moved_instances(s, 0.0f, 7.0f).empty());
}

TEST_CASE("builtin boxes-move: exactly one instance moves and it ends elsewhere") {
  const Scene s = builtin_scene("cornell", "boxes-move");
  const auto moved = moved_instances(s, 0.0f, static_cast<float>(s.frame_count - 1));
  REQUIRE(moved.size() == 1);
  CHECK(s.instances[moved[0]].name == "short_box");
  CHECK(same_state(evaluate(s, 0.0f), evaluate(s, 3.0f)));
  CHECK_FALSE(same_state(evaluate(s, 3.0f), evaluate(s, 5.0f)));
  for (int f = 0; f < s.frame_count; ++f) {
    CHECK(moved_instances(s, 0.0f, static_cast<float>(f)).size() <= 1);
    CHECK(evaluate(s, static_cast<float>(f)).lights[0].position == evaluate(s, 0.0f).lights[0].position);
  }
}

TEST_CASE("builtin_scene rejects an unknown scene or animation, listing the valid names") {
  const std::string bad_scene = error_of("sponza", "static");
  CHECK(bad_scene.find("sponza") != std::string::npos);
  CHECK(bad_scene.find("cornell") != std::string::npos);
  const std::string bad_anim = error_of("cornell", "spin");
  CHECK(bad_anim.find("spin") != std::string::npos);
  for (const std::string& a : builtin_animations()) CHECK(bad_anim.find(a) != std::string::npos);
}

TEST_CASE("builtin scenes: every scene validates for every animation, and each animation moves what it says") {
  for (const std::string& name : builtin_scenes()) {
    for (const std::string& animation : builtin_animations()) {
      CAPTURE(name);
      CAPTURE(animation);
      Scene s;
      REQUIRE_NOTHROW(s = builtin_scene(name, animation));
      CHECK(s.name == name + "/" + animation);
      const float last = static_cast<float>(s.frame_count - 1);
      const FrameState first = evaluate(s, 0.0f), end = evaluate(s, last);
      bool lights_moved = false;
      for (std::size_t l = 0; l < first.lights.size(); ++l) {
        lights_moved = lights_moved || first.lights[l].position != end.lights[l].position;
      }
      const bool camera_moved = first.camera.position != end.camera.position;
      const bool instances_moved = !moved_instances(s, 0.0f, last).empty();
      CHECK(lights_moved == (animation == "light-exit"));
      CHECK(camera_moved == (animation == "orbit"));
      CHECK(instances_moved == (animation == "boxes-move"));
    }
    CHECK_FALSE(error_of(name, "nope").empty());
  }
}

TEST_CASE("builtin glossy: a metal floor and a glossy dielectric tall box, the short box stays diffuse") {
  const Scene s = builtin_scene("glossy", "static");
  auto material_of = [&](std::size_t instance, std::size_t triangle = 0) {
    return s.materials[s.meshes[s.instances[instance].mesh].materials[triangle]];
  };
  const Material floor = material_of(0, 0);  // the room's first quad is the floor
  CHECK(floor.metallic == 1.0f);
  CHECK(floor.roughness < 0.5f);
  CHECK(material_of(1).glossy());
  CHECK(material_of(1).metallic == 0.0f);
  CHECK_FALSE(material_of(2).glossy());
  CHECK_FALSE(material_of(0, 2).glossy());  // ceiling
}

TEST_CASE("builtin textured: floor, back wall and boxes are textured with uvs, side walls and ceiling are not") {
  const Scene s = builtin_scene("textured", "static");
  REQUIRE(s.textures.size() == 2);
  for (const Instance& inst : s.instances) {
    const Mesh& m = s.meshes[inst.mesh];
    CAPTURE(inst.name);
    CHECK(m.uvs.size() == m.positions.size());
  }
  const Mesh& room = s.meshes[s.instances[0].mesh];
  int textured = 0;
  for (std::uint32_t t = 0; t < room.triangle_count(); ++t) {
    textured += s.materials[room.materials[t]].albedo_texture >= 0 ? 1 : 0;
  }
  CHECK(textured == 4);  // floor and back wall
  CHECK(s.materials[s.meshes[s.instances[1].mesh].materials[0]].albedo_texture >= 0);
  CHECK(s.materials[s.meshes[s.instances[2].mesh].materials[0]].albedo_texture >= 0);
}

TEST_CASE("builtin many: about 100k triangles, several lights, nothing overlapping the ground") {
  const Scene s = builtin_scene("many", "static");
  std::size_t triangles = 0;
  for (const Instance& inst : s.instances) triangles += s.meshes[inst.mesh].triangle_count();
  MESSAGE("many: " << triangles << " triangles, " << s.instances.size() << " instances");
  CHECK(triangles >= 90000);
  CHECK(triangles <= 110000);
  CHECK(s.sphere_lights.size() >= 3);
  // Every object rests on or above the ground plane y = 0.
  const FrameState f = evaluate(s, 0.0f);
  for (std::size_t i = 1; i < s.instances.size(); ++i) {
    const Mesh& m = s.meshes[s.instances[i].mesh];
    float lowest = 1e30f;
    for (const glm::vec3& p : m.positions) lowest = std::min(lowest, (f.instance_transforms[i] * glm::vec4(p, 1.0f)).y);
    CAPTURE(s.instances[i].name);
    CHECK(lowest > -1e-4f);
  }
}
