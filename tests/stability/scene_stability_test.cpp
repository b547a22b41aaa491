// Extreme geometry through the whole frame (real path tracer and denoiser): degenerate triangles
// met by forward projection and by the path tracer must not put NaN or Inf into any output, and the
// path tracer must not produce samples the sanitiser has to drop.
#include <doctest/doctest.h>

#include <cmath>

#include "renderer/renderer.hpp"
#include "renderer/scene/builtin.hpp"
#include "vulkan/validated_device.hpp"

using namespace asvgf;

TEST_CASE("degenerate triangles in a moving scene leave every asvgf output finite") {
  ValidatedDevice device;
  // The built-in room with extra triangles of zero area in view (a point and a line), on a box
  // that moves, so that gradient_select forward-projects samples that land on them.
  auto scene = scene::builtin_scene("cornell", "boxes-move");
  scene::Mesh& box = scene.meshes.at(scene.instances.at(2).mesh);
  const auto base = static_cast<std::uint32_t>(box.positions.size());
  const glm::vec3 p = box.positions.front();
  box.positions.insert(box.positions.end(), {p, p, p, p + glm::vec3(0.3f, 0, 0), p + glm::vec3(0.6f, 0, 0)});
  box.indices.insert(box.indices.end(), {base, base + 1, base + 2, base + 2, base + 3, base + 4});
  box.materials.insert(box.materials.end(), {box.materials.front(), box.materials.front()});
  // And the tall box flattens to a horizontal square at frame 5: its side faces become triangles
  // of zero area lying in the square, where last frame's samples on them are forward-projected
  // and pass the depth test.
  auto& tall = scene.instances.at(1).transform;
  scene::Transform collapsed = tall.back().value;
  collapsed.scale.y = 0.0f;
  tall = {{4.0f, tall.back().value}, {5.0f, collapsed}};
  scene::validate(scene, "degenerate triangles");

  render::RenderSettings s;
  s.method = frame::Method::Asvgf;
  s.width = 48;
  s.height = 40;
  for (bool ray_query : {true, false}) {
    CAPTURE(ray_query);
    s.ray_query = ray_query;
    render::Renderer r(*device, scene, s);
    for (int f = 2; f < 9; ++f) {
      const auto img = r.render(f);
      std::size_t bad = 0;
      for (float v : img.hdr) bad += !std::isfinite(v);
      CHECK(bad == 0);
    }
    const auto dropped = r.dropped_samples();
    CHECK(dropped.nan_samples == 0);
    CHECK(dropped.inf_samples == 0);
  }
}
