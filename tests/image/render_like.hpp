#pragma once

// A deterministic, noise-free "Cornell box" image used by the PNG benchmark and
// tests: smooth diffuse shading gradients on the walls, a flat emissive
// ceiling light, two boxes with hard edges and hard shadows, sRGB-encoded to
// 8 bits like a real render of the server. Ray cast analytically, so it needs
// no renderer.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "image/image.hpp"

namespace test_images {

namespace detail {

struct V3 {
  float x = 0, y = 0, z = 0;
};
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(V3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
inline V3 operator*(V3 a, V3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline float dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 normalize(V3 a) { return a * (1.0f / std::sqrt(dot(a, a))); }

// Box rotated by `angle` around the vertical axis through its centre.
struct Box {
  V3 center, half;
  float angle;
  V3 albedo;
};

struct Hit {
  float t = std::numeric_limits<float>::infinity();
  V3 normal, albedo;
  bool emissive = false;
};

inline V3 rot_y(V3 v, float c, float s) { return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z}; }

inline void intersect_box(const Box& b, V3 o, V3 d, Hit& hit) {
  const float c = std::cos(b.angle), s = std::sin(b.angle);
  const V3 lo = rot_y(o - b.center, c, -s);  // world -> box space
  const V3 ld = rot_y(d, c, -s);
  float tmin = 1e-4f, tmax = hit.t;
  int axis = -1;
  float sign = 0;
  const float oo[3] = {lo.x, lo.y, lo.z}, dd[3] = {ld.x, ld.y, ld.z}, hh[3] = {b.half.x, b.half.y, b.half.z};
  for (int i = 0; i < 3; ++i) {
    if (std::abs(dd[i]) < 1e-12f) {
      if (std::abs(oo[i]) > hh[i]) return;
      continue;
    }
    float t0 = (-hh[i] - oo[i]) / dd[i], t1 = (hh[i] - oo[i]) / dd[i];
    float sg = -1;
    if (t0 > t1) {
      std::swap(t0, t1);
      sg = 1;
    }
    if (t0 > tmin) {
      tmin = t0;
      axis = i;
      sign = sg;
    }
    tmax = std::min(tmax, t1);
    if (tmin > tmax) return;
  }
  if (axis < 0) return;  // origin inside the box
  V3 n{axis == 0 ? sign : 0.0f, axis == 1 ? sign : 0.0f, axis == 2 ? sign : 0.0f};
  hit.t = tmin;
  hit.normal = rot_y(n, c, s);
  hit.albedo = b.albedo;
  hit.emissive = false;
}

inline const Box kBoxes[2] = {
    {{-0.33f, 0.6f, -0.3f}, {0.3f, 0.6f, 0.3f}, 0.3f, {0.725f, 0.71f, 0.68f}},
    {{0.35f, 0.3f, 0.35f}, {0.3f, 0.3f, 0.3f}, -0.3f, {0.725f, 0.71f, 0.68f}},
};

inline Hit trace(V3 o, V3 d) {
  Hit hit;
  // Room: x in [-1, 1], y in [0, 2], z in [-1, 1], open towards +z.
  auto plane = [&](float t, V3 n, V3 albedo) {
    if (t <= 1e-4f || t >= hit.t) return;
    const V3 p = o + d * t;
    if (p.x < -1.0001f || p.x > 1.0001f || p.y < -0.0001f || p.y > 2.0001f || p.z < -1.0001f ||
        p.z > 1.0001f)
      return;
    hit.t = t;
    hit.normal = n;
    hit.albedo = albedo;
    hit.emissive = n.y < 0 && std::abs(p.x) < 0.25f && std::abs(p.z) < 0.22f;
  };
  const V3 white{0.725f, 0.71f, 0.68f}, red{0.63f, 0.065f, 0.05f}, green{0.14f, 0.45f, 0.091f};
  if (d.x != 0) plane((-1 - o.x) / d.x, {1, 0, 0}, red), plane((1 - o.x) / d.x, {-1, 0, 0}, green);
  if (d.y != 0) plane((0 - o.y) / d.y, {0, 1, 0}, white), plane((2 - o.y) / d.y, {0, -1, 0}, white);
  if (d.z != 0) plane((-1 - o.z) / d.z, {0, 0, 1}, white);
  for (const Box& b : kBoxes) intersect_box(b, o, d, hit);
  return hit;
}

inline float linear_to_srgb(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

// Linear radiance of pixel (x, y), row 0 = top.
inline V3 shade_pixel(uint32_t x, uint32_t y, uint32_t width, uint32_t height) {
  const V3 eye{0.0f, 1.0f, 3.9f};
  const float tan_half_fov = std::tan(0.5f * 39.3f * 3.14159265f / 180.0f);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const float sx = (2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(width) - 1.0f) *
                   tan_half_fov * aspect;
  const float sy = (1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(height)) *
                   tan_half_fov;
  const V3 d = normalize({sx, sy, -1.0f});
  const Hit hit = trace(eye, d);
  if (!std::isfinite(hit.t)) return {0, 0, 0};
  if (hit.emissive) return {17.0f, 12.0f, 4.0f};
  const V3 p = eye + d * hit.t;
  const V3 light{0.0f, 1.98f, 0.0f};
  V3 l = light - p;
  const float dist2 = dot(l, l);
  l = normalize(l);
  float direct = std::max(0.0f, dot(hit.normal, l)) * std::max(0.0f, l.y) * 1.6f / (0.3f + dist2);
  if (direct > 0) {  // hard shadow from the boxes
    const Hit occ = trace(p + hit.normal * 1e-3f, l);
    if (occ.t * occ.t < dist2 && !occ.emissive) direct = 0;
  }
  // Smooth fake indirect light: brighter near the top and centre of the room.
  const float indirect = 0.08f + 0.06f * p.y - 0.03f * (p.x * p.x + p.z * p.z);
  return hit.albedo * (direct + std::max(0.0f, indirect));
}

}  // namespace detail

// 8-bit sRGB render-like image, alpha = 255.
inline image::Rgba8Image make_render_like_image(uint32_t width, uint32_t height) {
  image::Rgba8Image img;
  img.width = width;
  img.height = height;
  img.pixels.resize(size_t{width} * height * 4);
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const detail::V3 c = detail::shade_pixel(x, y, width, height);
      uint8_t* px = img.pixels.data() + (size_t{y} * width + x) * 4;
      px[0] = static_cast<uint8_t>(std::lround(255.0f * detail::linear_to_srgb(c.x)));
      px[1] = static_cast<uint8_t>(std::lround(255.0f * detail::linear_to_srgb(c.y)));
      px[2] = static_cast<uint8_t>(std::lround(255.0f * detail::linear_to_srgb(c.z)));
      px[3] = 255;
    }
  }
  return img;
}

// The same picture as linear float radiance, alpha = 1.
inline image::RgbaF32Image make_render_like_image_f32(uint32_t width, uint32_t height) {
  image::RgbaF32Image img;
  img.width = width;
  img.height = height;
  img.pixels.resize(size_t{width} * height * 4);
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const detail::V3 c = detail::shade_pixel(x, y, width, height);
      float* px = img.pixels.data() + (size_t{y} * width + x) * 4;
      px[0] = c.x;
      px[1] = c.y;
      px[2] = c.z;
      px[3] = 1.0f;
    }
  }
  return img;
}

}  // namespace test_images
