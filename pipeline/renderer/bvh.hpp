// renderer/bvh.hpp: a bounding volume hierarchy over triangles, built on the CPU with the surface
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

// An axis-aligned box; 24 bytes, the layout of a BLAS box buffer (hal::BlasGeometry::Boxes).
struct TriangleBox {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
};
static_assert(sizeof(TriangleBox) == 24);

// Each triangle's bounds grown by a margin of 2^-12 times the largest coordinate of the input, so
// that a ray the triangle test of trace.glsl says hits a triangle passes strictly inside its box
// even after a float box test's rounding: the BVH's nodes and the ray-query variant's boxes are
// then conservative, and a triangle hit exactly at the current closest depth (a tie) still has its
// box entered before that depth.
std::vector<TriangleBox> padded_triangle_boxes(std::span<const glm::vec3> triangle_vertices);

struct Bvh {
  std::vector<BvhNode> nodes;            // nodes[0] is the root
  std::vector<std::uint32_t> triangles;  // triangle indices, leaves refer to ranges of it
  // Expected cost under the SAH (traversal 1, intersection 1), relative to the root's area.
  double sah_cost = 0.0;
  std::uint32_t depth = 0;
};

struct BvhOptions {
  // Always a leaf at this many triangles; the SAH may still choose one up to 4 times as many. 3 (against 2
  // and 4) had the fastest path tracing on the small built-in scenes (-7% to -10% against 4) for +0.6% on
  // `many` (docs/performance.md, "The BVH's leaves").
  std::uint32_t max_leaf_triangles = 3;
  std::uint32_t bins = 16;
};

// Builds over triangles given as three world-space positions each (positions.size() % 3 == 0);
// node boxes bound the padded_triangle_boxes.
// An empty input gives a single empty leaf.
Bvh build_bvh(std::span<const glm::vec3> triangle_vertices, const BvhOptions& options = {});

// Maximum depth the GPU traversal stack supports; build_bvh never exceeds it.
inline constexpr std::uint32_t kMaxBvhDepth = 48;

}  // namespace asvgf::render
