// SceneGpu::update on the recording HAL: the acceleration structures are rebuilt when geometry
// moves, not when only the camera or a light does (a 100k-triangle rebuild costs the CPU
// milliseconds a frame and leaves the GPU idle meanwhile).
#include <doctest/doctest.h>

#include <string>

#include "checked_record.hpp"
#include "renderer/scene_gpu.hpp"
#include "renderer/scene/builtin.hpp"

using namespace asvgf;

namespace {

// Updates frames 0..frames-1 and counts the BLAS builds recorded.
int blas_builds(const std::string& animation, int frames) {
  CheckedRecord r;
  const scene::Scene room = scene::builtin_scene("cornell", animation);
  render::SceneGpu gpu(r.device, room, true);
  int moving = 0;
  for (int f = 0; f < frames; ++f) moving += gpu.update(static_cast<float>(f)) ? 1 : 0;
  CHECK_MESSAGE(moving > 1, animation << ": expected moving frames");
  int builds = 0;
  for (const auto& entry : r.record.log())
    if (entry.text.find("build blas") != std::string::npos) ++builds;
  CHECK(r.record.reports().empty());
  return builds;
}

}  // namespace

TEST_CASE("scene update: a camera path or a moving light keeps the BLAS, moving boxes rebuild it") {
  CHECK(blas_builds("orbit", 8) == 1);  // built once, at the first update
  CHECK(blas_builds("light-exit", 12) == 1);
  CHECK(blas_builds("boxes-move", 12) > 2);  // every frame a box moves
}
