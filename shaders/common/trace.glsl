// common/trace.glsl: the one way shaders trace rays. Compiled two ways:
//   TRACE_RAY_QUERY  GL_EXT_ray_query against `scene`: a TLAS over a BLAS of boxes, one per
//                    triangle of `triangles` (same index), so the traversal only culls and the
//                    triangle test below decides every hit;
//   TRACE_SOFTWARE   a stack-based traversal of the SAH BVH in `bvh_nodes` / `bvh_triangles`.
// The including shader declares `triangles` (world-space Triangle[]) and the variant's buffers.
// Both variants run the same watertight triangle test over conservative candidate sets and break
// ties in depth by the lower triangle index, so they return the same hit to the bit, even for a ray
// through an edge two triangles share. `skip` is a triangle the ray never hits: the one it leaves
// from (a planar triangle cannot be hit again by a ray leaving its front side), or kNoTriangle.
#ifndef ASVGF_COMMON_TRACE_GLSL
#define ASVGF_COMMON_TRACE_GLSL

#if !defined(TRACE_RAY_QUERY) && !defined(TRACE_SOFTWARE)
#error "define TRACE_RAY_QUERY or TRACE_SOFTWARE"
#endif

const uint kNoTriangle = 0xFFFFFFFFu;

struct Hit {
  bool hit;
  uint triangle;  // index into `triangles`
  float t;
  vec2 bary;      // weights of p1 and p2
};

Hit no_hit(float tmax) {
  Hit h;
  h.hit = false;
  h.triangle = 0u;
  h.t = tmax;
  h.bary = vec2(0.0);
  return h;
}

// A ray in the frame of the watertight test (Woop, Benthin and Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013): axes permuted so that z is the direction's largest component,
// then sheared so that the ray runs along +z.
struct ShearedRay {
  vec3 o;
  uint kz;  // which axis became z
  vec3 shear;  // (dx/dz, dy/dz, 1/dz) after the permutation
};

// (v[kx], v[ky], v[kz]) with kx = (kz + 1) % 3, ky = (kz + 2) % 3; selects, not dynamic indexing.
vec3 permute_axes(vec3 v, uint kz) { return kz == 0u ? v.yzx : (kz == 1u ? v.zxy : v.xyz); }

ShearedRay shear_ray(vec3 o, vec3 d) {
  vec3 a = abs(d);
  uint kz = a.x >= a.y && a.x >= a.z ? 0u : (a.y >= a.z ? 1u : 2u);
  vec3 dp = permute_axes(d, kz);
  ShearedRay r;
  r.o = o;
  r.kz = kz;
  r.shear = vec3(dp.x / dp.z, dp.y / dp.z, 1.0 / dp.z);
  return r;
}

// Two-sided and watertight: a ray through an edge shared by two triangles hits at least one of
// them (the edge functions of a shared edge are exact negatives; `precise` keeps compilers from
// fusing them into FMAs, which would break that). Points on an edge count as inside.
// Returns (t, weight of p1, weight of p2); t < 0 when there is no hit in (tmin, tmax). Rejects as
// early as it can (most candidates of a traversal miss), by nested tests and one `return`: an early
// return becomes a one-trip loop when inlined, and NVIDIA's OpenGL compiles that as a loop in the
// traversal's innermost loop (docs/performance.md).
vec3 intersect_triangle(ShearedRay r, vec3 p0, vec3 p1, vec3 p2, float tmin, float tmax) {
  vec3 result = vec3(-1.0);
  precise vec3 a = permute_axes(p0 - r.o, r.kz);
  precise vec3 b = permute_axes(p1 - r.o, r.kz);
  precise vec3 c = permute_axes(p2 - r.o, r.kz);
  precise float ax = a.x - r.shear.x * a.z;
  precise float ay = a.y - r.shear.y * a.z;
  precise float bx = b.x - r.shear.x * b.z;
  precise float by = b.y - r.shear.y * b.z;
  precise float cx = c.x - r.shear.x * c.z;
  precise float cy = c.y - r.shear.y * c.z;
  precise float u = cx * by - cy * bx;
  precise float v = ax * cy - ay * cx;
  if (!((u < 0.0 && v > 0.0) || (u > 0.0 && v < 0.0))) {
    precise float w = bx * ay - by * ax;
    if (!((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0))) {
      precise float det = u + v + w;
      if (det != 0.0) {
        precise float depth = u * (r.shear.z * a.z) + v * (r.shear.z * b.z) + w * (r.shear.z * c.z);
        float t = depth / det;
        if (t > tmin && t < tmax) result = vec3(t, v / det, w / det);
      }
    }
  }
  return result;
}

vec3 intersect_triangle_index(ShearedRay r, uint tri, float tmin, float tmax) {
  return intersect_triangle(r, triangles.values[tri].p0, triangles.values[tri].p1, triangles.values[tri].p2, tmin,
                            tmax);
}

// Whether a hit at (t, tri) replaces `h`: nearer, or as near with a lower triangle index, so that
// the answer never depends on the order in which a traversal meets the candidates.
bool closer(float t, uint tri, Hit h) { return t < h.t || (h.hit && t == h.t && tri < h.triangle); }

#ifdef TRACE_RAY_QUERY

Hit trace_closest(vec3 o, vec3 d, float tmin, float tmax, uint skip) {
  ShearedRay r = shear_ray(o, d);
  Hit h = no_hit(tmax);
  rayQueryEXT rq;
  rayQueryInitializeEXT(rq, scene, gl_RayFlagsNoneEXT, 0xFF, o, tmin, d, tmax);
  while (rayQueryProceedEXT(rq)) {
    if (rayQueryGetIntersectionTypeEXT(rq, false) != gl_RayQueryCandidateIntersectionAABBEXT) continue;
    uint tri = uint(rayQueryGetIntersectionPrimitiveIndexEXT(rq, false));
    if (tri == skip) continue;
    vec3 x = intersect_triangle_index(r, tri, tmin, tmax);
    if (x.x >= 0.0 && closer(x.x, tri, h)) {
      // Committing lets the traversal skip boxes beyond t; a box whose triangle ties at t still
      // starts before t (boxes are padded, renderer/bvh.hpp), so it is still reported.
      if (x.x < h.t) rayQueryGenerateIntersectionEXT(rq, x.x);
      h.hit = true;
      h.triangle = tri;
      h.t = x.x;
      h.bary = x.yz;
    }
  }
  return h;
}

bool trace_any(vec3 o, vec3 d, float tmin, float tmax, uint skip) {
  ShearedRay r = shear_ray(o, d);
  bool hit = false;
  rayQueryEXT rq;
  rayQueryInitializeEXT(rq, scene, gl_RayFlagsTerminateOnFirstHitEXT, 0xFF, o, tmin, d, tmax);
  while (rayQueryProceedEXT(rq)) {
    if (rayQueryGetIntersectionTypeEXT(rq, false) != gl_RayQueryCandidateIntersectionAABBEXT) continue;
    uint tri = uint(rayQueryGetIntersectionPrimitiveIndexEXT(rq, false));
    if (tri == skip) continue;
    vec3 x = intersect_triangle_index(r, tri, tmin, tmax);
    if (x.x >= 0.0) {
      rayQueryGenerateIntersectionEXT(rq, x.x);
      hit = true;
    }
  }
  return hit;
}

#else  // TRACE_SOFTWARE

const uint kBvhStackSize = 48u;  // render::kMaxBvhDepth
// One traversal stack for every call site (the path tracer traces closest hits and shadow rays,
// never both at once). Declared in traverse(), each inlined call got an array of its own, and
// compilers that keep the array in local memory kept both: NVIDIA's OpenGL two of 48 16-byte slots
// an invocation, its path tracer 1.6-1.8x slower than with one (docs/performance.md, issue 37).
uint bvh_stack[kBvhStackSize];

// Where the ray enters a node's box within [tmin, tmax], or -1.0 when it misses it (callers pass
// tmin >= 0). The miss was once tmax + 1.0, which rounds back to tmax at the callers' tmax of 1e30:
// every box counted as entered until a triangle was hit, and a ray into the sky visited the whole tree.
float box_entry(vec3 o, vec3 inv_d, vec3 bmin, vec3 bmax, float tmin, float tmax) {
  vec3 t0 = (bmin - o) * inv_d;
  vec3 t1 = (bmax - o) * inv_d;
  vec3 lo = min(t0, t1);
  vec3 hi = max(t0, t1);
  float enter = max(max(lo.x, lo.y), max(lo.z, tmin));
  float leave = min(min(hi.x, hi.y), min(hi.z, tmax));
  return enter <= leave ? enter : -1.0;
}

vec3 safe_inverse(vec3 d) {
  const float tiny = 1e-30;
  return vec3(1.0 / (abs(d.x) > tiny ? d.x : (d.x >= 0.0 ? tiny : -tiny)),
              1.0 / (abs(d.y) > tiny ? d.y : (d.y >= 0.0 ? tiny : -tiny)),
              1.0 / (abs(d.z) > tiny ? d.z : (d.z >= 0.0 ? tiny : -tiny)));
}

// any_hit: stop at the first hit found. tmin >= 0 (box_entry's miss is negative).
// Two loops in turn ("while-while", Aila and Laine, HPG 2009): interior nodes until a leaf (or the
// stack's end), then that leaf's triangles. A warp's lanes reach their leaves at different steps;
// here they test triangles together, where a leaf loop inside the node loop ran each lane's leaf
// while the others waited. Frames the same; on NVIDIA, path tracing 11-20% faster on OpenGL and
// 13-15% on Vulkan, but for the largest scene, 2% slower there (docs/performance.md, "The traversal
// as two loops").
Hit traverse(vec3 o, vec3 d, float tmin, float tmax, uint skip, bool any_hit) {
  Hit h = no_hit(tmax);
  ShearedRay r = shear_ray(o, d);
  vec3 inv_d = safe_inverse(d);
  uint top = 0u;
  uint node = 0u;
  bool have_node = true;  // false: the next node comes from the stack
  bool found_any = false;  // any_hit's stop: breaks, not a `return` (see intersect_triangle)
  for (;;) {
    uint leaf_first = 0u;
    uint leaf_end = 0u;
    bool done = false;
    for (;;) {
      if (!have_node) {
        if (top == 0u) {
          done = true;
          break;
        }
        top -= 1u;
        node = bvh_stack[top];
      }
      have_node = false;
      uint first = bvh_nodes.values[node].first;
      uint count = bvh_nodes.values[node].count;
      if (count > 0u) {
        leaf_first = first;
        leaf_end = first + count;
        break;
      }
      uint left = first;
      uint right = first + 1u;
      // A box entered exactly at h.t may still hold a tie with a lower index: box_entry keeps it.
      float tl = box_entry(o, inv_d, bvh_nodes.values[left].bmin, bvh_nodes.values[left].bmax, tmin, h.t);
      float tr = box_entry(o, inv_d, bvh_nodes.values[right].bmin, bvh_nodes.values[right].bmax, tmin, h.t);
      bool hit_l = tl >= 0.0;
      bool hit_r = tr >= 0.0;
      if (hit_l && hit_r) {
        // Nearer child first; the other waits on the stack.
        uint near_child = tl <= tr ? left : right;
        uint far_child = tl <= tr ? right : left;
        if (top < kBvhStackSize) {
          bvh_stack[top] = far_child;
          top += 1u;
        }
        node = near_child;
        have_node = true;
      } else if (hit_l || hit_r) {
        node = hit_l ? left : right;
        have_node = true;
      }
    }
    for (uint i = leaf_first; i < leaf_end; ++i) {
      uint tri = bvh_triangles.values[i];
      vec3 x = tri == skip ? vec3(-1.0) : intersect_triangle_index(r, tri, tmin, tmax);
      if (x.x >= 0.0 && closer(x.x, tri, h)) {
        h.hit = true;
        h.triangle = tri;
        h.t = x.x;
        h.bary = x.yz;
        found_any = any_hit;
        if (found_any) break;
      }
    }
    if (done || found_any) break;
  }
  return h;
}

Hit trace_closest(vec3 o, vec3 d, float tmin, float tmax, uint skip) { return traverse(o, d, tmin, tmax, skip, false); }

bool trace_any(vec3 o, vec3 d, float tmin, float tmax, uint skip) { return traverse(o, d, tmin, tmax, skip, true).hit; }

#endif

// The closest sphere light hit in (tmin, tmax): returns its index, or -1; writes t.
int hit_sphere_lights(vec3 o, vec3 d, float tmin, float tmax, uint sphere_count, out float t_hit) {
  int best = -1;
  t_hit = tmax;
  for (uint i = 0u; i < sphere_count; ++i) {
    vec3 oc = o - lights.values[i].position;
    float radius = lights.values[i].radius;
    float b = dot(oc, d);
    float c = dot(oc, oc) - radius * radius;
    float disc = b * b - c;
    if (disc < 0.0) continue;
    float s = sqrt(disc);
    float t = -b - s;
    if (t <= tmin) t = -b + s;
    if (t > tmin && t < t_hit) {
      t_hit = t;
      best = int(i);
    }
  }
  return best;
}

#endif
