// The noisy input against analytic results: a closed furnace, a plane under a sphere light, motion
// vectors of known moves, the two tracing variants against each other, and reproducibility.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "cpu_oracle/bsdf.hpp"
#include "frame_inputs.hpp"
#include "renderer/renderer.hpp"
#include "renderer/scene/builtin.hpp"
#include "vulkan/validated_device.hpp"

using namespace asvgf;

namespace {

// Two triangles spanning the quad a, b, c, d (counter-clockwise seen from the side it faces).
void add_quad(scene::Mesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, std::uint32_t material) {
  const auto base = static_cast<std::uint32_t>(m.positions.size());
  m.positions.insert(m.positions.end(), {a, b, c, d});
  m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  m.materials.insert(m.materials.end(), {material, material});
}

scene::Scene one_mesh_scene(scene::Mesh mesh, std::vector<scene::Material> materials, scene::CameraState camera) {
  scene::Scene s;
  s.name = "test";
  s.meshes.push_back(std::move(mesh));
  s.materials = std::move(materials);
  s.instances.push_back({"mesh", 0, {{0.0f, scene::Transform{}}}});
  s.camera.push_back({0.0f, camera});
  scene::validate(s, "test scene");
  return s;
}

// A closed cube of side 2 around the origin, every face emitting Le and reflecting rho.
scene::Scene furnace(float le, float rho) {
  scene::Mesh m;
  m.name = "box";
  const float e = 1.0f;
  add_quad(m, {-e, -e, -e}, {e, -e, -e}, {e, -e, e}, {-e, -e, e}, 0);  // floor
  add_quad(m, {-e, e, -e}, {-e, e, e}, {e, e, e}, {e, e, -e}, 0);      // ceiling
  add_quad(m, {-e, -e, -e}, {-e, e, -e}, {e, e, -e}, {e, -e, -e}, 0);  // back
  add_quad(m, {-e, -e, e}, {e, -e, e}, {e, e, e}, {-e, e, e}, 0);      // front
  add_quad(m, {-e, -e, -e}, {-e, -e, e}, {-e, e, e}, {-e, e, -e}, 0);  // left
  add_quad(m, {e, -e, -e}, {e, e, -e}, {e, e, e}, {e, -e, e}, 0);      // right
  scene::Material mat;
  mat.name = "furnace";
  mat.albedo = glm::vec3(rho);
  mat.emission = glm::vec3(le);
  return one_mesh_scene(m, {mat}, {{0.2f, 0.1f, 0.3f}, {0.2f, 0.1f, -1.0f}, {0, 1, 0}, 70.0f});
}

double luminance(const float* p) {
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

}  // namespace

TEST_CASE("a closed diffuse enclosure with emission Le and albedo rho renders Le/(1-rho)") {
  ValidatedDevice device;
  const float le = 1.0f, rho = 0.5f;
  const auto scene = furnace(le, rho);
  const std::uint32_t w = 16, h = 16, spp = 64;
  const FrameInputs in =
      render_frame_inputs(*device, scene, device->capabilities().ray_query, w, h, 0, spp, /*max_bounces=*/64);
  // Radiance = illumination: the walls emit, and the path tracer does not demodulate emitters
  // (their demodulation albedo is 1, see demodulation_albedo in frame/scene_bindings.glsl).
  double sum = 0.0, worst = 0.0;
  for (std::size_t p = 0; p < std::size_t(w) * h; ++p) {
    const double l = luminance(&in.illumination[4 * p]);
    sum += l;
    worst = std::max(worst, std::abs(l - le / (1.0 - rho)));
  }
  const double mean = sum / (w * h);
  // Expected 2.0. The estimate per pixel averages 64 paths of geometric length (mean 2 bounces
  // with Russian roulette); over 256 pixels the mean's standard error is well under 1%.
  MESSAGE("furnace mean " << mean << " (expected " << le / (1 - rho) << "), worst pixel off by " << worst);
  CHECK(mean == doctest::Approx(le / (1.0 - rho)).epsilon(0.02));
  CHECK(worst < 0.25 * le / (1.0 - rho));
}

TEST_CASE("a diffuse plane lit by a sphere light matches the analytic irradiance") {
  ValidatedDevice device;
  scene::Mesh plane;
  plane.name = "plane";
  const float e = 20.0f;
  add_quad(plane, {-e, 0, -e}, {-e, 0, e}, {e, 0, e}, {e, 0, -e}, 0);
  scene::Material mat;
  mat.name = "grey";
  mat.albedo = glm::vec3(0.5f);
  auto scene = one_mesh_scene(plane, {mat}, {{0, 6, 0.01f}, {0, 0, 0}, {0, 0, -1}, 60.0f});
  const glm::vec3 centre{0.7f, 1.5f, -0.3f};
  const float radius = 0.4f, emission = 10.0f;
  scene.sphere_lights.push_back({"light", {{0.0f, {centre, radius, glm::vec3(emission)}}}});
  scene::validate(scene, "sphere over plane");

  const std::uint32_t w = 24, h = 24, spp = 256;
  const FrameInputs in =
      render_frame_inputs(*device, scene, device->capabilities().ray_query, w, h, 0, spp, /*max_bounces=*/1);
  const auto cam = render::make_camera(scene.camera[0].value, w, h);
  int compared = 0;
  double worst_rel = 0.0, sum_rel = 0.0;
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x) {
      const std::size_t p = std::size_t(y) * w + x;
      if (in.visibility[4 * p] != 1u) continue;  // only pixels that see the plane
      const glm::vec2 ndc{2.0f * (x + 0.5f) / w - 1.0f, 1.0f - 2.0f * (y + 0.5f) / h};
      const glm::vec3 d =
          glm::normalize(glm::vec3(cam.forward) + ndc.x * glm::vec3(cam.right) + ndc.y * glm::vec3(cam.up));
      const glm::vec3 o = glm::vec3(cam.position);
      const glm::vec3 x_world = o + d * (-o.y / d.y);
      const glm::vec3 to = centre - x_world;
      const double dist = glm::length(to);
      // Irradiance from a uniform sphere wholly above the horizon: pi * Le * (r/D)^2 * cos(theta).
      const double expected = 0.5 * emission * (radius / dist) * (radius / dist) * (to.y / dist);
      const double got = in.illumination[4 * p] * 0.5;  // remodulate
      const double rel = std::abs(got - expected) / expected;
      worst_rel = std::max(worst_rel, rel);
      sum_rel += rel;
      ++compared;
    }
  REQUIRE(compared > int(w * h) / 2);
  MESSAGE(compared << " plane pixels: mean relative error " << sum_rel / compared << ", worst " << worst_rel);
  // Light sampling of the cone is exact in expectation; with 256 samples per pixel and MIS against
  // cosine sampling the per-pixel error stays within a few percent.
  CHECK(sum_rel / compared < 0.02);
  CHECK(worst_rel < 0.08);
}

TEST_CASE(
    "a sphere light between a point and an emissive triangle shades it: the triangle's light sample is occluded") {
  ValidatedDevice device;
  scene::Mesh m;
  m.name = "floor and lamp";
  const float e = 4.0f, q = 0.25f;
  add_quad(m, {-e, 0, -e}, {-e, 0, e}, {e, 0, e}, {e, 0, -e}, 0);  // floor, facing up
  add_quad(m, {-q, 2, -q}, {q, 2, -q}, {q, 2, q}, {-q, 2, q}, 1);  // emissive quad at y = 2, facing down
  scene::Material grey, lamp;
  grey.name = "grey";
  grey.albedo = glm::vec3(0.5f);
  lamp.name = "lamp";
  lamp.albedo = glm::vec3(0.0f);
  lamp.emission = glm::vec3(20.0f);
  auto scene = one_mesh_scene(m, {grey, lamp}, {{0, 0.35f, 1.2f}, {0, 0, 0}, {0, 1, 0}, 50.0f});
  // A black sphere light (no power: never sampled) between the floor around the origin and the quad:
  // seen from |x|, |z| < 0.15 on the floor it covers the whole quad (cone half-angle 37 degrees).
  scene.sphere_lights.push_back({"blocker", {{0.0f, {{0.0f, 1.0f, 0.0f}, 0.6f, glm::vec3(0.0f)}}}});
  scene::validate(scene, "sphere between floor and lamp");

  const std::uint32_t w = 32, h = 32, spp = 64;
  const FrameInputs in =
      render_frame_inputs(*device, scene, device->capabilities().ray_query, w, h, 0, spp, /*max_bounces=*/1);
  const auto cam = render::make_camera(scene.camera[0].value, w, h);
  int shaded = 0, lit = 0;
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x) {
      const std::size_t p = std::size_t(y) * w + x;
      if (in.visibility[4 * p] != 1u) continue;  // pixels that see the floor
      const glm::vec2 ndc{2.0f * (x + 0.5f) / w - 1.0f, 1.0f - 2.0f * (y + 0.5f) / h};
      const glm::vec3 d =
          glm::normalize(glm::vec3(cam.forward) + ndc.x * glm::vec3(cam.right) + ndc.y * glm::vec3(cam.up));
      const glm::vec3 o = glm::vec3(cam.position);
      const glm::vec3 xw = o + d * (-o.y / d.y);
      if (std::abs(xw.x) < 0.15f && std::abs(xw.z) < 0.15f) {
        // Every path from here to the quad meets the sphere first: nothing reaches it, exactly.
        CHECK_MESSAGE(in.illumination[4 * p] == 0.0f, "pixel ("
                                                          << x << "," << y << ") at (" << xw.x << ", " << xw.z
                                                          << ") sees the occluded quad: " << in.illumination[4 * p]);
        ++shaded;
      } else if (std::abs(xw.x) > 2.0f && in.illumination[4 * p] > 0.0f) {
        ++lit;  // far out the quad shows beside the sphere
      }
    }
  CHECK(shaded >= 4);
  CHECK(lit > 0);
}

namespace {

// The furnace cube with a glossy floor and black emitting walls (albedo 0): the floor sees unit
// radiance in every direction and nothing else, so it reflects exactly Le times its BRDF's
// directional albedo, and paths end at the walls.
scene::Scene glossy_furnace(float le, const scene::Material& floor) {
  scene::Scene s = furnace(le, 0.0f);
  s.materials.push_back(floor);
  for (std::size_t t = 0; t < 2; ++t) s.meshes[0].materials[t] = 1;  // the first quad is the floor y = -1
  s.camera[0].value = {{0.0f, 0.2f, 0.9f}, {0.0f, -1.0f, -0.5f}, {0, 1, 0}, 40.0f};
  scene::validate(s, "glossy furnace");
  return s;
}

}  // namespace

TEST_CASE("a glossy floor in a black furnace of radiance Le reflects Le times the BRDF's directional albedo") {
  ValidatedDevice device;
  struct Case {
    const char* name;
    float roughness, metallic, specular;
  };
  for (const Case c : {Case{"rough metal", 0.8f, 1.0f, 0.0f}, Case{"glossy metal", 0.3f, 1.0f, 0.0f},
                       Case{"white dielectric", 0.5f, 0.0f, 1.0f}}) {
    CAPTURE(c.name);
    scene::Material floor;
    floor.name = "floor";
    floor.albedo = glm::vec3(1.0f);
    floor.roughness = c.roughness;
    floor.metallic = c.metallic;
    floor.specular = c.specular;
    const float le = 2.0f;
    const auto scene = glossy_furnace(le, floor);
    const std::uint32_t w = 16, h = 16, spp = 256;
    const FrameInputs in = render_frame_inputs(*device, scene, device->capabilities().ray_query, w, h, 0, spp, 1);
    // The directional albedo on 33 values of n.v, interpolated linearly (A is smooth in n.v: the
    // interpolation error is below 1e-3 of the tolerance).
    const reference::GlossyMaterial model{{1, 1, 1}, c.roughness, c.metallic, c.specular};
    std::array<double, 33> table{};
    for (std::size_t i = 0; i < table.size(); ++i) {
      table[i] = reference::glossy_directional_albedo(model, std::max(double(i) / 32.0, 1e-3), 600, 360)[1];
    }
    auto albedo_at = [&](double mu) {
      const double f = std::clamp(mu, 0.0, 1.0) * 32.0;
      const auto i = std::min<std::size_t>(static_cast<std::size_t>(f), 31);
      return table[i] + (f - double(i)) * (table[i + 1] - table[i]);
    };
    const auto cam = render::make_camera(scene.camera[0].value, w, h);
    double sum_got = 0.0, sum_want = 0.0, worst_rel = 0.0;
    int compared = 0;
    for (std::uint32_t y = 0; y < h; ++y)
      for (std::uint32_t x = 0; x < w; ++x) {
        const std::size_t p = std::size_t(y) * w + x;
        if (in.visibility[4 * p] == 0u || in.visibility[4 * p + 1] > 1u) continue;  // floor pixels only
        const glm::vec2 ndc{2.0f * (x + 0.5f) / w - 1.0f, 1.0f - 2.0f * (y + 0.5f) / h};
        const glm::vec3 d =
            glm::normalize(glm::vec3(cam.forward) + ndc.x * glm::vec3(cam.right) + ndc.y * glm::vec3(cam.up));
        const double want = le * albedo_at(-d.y);
        // Radiance = demodulated illumination times the G-buffer's demodulation albedo.
        const double got = in.illumination[4 * p + 1] * in.albedo[4 * p + 1];
        sum_got += got;
        sum_want += want;
        worst_rel = std::max(worst_rel, std::abs(got - want) / want);
        ++compared;
      }
    REQUIRE(compared > int(w * h) / 2);
    MESSAGE(std::string(c.name) << ": " << compared << " floor pixels, mean " << sum_got / compared << " (expected "
                                << sum_want / compared << "), worst pixel off by " << worst_rel);
    // 256 paths a pixel, MIS between the lobe mixture and the walls' area sampling: a pixel's
    // standard error is about 4% on the rough metal (measured), so the worst of 176 pixels is about
    // 3 sigma (12%) and 20% is 5 sigma; the mean over them has a standard error near 0.3%.
    CHECK(sum_got / sum_want == doctest::Approx(1.0).epsilon(0.015));
    CHECK(worst_rel < 0.2);

    // Split into the two signals (--specular-split), the diffuse lobe reflects exactly
    // Le (1 - m)(1 - F_dielectric(n.v)) c (its weight depends on n.v only) and the GGX lobe the rest
    // of the directional albedo. Same paths, so the same statistics for each part's mean.
    const FrameInputs two =
        render_frame_inputs(*device, scene, device->capabilities().ray_query, w, h, 0, spp, 1, 7, true);
    double diffuse_got = 0.0, diffuse_want = 0.0, specular_got = 0.0, specular_want = 0.0;
    for (std::uint32_t y = 0; y < h; ++y)
      for (std::uint32_t x = 0; x < w; ++x) {
        const std::size_t p = std::size_t(y) * w + x;
        if (two.visibility[4 * p] == 0u || two.visibility[4 * p + 1] > 1u) continue;
        const glm::vec2 ndc{2.0f * (x + 0.5f) / w - 1.0f, 1.0f - 2.0f * (y + 0.5f) / h};
        const glm::vec3 d =
            glm::normalize(glm::vec3(cam.forward) + ndc.x * glm::vec3(cam.right) + ndc.y * glm::vec3(cam.up));
        const double mu = -d.y;
        const double f_dielectric = c.specular * (0.04 + 0.96 * std::pow(1.0 - mu, 5.0));
        const double diffuse = le * (1.0 - c.metallic) * (1.0 - f_dielectric);
        diffuse_want += diffuse;
        specular_want += le * albedo_at(mu) - diffuse;
        diffuse_got += two.illumination[4 * p + 1] * two.albedo[4 * p + 1];
        specular_got += two.specular[4 * p + 1] * half_to_float(two.specular_albedo[4 * p + 1]);
      }
    MESSAGE(std::string(c.name) << ": diffuse " << diffuse_got / compared << " (expected " << diffuse_want / compared
                                << "), specular " << specular_got / compared << " (expected "
                                << specular_want / compared << ")");
    if (c.metallic == 1.0f)
      CHECK(diffuse_got == 0.0);
    else
      CHECK(diffuse_got / diffuse_want == doctest::Approx(1.0).epsilon(0.015));
    CHECK(specular_got / specular_want == doctest::Approx(1.0).epsilon(0.015));
  }
}

TEST_CASE(
    "split signals: diffuse times its albedo plus specular times its albedo is the one-signal radiance, matte "
    "surfaces have no specular signal, metals no diffuse one") {
  ValidatedDevice device;
  const auto scene = scene::builtin_scene("glossy", "static");
  const std::uint32_t w = 40, h = 40, spp = 2;
  const bool rq = device->capabilities().ray_query;
  // The same seed: the same paths, only their light written to two images.
  const FrameInputs one = render_frame_inputs(*device, scene, rq, w, h, 0, spp, 4, 7, false);
  const FrameInputs two = render_frame_inputs(*device, scene, rq, w, h, 0, spp, 4, 7, true);
  REQUIRE(one.visibility == two.visibility);
  const auto albedo = [](float a) { return std::max(a, 1e-3f); };  // the path tracer's and composite's guard
  const auto half = [](const std::vector<std::uint16_t>& a, std::size_t i) { return half_to_float(a[i]); };
  int specular_pixels = 0, metal_pixels = 0, matte_pixels = 0;
  double worst = 0.0;
  for (std::size_t p = 0; p < std::size_t(w) * h; ++p) {
    for (std::size_t c = 0; c < 3; ++c) {
      const std::size_t i = 4 * p + c;
      const double want = double(one.illumination[i]) * albedo(one.albedo[i]);
      const double got = double(two.illumination[i]) * albedo(two.albedo[i]) +
                         double(two.specular[i]) * albedo(half(two.specular_albedo, i));
      // The path tracer divides the signals by the G-buffer's RGB9E5 albedos (exact to multiply
      // back) and the specular one by an fp32 albedo, which the test multiplies back as the path
      // tracer's fp16 copy (<= 2^-11 relative); the illumination is stored as halves on both sides
      // (2^-11 each); plus a few fp32 roundings of the contributions (sum, share, difference).
      worst = std::max(worst, std::abs(got - want) / std::max(want, 1e-3));
    }
    // illumination.a: the one-signal luminance, for the gradient. Both images hold half floats: the
    // luminance rounded once (2^-11 relative), the channels it is computed from here once each.
    CHECK(two.illumination[4 * p + 3] ==
          doctest::Approx(luminance(&one.illumination[4 * p])).epsilon(std::ldexp(1.0, -10)));
    const bool surface = one.visibility[4 * p] != 0u && one.visibility[4 * p] != 0xFFFFFFFFu;
    if (!surface) continue;
    const bool has_specular = two.specular[4 * p] + two.specular[4 * p + 1] + two.specular[4 * p + 2] > 0.0f;
    const bool no_diffuse_lobe = two.albedo[4 * p] == 0.0f && two.albedo[4 * p + 1] == 0.0f;
    specular_pixels += has_specular;
    if (no_diffuse_lobe) {
      ++metal_pixels;
      CHECK(two.illumination[4 * p] + two.illumination[4 * p + 1] + two.illumination[4 * p + 2] == 0.0f);
    }
    // A surface whose one-signal albedo equals its diffuse albedo has no GGX lobe.
    if (one.albedo[4 * p] == two.albedo[4 * p] && one.albedo[4 * p + 1] == two.albedo[4 * p + 1] &&
        one.albedo[4 * p + 2] == two.albedo[4 * p + 2]) {
      ++matte_pixels;
      CHECK_FALSE(has_specular);
      CHECK(half_to_float(two.specular_albedo[4 * p]) == 0.0f);
    }
  }
  MESSAGE("split vs one signal: worst relative difference "
          << worst << "; " << specular_pixels << " pixels with a specular signal, " << metal_pixels << " metal, "
          << matte_pixels << " matte");
  CHECK(worst < std::ldexp(1.0, -9) + 1e-5);
  // The scene has all three kinds: a metal floor, a glossy dielectric box, matte walls.
  CHECK(metal_pixels > int(w * h) / 10);
  CHECK(matte_pixels > int(w * h) / 10);
  CHECK(specular_pixels > metal_pixels);
}

namespace {

// Where a world point appears in a camera (pixel coordinates, not centres).
glm::vec2 project(const render::GpuCamera& c, glm::vec3 p, std::uint32_t w, std::uint32_t h) {
  const glm::vec3 v = p - glm::vec3(c.position);
  const float z = glm::dot(v, glm::vec3(c.forward));
  const glm::vec3 r(c.right), u(c.up);
  const glm::vec2 ndc{glm::dot(v, r) / glm::dot(r, r) / z, glm::dot(v, u) / glm::dot(u, u) / z};
  return {(ndc.x + 1.0f) * 0.5f * w, (1.0f - ndc.y) * 0.5f * h};
}

// World position of pixel (x, y) from its view depth.
glm::vec3 world_point(const render::GpuCamera& c, std::uint32_t x, std::uint32_t y, float depth, std::uint32_t w,
                      std::uint32_t h) {
  const glm::vec2 ndc{2.0f * (x + 0.5f) / w - 1.0f, 1.0f - 2.0f * (y + 0.5f) / h};
  const glm::vec3 d = glm::normalize(glm::vec3(c.forward) + ndc.x * glm::vec3(c.right) + ndc.y * glm::vec3(c.up));
  return glm::vec3(c.position) + d * (depth / glm::dot(d, glm::vec3(c.forward)));
}

}  // namespace

TEST_CASE("motion vectors are right for a known camera move and a known object move") {
  ValidatedDevice device;
  const std::uint32_t w = 40, h = 32;
  SUBCASE("camera move") {
    auto scene = scene::builtin_scene("cornell", "static");
    auto c1 = scene.camera[0].value;
    c1.position += glm::vec3(0.15f, -0.05f, 0.1f);
    c1.target += glm::vec3(0.05f, 0.0f, 0.0f);
    scene.camera.push_back({1.0f, c1});
    const FrameInputs in = render_frame_inputs(*device, scene, device->capabilities().ray_query, w, h, 1);
    const auto prev = render::make_camera(scene.camera[0].value, w, h);
    const auto cur = render::make_camera(c1, w, h);
    double worst = 0.0;
    int n = 0;
    for (std::uint32_t y = 0; y < h; ++y)
      for (std::uint32_t x = 0; x < w; ++x) {
        const std::size_t p = std::size_t(y) * w + x;
        if (in.visibility[4 * p] == 0u || in.visibility[4 * p] == 0xFFFFFFFFu) continue;
        const glm::vec3 X = world_point(cur, x, y, in.depth_normal[4 * p], w, h);
        const glm::vec2 expected = project(prev, X, w, h) - glm::vec2(x + 0.5f, y + 0.5f);
        worst = std::max(worst, double(glm::length(glm::vec2(in.motion[4 * p], in.motion[4 * p + 1]) - expected)));
        ++n;
      }
    MESSAGE(n << " pixels, worst motion error " << worst << " px");
    CHECK(n > int(w * h) / 2);
    CHECK(worst < 2e-3);
  }
  SUBCASE("camera move, the specular history through the reflection's virtual point") {
    // The metal floor reflects the room: its specular history lies where last frame's camera saw the
    // virtual image, on the view ray at the primary distance plus the reflected ray's length.
    auto scene = scene::builtin_scene("glossy", "static");
    auto c1 = scene.camera[0].value;
    c1.position += glm::vec3(0.2f, 0.05f, 0.1f);
    scene.camera.push_back({1.0f, c1});
    const FrameInputs in =
        render_frame_inputs(*device, scene, device->capabilities().ray_query, w, h, 1, 1, 4, 7, true);
    const auto prev = render::make_camera(scene.camera[0].value, w, h);
    const auto cur = render::make_camera(c1, w, h);
    double worst = 0.0, apart = 0.0;
    int virtual_pixels = 0, surface_pixels = 0;
    for (std::uint32_t y = 0; y < h; ++y)
      for (std::uint32_t x = 0; x < w; ++x) {
        const std::size_t p = std::size_t(y) * w + x;
        if (in.visibility[4 * p] == 0u || in.visibility[4 * p] == 0xFFFFFFFFu) continue;
        const glm::vec2 got{in.specular_motion[4 * p], in.specular_motion[4 * p + 1]};
        const glm::vec2 surface{in.motion[4 * p], in.motion[4 * p + 1]};
        const float reflected = in.specular[4 * p + 3];
        if (reflected <= 0.0f) {  // no specular ray, or it left the scene (at infinity)
          if (reflected == 0.0f) {
            CHECK(got == surface);
            CHECK(in.specular_motion[4 * p + 2] == 0.0f);
            ++surface_pixels;
          }
          continue;
        }
        const glm::vec3 X = world_point(cur, x, y, in.depth_normal[4 * p], w, h);
        const glm::vec3 eye(cur.position);
        const glm::vec3 virtual_point = eye + glm::normalize(X - eye) * (glm::length(X - eye) + reflected);
        const glm::vec2 expected = project(prev, virtual_point, w, h) - glm::vec2(x + 0.5f, y + 0.5f);
        worst = std::max(worst, double(glm::length(got - expected)));
        apart = std::max(apart, double(glm::length(got - surface)));
        CHECK(in.specular_motion[4 * p + 2] == 1.0f);  // marked: the temporal pass's looser test
        ++virtual_pixels;
      }
    MESSAGE(virtual_pixels << " pixels through a reflection (up to " << apart << " px from the surface's motion), "
                           << surface_pixels << " with the surface's; worst error " << worst << " px");
    CHECK(virtual_pixels > 60);  // the metal floor and part of the lacquer box (of 1280)
    CHECK(surface_pixels > int(w * h) / 10);
    CHECK(apart > 0.5);  // the camera move separates the two
    CHECK(worst < 2e-3);
  }
  SUBCASE("object move") {
    const auto scene = scene::builtin_scene("cornell", "boxes-move");
    const int frame = 5;  // the short box slides between frames 3 and 7
    const FrameInputs in = render_frame_inputs(*device, scene, device->capabilities().ray_query, w, h, frame);
    const auto now = scene::evaluate(scene, float(frame)), before = scene::evaluate(scene, float(frame - 1));
    const auto cam = render::make_camera(now.camera, w, h);
    const glm::mat4 back = before.instance_transforms[2] * glm::inverse(now.instance_transforms[2]);
    double worst = 0.0, biggest = 0.0;
    int n = 0;
    for (std::uint32_t y = 0; y < h; ++y)
      for (std::uint32_t x = 0; x < w; ++x) {
        const std::size_t p = std::size_t(y) * w + x;
        if (in.visibility[4 * p] != 3u) continue;  // instance 2 (the short box) + 1
        const glm::vec3 X = world_point(cam, x, y, in.depth_normal[4 * p], w, h);
        const glm::vec3 X_prev = glm::vec3(back * glm::vec4(X, 1.0f));
        const glm::vec2 expected = project(cam, X_prev, w, h) - glm::vec2(x + 0.5f, y + 0.5f);
        worst = std::max(worst, double(glm::length(glm::vec2(in.motion[4 * p], in.motion[4 * p + 1]) - expected)));
        biggest = std::max(biggest, double(glm::length(expected)));
        ++n;
      }
    MESSAGE(n << " box pixels, motion up to " << biggest << " px, worst error " << worst << " px");
    CHECK(n > 20);
    CHECK(biggest > 1.0);
    CHECK(worst < 2e-3);
  }
}

// Pixels where two renders differ in any G-buffer or illumination bit.
struct Differences {
  int gbuffer = 0, illumination = 0;
};
Differences compare_bits(const FrameInputs& a, const FrameInputs& b) {
  Differences d;
  for (std::size_t p = 0; p < std::size_t(a.width) * a.height; ++p) {
    d.gbuffer += std::memcmp(&a.visibility[4 * p], &b.visibility[4 * p], 16) != 0 ||
                 std::memcmp(&a.depth_normal[4 * p], &b.depth_normal[4 * p], 16) != 0 ||
                 std::memcmp(&a.motion[4 * p], &b.motion[4 * p], 8) != 0 ||
                 std::memcmp(&a.albedo[4 * p], &b.albedo[4 * p], 16) != 0;
    d.illumination += std::memcmp(&a.illumination[4 * p], &b.illumination[4 * p], 12) != 0;
  }
  return d;
}

TEST_CASE("ray-query and software-BVH variants give bit-identical G-buffers and path-traced images") {
  // Both variants run one watertight triangle test over conservative candidate sets and break depth
  // ties by triangle index (shaders/common/trace.glsl), so even a ray through a quad's diagonal or
  // a room's corner edge, which hits two triangles at the same point, gets the same answer.
  ValidatedDevice device;
  if (!device->capabilities().ray_query) {
    MESSAGE("skipped: " << device->adapter().name << " has no ray queries (the OpenGL backend never has)");
    return;
  }
  const std::uint32_t w = 48, h = 40;
  for (const char* animation : {"static", "boxes-move", "orbit"}) {
    CAPTURE(animation);
    const auto scene = scene::builtin_scene("cornell", animation);
    const FrameInputs rq = render_frame_inputs(*device, scene, true, w, h, 5, 2);
    const FrameInputs sw = render_frame_inputs(*device, scene, false, w, h, 5, 2);
    const Differences d = compare_bits(rq, sw);
    MESSAGE(d.gbuffer << " G-buffer and " << d.illumination << " illumination differences in " << w * h << " pixels");
    CHECK(d.gbuffer == 0);
    CHECK(d.illumination == 0);
  }
}

TEST_CASE("tracing is watertight: rays through the shared vertices and edges of a tessellated wall all hit it") {
  // A 2x2 wall of 64x64 quads (two triangles each) seen head-on by a 90-degree camera 1 unit away:
  // every pixel centre projects onto a grid vertex, where six triangles meet, and the float ray
  // passes within an ulp of it on some side. A test that is not watertight lets such rays through
  // to the black background; both variants must hit the wall at every pixel, with the same bits.
  scene::Mesh wall;
  wall.name = "wall";
  const int n = 64;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      auto at = [&](int x, int y) { return glm::vec3(-1.0f + 2.0f * float(x) / n, -1.0f + 2.0f * float(y) / n, 0.0f); };
      // Alternate the diagonal so that both diagonal directions meet pixel-centre rays.
      if ((i + j) % 2 == 0)
        add_quad(wall, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), 0);
      else
        add_quad(wall, at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), at(i, j), 0);
    }
  scene::Material grey;
  grey.name = "grey";
  grey.albedo = glm::vec3(0.5f);
  const auto s = one_mesh_scene(wall, {grey}, {{0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.0f}, {0, 1, 0}, 90.0f});
  ValidatedDevice device;
  const std::uint32_t size = 32;
  auto missed = [&size](const FrameInputs& in) {
    int count = 0;
    for (std::size_t p = 0; p < std::size_t(size) * size; ++p) count += in.visibility[4 * p] == 0u;  // 0 = background
    return count;
  };
  const FrameInputs sw = render_frame_inputs(*device, s, false, size, size, 0);
  MESSAGE("missed pixels, software BVH: " << missed(sw));
  CHECK(missed(sw) == 0);
  if (!device->capabilities().ray_query) return;  // OpenGL: the software BVH is the only variant
  const FrameInputs rq = render_frame_inputs(*device, s, true, size, size, 0);
  const Differences d = compare_bits(rq, sw);
  MESSAGE("missed pixels, ray query: " << missed(rq) << "; pixels differing from the software BVH " << d.gbuffer);
  CHECK(missed(rq) == 0);
  CHECK(d.gbuffer == 0);
}

TEST_CASE("no light leaks into the room once light-exit's light is outside: every pixel is exactly black") {
  // From frame 6 the sphere light is wholly outside the right wall. The room is open only at the
  // front, and the only surface the light reaches, the right wall's outer face, reflects away from
  // the opening: no path carries light inside, so every pixel's radiance is exactly 0. Pixel-centre
  // rays that hit the creases where walls meet (the image's diagonals here) used to start their
  // rays on the neighbouring wall's plane and see the light through it.
  ValidatedDevice device;
  const auto scene = scene::builtin_scene("cornell", "light-exit");
  const std::uint32_t size = 64;
  for (bool ray_query : {true, false}) {
    if (ray_query && !device->capabilities().ray_query) continue;
    CAPTURE(ray_query);
    const FrameInputs in = render_frame_inputs(*device, scene, ray_query, size, size, 8, 8);
    int lit = 0;
    for (std::size_t p = 0; p < std::size_t(size) * size; ++p)
      lit += in.illumination[4 * p] != 0.0f || in.illumination[4 * p + 1] != 0.0f || in.illumination[4 * p + 2] != 0.0f;
    MESSAGE(lit << " lit pixels of " << size * size);
    CHECK(lit == 0);
  }
}

TEST_CASE("albedo textures reach the G-buffer: each texel of a 2x2 texture lands in its quadrant") {
  ValidatedDevice device;
  scene::Mesh quad;
  quad.name = "quad";
  add_quad(quad, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, 0);
  quad.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};  // v = 0 at the texture's top row
  scene::Material mat;
  mat.name = "checker";
  mat.albedo = glm::vec3(0.5f);
  scene::Texture tex;
  tex.name = "2x2";
  tex.width = tex.height = 2;
  tex.rgba8 = {255, 0, 0,   255, 0,   255, 0,   255,   // red, green (top row)
               0,   0, 255, 255, 255, 255, 255, 255};  // blue, white
  auto scene = one_mesh_scene(quad, {mat}, {{0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 60.0f});
  scene.textures.push_back(tex);
  scene.materials[0].albedo_texture = 0;
  scene::validate(scene, "textured quad");
  for (bool ray_query : {true, false}) {
    if (ray_query && !device->capabilities().ray_query) continue;
    CAPTURE(ray_query);
    const std::uint32_t w = 32, h = 32;
    const FrameInputs in = render_frame_inputs(*device, scene, ray_query, w, h, 0);
    const auto cam = render::make_camera(scene.camera[0].value, w, h);
    const struct {
      glm::vec3 point, albedo;
    } expect[] = {{{-0.5f, 0.5f, 0}, {0.5f, 0, 0}},
                  {{0.5f, 0.5f, 0}, {0, 0.5f, 0}},
                  {{-0.5f, -0.5f, 0}, {0, 0, 0.5f}},
                  {{0.5f, -0.5f, 0}, {0.5f, 0.5f, 0.5f}}};
    for (const auto& e : expect) {
      const glm::vec2 px = project(cam, e.point, w, h);
      const std::size_t p = std::size_t(px.y) * w + std::size_t(px.x);
      CAPTURE(e.point.x);
      CAPTURE(e.point.y);
      REQUIRE(in.visibility[4 * p] == 1u);
      for (int c = 0; c < 3; ++c) CHECK(in.albedo[4 * p + c] == doctest::Approx(e.albedo[c]).epsilon(1e-3));
    }
  }
}

TEST_CASE("a fixed seed gives bit-identical frames, another seed different ones") {
  // orbit: the camera moves every frame, so A-SVGF's gradient samples are selected every frame;
  // their selection must not depend on the order the GPU runs invocations in.
  ValidatedDevice device;
  const auto scene = scene::builtin_scene("cornell", "orbit");
  auto frames = [&](std::uint32_t seed) {
    render::RenderSettings s;
    s.method = frame::Method::Asvgf;
    s.width = 64;
    s.height = 48;
    s.seed = seed;
    render::Renderer r(*device, scene, s);
    std::vector<float> all;
    for (int f = 0; f < 8; ++f) {
      const auto img = r.render(f);
      all.insert(all.end(), img.hdr.begin(), img.hdr.end());
    }
    return all;
  };
  const auto a = frames(3), b = frames(3), c = frames(4);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differ += std::memcmp(&a[i], &b[i], 4) != 0;
  CHECK(differ == 0);
  CHECK(std::memcmp(a.data(), c.data(), a.size() * 4) != 0);
}
