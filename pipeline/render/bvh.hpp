// render/bvh.hpp: a bounding volume hierarchy over triangles, built on the CPU with the surface
// area heuristic (binned), laid out for the software-BVH tracing variant (shaders/common/trace.glsl).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace asvgf::render {

// 32 bytes, std430-compatible: two vec4s on the GPU.
struct BvhNode {
  glm::vec3 min{0.0f};
  std::uint32_t first = 0;  // leaf: first entry of Bvh::triangles; inner: index of the left child
  glm::vec3 max{0.0f};
  std::uint32_t count = 0;  // leaf: number of triangles (> 0); inner: 0, right child = first + 1
};
static_assert(sizeof(BvhNode) == 32);

struct Bvh {
  std::vector<BvhNode> nodes;           // nodes[0] is the root
  std::vector<std::uint32_t> triangles;  // triangle indices, leaves refer to ranges of it
  // Expected cost under the SAH (traversal 1, intersection 1), relative to the root's area.
  double sah_cost = 0.0;
  std::uint32_t depth = 0;
};

struct BvhOptions {
  std::uint32_t max_leaf_triangles = 4;
  std::uint32_t bins = 16;
};

// Builds over triangles given as three world-space positions each (positions.size() % 3 == 0).
// An empty input gives a single empty leaf.
Bvh build_bvh(std::span<const glm::vec3> triangle_vertices, const BvhOptions& options = {});

// Maximum depth the GPU traversal stack supports; build_bvh never exceeds it.
inline constexpr std::uint32_t kMaxBvhDepth = 48;

}  // namespace asvgf::render
