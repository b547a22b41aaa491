// common/trace.glsl: the one way shaders trace rays. Compiled two ways:
//   TRACE_RAY_QUERY  GL_EXT_ray_query against `scene` (a TLAS over the world-space triangles);
//   TRACE_SOFTWARE   a stack-based traversal of the SAH BVH in `bvh_nodes` / `bvh_triangles`.
// The including shader declares `triangles` (world-space Triangle[]) and the variant's buffers.
// Both variants report the closest triangle, then recompute t and the barycentrics with the same
// ray/triangle routine, so that hits agree to the bit whenever they pick the same triangle.
#ifndef ASVGF_COMMON_TRACE_GLSL
#define ASVGF_COMMON_TRACE_GLSL

#if !defined(TRACE_RAY_QUERY) && !defined(TRACE_SOFTWARE)
#error "define TRACE_RAY_QUERY or TRACE_SOFTWARE"
#endif

struct Hit {
  bool hit;
  uint triangle;  // index into `triangles`
  float t;
  vec2 bary;      // weights of p1 and p2
};

// Moller-Trumbore, two-sided. Returns (t, u, v); t < 0 when there is no hit in (tmin, tmax).
vec3 intersect_triangle(vec3 o, vec3 d, vec3 p0, vec3 p1, vec3 p2, float tmin, float tmax) {
  vec3 e1 = p1 - p0;
  vec3 e2 = p2 - p0;
  vec3 pv = cross(d, e2);
  float det = dot(e1, pv);
  if (det == 0.0) return vec3(-1.0);
  float inv = 1.0 / det;
  vec3 tv = o - p0;
  float u = dot(tv, pv) * inv;
  if (u < 0.0 || u > 1.0) return vec3(-1.0);
  vec3 qv = cross(tv, e1);
  float v = dot(d, qv) * inv;
  if (v < 0.0 || u + v > 1.0) return vec3(-1.0);
  float t = dot(e2, qv) * inv;
  if (t <= tmin || t >= tmax) return vec3(-1.0);
  return vec3(t, u, v);
}

Hit refine_hit(vec3 o, vec3 d, uint tri, float tmin, float tmax, float t_found, vec2 bary_found) {
  Triangle t = load_triangle(tri);
  vec3 r = intersect_triangle(o, d, t.p0, t.p1, t.p2, tmin, tmax);
  Hit h;
  h.hit = true;
  h.triangle = tri;
  h.t = r.x >= 0.0 ? r.x : t_found;
  h.bary = r.x >= 0.0 ? r.yz : bary_found;
  return h;
}

#ifdef TRACE_RAY_QUERY

Hit trace_closest(vec3 o, vec3 d, float tmin, float tmax) {
  rayQueryEXT rq;
  rayQueryInitializeEXT(rq, scene, gl_RayFlagsOpaqueEXT, 0xFF, o, tmin, d, tmax);
  while (rayQueryProceedEXT(rq)) {
  }
  Hit h;
  h.hit = false;
  h.triangle = 0u;
  h.t = tmax;
  h.bary = vec2(0.0);
  if (rayQueryGetIntersectionTypeEXT(rq, true) == gl_RayQueryCommittedIntersectionTriangleEXT) {
    uint tri = uint(rayQueryGetIntersectionPrimitiveIndexEXT(rq, true));
    h = refine_hit(o, d, tri, tmin, tmax, rayQueryGetIntersectionTEXT(rq, true),
                   rayQueryGetIntersectionBarycentricsEXT(rq, true));
  }
  return h;
}

bool trace_any(vec3 o, vec3 d, float tmin, float tmax) {
  rayQueryEXT rq;
  rayQueryInitializeEXT(rq, scene, gl_RayFlagsOpaqueEXT | gl_RayFlagsTerminateOnFirstHitEXT, 0xFF, o, tmin, d, tmax);
  while (rayQueryProceedEXT(rq)) {
  }
  return rayQueryGetIntersectionTypeEXT(rq, true) != gl_RayQueryCommittedIntersectionNoneEXT;
}

#else  // TRACE_SOFTWARE

const uint kBvhStackSize = 48u;  // render::kMaxBvhDepth

// Distance to a node's box, or a value > tmax when the ray misses it.
float box_entry(vec3 o, vec3 inv_d, vec3 bmin, vec3 bmax, float tmin, float tmax) {
  vec3 t0 = (bmin - o) * inv_d;
  vec3 t1 = (bmax - o) * inv_d;
  vec3 lo = min(t0, t1);
  vec3 hi = max(t0, t1);
  float enter = max(max(lo.x, lo.y), max(lo.z, tmin));
  float leave = min(min(hi.x, hi.y), min(hi.z, tmax));
  return enter <= leave ? enter : tmax + 1.0;
}

vec3 safe_inverse(vec3 d) {
  const float tiny = 1e-30;
  return vec3(1.0 / (abs(d.x) > tiny ? d.x : (d.x >= 0.0 ? tiny : -tiny)),
              1.0 / (abs(d.y) > tiny ? d.y : (d.y >= 0.0 ? tiny : -tiny)),
              1.0 / (abs(d.z) > tiny ? d.z : (d.z >= 0.0 ? tiny : -tiny)));
}

// any_hit: stop at the first hit found.
Hit traverse(vec3 o, vec3 d, float tmin, float tmax, bool any_hit) {
  Hit h;
  h.hit = false;
  h.triangle = 0u;
  h.t = tmax;
  h.bary = vec2(0.0);
  vec3 inv_d = safe_inverse(d);
  uint stack[kBvhStackSize];
  uint top = 0u;
  uint node = 0u;
  for (;;) {
    uint first = bvh_nodes.values[node].first;
    uint count = bvh_nodes.values[node].count;
    if (count > 0u) {
      for (uint i = 0u; i < count; ++i) {
        uint tri = bvh_triangles.values[first + i];
        vec3 r = intersect_triangle(o, d, triangles.values[tri].p0, triangles.values[tri].p1, triangles.values[tri].p2,
                                    tmin, h.t);
        if (r.x >= 0.0) {
          h.hit = true;
          h.triangle = tri;
          h.t = r.x;
          h.bary = r.yz;
          if (any_hit) return h;
        }
      }
    } else {
      uint left = first;
      uint right = first + 1u;
      float tl = box_entry(o, inv_d, bvh_nodes.values[left].bmin, bvh_nodes.values[left].bmax, tmin, h.t);
      float tr = box_entry(o, inv_d, bvh_nodes.values[right].bmin, bvh_nodes.values[right].bmax, tmin, h.t);
      bool hit_l = tl <= h.t;
      bool hit_r = tr <= h.t;
      if (hit_l && hit_r) {
        // Nearer child first; the other waits on the stack.
        uint near_child = tl <= tr ? left : right;
        uint far_child = tl <= tr ? right : left;
        if (top < kBvhStackSize) {
          stack[top] = far_child;
          top += 1u;
        }
        node = near_child;
        continue;
      }
      if (hit_l || hit_r) {
        node = hit_l ? left : right;
        continue;
      }
    }
    if (top == 0u) break;
    top -= 1u;
    node = stack[top];
  }
  return h;
}

Hit trace_closest(vec3 o, vec3 d, float tmin, float tmax) {
  Hit h = traverse(o, d, tmin, tmax, false);
  if (h.hit) h = refine_hit(o, d, h.triangle, tmin, tmax, h.t, h.bary);
  return h;
}

bool trace_any(vec3 o, vec3 d, float tmin, float tmax) { return traverse(o, d, tmin, tmax, true).hit; }

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
