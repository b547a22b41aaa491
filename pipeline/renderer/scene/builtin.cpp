// renderer/scene/builtin.cpp: the seed's semi-closed room with two boxes and a sphere light, in three looks
// (cornell: diffuse; glossy: metal floor and glossy box; textured: high-frequency albedo textures),
// and the dispatch to every built-in scene (`many` is builtin_many.cpp).
//
// Light: a sphere of radius 0.12 with radiance 80 at (0, 0.75, 0). Its irradiance on a surface at
// distance d facing it is E = L*pi*(r/d)^2, so the floor below (d = 1.75) gets E ~ 1.19 and, with
// albedo 0.73, reflects radiance rho*E/pi ~ 0.28; the back wall's centre ~ 0.4. Direct light alone
// therefore gives pixel values of about 0.2-0.5, and the bounces in the closed part of the room add
// to that. (Power: L * 4 pi^2 r^2 ~ 45 W per channel.)
#include "renderer/scene/builtin.hpp"
#include "renderer/scene/builtin_many.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace asvgf::scene {

namespace {

constexpr std::uint32_t kWhite = 0, kRed = 1, kGreen = 2;

enum class Look { Diffuse, Glossy, Textured };

// Appends a quad a-b-c-d (a cycle around its edge) as two triangles whose normal
// cross(v1 - v0, v2 - v0) points along `facing`; with uv_repeat > 0 also texture coordinates
// spanning the texture uv_repeat times along each edge.
void add_quad(Mesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 facing, std::uint32_t material,
              float uv_repeat = 0.0f) {
  if (glm::dot(glm::cross(b - a, c - a), facing) < 0.0f) std::swap(b, d);
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
  mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  mesh.materials.insert(mesh.materials.end(), {material, material});
  if (uv_repeat > 0.0f) {
    const float r = uv_repeat;
    mesh.uvs.insert(mesh.uvs.end(), {{0.0f, 0.0f}, {r, 0.0f}, {r, r}, {0.0f, r}});
  }
}

// The face of the cube [-1,1]^3 on `axis` at `side` (+1 or -1), as four corners in cycle order.
void cube_face(int axis, float side, glm::vec3 corners[4]) {
  glm::vec3 n(0.0f), u(0.0f), v(0.0f);
  n[axis] = side;
  u[(axis + 1) % 3] = 1.0f;
  v[(axis + 2) % 3] = 1.0f;
  corners[0] = n - u - v;
  corners[1] = n + u - v;
  corners[2] = n + u + v;
  corners[3] = n - u + v;
}

// The room's surfaces: the floor and back wall get their own materials (the glossy and textured
// looks change them), uv_repeat > 0 gives every wall texture coordinates.
struct RoomMaterials {
  std::uint32_t floor = kWhite, back = kWhite;
  float uv_repeat = 0.0f;
};

Mesh room_mesh(const RoomMaterials& m) {
  Mesh mesh;
  mesh.name = "room";
  struct Wall {
    int axis;
    float side;
    std::uint32_t material;
  };
  // Floor, ceiling, back, left (red), right (green); no front wall (z = +1 is open).
  const Wall walls[] = {
      {1, -1.0f, m.floor}, {1, 1.0f, kWhite}, {2, -1.0f, m.back}, {0, -1.0f, kRed}, {0, 1.0f, kGreen}};
  for (const Wall& w : walls) {
    glm::vec3 c[4];
    cube_face(w.axis, w.side, c);
    glm::vec3 inward(0.0f);
    inward[w.axis] = -w.side;
    add_quad(mesh, c[0], c[1], c[2], c[3], inward, w.material, m.uv_repeat);
  }
  return mesh;
}

}  // namespace

Mesh box_mesh(const std::string& name, std::uint32_t material, float uv_repeat) {
  Mesh mesh;
  mesh.name = name;
  for (int axis = 0; axis < 3; ++axis) {
    for (float side : {-1.0f, 1.0f}) {
      glm::vec3 c[4];
      cube_face(axis, side, c);
      glm::vec3 outward(0.0f);
      outward[axis] = side;
      add_quad(mesh, 0.5f * c[0], 0.5f * c[1], 0.5f * c[2], 0.5f * c[3], outward, material, uv_repeat);
    }
  }
  return mesh;
}

namespace {

// sRGB bytes of a grey level in [0, 1] (linear), for the procedural textures.
std::uint8_t srgb_byte(float linear) {
  const float c = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

// A checkerboard of `cells` x `cells` squares of `cell` texels, two reflectances, slightly tinted.
Texture checker_texture(int cells, int cell) {
  Texture t{"checker (procedural)", std::uint32_t(cells * cell), std::uint32_t(cells * cell), {}};
  for (std::uint32_t y = 0; y < t.height; ++y)
    for (std::uint32_t x = 0; x < t.width; ++x) {
      const bool light = ((x / cell) + (y / cell)) % 2 == 0;
      const float v = light ? 0.8f : 0.15f;
      t.rgba8.insert(t.rgba8.end(), {srgb_byte(v), srgb_byte(v * 0.9f), srgb_byte(v * 0.75f), 255});
    }
  return t;
}

// Uniform white noise per texel (a deterministic hash): reflectances in [0.1, 0.9], independent
// per channel, the hardest texture for a filter that blurs albedo.
Texture noise_texture(std::uint32_t size) {
  Texture t{"noise (procedural)", size, size, {}};
  std::uint32_t state = 0x9e3779b9u;
  auto next = [&state] {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return static_cast<float>(state >> 8) / 16777216.0f;
  };
  for (std::uint32_t i = 0; i < size * size; ++i) {
    t.rgba8.insert(t.rgba8.end(), {srgb_byte(0.1f + 0.8f * next()), srgb_byte(0.1f + 0.8f * next()),
                                   srgb_byte(0.1f + 0.8f * next()), 255});
  }
  return t;
}

glm::quat yaw(float degrees) {
  return glm::angleAxis(glm::radians(degrees), glm::vec3(0.0f, 1.0f, 0.0f));
}

Instance instance(std::string name, std::uint32_t mesh, const Transform& t) {
  return Instance{std::move(name), mesh, {{0.0f, t}}};
}

const CameraState kFrontCamera{glm::vec3(0.0f, 0.0f, 3.9f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), 40.0f};

Material material(std::string name, glm::vec3 albedo) {
  Material m;
  m.name = std::move(name);
  m.albedo = albedo;
  return m;
}

Scene room(const std::string& name, Look look, const std::string& animation) {
  Scene s;
  s.name = name + "/" + animation;
  s.frame_count = kCornellFrameCount;
  // Classic Cornell box reflectances.
  s.materials = {material("white", glm::vec3(0.73f)), material("red", glm::vec3(0.63f, 0.065f, 0.05f)),
                 material("green", glm::vec3(0.14f, 0.45f, 0.091f))};
  RoomMaterials walls;
  std::uint32_t tall_material = kWhite, short_material = kWhite;
  float box_uv_repeat = 0.0f;
  if (look == Look::Glossy) {
    Material floor = material("brushed_metal", glm::vec3(0.9f, 0.88f, 0.85f));
    floor.metallic = 1.0f;
    floor.roughness = 0.25f;
    Material lacquer = material("blue_lacquer", glm::vec3(0.1f, 0.2f, 0.6f));
    lacquer.specular = 1.0f;
    lacquer.roughness = 0.12f;
    walls.floor = 3;
    tall_material = 4;
    s.materials.insert(s.materials.end(), {floor, lacquer});
  } else if (look == Look::Textured) {
    // Floor and back wall: a 16 x 16 checker repeated twice a wall (cells 1/16 of the room); the
    // boxes: per-texel white noise, 32 texels a face. The side walls and ceiling stay untextured.
    s.textures = {checker_texture(16, 4), noise_texture(32)};
    Material tiles = material("tiles", glm::vec3(1.0f));
    tiles.albedo_texture = 0;
    Material speckle = material("speckle", glm::vec3(1.0f));
    speckle.albedo_texture = 1;
    walls = {3, 3, 2.0f};
    tall_material = short_material = 4;
    box_uv_repeat = 1.0f;
    s.materials.insert(s.materials.end(), {tiles, speckle});
  }
  s.meshes = {room_mesh(walls), box_mesh("tall_box", tall_material, box_uv_repeat),
              box_mesh("short_box", short_material, box_uv_repeat)};
  // Boxes stand on the floor (y = -1); their footprints are apart in z so the short box can slide
  // across in front of the tall one.
  s.instances = {instance("room", 0, Transform{}),
                 instance("tall_box", 1, Transform{{-0.38f, -0.4f, -0.4f}, yaw(17.0f), {0.56f, 1.2f, 0.56f}}),
                 instance("short_box", 2, Transform{{0.38f, -0.7f, 0.35f}, yaw(-18.0f), {0.5f, 0.6f, 0.5f}})};
  const SphereLightState light{{0.0f, 0.75f, 0.0f}, kCornellLightRadius, glm::vec3(kCornellLightRadiance)};
  s.sphere_lights = {SphereLight{"light", {{0.0f, light}}}};
  s.camera = {{0.0f, kFrontCamera}};

  if (animation == "light-exit") {
    // Inside for frames 0..3, then 0.4 units a frame to the right: through the wall from frame ~5,
    // wholly outside (x > 1 + r) from frame 6, stopping at x = 2.4 at frame 9.
    SphereLightState gone = light;
    gone.position.x = 2.4f;
    s.sphere_lights[0].state = {{0.0f, light}, {3.0f, light}, {9.0f, gone}};
  } else if (animation == "orbit") {
    // One keyframe a frame so the (linearly interpolated) position stays on the circle at every
    // integer frame. +-14 degrees keeps the camera within x in [-1, 1], in front of the opening.
    const float radius = glm::length(kFrontCamera.position - kFrontCamera.target);
    s.camera.clear();
    for (int f = 0; f <= s.frame_count; ++f) {
      const float phase = 2.0f * std::numbers::pi_v<float> * static_cast<float>(f) / static_cast<float>(s.frame_count);
      const float angle = glm::radians(14.0f) * std::sin(phase);
      CameraState c = kFrontCamera;
      c.position = c.target + radius * glm::vec3(std::sin(angle), 0.0f, std::cos(angle));
      s.camera.push_back({static_cast<float>(f), c});
    }
  } else if (animation == "boxes-move") {
    Transform rest = s.instances[2].transform[0].value;
    Transform moved = rest;
    moved.translation.x -= 0.6f;
    s.instances[2].transform = {{0.0f, rest}, {3.0f, rest}, {7.0f, moved}};
  } else if (animation != "static") {
    std::string valid;
    for (const std::string& a : builtin_animations()) valid += (valid.empty() ? "" : ", ") + a;
    throw SceneError("builtin scene '" + name + "': unknown animation '" + animation + "' (valid: " + valid + ")");
  }
  validate(s, "builtin scene '" + s.name + "'");
  return s;
}

}  // namespace

std::vector<std::string> builtin_scenes() {
  return {"cornell", "glossy", "textured", "many"};
}

std::vector<std::string> builtin_animations() {
  return {"static", "light-exit", "orbit", "boxes-move"};
}

Scene builtin_scene(const std::string& name, const std::string& animation) {
  if (name == "cornell") return room(name, Look::Diffuse, animation);
  if (name == "glossy") return room(name, Look::Glossy, animation);
  if (name == "textured") return room(name, Look::Textured, animation);
  if (name == "many") return many_scene(animation);
  std::string valid;
  for (const std::string& n : builtin_scenes()) valid += (valid.empty() ? "" : ", ") + n;
  throw SceneError("unknown builtin scene '" + name + "' (valid: " + valid + ")");
}

}  // namespace asvgf::scene
