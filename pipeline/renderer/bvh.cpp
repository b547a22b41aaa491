// Binned SAH BVH build (after Wald, "On fast Construction of SAH-based Bounding Volume
// Hierarchies", 2007): at each node, bin triangle centroids along each axis and split where the
// surface-area cost is lowest; make a leaf when no split beats it.
#include "renderer/bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace asvgf::render {
namespace {

struct Box {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{-std::numeric_limits<float>::max()};
  void grow(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void grow(const Box& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
  bool empty() const { return min.x > max.x; }
  double area() const {
    if (empty()) return 0.0;
    const glm::dvec3 d = glm::dvec3(max) - glm::dvec3(min);
    return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

struct Builder {
  std::span<const glm::vec3> v;
  BvhOptions options;
  std::vector<Box> boxes;
  std::vector<glm::vec3> centroids;
  Bvh bvh;

  Box bounds(std::uint32_t begin, std::uint32_t end) const {
    Box b;
    for (std::uint32_t i = begin; i < end; ++i) b.grow(boxes[bvh.triangles[i]]);
    return b;
  }

  void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, std::uint32_t depth) {
    bvh.depth = std::max(bvh.depth, depth);
    const Box box = bounds(begin, end);
    bvh.nodes[node].min = box.empty() ? glm::vec3(0) : box.min;
    bvh.nodes[node].max = box.empty() ? glm::vec3(0) : box.max;
    const std::uint32_t n = end - begin;
    auto make_leaf = [&] {
      bvh.nodes[node].first = begin;
      bvh.nodes[node].count = n;
      bvh.sah_cost += box.area() * n;
    };
    if (n <= options.max_leaf_triangles || depth + 1 >= kMaxBvhDepth) return make_leaf();

    Box centroid_box;
    for (std::uint32_t i = begin; i < end; ++i) centroid_box.grow(centroids[bvh.triangles[i]]);
    double best_cost = std::numeric_limits<double>::max();
    int best_axis = -1;
    std::uint32_t best_bin = 0;
    const std::uint32_t bins = options.bins;
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = centroid_box.min[axis], hi = centroid_box.max[axis];
      if (!(hi > lo)) continue;
      std::vector<Box> bin_box(bins);
      std::vector<std::uint32_t> bin_count(bins, 0);
      const float scale = static_cast<float>(bins) / (hi - lo);
      for (std::uint32_t i = begin; i < end; ++i) {
        const std::uint32_t t = bvh.triangles[i];
        const auto b = std::min(bins - 1, static_cast<std::uint32_t>((centroids[t][axis] - lo) * scale));
        bin_box[b].grow(boxes[t]);
        ++bin_count[b];
      }
      // Sweep: cost of splitting after bin k = A(left)*N(left) + A(right)*N(right).
      std::vector<double> right_cost(bins, 0.0);
      Box acc;
      std::uint32_t count = 0;
      for (std::uint32_t k = bins - 1; k > 0; --k) {
        acc.grow(bin_box[k]);
        count += bin_count[k];
        right_cost[k - 1] = acc.area() * count;
      }
      acc = Box{};
      count = 0;
      for (std::uint32_t k = 0; k + 1 < bins; ++k) {
        acc.grow(bin_box[k]);
        count += bin_count[k];
        const double cost = acc.area() * count + right_cost[k];
        if (count > 0 && count < n && cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_bin = k;
        }
      }
    }
    // A leaf costs A*n; a split costs one traversal step plus its children.
    if (best_axis < 0 || best_cost + box.area() >= box.area() * n) {
      if (n <= 4 * options.max_leaf_triangles || best_axis < 0) return make_leaf();
    }
    std::uint32_t mid = begin;
    if (best_axis >= 0) {
      const float lo = centroid_box.min[best_axis], hi = centroid_box.max[best_axis];
      const float scale = static_cast<float>(bins) / (hi - lo);
      auto* first = bvh.triangles.data() + begin;
      auto* split = std::partition(first, bvh.triangles.data() + end, [&](std::uint32_t t) {
        return std::min(bins - 1, static_cast<std::uint32_t>((centroids[t][best_axis] - lo) * scale)) <= best_bin;
      });
      mid = static_cast<std::uint32_t>(split - bvh.triangles.data());
    }
    if (mid == begin || mid == end) mid = begin + n / 2;  // degenerate centroids: split by count
    bvh.sah_cost += box.area();
    const auto left = static_cast<std::uint32_t>(bvh.nodes.size());
    bvh.nodes.resize(bvh.nodes.size() + 2);
    bvh.nodes[node].first = left;
    bvh.nodes[node].count = 0;
    build(left, begin, mid, depth + 1);
    build(left + 1, mid, end, depth + 1);
  }
};

}  // namespace

std::vector<TriangleBox> padded_triangle_boxes(std::span<const glm::vec3> triangle_vertices) {
  float largest = 0.0f;
  for (const glm::vec3& p : triangle_vertices) largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  // The floor keeps boxes of a scene at the origin from being flat.
  const glm::vec3 margin(std::max(largest * 0x1p-12f, 1e-30f));
  std::vector<TriangleBox> boxes(triangle_vertices.size() / 3);
  for (std::size_t t = 0; t < boxes.size(); ++t) {
    const glm::vec3 &a = triangle_vertices[3 * t], &b = triangle_vertices[3 * t + 1], &c = triangle_vertices[3 * t + 2];
    boxes[t].min = glm::min(glm::min(a, b), c) - margin;
    boxes[t].max = glm::max(glm::max(a, b), c) + margin;
  }
  return boxes;
}

Bvh build_bvh(std::span<const glm::vec3> triangle_vertices, const BvhOptions& options) {
  Builder b{triangle_vertices, options, {}, {}, {}};
  const auto n = static_cast<std::uint32_t>(triangle_vertices.size() / 3);
  b.boxes.resize(n);
  b.centroids.resize(n);
  const std::vector<TriangleBox> padded = padded_triangle_boxes(triangle_vertices);
  for (std::uint32_t t = 0; t < n; ++t) {
    b.boxes[t] = Box{padded[t].min, padded[t].max};
    b.centroids[t] = (b.boxes[t].min + b.boxes[t].max) * 0.5f;
  }
  b.bvh.triangles.resize(n);
  for (std::uint32_t t = 0; t < n; ++t) b.bvh.triangles[t] = t;
  b.bvh.nodes.reserve(2 * std::max<std::uint32_t>(n, 1));
  b.bvh.nodes.emplace_back();
  b.build(0, 0, n, 0);
  const Box root{b.bvh.nodes[0].min, b.bvh.nodes[0].max};
  if (root.area() > 0) b.bvh.sah_cost /= root.area();
  return std::move(b.bvh);
}

}  // namespace asvgf::render
