// Scene keyframes: evaluate() interpolates and holds, same_state() sees every change, validate()
// names the place of each problem.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/scene.hpp"

using namespace asvgf::scene;

namespace {

bool near(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) { return glm::length(a - b) <= eps; }

glm::vec3 translation_of(const glm::mat4& m) { return glm::vec3(m[3]); }

// One triangle, one material, one instance, one light, one camera keyframe: valid.
Scene tiny_scene() {
  Scene s;
  s.name = "tiny";
  Mesh m;
  m.name = "tri";
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  m.materials = {0};
  s.meshes = {m};
  s.materials = {Material{"white", glm::vec3(0.5f), glm::vec3(0.0f), -1}};
  s.instances = {Instance{"inst", 0, {{0.0f, Transform{}}}}};
  s.sphere_lights = {SphereLight{"lamp", {{0.0f, SphereLightState{}}}}};
  s.camera = {{0.0f, CameraState{}}};
  return s;
}

// validate() must throw a SceneError whose message contains every one of `parts`.
void check_rejects(const Scene& s, std::initializer_list<const char*> parts) {
  std::string what;
  try {
    validate(s, "test.json");
  } catch (const SceneError& e) {
    what = e.what();
  }
  CAPTURE(what);
  REQUIRE_FALSE(what.empty());
  CHECK(what.find("test.json") != std::string::npos);
  for (const char* p : parts) {
    CAPTURE(p);
    CHECK(what.find(p) != std::string::npos);
  }
}

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

}  // namespace

TEST_CASE("Transform::matrix is translation * rotation * scale") {
  Transform t{{1, 2, 3}, glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0)), {2, 2, 2}};
  const glm::vec4 p = t.matrix() * glm::vec4(1, 0, 0, 1);
  // scale -> (2,0,0), rotate 90 deg about y -> (0,0,-2), translate -> (1,2,1)
  CHECK(near(glm::vec3(p), {1, 2, 1}));
}

TEST_CASE("evaluate interpolates linearly between keyframes and holds before the first and after the last") {
  Scene s = tiny_scene();
  s.instances[0].transform = {{2.0f, Transform{{0, 0, 0}, glm::quat(1, 0, 0, 0), {1, 1, 1}}}, {6.0f, Transform{{4, 0, 0}, glm::quat(1, 0, 0, 0), {1, 1, 1}}}};
  SphereLightState a, b;
  a.position = {0, 0, 0};
  a.radius = 0.1f;
  a.emission = glm::vec3(10.0f);
  b.position = {0, 2, 0};
  b.radius = 0.3f;
  b.emission = glm::vec3(20.0f);
  s.sphere_lights[0].state = {{0.0f, a}, {10.0f, b}};
  CameraState c0, c1;
  c1.position = {0, 0, 9};
  c1.vertical_fov_degrees = 65.0f;
  s.camera = {{0.0f, c0}, {4.0f, c1}};
  validate(s, "interp");

  CHECK(near(translation_of(evaluate(s, 0.0f).instance_transforms[0]), {0, 0, 0}));  // hold before
  CHECK(near(translation_of(evaluate(s, 2.0f).instance_transforms[0]), {0, 0, 0}));
  CHECK(near(translation_of(evaluate(s, 3.0f).instance_transforms[0]), {1, 0, 0}));
  CHECK(near(translation_of(evaluate(s, 5.0f).instance_transforms[0]), {3, 0, 0}));
  CHECK(near(translation_of(evaluate(s, 6.0f).instance_transforms[0]), {4, 0, 0}));
  CHECK(near(translation_of(evaluate(s, 100.0f).instance_transforms[0]), {4, 0, 0}));  // hold after

  const FrameState mid = evaluate(s, 5.0f);
  CHECK(near(mid.lights[0].position, {0, 1, 0}));
  CHECK(mid.lights[0].radius == doctest::Approx(0.2f));
  CHECK(near(mid.lights[0].emission, glm::vec3(15.0f)));
  CHECK(evaluate(s, -3.0f).lights[0].radius == doctest::Approx(0.1f));
  CHECK(near(evaluate(s, 2.0f).camera.position, {0, 0, 7}));
  CHECK(evaluate(s, 2.0f).camera.vertical_fov_degrees == doctest::Approx(55.0f));
  CHECK(evaluate(s, 50.0f).camera.vertical_fov_degrees == doctest::Approx(65.0f));
}

TEST_CASE("evaluate slerps rotation along the shorter arc") {
  Scene s = tiny_scene();
  Transform r0, r1;
  r1.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
  s.instances[0].transform = {{0.0f, r0}, {2.0f, r1}};
  const glm::vec4 p = evaluate(s, 1.0f).instance_transforms[0] * glm::vec4(1, 0, 0, 1);
  // Halfway: 45 degrees about y, still unit length (slerp, not a lerp of matrices).
  CHECK(near(glm::vec3(p), {std::sqrt(0.5f), 0, -std::sqrt(0.5f)}));

  // -q is the same rotation as q: the halfway point must not swing the long way round.
  s.instances[0].transform[1].value.rotation = -r1.rotation;
  const glm::vec4 q = evaluate(s, 1.0f).instance_transforms[0] * glm::vec4(1, 0, 0, 1);
  CHECK(near(glm::vec3(q), {std::sqrt(0.5f), 0, -std::sqrt(0.5f)}));
}

TEST_CASE("evaluate holds a value exactly between equal keyframes, so same_state sees no change") {
  Scene s = tiny_scene();
  Transform t{{0.3f, -0.7f, 0.11f}, glm::normalize(glm::quat(0.9f, 0.1f, 0.3f, 0.2f)), {0.5f, 0.6f, 0.7f}};
  s.instances[0].transform = {{0.0f, t}, {3.0f, t}, {9.0f, Transform{}}};
  CHECK(same_state(evaluate(s, 0.0f), evaluate(s, 1.37f)));
  CHECK(same_state(evaluate(s, 0.0f), evaluate(s, 3.0f)));
  CHECK_FALSE(same_state(evaluate(s, 0.0f), evaluate(s, 3.5f)));
}

TEST_CASE("same_state detects a change of camera, instance transform, light position, radius, emission or count") {
  const Scene s = tiny_scene();
  const FrameState base = evaluate(s, 0.0f);
  CHECK(same_state(base, base));

  FrameState f = base;
  f.camera.position.x += 1e-4f;
  CHECK_FALSE(same_state(base, f));
  f = base;
  f.camera.target.y += 0.5f;
  CHECK_FALSE(same_state(base, f));
  f = base;
  f.camera.up = {1, 0, 0};
  CHECK_FALSE(same_state(base, f));
  f = base;
  f.camera.vertical_fov_degrees = 30.0f;
  CHECK_FALSE(same_state(base, f));
  f = base;
  f.instance_transforms[0][3][2] = 0.25f;
  CHECK_FALSE(same_state(base, f));
  f = base;
  f.instance_transforms.push_back(glm::mat4(1.0f));
  CHECK_FALSE(same_state(base, f));
  f = base;
  f.lights[0].position.z = 2.0f;
  CHECK_FALSE(same_state(base, f));
  f = base;
  f.lights[0].radius = 0.2f;
  CHECK_FALSE(same_state(base, f));
  f = base;
  f.lights[0].emission.g = 3.0f;
  CHECK_FALSE(same_state(base, f));
  f = base;
  f.lights.clear();
  CHECK_FALSE(same_state(base, f));
}

TEST_CASE("validate accepts a minimal scene") { CHECK_NOTHROW(validate(tiny_scene(), "tiny")); }

TEST_CASE("validate names the place of each problem") {
  SUBCASE("no triangles at all") {
    Scene s = tiny_scene();
    s.meshes[0].indices.clear();
    s.meshes[0].materials.clear();
    check_rejects(s, {"no triangles"});
  }
  SUBCASE("no instances") {
    Scene s = tiny_scene();
    s.instances.clear();
    check_rejects(s, {"no triangles"});
  }
  SUBCASE("NaN vertex names mesh and vertex") {
    Scene s = tiny_scene();
    s.meshes[0].positions[2].y = kNaN;
    check_rejects(s, {"mesh 'tri'", "vertex 2", "not finite"});
  }
  SUBCASE("infinite vertex") {
    Scene s = tiny_scene();
    s.meshes[0].positions[1].x = std::numeric_limits<float>::infinity();
    check_rejects(s, {"mesh 'tri'", "vertex 1"});
  }
  SUBCASE("index out of range names mesh and triangle") {
    Scene s = tiny_scene();
    s.meshes[0].indices[1] = 7;
    check_rejects(s, {"mesh 'tri'", "triangle 0", "index 7 out of range"});
  }
  SUBCASE("material index out of range") {
    Scene s = tiny_scene();
    s.meshes[0].materials[0] = 3;
    check_rejects(s, {"mesh 'tri'", "triangle 0", "material index 3 out of range"});
  }
  SUBCASE("texture index out of range") {
    Scene s = tiny_scene();
    s.materials[0].albedo_texture = 0;
    check_rejects(s, {"material 'white'", "texture index 0 out of range"});
  }
  SUBCASE("texture of bad size") {
    Scene s = tiny_scene();
    s.textures = {Texture{"wood.png", 4, 4, std::vector<std::uint8_t>(10)}};
    check_rejects(s, {"texture 'wood.png'", "10 bytes for 4x4"});
  }
  SUBCASE("no camera keyframe") {
    Scene s = tiny_scene();
    s.camera.clear();
    check_rejects(s, {"camera", "no keyframe"});
  }
  SUBCASE("keyframes not sorted") {
    Scene s = tiny_scene();
    s.instances[0].transform = {{5.0f, Transform{}}, {2.0f, Transform{}}};
    check_rejects(s, {"instance 'inst'", "not sorted", "keyframe 1"});
  }
  SUBCASE("light keyframes not sorted") {
    Scene s = tiny_scene();
    s.sphere_lights[0].state = {{1.0f, {}}, {1.0f, {}}};
    check_rejects(s, {"sphere light 'lamp'", "not sorted"});
  }
  SUBCASE("negative emission") {
    Scene s = tiny_scene();
    s.materials[0].emission = {1, -1, 1};
    check_rejects(s, {"material 'white'", "emission"});
  }
  SUBCASE("NaN albedo") {
    Scene s = tiny_scene();
    s.materials[0].albedo.z = kNaN;
    check_rejects(s, {"material 'white'", "albedo"});
  }
  SUBCASE("negative albedo") {
    Scene s = tiny_scene();
    s.materials[0].albedo.x = -0.1f;
    check_rejects(s, {"material 'white'", "albedo"});
  }
  SUBCASE("negative light emission") {
    Scene s = tiny_scene();
    s.sphere_lights[0].state[0].value.emission = {-1, 0, 0};
    check_rejects(s, {"sphere light 'lamp'", "keyframe 0", "emission"});
  }
  SUBCASE("sphere radius zero") {
    Scene s = tiny_scene();
    s.sphere_lights[0].state[0].value.radius = 0.0f;
    check_rejects(s, {"sphere light 'lamp'", "radius"});
  }
  SUBCASE("sphere radius NaN") {
    Scene s = tiny_scene();
    s.sphere_lights[0].state[0].value.radius = kNaN;
    check_rejects(s, {"sphere light 'lamp'", "radius"});
  }
  SUBCASE("instance mesh out of range") {
    Scene s = tiny_scene();
    s.instances[0].mesh = 4;
    check_rejects(s, {"instance 'inst'", "mesh index 4"});
  }
  SUBCASE("frame_count below one") {
    Scene s = tiny_scene();
    s.frame_count = 0;
    check_rejects(s, {"frame_count"});
  }
}
