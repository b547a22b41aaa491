// CPU twins of shaders/denoise/*.comp; see the shaders for the reasons behind each step.
#include "cpu_oracle/denoise_reference.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "asvgf/denoiser.hpp"
#include "cpu_oracle/denoise_math.hpp"
#include "cpu_oracle/depth_normal.hpp"
#include "cpu_oracle/rgb9e5.hpp"

namespace asvgf::reference {
namespace {

Surface surface_at(const ImageD& dn, int x, int y) {
  return surface_from(dn.at(x, y, 0), dn.at(x, y, 1), dn.at(x, y, 2), dn.at(x, y, 3));
}
double lum_at(const ImageD& img, int x, int y) {
  return luminance(img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2));
}
int clampi(int v, int lo, int hi) {
  return std::min(std::max(v, lo), hi);
}

}  // namespace

ConvertedInputs convert_inputs(const ImageD& color, const ImageD& albedo, const ImageD& motion, bool color_is_radiance,
                               double scale_x, double scale_y) {
  const int w = color.width, h = color.height;
  ConvertedInputs out{ImageD(w, h, 4), ImageD(w, h, 4), ImageD(w, h, 4)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::array<double, 3> m{};
      for (int c = 0; c < 3; ++c) {
        const double a = albedo.at(x, y, c);
        m[c] = !color_is_radiance ? a : (std::isfinite(a) && a >= 1e-3 ? a : 1.0);
      }
      // Radiance is divided by what the modulation's RGB9E5 word holds (under composite's guard).
      if (color_is_radiance) m = unpack_rgb9e5(pack_rgb9e5(m[0], m[1], m[2]));
      for (int c = 0; c < 3; ++c) {
        out.illumination.at(x, y, c) = color_is_radiance ? color.at(x, y, c) / std::max(m[c], 1e-3) : color.at(x, y, c);
        out.modulation.at(x, y, c) = m[c];
      }
      out.modulation.at(x, y, 3) = 1.0;
      out.motion.at(x, y, 0) = scale_x * motion.at(x, y, 0);
      out.motion.at(x, y, 1) = scale_y * motion.at(x, y, 1);
    }
  return out;
}

ImageD pack_surface(const ImageD& depth, const ImageD& normal, bool depth_gradient_given) {
  const int w = depth.width, h = depth.height;
  ImageD out(w, h, 4);
  auto depth_at = [&](int x, int y) {
    if (!depth.inside(x, y)) return 0.0;
    const double z = depth.at(x, y, 0);
    return asvgf::is_background_depth(z) ? 0.0 : z;
  };
  // The smaller difference to a neighbour along the axis that is not background; 0 if neither is.
  auto axis_gradient = [&](int x, int y, int ax, int ay, double z) {
    const double a = depth_at(x - ax, y - ay), b = depth_at(x + ax, y + ay);
    double g = -1;
    if (a > 0) g = std::abs(a - z);
    if (b > 0) g = g < 0 ? std::abs(b - z) : std::min(g, std::abs(b - z));
    return std::max(g, 0.0);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double z = depth.at(x, y, 0);
      const std::array<double, 3> n{normal.at(x, y, 0), normal.at(x, y, 1), normal.at(x, y, 2)};
      if (asvgf::is_background(z, n)) continue;
      double dz = depth.at(x, y, 1);
      if (!depth_gradient_given || !std::isfinite(dz) || dz < 0)
        dz = std::max(axis_gradient(x, y, 1, 0, z), axis_gradient(x, y, 0, 1, z));
      // As the texel holds them (cpu_oracle/depth_normal.hpp).
      const DepthNormal t = unpack_depth_normal(
          pack_depth_normal(static_cast<float>(z), static_cast<float>(dz),
                            {static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2])}));
      out.at(x, y, 0) = t.z;
      out.at(x, y, 1) = t.dz;
      out.at(x, y, 2) = t.oct[0];
      out.at(x, y, 3) = t.oct[1];
    }
  return out;
}

ImageD gradient(const ImageD& illumination, const ImageD& gradient_prev, bool current_given) {
  const int w = illumination.width, h = illumination.height;
  ImageD out((w + 2) / 3, (h + 2) / 3, 4);
  for (int sy = 0; sy < out.height; ++sy)
    for (int sx = 0; sx < out.width; ++sx) {
      const double l_prev_raw = gradient_prev.at(sx, sy, 0), index_f = gradient_prev.at(sx, sy, 1);
      if (!(index_f >= 0 && index_f < 9) || !std::isfinite(l_prev_raw)) continue;
      const int index = static_cast<int>(index_f);
      const int x = 3 * sx + index % 3, y = 3 * sy + index / 3;
      if (!illumination.inside(x, y)) continue;
      double l_cur = 0;
      if (current_given) {
        l_cur = gradient_prev.at(sx, sy, 2);
        if (!(l_cur >= 0) || !std::isfinite(l_cur)) continue;
        l_cur = std::min(l_cur, kFp16Max);
      } else {
        const double r = illumination.at(x, y, 0), g = illumination.at(x, y, 1), b = illumination.at(x, y, 2);
        if (any_not_finite(r, g, b)) continue;
        l_cur = luminance(clamp_sample(r), clamp_sample(g), clamp_sample(b));
      }
      const double l_prev = std::clamp(l_prev_raw, 0.0, kFp16Max);
      out.at(sx, sy, 0) = l_cur - l_prev;
      out.at(sx, sy, 1) = std::max(l_cur, l_prev);
    }
  return out;
}

ReprojectedGradientResult gradient_reprojected(const ReprojectedGradientInputs& in) {
  const ImageD& illum = *in.illumination;
  const int w = illum.width, h = illum.height;
  ReprojectedGradientResult out{ImageD((w + 2) / 3, (h + 2) / 3, 4), ImageD(w, h, 4)};
  for (int sy = 0; sy < out.gradient.height; ++sy)
    for (int sx = 0; sx < out.gradient.width; ++sx) {
      double sum_cur = 0, sum_prev = 0;
      for (int i = 0; i < 9; ++i) {
        const int x = 3 * sx + i % 3, y = 3 * sy + i / 3;
        if (!illum.inside(x, y)) continue;
        const double r = illum.at(x, y, 0), g = illum.at(x, y, 1), b = illum.at(x, y, 2);
        const bool finite = !any_not_finite(r, g, b);
        const double l = finite ? luminance(clamp_sample(r), clamp_sample(g), clamp_sample(b)) : 0.0;
        out.luminance.at(x, y, 0) = l;
        const Surface cur = surface_at(*in.depth_normal, x, y);
        if (!in.history_valid || !finite || !cur.hit()) continue;
        const double qx = x + 0.5 + in.motion->at(x, y, 0), qy = y + 0.5 + in.motion->at(x, y, 1);
        if (!(qx >= 0 && qy >= 0 && qx < w && qy < h)) continue;
        const int px = static_cast<int>(qx), py = static_cast<int>(qy);
        if (!reprojection_consistent(cur, surface_at(*in.prev_depth_normal, px, py))) continue;
        const double lp = in.prev_luminance->at(px, py, 0);
        if (!std::isfinite(lp)) continue;
        sum_cur += l;
        sum_prev += std::clamp(lp, 0.0, kFp16Max);
      }
      out.gradient.at(sx, sy, 0) = clamp_fp16(sum_cur - sum_prev);
      out.gradient.at(sx, sy, 1) = clamp_fp16(std::max(sum_cur, sum_prev));
    }
  return out;
}

ImageD gradient_atrous(const ImageD& in, const ImageD& dn, const GradientAtrousParams& params) {
  ImageD out(in.width, in.height, 4);
  auto guide = [&](int sx, int sy) {
    return std::array<int, 2>{std::min(3 * sx + 1, dn.width - 1), std::min(3 * sy + 1, dn.height - 1)};
  };
  for (int sy = 0; sy < in.height; ++sy)
    for (int sx = 0; sx < in.width; ++sx) {
      const auto gp = guide(sx, sy);
      const Surface center = surface_at(dn, gp[0], gp[1]);
      double sum0 = 0, sum1 = 0, weights = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int qx = sx + params.step * dx, qy = sy + params.step * dy;
          if (!in.inside(qx, qy)) continue;
          double w = binomial3(dx) * binomial3(dy);
          if ((dx != 0 || dy != 0) && center.hit()) {
            const auto gq = guide(qx, qy);
            const Surface other = surface_at(dn, gq[0], gq[1]);
            const double dist = std::abs(gq[0] - gp[0]) + std::abs(gq[1] - gp[1]);
            w *= weight_depth(center, other, dist, params.sigma_z) * weight_normal(center, other, params.sigma_n);
          }
          sum0 += w * in.at(qx, qy, 0);
          sum1 += w * in.at(qx, qy, 1);
          weights += w;
        }
      out.at(sx, sy, 0) = sum0 / weights;
      out.at(sx, sy, 1) = sum1 / weights;
    }
  return out;
}

namespace {

// A weighted mixture of luminance distributions given as (mean, standard deviation): its mean, and
// its variance as the parts' mean variance plus the spread of their means (shaders/common/
// denoise.glsl: mixture_term, mixture_moments).
struct Mixture {
  double weight = 0, mean = 0, variance = 0, mean_sq = 0;  // weighted sums
  void add(double w, double part_mean, double part_std_dev) {
    weight += w;
    mean += w * part_mean;
    variance += w * part_std_dev * part_std_dev;
    mean_sq += w * part_mean * part_mean;
  }
  double mixture_mean() const { return mean / weight; }
  double mixture_variance() const {
    const double mu = mixture_mean();
    return variance / weight + std::max(0.0, mean_sq / weight - mu * mu);
  }
};

struct History {
  double color[3] = {0, 0, 0};
  double mean = 0, variance = 0;  // of the luminance
  double len = 0;
  bool valid = false;
};

History reproject(const TemporalInputs& in, const TemporalParams& params, int x, int y, const Surface& cur) {
  History h;
  const ImageD& pc = *in.prev_color;
  if (!params.history_valid || !cur.hit()) return h;
  const double px = x + 0.5 + in.motion->at(x, y, 0), py = y + 0.5 + in.motion->at(x, y, 1);
  if (!std::isfinite(px) || !std::isfinite(py)) return h;
  const double bx = std::floor(px - 0.5), by = std::floor(py - 0.5);
  const double fx = (px - 0.5) - bx, fy = (py - 0.5) - by;
  if (bx < -1 || by < -1 || bx >= pc.width || by >= pc.height) return h;
  double sum_w = 0;
  Mixture moments;
  for (int k = 0; k < 4; ++k) {
    const int ox = k & 1, oy = k >> 1;
    const int qx = static_cast<int>(bx) + ox, qy = static_cast<int>(by) + oy;
    if (!pc.inside(qx, qy)) continue;
    const double w = (ox == 1 ? fx : 1 - fx) * (oy == 1 ? fy : 1 - fy);
    if (w <= 0) continue;
    const double len = in.prev_moments->at(qx, qy, 2);
    if (!(len > 0)) continue;
    if (!reprojection_consistent(cur, surface_at(*in.prev_depth_normal, qx, qy))) continue;
    for (int c = 0; c < 3; ++c) h.color[c] += w * pc.at(qx, qy, c);
    moments.add(w, in.prev_moments->at(qx, qy, 0), in.prev_moments->at(qx, qy, 1));
    h.len += w * len;
    sum_w += w;
  }
  if (sum_w < 0.01) return History{};
  for (double& c : h.color) c /= sum_w;
  h.mean = moments.mixture_mean();
  h.variance = moments.mixture_variance();
  h.len /= sum_w;
  h.valid = true;
  return h;
}

}  // namespace

TemporalResult temporal(const TemporalInputs& in, const TemporalParams& params) {
  const int w = in.illumination->width, h = in.illumination->height;
  TemporalResult out{ImageD(w, h, 4), ImageD(w, h, 4), 0, 0, 0};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Surface cur = surface_at(*in.depth_normal, x, y);
      const double s[3] = {in.illumination->at(x, y, 0), in.illumination->at(x, y, 1), in.illumination->at(x, y, 2)};
      const bool missing = any_not_finite(s[0], s[1], s[2]);
      if (missing) {
        if (std::isnan(s[0]) || std::isnan(s[1]) || std::isnan(s[2]))
          ++out.nan_samples;
        else
          ++out.inf_samples;
      }
      const History hist = reproject(in, params, x, y, cur);
      double color[3], mean, var, n;
      if (missing) {
        for (int c = 0; c < 3; ++c) color[c] = hist.valid ? hist.color[c] : 0;
        mean = hist.valid ? hist.mean : 0;
        var = hist.valid ? hist.variance : 0;
        n = hist.valid ? std::min(hist.len, params.history_cap) : 0;
      } else {
        if (s[0] >= kFp16Max || s[1] >= kFp16Max || s[2] >= kFp16Max) ++out.clamped_samples;
        const double c3[3] = {clamp_sample(s[0]), clamp_sample(s[1]), clamp_sample(s[2])};
        const double l = luminance(c3[0], c3[1], c3[2]);
        if (hist.valid) {
          double lambda = 0;
          if (in.gradient) {
            const int gx = std::min(x / 3, in.gradient->width - 1), gy = std::min(y / 3, in.gradient->height - 1);
            const double d = in.gradient->at(gx, gy, 0), big = in.gradient->at(gx, gy, 1);
            lambda = big > 0 ? std::min(1.0, params.antilag * std::abs(d) / big) : 0;
          }
          n = std::min(hist.len * (1 - lambda) + 1, params.history_cap);
          const double a = std::max((1 - lambda) * params.alpha + lambda, 1 / n);
          const double am = std::max((1 - lambda) * params.moments_alpha + lambda, 1 / n);
          for (int c = 0; c < 3; ++c) color[c] = hist.color[c] * (1 - a) + c3[c] * a;
          // The blend of two distributions (shaders/common/denoise.glsl: blend_moments).
          const double d = l - hist.mean;
          mean = hist.mean + am * d;
          var = (1 - am) * (hist.variance + am * d * d);
        } else {
          for (int c = 0; c < 3; ++c) color[c] = c3[c];
          mean = l;
          var = 0;
          n = 1;
        }
      }
      for (int c = 0; c < 3; ++c) out.integrated.at(x, y, c) = clamp_fp16(color[c]);
      out.integrated.at(x, y, 3) = clamp_fp16(var);
      out.moments.at(x, y, 0) = mean;
      out.moments.at(x, y, 1) = std::sqrt(std::max(0.0, var));
      out.moments.at(x, y, 2) = n;
    }
  return out;
}

ImageD variance(const ImageD& integrated, const ImageD& moments, const ImageD& dn, const ImageD& albedo,
                const VarianceParams& params) {
  const int w = integrated.width, h = integrated.height;
  ImageD out(w, h, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double color[3] = {integrated.at(x, y, 0), integrated.at(x, y, 1), integrated.at(x, y, 2)};
      const double mean = moments.at(x, y, 0), std_dev = moments.at(x, y, 1);
      const double n = moments.at(x, y, 2);
      const Surface center = surface_at(dn, x, y);
      double var = std_dev * std_dev;
      if (center.hit() && n > 0 && n < params.min_history) {
        // The luminance weight compares radiance: colours re-modulated by this pixel's albedo.
        const double a[3] = {albedo.at(x, y, 0), albedo.at(x, y, 1), albedo.at(x, y, 2)};
        const auto radiance_lum = [&](int qx, int qy) {
          return luminance(a[0] * integrated.at(qx, qy, 0), a[1] * integrated.at(qx, qy, 1),
                           a[2] * integrated.at(qx, qy, 2));
        };
        const double lp = radiance_lum(x, y);
        double sum_c[3] = {0, 0, 0}, sum_w = 0;
        Mixture moments_mix;  // the neighbours' moments
        for (int dy = -3; dy <= 3; ++dy)
          for (int dx = -3; dx <= 3; ++dx) {
            const int qx = x + dx, qy = y + dy;
            if (!integrated.inside(qx, qy)) continue;
            double wgt = 1, w_surface = 1, mq[2] = {mean, std_dev};
            if (dx != 0 || dy != 0) {
              if (!(moments.at(qx, qy, 2) > 0)) continue;
              mq[0] = moments.at(qx, qy, 0), mq[1] = moments.at(qx, qy, 1);
              const Surface other = surface_at(dn, qx, qy);
              const double dist = std::abs(dx) + std::abs(dy);
              w_surface =
                  weight_depth(center, other, dist, params.sigma_z) * weight_normal(center, other, params.sigma_n);
              wgt = w_surface * weight_luminance(lp, radiance_lum(qx, qy), params.sigma_l, 1.0);
            }
            // One frame of history: the moments by depth and normal alone (shaders/denoise/variance.comp).
            const double wm = n < 1.5 ? w_surface : wgt;
            for (int c = 0; c < 3; ++c) sum_c[c] += wgt * integrated.at(qx, qy, c);
            moments_mix.add(wm, mq[0], mq[1]);
            sum_w += wgt;
          }
        for (int c = 0; c < 3; ++c) color[c] = sum_c[c] / sum_w;
        var = moments_mix.mixture_variance() * (params.min_history / n);
      }
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = clamp_fp16(color[c]);
      out.at(x, y, 3) = clamp_fp16(var);
    }
  return out;
}

ImageD atrous(const ImageD& in, const ImageD& dn, const AtrousParams& params) {
  const int w = in.width, h = in.height;
  ImageD out(w, h, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double result[4] = {in.at(x, y, 0), in.at(x, y, 1), in.at(x, y, 2), in.at(x, y, 3)};
      const Surface center = surface_at(dn, x, y);
      if (center.hit()) {
        const double lp = luminance(result[0], result[1], result[2]);
        double prefiltered = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
            prefiltered += binomial3(dx) * binomial3(dy) * in.at(clampi(x + dx, 0, w - 1), clampi(y + dy, 0, h - 1), 3);
        const double std_dev = std::sqrt(std::max(prefiltered, 0.0));
        const int radius = params.kernel == 0 ? 2 : 1;
        double sum_c[3] = {0, 0, 0}, sum_v = 0, sum_w = 0;
        for (int dy = -radius; dy <= radius; ++dy)
          for (int dx = -radius; dx <= radius; ++dx) {
            const int qx = x + params.step * dx, qy = y + params.step * dy;
            if (!in.inside(qx, qy) || std::abs(dx) + std::abs(dy) > 2) continue;
            const double hk = params.kernel == 0 ? b3spline(dx) * b3spline(dy) : 1.0;
            double wgt = hk;
            if (dx != 0 || dy != 0) {
              const Surface other = surface_at(dn, qx, qy);
              const double dist = params.step * (std::abs(dx) + std::abs(dy));
              wgt *= weight_depth(center, other, dist, params.sigma_z) * weight_normal(center, other, params.sigma_n) *
                     weight_luminance(lp, lum_at(in, qx, qy), params.sigma_l, std_dev);
            }
            for (int c = 0; c < 3; ++c) sum_c[c] += wgt * in.at(qx, qy, c);
            sum_v += wgt * wgt * in.at(qx, qy, 3);
            sum_w += wgt;
          }
        for (int c = 0; c < 3; ++c) result[c] = sum_c[c] / sum_w;
        result[3] = sum_v / (sum_w * sum_w);
      }
      for (int c = 0; c < 4; ++c) out.at(x, y, c) = clamp_fp16(result[c]);
    }
  return out;
}

CompositeResult composite(const ImageD& illumination, const ImageD& albedo, double exposure, int tonemap) {
  const int w = illumination.width, h = illumination.height;
  CompositeResult out{ImageD(w, h, 4), ImageD(w, h, 4)};
  auto aces = [](double x) { return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); };
  auto srgb = [](double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double light[3] = {illumination.at(x, y, 0), illumination.at(x, y, 1), illumination.at(x, y, 2)};
      if (any_not_finite(light[0], light[1], light[2])) light[0] = light[1] = light[2] = 0;
      for (int c = 0; c < 3; ++c) {
        const double radiance = light[c] * std::max(albedo.at(x, y, c), 1e-3);
        out.hdr.at(x, y, c) = radiance;
        const double v = std::max(radiance * exposure, 0.0);
        out.display.at(x, y, c) = srgb(tonemap == 1 ? aces(v) : std::clamp(v, 0.0, 1.0));
      }
      out.hdr.at(x, y, 3) = 1;
      out.display.at(x, y, 3) = 1;
    }
  return out;
}

ImageD local_mean(const ImageD& temporal, const ImageD& filtered, int block, int radius, bool gated) {
  const int w = filtered.width, h = filtered.height;
  const int bw = (w + block - 1) / block, bh = (h + block - 1) / block;
  const auto lum = [](const ImageD& img, int x, int y) {
    return luminance(img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2));
  };
  // Per block: the sums of the temporal luminance, the filtered one, the temporal one squared, and
  // the pixels inside the image.
  ImageD sums(bw, bh, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double t = lum(temporal, x, y);
      const double terms[4] = {t, lum(filtered, x, y), t * t, 1.0};
      for (int c = 0; c < 4; ++c) sums.at(x / block, y / block, c) += terms[c];
    }
  ImageD means(bw, bh, 3);
  for (int by = 0; by < bh; ++by)
    for (int bx = 0; bx < bw; ++bx) {
      double total[4] = {0, 0, 0, 0};
      for (int qy = std::max(by - radius, 0); qy <= std::min(by + radius, bh - 1); ++qy)
        for (int qx = std::max(bx - radius, 0); qx <= std::min(bx + radius, bw - 1); ++qx)
          for (int c = 0; c < 4; ++c) total[c] += sums.at(qx, qy, c);
      for (int c = 0; c < 3; ++c) means.at(bx, by, c) = total[c] / total[3];
    }
  // The gate's standard error counts the window's full pixel count also where it is clamped (as the shader).
  const double window = double(2 * radius + 1) * block;
  ImageD out(w, h, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double ux = std::clamp((x + 0.5) / block - 0.5, 0.0, double(bw - 1));
      const double uy = std::clamp((y + 0.5) / block - 0.5, 0.0, double(bh - 1));
      const int x0 = int(std::floor(ux)), y0 = int(std::floor(uy));
      const int x1 = std::min(x0 + 1, bw - 1), y1 = std::min(y0 + 1, bh - 1);
      const double fx = ux - x0, fy = uy - y0;
      double m[3];
      for (int c = 0; c < 3; ++c) {
        const double top = means.at(x0, y0, c) * (1 - fx) + means.at(x1, y0, c) * fx;
        const double bottom = means.at(x0, y1, c) * (1 - fx) + means.at(x1, y1, c) * fx;
        m[c] = top * (1 - fy) + bottom * fy;
      }
      const double d2 = (m[0] - m[1]) * (m[0] - m[1]);
      const double se2 = std::max(m[2] - m[0] * m[0], 0.0) / (window * window);
      const double g = !gated ? 1.0 : d2 + se2 > 0 ? d2 / (d2 + se2) : 0.0;
      const double scale = m[1] > 1e-6 ? 1 + g * (m[0] / m[1] - 1) : 1.0;
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = filtered.at(x, y, c) * scale;
      out.at(x, y, 3) = filtered.at(x, y, 3);
    }
  return out;
}

}  // namespace asvgf::reference
