// Ray queries over a BLAS of boxes (procedural primitives): the traversal must report every box a
// ray passes through as a candidate, with the box's position in the buffer as primitive index, so
// that a shader committing the nearest box entry point finds what a CPU brute force finds.
//
// Rays whose answer is ambiguous in float (two boxes entered within 1e-4 relative, a ray grazing a
// box, an entry within 1e-4 of tmax) are excluded and counted; they must stay under 5%.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "backends.hpp"
#include "data.hpp"
#include "shaders/hal_test_ray_query.rayquery_boxes.hpp"

using namespace conformance;
using hal::State;

namespace {

struct Box {
  std::array<float, 3> min, max;
};
static_assert(sizeof(Box) == 24);
struct Ray {
  std::array<float, 3> origin;
  float tmin;
  std::array<float, 3> direction;
  float tmax;
};
struct Expected {
  bool hit = false, ambiguous = false;
  std::uint32_t box = 0;
  double t = 0;
};

// Entry and exit of the ray's line into box b in double; entry > exit when it misses.
std::array<double, 2> slab(const Box& b, const Ray& r) {
  double enter = -std::numeric_limits<double>::infinity(), leave = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    const double t0 = (double(b.min[a]) - r.origin[a]) / r.direction[a];
    const double t1 = (double(b.max[a]) - r.origin[a]) / r.direction[a];
    enter = std::max(enter, std::min(t0, t1));
    leave = std::min(leave, std::max(t0, t1));
  }
  return {enter, leave};
}

Expected nearest_entry(const std::vector<Box>& boxes, const Ray& r) {
  constexpr double kTie = 1e-4;
  Expected best;
  std::vector<double> entries;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    auto [enter, leave] = slab(boxes[i], r);
    enter = std::max(enter, double(r.tmin));
    leave = std::min(leave, double(r.tmax));
    const double scale = std::max(1.0, std::abs(enter));
    if (std::abs(leave - enter) <= kTie * scale) best.ambiguous = true;  // grazes or touches tmax
    if (enter > leave) continue;
    entries.push_back(enter);
    if (!best.hit || enter < best.t) best = {true, best.ambiguous, i, enter};
  }
  for (double t : entries)
    if (best.hit && t != best.t && std::abs(t - best.t) <= kTie * std::max(1.0, best.t)) best.ambiguous = true;
  if (std::count(entries.begin(), entries.end(), best.t) > 1) best.ambiguous = true;
  return best;
}

std::vector<Box> random_boxes(std::mt19937& rng, int count) {
  std::uniform_real_distribution<float> centre(-3.0f, 3.0f), half(0.05f, 0.6f);
  std::vector<Box> boxes;
  for (int i = 0; i < count; ++i) {
    Box b{};
    for (int a = 0; a < 3; ++a) {
      const float c = centre(rng), h = half(rng);
      b.min[a] = c - h;
      b.max[a] = c + h;
    }
    boxes.push_back(b);
  }
  return boxes;
}

}  // namespace

TEST_CASE(
    "conformance: ray queries over boxes report every box a ray enters (nearest entry matches a CPU brute force)") {
  for_each_backend([](hal::Device& device) {
    if (!device.capabilities().ray_query) {
      MESSAGE("device has no ray queries: skipped");
      return;
    }
    std::mt19937 rng(99);
    std::vector<Box> boxes = random_boxes(rng, 150);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<Ray> rays;
    for (int i = 0; i < 2000; ++i) {
      const std::array<float, 3> origin{6 * unit(rng), 6 * unit(rng), 6 * unit(rng)};
      const std::array<float, 3> to{3 * unit(rng) - origin[0], 3 * unit(rng) - origin[1], 3 * unit(rng) - origin[2]};
      rays.push_back({origin, i % 5 == 0 ? 0.2f : 0.0f, to, i % 7 == 0 ? 0.6f : 100.0f});
    }

    const hal::ShaderInfo& shader = asvgf::shaders::hal_test_ray_query_rayquery_boxes;
    const auto usage = hal::BufferUsage::AccelBuildInput | hal::BufferUsage::Storage | hal::BufferUsage::CopyDst;
    const auto box_buffer = device.create_buffer({"boxes", boxes.size() * sizeof(Box), usage});
    const auto count = static_cast<std::uint32_t>(boxes.size());
    const auto blas = device.create_blas(hal::BlasDesc::of_boxes("boxes blas", box_buffer, count, true));
    const auto tlas = device.create_tlas({"boxes tlas", 1});
    const auto ray_buffer = device.create_buffer(
        {"rays", rays.size() * sizeof(Ray), hal::BufferUsage::Storage | hal::BufferUsage::CopyDst});
    const auto hit_buffer =
        device.create_buffer({"hits", rays.size() * 16, hal::BufferUsage::Storage | hal::BufferUsage::CopySrc});
    device.upload_buffer(ray_buffer, 0, as_bytes(rays));
    const auto pipeline = device.create_pipeline({"ray query boxes", &shader});
    const auto set = device.create_binding_set(
        {"ray query boxes set",
         pipeline,
         {{"scene", tlas}, {"rays", ray_buffer}, {"hits", hit_buffer}, {"boxes", box_buffer}}});
    auto cmd = device.create_command_list("ray query boxes");

    // Builds (or refits) the structures, traces every ray and compares with the CPU.
    auto trace_and_compare = [&](bool update, const std::string& what) {
      device.upload_buffer(box_buffer, 0, as_bytes(boxes));
      cmd->reset();
      const State accel_before = update ? State::AccelRead : State::Undefined;
      cmd->barrier({{box_buffer, State::CopyDst, State::AccelBuildInput}, {blas, accel_before, State::AccelWrite}});
      cmd->build_blas(blas, update);
      cmd->barrier({{blas, State::AccelWrite, State::AccelRead}, {tlas, accel_before, State::AccelWrite}});
      const hal::TlasInstance instance{blas, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, 7};
      cmd->build_tlas(tlas, std::span(&instance, 1), false);
      cmd->barrier({{tlas, State::AccelWrite, State::AccelRead},
                    {box_buffer, State::AccelBuildInput, State::ShaderRead},
                    {ray_buffer, update ? State::ShaderRead : State::CopyDst, State::ShaderRead},
                    {hit_buffer, update ? State::CopySrc : State::Undefined, State::ShaderWrite}});
      Uniforms uniforms(shader);
      uniforms.set("count", static_cast<std::uint32_t>(rays.size()));
      const auto groups =
          (static_cast<std::uint32_t>(rays.size()) + shader.workgroup_size[0] - 1) / shader.workgroup_size[0];
      cmd->dispatch({pipeline, set, uniforms.bytes(), groups, 1, 1});
      cmd->barrier({{hit_buffer, State::ShaderWrite, State::CopySrc}, {box_buffer, State::ShaderRead, State::CopyDst}});
      device.submit(*cmd);
      device.wait();
      std::vector<std::array<std::uint32_t, 4>> raw(rays.size());
      device.read_buffer(hit_buffer, 0, as_writable(raw));

      int ambiguous = 0, hits = 0, mismatches = 0;
      for (std::size_t i = 0; i < rays.size(); ++i) {
        const Expected cpu = nearest_entry(boxes, rays[i]);
        if (cpu.ambiguous) {
          ++ambiguous;
          continue;
        }
        hits += cpu.hit;
        float t;
        std::memcpy(&t, &raw[i][2], 4);
        bool same = (raw[i][3] == 1) == cpu.hit;
        if (same && cpu.hit)
          same = raw[i][0] == 7 && raw[i][1] == cpu.box && std::abs(t - cpu.t) <= 1e-5 * std::max(1.0, cpu.t);
        if (!same && ++mismatches <= 5)
          MESSAGE(what << " ray " << i << ": cpu hit=" << cpu.hit << " box=" << cpu.box << " t=" << cpu.t
                       << " | gpu hit=" << raw[i][3] << " custom=" << raw[i][0] << " box=" << raw[i][1] << " t=" << t);
      }
      MESSAGE(what << ": " << rays.size() << " rays, " << hits << " hit a box, " << ambiguous
                   << " ambiguous (excluded), " << mismatches << " mismatches");
      CHECK(mismatches == 0);
      CHECK(ambiguous * 20 < static_cast<int>(rays.size()));
      CHECK(hits * 4 > static_cast<int>(rays.size()));
    };
    trace_and_compare(false, "box build");
    // Boxes move a little: refit in place.
    for (Box& b : boxes)
      for (int a = 0; a < 3; ++a) {
        const float shift = 0.2f * unit(rng);
        b.min[a] += shift;
        b.max[a] += shift;
      }
    trace_and_compare(true, "box refit");

    device.destroy(set);
    device.destroy(pipeline);
    for (auto b : {box_buffer, ray_buffer, hit_buffer}) device.destroy(b);
    device.destroy(tlas);
    device.destroy(blas);
  });
}
