// pathtrace: 1 spp (or `spp` for references) of path tracing from the primary hit in the
// visibility buffer: next-event estimation to sphere lights and emissive triangles combined with
// BSDF sampling (cosine-weighted on Lambertian surfaces, common/bsdf.glsl's lobe mixture on glossy
// ones) by multiple importance sampling (power heuristic), Russian roulette after two bounces. Writes
// demodulated illumination (radiance / demodulation_albedo, guarded) and, for each 3x3 stratum, the
// sample of the pixel that next frame's forward projection re-shades (renderer/gradient_candidate.glsl:
// its seed, surface point and luminance). Every pixel traces a fresh path of its own.
// With CARRIED_SAMPLES (A-SVGF's re-shading) workgroups past the image's rows shade 3x3 strata: each
// stratum that gradient_resolve gave a carried sample traces it from last frame's surface point
// with last frame's seed, and writes its luminance beside last frame's into the gradient sample
// (l_prev, index, l_cur, 1). Shading it apart keeps the landing pixel's own fresh sample for the
// histories: the carried sample repeats one the history already holds (docs/quality.md,
// camera-only path). In the same dispatch as the pixels, so that its paths fill the pixels' tail
// instead of running as one short wave of their own (+0.163 ms at 1080p on the H200 against 0.230
// for a pass of its own).
// CARRIED_ONLY shades the strata alone (split signals: their storage images are at WebGPU's limit).
// With SPLIT_SPECULAR the radiance is written as two signals, as Q2RTX and NRD filter them: what
// the primary surface's GGX lobe reflects (`specular`, divided by that lobe's directional albedo)
// and the rest (`illumination`, divided by the diffuse albedo), with the luminance of the one-signal
// illumination in illumination.a for the temporal gradient. The split does not change a path: each
// contribution after the first bounce is shared by the first bounce's f_specular / f (per
// channel), so the two signals re-modulated add up to the one-signal radiance.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#ifdef TRACE_RAY_QUERY
#extension GL_EXT_ray_query : require
#endif
#include "common/scene_data.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std140) uniform Params {
  Camera camera;
  uint width;
  uint height;
  uint frame;
  uint seed;
  uint light_count;
  uint sphere_count;
  uint max_bounces;
  uint spp;
  uint demodulate;  // 0: leave the albedo in the signal (--no-demodulation)
  // CARRIED_SAMPLES: 1 when the gradient's luminance is illumination.a's (split signals), 0 when it
  // is the luminance of the stored rgb (what gradient_resolve read last frame).
  uint luminance_in_alpha;
  uint pad0;        // WGSL rounds a uniform block up to 16 bytes: the C++ struct must be that size
  uint pad1;
} params;

#include "renderer/scene_bindings.glsl"
#include "common/random.glsl"
#include "common/sampling.glsl"
#include "renderer/gradient_candidate.glsl"

#ifndef CARRIED_ONLY
layout(set = 0, binding = 10) uniform utexture2D visibility;
// The G-buffer's albedo, RGB9E5 words (common/albedo.glsl): what a pixel's signal is divided by, so
// that the composite's re-modulation by the same word gives the radiance back exactly.
layout(set = 0, binding = 19) uniform utexture2D albedo;
#endif
// Half floats for the filtering methods: their temporal pass clamps every sample to the fp16
// maximum anyway, so 8 bytes a pixel of the 16 written here and read by the denoiser carried
// nothing it keeps; finite samples are clamped to [0, kFp16Max] on the way (a wider value would
// turn into Inf), non-finite ones stay what they are, for the temporal pass to drop and count.
// Rounded to the nearest half exactly (subnormals too), so the store keeps them as they are: a
// carried sample's luminance, computed here from the same values, then equals the one
// gradient_resolve reads back from the image next frame.
// FULL_RANGE (raw output and the accumulated reference) keeps fp32: their radiance reaches the EXR
// unclamped.
#ifdef FULL_RANGE
layout(set = 0, binding = 11, rgba32f) writeonly uniform image2D illumination;
vec3 stored_sample(vec3 v) { return v; }
#else
#ifndef CARRIED_ONLY
layout(set = 0, binding = 11, rgba16f) writeonly uniform image2D illumination;
#endif
vec3 stored_sample(vec3 v) { return any_not_finite(v) ? v : round_to_half(clamp_sample(v)); }
#endif
// The luminance of a one-signal sample that the split signals store in illumination.a for the
// gradient, as the image keeps it; -1: not finite (missing).
float alpha_luminance(vec3 one_signal) {
  return any_not_finite(one_signal) ? -1.0 : round_to_half(luminance(clamp_sample(one_signal)));
}
#ifdef CARRIED_SAMPLES
// One entry a 3x3 stratum (gradient_resolve): the carried seed and surface point, for the pixel
// that gradient_prev.y names (0-8; -1: none). Entries of strata without a sample are undefined.
layout(set = 0, binding = 13) uniform utexture2D gradient_seeds;
layout(set = 0, binding = 17) uniform texture2D gradient_prev;
// The gradient samples the denoiser reads (DenoiserConfig::gradient_current_given).
layout(set = 0, binding = 18, rgba32f) writeonly uniform image2D gradient_samples;
#endif
#ifndef CARRIED_ONLY
// Two texels a stratum (renderer/gradient_candidate.glsl), written by each stratum's picked pixel.
layout(set = 0, binding = 12, rgba32ui) writeonly uniform uimage2D gradient_candidates;
#endif
// Rays traced this frame (closest and shadow), for the rays-per-second benchmark.
layout(set = 0, binding = 14, std430) buffer RayCounter { uint count; } ray_counter;
#ifdef SPLIT_SPECULAR
layout(set = 0, binding = 15, rgba32f) writeonly uniform image2D specular;
// The GGX lobe's albedo of the pixel's surface (0 without a surface or a GGX lobe, so that
// specular light the filters spread there stays dark),
// what composite re-modulates the filtered specular signal by; here and not in the gbuffer, whose
// storage images are at WebGPU's limit of 4.
layout(set = 0, binding = 16, rgba16f) writeonly uniform image2D specular_albedo;
#endif

uint rays_traced = 0u;
// How far the first bounce's ray went when the GGX lobe chose it (-1: it left the scene, 0: the
// diffuse lobe chose it or there was no bounce): specular.a, for the specular history's
// reprojection through the reflection's virtual point.
float first_specular_distance = 0.0;

Camera cam;
const float kAlbedoGuard = 1e-3;

vec3 triangle_normal(Triangle t) { return normalize(cross(t.p1 - t.p0, t.p2 - t.p0)); }

// Where rays leave a surface point, independent of the scene's scale. The method: the offset of
// Waechter and Binder ("A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems,
// ch. 6, 2019) is 256 float ulps of the point's own coordinates along the geometric normal, plus an
// absolute fallback near the origin (1/65536 world units under 1/32), and that absolute constant
// makes it scale-dependent (a room scaled by 1e-4 is 5e-4 units wide). We measure the ulps on the
// triangle instead: the point is interpolated from the vertices, so its error is bounded by a few
// ulps of the largest vertex coordinate (Pharr, Jakob and Humphreys, "Physically Based Rendering",
// 3rd ed., sec. 3.9), whatever the point's own magnitude, and
//   eps = 2^-18 max|vertex coordinate|   (>= 32 ulps of that coordinate, no absolute term)
// scales exactly with the scene. Three parts:
// 1. the point is re-interpolated from the barycentrics (not o + t d, whose error grows with t);
// 2. it moves towards the centroid until it is at least kEdgeOffsets * eps inside every edge: a
//    point on the crease where a ceiling meets a wall would otherwise stay on the wall's plane, and
//    a ray from it would leave through the wall (light leaked into closed rooms along such edges);
//    at a crease of interior angle a this leaves the point inside the neighbour by
//    eps (kEdgeOffsets sin a - cos a) > 0 for a > 14 degrees;
// 3. it moves eps along the normal (n faces the side the ray leaves to);
// and the ray skips its own triangle (trace.glsl's `skip`).
const float kSpawnOffsetRel = 1.0 / 262144.0;  // 2^-18
const float kEdgeOffsets = 4.0;

float spawn_eps(Triangle t) {
  vec3 m = max(abs(t.p0), max(abs(t.p1), abs(t.p2)));
  return kSpawnOffsetRel * max(m.x, max(m.y, m.z));
}

vec3 spawn_origin(Triangle t, vec2 b, vec3 n) {
  vec3 x = t.p0 * (1.0 - b.x - b.y) + t.p1 * b.x + t.p2 * b.y;
  float eps = spawn_eps(t);
  // Moving a fraction s of the way to the centroid leaves every barycentric >= s/3, i.e. the point
  // >= s/3 of the smallest altitude (twice the area over the longest edge) inside every edge.
  vec3 e0 = t.p1 - t.p0, e1 = t.p2 - t.p1, e2 = t.p0 - t.p2;
  float longest = sqrt(max(dot(e0, e0), max(dot(e1, e1), dot(e2, e2))));
  float altitude = length(cross(e0, -e2)) / max(longest, 1e-30);
  float s = altitude > 0.0 ? min(0.5, 3.0 * kEdgeOffsets * eps / altitude) : 0.0;
  vec3 centre = (t.p0 + t.p1 + t.p2) / 3.0;
  return mix(x, centre, s) + n * eps;
}

// Shadow rays stop this fraction short of the light sample: the sample lies on the light, whose own
// test may round either way (relative, so independent of scale too).
const float kShadowEnd = 1.0 - 1.0 / 4096.0;

// The BSDF at a path vertex: Lambertian (its albedo applied by the caller) or glossy, with the
// shading frame (t, b, n) and the direction back along the path in that frame.
struct Vertex {
  bool glossy;
  Glossy model;
  vec3 t;
  vec3 b;
  vec3 v;  // towards the previous vertex, in (t, b, n)
};

Vertex make_vertex(uint tri, vec3 n, vec3 v_world, vec3 albedo) {
  Vertex s;
  s.glossy = triangle_glossy(tri);
  s.model = triangle_glossy_model(tri, albedo);
  basis(n, s.t, s.b);
  s.v = vec3(dot(v_world, s.t), dot(v_world, s.b), max(dot(v_world, n), 1e-6));
  return s;
}

// One light sample's radiance at a surface point (normal n, facing the incoming side), MIS-weighted
// against BSDF sampling; x is the point's spawn_origin. On a Lambertian vertex the result still
// needs the albedo (Le cos / (pi pdf) w), on a glossy one it is complete (Le f cos / pdf w). Skips
// the emissive triangle `self` (no self-illumination); shadow rays skip it too. `specular`: the
// GGX lobe's part of the result. Each rejection clears `usable` instead of returning: an early
// return becomes a one-trip loop when inlined, which NVIDIA's OpenGL compiles as a loop around the
// shadow ray's traversal (docs/performance.md). The random numbers are drawn as before.
vec3 sample_light(vec3 x, vec3 n, uint self, Vertex vertex, inout uint state, out vec3 specular) {
  specular = vec3(0.0);
  vec3 result = vec3(0.0);
  if (params.light_count != 0u) {
    // Pick a light by its probability (power).
    float u = next_random(state);
    uint index = params.light_count - 1u;
    float acc = 0.0;
    for (uint i = 0u; i < params.light_count; ++i) {
      acc += lights.values[i].pdf;
      if (u < acc) {
        index = i;
        break;
      }
    }
    Light l = load_light(index);
    float u1 = next_random(state);
    float u2 = next_random(state);
    bool usable = !(l.pdf <= 0.0);
    vec3 dir = vec3(0.0);
    float dist = 0.0;
    float pdf_light = 0.0;  // per solid angle, including the choice of light
    if (usable && l.type == 0u) {
      vec4 s = sample_sphere_cone(x, l.position, l.radius, u1, u2);
      usable = !(s.w <= 0.0);
      if (usable) {
        dir = s.xyz;
        float t_hit;
        // Another sphere light in front occludes this one (its own sample counts it), as does a miss.
        int hit = hit_sphere_lights(x, dir, 0.0, 1e30, params.sphere_count, t_hit);
        usable = hit == int(index);
        dist = t_hit;
        pdf_light = s.w * l.pdf;
      }
    } else if (usable) {
      usable = l.triangle != self;
      if (usable) {
        Triangle t = load_triangle(l.triangle);
        vec2 b = sample_triangle(u1, u2);
        vec3 y = t.p0 * (1.0 - b.x - b.y) + t.p1 * b.x + t.p2 * b.y;
        vec3 to = y - x;
        float d2 = dot(to, to);
        dist = sqrt(d2);
        dir = to / dist;
        float cos_light = abs(dot(triangle_normal(t), dir));
        usable = !(cos_light <= 0.0 || l.area <= 0.0);
        if (usable) pdf_light = l.pdf * d2 / (l.area * cos_light);
      }
    }
    float cos_x = dot(n, dir);
    usable = usable && !(cos_x <= 0.0);
    if (usable) {
      vec3 f_cos = vec3(cos_x / kPi);
      vec3 f_cos_specular = vec3(0.0);
      float pdf_bsdf = cos_x / kPi;
      if (vertex.glossy) {
        f_cos = glossy_f_cos(vertex.model, vertex.v, vec3(dot(dir, vertex.t), dot(dir, vertex.b), cos_x), pdf_bsdf,
                             f_cos_specular);
        usable = !(pdf_bsdf <= 0.0);
      }
      // A sphere light in front of a triangle light occludes it, as a BSDF-sampled path would find.
      float t_sphere;
      if (usable && l.type != 0u)
        usable = hit_sphere_lights(x, dir, 0.0, dist * kShadowEnd, params.sphere_count, t_sphere) < 0;
      if (usable) {
        rays_traced += 1u;
        if (!trace_any(x, dir, 0.0, dist * kShadowEnd, self)) {
          float w = power_heuristic(pdf_light, pdf_bsdf);
          specular = l.emission * f_cos_specular / pdf_light * w;
          result = l.emission * f_cos / pdf_light * w;
        }
      }
    }
  }
  return result;
}

// Light pdf (per solid angle) of hitting emissive triangle `tri` from x along dir at distance t.
float emissive_triangle_pdf(uint tri, vec3 x, vec3 dir, float t) {
  float pdf = 0.0;
  for (uint i = params.sphere_count; i < params.light_count; ++i) {
    if (lights.values[i].triangle == tri) {
      Triangle tr = load_triangle(tri);
      float cos_light = abs(dot(triangle_normal(tr), dir));
      float area = lights.values[i].area;
      if (!(cos_light <= 0.0 || area <= 0.0)) pdf = lights.values[i].pdf * t * t / (area * cos_light);
      break;
    }
  }
  return pdf;
}

// One path from a known first surface point (triangle tri at barycentrics b, normal n facing the
// viewer v); returns radiance towards the camera, and in `specular` the part of it the first
// vertex's GGX lobe reflected.
vec3 trace_path(uint tri, vec2 b, vec3 n, vec3 v, vec3 albedo, vec3 emission, inout uint state, out vec3 specular) {
  vec3 radiance = emission;
  vec3 throughput = vec3(1.0);
  specular = vec3(0.0);
  vec3 specular_share = vec3(0.0);  // of each contribution after the first bounce
  for (uint bounce = 0u; bounce < params.max_bounces; ++bounce) {
    vec3 o = spawn_origin(load_triangle(tri), b, n);
    Vertex vertex = make_vertex(tri, n, v, albedo);
    vec3 light_specular;
    vec3 light = throughput * (vertex.glossy ? vec3(1.0) : albedo) * sample_light(o, n, tri, vertex, state, light_specular);
    radiance += light;
    specular += bounce == 0u ? light_specular : light * specular_share;
    vec3 dir;
    float pdf_bsdf;
    if (!vertex.glossy) {
      // Cosine-weighted, so f * cos / pdf = albedo.
      float u1 = next_random(state);
      float u2 = next_random(state);
      dir = sample_cosine(n, u1, u2);
      pdf_bsdf = max(dot(n, dir), 0.0) / kPi;
      throughput *= albedo;
    } else {
      float u0 = next_random(state);
      float u1 = next_random(state);
      float u2 = next_random(state);
      if (bounce == 0u) first_specular_distance = u0 < glossy_lobe_probability(vertex.model, vertex.v.z) ? -1.0 : 0.0;
      vec3 l = glossy_sample(vertex.model, vertex.v, u0, u1, u2);
      if (l.z <= 0.0) {
        if (bounce == 0u) first_specular_distance = 0.0;  // no ray: the surface's motion
        break;
      }
      vec3 f_cos_specular;
      vec3 f_cos = glossy_f_cos(vertex.model, vertex.v, l, pdf_bsdf, f_cos_specular);
      if (pdf_bsdf <= 0.0) {
        if (bounce == 0u) first_specular_distance = 0.0;
        break;
      }
      dir = normalize(l.x * vertex.t + l.y * vertex.b + l.z * n);
      throughput *= f_cos / pdf_bsdf;
      if (bounce == 0u)
        specular_share = vec3(f_cos.r > 0.0 ? f_cos_specular.r / f_cos.r : 0.0,
                              f_cos.g > 0.0 ? f_cos_specular.g / f_cos.g : 0.0,
                              f_cos.b > 0.0 ? f_cos_specular.b / f_cos.b : 0.0);
    }
    rays_traced += 1u;
    Hit h = trace_closest(o, dir, 0.0, 1e30, tri);
    float t_sphere;
    int sphere = hit_sphere_lights(o, dir, 0.0, h.hit ? h.t : 1e30, params.sphere_count, t_sphere);
    if (bounce == 0u && first_specular_distance < 0.0)
      first_specular_distance = sphere >= 0 ? t_sphere : h.hit ? h.t : -1.0;
    if (sphere >= 0) {
      Light l = load_light(uint(sphere));
      float pdf_light = l.pdf * sphere_cone_pdf(o, l.position, l.radius);
      vec3 c = throughput * l.emission * power_heuristic(pdf_bsdf, pdf_light);
      radiance += c;
      specular += c * specular_share;
      break;
    }
    if (!h.hit) break;
    Triangle t = load_triangle(h.triangle);
    Material m;
    m.emission = materials.values[t.material].emission;
    if (m.emission.a > 0.0) {
      float pdf_light = emissive_triangle_pdf(h.triangle, o, dir, h.t);
      vec3 c = throughput * m.emission.rgb * power_heuristic(pdf_bsdf, pdf_light);
      radiance += c;
      specular += c * specular_share;
    }
    n = triangle_normal(t);
    if (dot(n, dir) > 0.0) n = -n;
    v = -dir;
    tri = h.triangle;
    b = h.bary;
    albedo = surface_albedo(h.triangle, h.bary);
    // Russian roulette after two bounces, by the throughput's largest component.
    if (bounce >= 1u) {
      float q = min(0.95, max(throughput.r, max(throughput.g, throughput.b)));
      if (q <= 0.0 || next_random(state) >= q) break;
      throughput /= q;
    }
  }
  return radiance;
}

// The primary surface point of a visibility texel that hit a triangle: normal facing the camera, and
// the direction to the camera.
void primary_surface(uvec4 vis, out Triangle t, out vec2 b, out vec3 n, out vec3 v) {
  t = load_triangle(vis.y);
  b = vec2(uintBitsToFloat(vis.z), uintBitsToFloat(vis.w));
  vec3 x = t.p0 * (1.0 - b.x - b.y) + t.p1 * b.x + t.p2 * b.y;
  n = triangle_normal(t);
  if (dot(n, x - cam.position.xyz) > 0.0) n = -n;
  v = normalize(cam.position.xyz - x);
}

// What `spp` paths from a primary surface (a visibility texel) give.
struct Shaded {
  vec3 radiance;           // towards the camera, averaged over the paths
  vec3 specular_radiance;  // the part of it the first vertex's GGX lobe reflected
  vec3 demodulation;       // the one signal's albedo (1 without demodulation; one_signal rounds it)
  vec3 diffuse_albedo;     // SPLIT_SPECULAR: what each of the two signals is divided by
  vec3 ggx_albedo;
};

Shaded shade(uvec4 vis, uint seed) {
  Shaded r;
  r.radiance = vec3(0.0);
  r.specular_radiance = vec3(0.0);
  r.demodulation = vec3(1.0);
  r.diffuse_albedo = vec3(1.0);
  r.ggx_albedo = vec3(1.0);
  if (vis.x == 0xFFFFFFFFu) {
    r.radiance = lights.values[vis.y].emission;  // a sphere light seen directly
  } else if (vis.x != 0u) {
    Triangle t;
    vec2 b;
    vec3 n, v;
    primary_surface(vis, t, b, n, v);
    vec3 albedo = surface_albedo(vis.y, b);
    if (params.demodulate != 0u) {
      r.demodulation = demodulation_albedo(vis.y, b, dot(n, v));
#ifdef SPLIT_SPECULAR
      split_demodulation_albedos(vis.y, b, dot(n, v), r.diffuse_albedo, r.ggx_albedo);
#endif
    }
    vec3 emission = materials.values[t.material].emission.rgb;
    for (uint s = 0u; s < params.spp; ++s) {
      uint state = s == 0u ? seed : pcg_hash(seed + s);
      vec3 path_specular;
      r.radiance += trace_path(vis.y, b, n, v, albedo, emission, state, path_specular);
      r.specular_radiance += path_specular;
    }
    r.radiance /= float(max(params.spp, 1u));
    r.specular_radiance /= float(max(params.spp, 1u));
  }
  return r;
}

// The one signal as a carried sample (and the split's gradient luminance) has it: divided by the
// RGB9E5 word gbuffer.comp would store for this albedo (a pixel's own signal is divided by the
// stored word itself: store_pixel).
vec3 one_signal(Shaded s) { return s.radiance / max(round_to_rgb9e5(s.demodulation), vec3(kAlbedoGuard)); }

// What an invocation shades: a pixel, with its visibility and seed, or a stratum's carried sample,
// with last frame's surface point and seed. One call of shade() serves both: each inlined call
// site is a copy of the whole path tracer, which NVIDIA's OpenGL compiles into a program twice as
// slow (docs/performance.md).
struct Work {
  bool pending;  // something to shade
  bool carried;
  ivec2 at;  // the pixel, or the stratum
  uvec4 vis;
  uint seed;
  vec2 prev;  // carried: gradient_prev.xy (last frame's luminance, the pixel in the stratum)
};

#ifdef CARRIED_SAMPLES
// A stratum's carried sample, if it has one; a stratum without one gets its "none" entry here.
Work carried_work(ivec2 stratum) {
  Work w;
  w.pending = false;
  w.carried = true;
  w.at = stratum;
  w.vis = uvec4(0u);
  w.seed = 0u;
  const vec4 prev = texelFetch(gradient_prev, stratum, 0);
  w.prev = prev.xy;
  if (prev.y >= 0.0 && prev.y < 9.0) {
    // Last frame's sample, forward-projected here: same surface point, same random numbers.
    const uvec4 carried = texelFetch(gradient_seeds, stratum, 0);
    w.vis = uvec4(load_triangle(carried.y).instance + 1u, carried.y, carried.z, carried.w);
    w.seed = carried.x;
    w.pending = true;
  } else {
    imageStore(gradient_samples, stratum, vec4(prev.xy, 0.0, 0.0));
  }
  return w;
}

void store_carried(Work w, Shaded shaded) {
  const vec3 one = one_signal(shaded);
  // The luminance as gradient_resolve reads last frame's back from the illumination image.
  float l = params.luminance_in_alpha != 0u ? alpha_luminance(one)
            : any_not_finite(one)           ? -1.0
                                            : luminance(stored_sample(one));
  imageStore(gradient_samples, w.at, vec4(w.prev, l, 1.0));
}
#endif

#ifndef CARRIED_ONLY
Work pixel_work(ivec2 p) {
  Work w;
  w.pending = p.x < int(params.width) && p.y < int(params.height);
  w.carried = false;
  w.at = p;
  w.vis = w.pending ? texelFetch(visibility, p, 0) : uvec4(0u);
  w.seed = pixel_seed(uvec2(p), params.width, params.frame, params.seed);
  w.prev = vec2(0.0);
  return w;
}

// Where p is its stratum's pick for next frame's projection (or, for a pick off the image, the pixel
// nearest it), the stratum's candidate: this pixel's seed, surface point and luminance `l`.
void store_gradient_candidate(Work w, float l) {
  const ivec2 p = w.at;
  const ivec2 size = ivec2(int(params.width), int(params.height));
  const ivec2 s = p / 3;
  const ivec2 from = gradient_candidate_pixel(uvec2(s), (params.width + 2u) / 3u, params.frame);
  if (any(notEqual(min(from, size - 1), p))) return;
  const bool ok = all(lessThan(from, size)) && w.vis.x != 0u && w.vis.x != 0xFFFFFFFFu;
  imageStore(gradient_candidates, gradient_candidate_texel(s), uvec4(ok ? w.seed : 0u, w.vis.yzw));
  imageStore(gradient_candidates, gradient_candidate_luminance_texel(s), uvec4(floatBitsToUint(l), 0u, 0u, 0u));
}

void store_pixel(Work w, Shaded shaded) {
  const ivec2 p = w.at;
  // The stored word, not shade()'s rounding of the same albedo: the G-buffer computes n.v along its
  // camera ray and shade() from the rebuilt point, a few ulps apart, which can round to another word.
  const vec3 stored_albedo = unpack_rgb9e5(texelFetch(albedo, p, 0).x);
#ifdef SPLIT_SPECULAR
  shaded.diffuse_albedo = stored_albedo;
  const vec3 one = one_signal(shaded);
#else
  const vec3 one = shaded.radiance / max(stored_albedo, vec3(kAlbedoGuard));
#endif
#ifdef SPLIT_SPECULAR
  // What composite re-modulates by: the GGX albedo of the pixel's surface, 0 without a surface
  // (specular light the filters spread there stays dark), 1 without demodulation (the signal is
  // radiance).
  vec3 specular_albedo_out = shaded.ggx_albedo;
  if (w.vis.x == 0u || w.vis.x == 0xFFFFFFFFu) specular_albedo_out = vec3(params.demodulate != 0u ? 0.0 : 1.0);
  imageStore(specular_albedo, p, round_to_half_clamped(vec4(specular_albedo_out, 1.0)));
  // Rounding can leave the difference a few ulps below 0 where the GGX lobe reflects everything. A
  // non-finite sample stays non-finite in both signals (max() could turn NaN into 0), so that each
  // chain's temporal pass drops it.
  vec3 specular_radiance = shaded.specular_radiance;
  vec3 diffuse_radiance = shaded.radiance - specular_radiance;
  if (any_not_finite(shaded.radiance) || any_not_finite(specular_radiance)) {
    diffuse_radiance = shaded.radiance;
    specular_radiance = shaded.radiance;
  } else {
    diffuse_radiance = max(diffuse_radiance, vec3(0.0));
  }
  // The gradient passes read a non-finite sample's luminance as -1: missing.
  imageStore(illumination, p,
             vec4(stored_sample(diffuse_radiance / max(shaded.diffuse_albedo, vec3(kAlbedoGuard))),
                  alpha_luminance(one)));
  imageStore(specular, p,
             vec4(specular_radiance / max(shaded.ggx_albedo, vec3(kAlbedoGuard)), first_specular_distance));
  store_gradient_candidate(w, alpha_luminance(one));
#else
  const vec3 stored = stored_sample(one);
  imageStore(illumination, p, vec4(stored, 0.0));
  store_gradient_candidate(w, luminance(stored));
#endif
}
#endif

// The invocation's work (pathtrace.cpp's dispatch: 8x8 workgroups).
Work find_work() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
#ifdef CARRIED_SAMPLES
  const uvec2 strata = (uvec2(params.width, params.height) + 2u) / 3u;
#ifdef CARRIED_ONLY
  if (all(lessThan(uvec2(p), strata))) return carried_work(p);
#else
  // The workgroups past the image's rows, in order, take 8x8 tiles of strata row by row.
  const uint pixel_group_rows = (params.height + 7u) / 8u;
  if (gl_WorkGroupID.y < pixel_group_rows) return pixel_work(p);
  const uint tile = (gl_WorkGroupID.y - pixel_group_rows) * ((params.width + 7u) / 8u) + gl_WorkGroupID.x;
  const uint tiles_x = (strata.x + 7u) / 8u;
  const uvec2 s = uvec2(tile % tiles_x, tile / tiles_x) * 8u + gl_LocalInvocationID.xy;
  if (all(lessThan(s, strata))) return carried_work(ivec2(s));
#endif
  Work none;
  none.pending = false;
  none.carried = true;
  none.at = p;
  none.vis = uvec4(0u);
  none.seed = 0u;
  none.prev = vec2(0.0);
  return none;
#else
  return pixel_work(p);
#endif
}

// The workgroup's rays, added to the global counter by one invocation: one atomic per pixel on a
// single address serialises every workgroup on it.
shared uint group_rays;

void main() {
  if (gl_LocalInvocationIndex == 0u) group_rays = 0u;
  memoryBarrierShared();
  barrier();
  LOAD_CAMERA(cam, params.camera);
  const Work work = find_work();
  if (work.pending) {
    const Shaded shaded = shade(work.vis, work.seed);
#if defined(CARRIED_SAMPLES) && defined(CARRIED_ONLY)
    store_carried(work, shaded);
#elif defined(CARRIED_SAMPLES)
    if (work.carried)
      store_carried(work, shaded);
    else
      store_pixel(work, shaded);
#else
    store_pixel(work, shaded);
#endif
  }
  if (rays_traced > 0u) atomicAdd(group_rays, rays_traced);
  memoryBarrierShared();
  barrier();
  if (gl_LocalInvocationIndex == 0u && group_rays > 0u) atomicAdd(ray_counter.count, group_rays);
}
