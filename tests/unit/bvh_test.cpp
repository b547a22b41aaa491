// The CPU BVH builder (renderer/bvh.hpp): structure, conservative padded boxes, and that the SAH
// splits pay off. The GPU traversal relies on every one of these.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "renderer/bvh.hpp"

using namespace asvgf::render;

namespace {

bool contains(const BvhNode& outer, glm::vec3 lo, glm::vec3 hi) {
  return glm::all(glm::lessThanEqual(outer.min, lo)) && glm::all(glm::lessThanEqual(hi, outer.max));
}

std::vector<glm::vec3> random_soup(std::uint32_t triangles, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> centre(-20.0f, 20.0f), offset(-0.5f, 0.5f);
  std::vector<glm::vec3> v;
  for (std::uint32_t t = 0; t < triangles; ++t) {
    const glm::vec3 c(centre(rng), centre(rng), centre(rng));
    for (int k = 0; k < 3; ++k) v.push_back(c + glm::vec3(offset(rng), offset(rng), offset(rng)));
  }
  return v;
}

// Walks the tree: each triangle in exactly one leaf, children inside parents, leaves bounding
// their triangles' padded boxes, depth within the traversal stack.
void check_structure(const Bvh& bvh, std::span<const glm::vec3> vertices) {
  const auto n = static_cast<std::uint32_t>(vertices.size() / 3);
  const std::vector<TriangleBox> boxes = padded_triangle_boxes(vertices);
  std::vector<int> seen(n, 0);
  struct Item {
    std::uint32_t node, depth;
  };
  std::vector<Item> stack = {{0, 0}};
  std::uint32_t deepest = 0;
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    deepest = std::max(deepest, item.depth);
    const BvhNode& node = bvh.nodes.at(item.node);
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const std::uint32_t t = bvh.triangles.at(i);
        ++seen.at(t);
        CHECK(contains(node, boxes[t].min, boxes[t].max));
      }
      continue;
    }
    for (std::uint32_t child : {node.first, node.first + 1}) {
      CHECK(contains(node, bvh.nodes.at(child).min, bvh.nodes.at(child).max));
      stack.push_back({child, item.depth + 1});
    }
  }
  CHECK(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
  CHECK(deepest < kMaxBvhDepth);
  CHECK(bvh.nodes.size() <= 2 * std::max<std::size_t>(n, 1));
}

}  // namespace

TEST_CASE("padded triangle boxes hold their triangle strictly inside, by a margin that scales with the scene") {
  const std::vector<glm::vec3> near = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};  // flat in z
  const std::vector<glm::vec3> far = {{1000, 0, 0}, {1001, 0, 0}, {1000, 1, 0}};
  const auto a = padded_triangle_boxes(near), b = padded_triangle_boxes(far);
  REQUIRE(a.size() == 1);
  auto strictly_inside = [](const TriangleBox& box, glm::vec3 v) {
    return glm::all(glm::lessThan(box.min, v)) && glm::all(glm::lessThan(v, box.max));
  };
  for (const auto& v : near) CHECK(strictly_inside(a[0], v));
  for (const auto& v : far) CHECK(strictly_inside(b[0], v));
  CHECK(a[0].max.z - a[0].min.z > 0.0f);  // a flat triangle still gets a box with volume
  CHECK(b[0].max.z - b[0].min.z > 100.0f * (a[0].max.z - a[0].min.z));
}

TEST_CASE(
    "BVH over a random soup: every triangle in one leaf, nested boxes, and SAH splits far cheaper than one leaf") {
  const auto soup = random_soup(2000, 5);
  const Bvh bvh = build_bvh(soup);
  check_structure(bvh, soup);
  MESSAGE("2000 triangles: " << bvh.nodes.size() << " nodes, depth " << bvh.depth << ", SAH cost " << bvh.sah_cost);
  // One leaf holding everything costs 2000 (intersection cost 1 per triangle, relative to the root).
  CHECK(bvh.sah_cost < 2000.0 / 20.0);
}

TEST_CASE("BVH of degenerate inputs: coincident triangles keep a valid tree, an empty scene is one empty leaf") {
  std::vector<glm::vec3> stacked;
  for (int t = 0; t < 100; ++t) stacked.insert(stacked.end(), {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}});
  const Bvh same = build_bvh(stacked);
  check_structure(same, stacked);  // no split separates them: one leaf is the right answer

  const Bvh empty = build_bvh({});
  REQUIRE(empty.nodes.size() == 1);
  CHECK(empty.nodes[0].count == 0);
  CHECK(empty.triangles.empty());
}
