// FLIP (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild, "FLIP: A
// Difference Evaluator for Alternating Images", HPG 2020): how different two pictures look to
// a person flipping between them at a given viewing distance, per pixel, in [0, 1]. This is
// LDR-FLIP, of the 8-bit sRGB images as a display shows them, so the exposure and tone map
// that made them are part of what it measures. Written from the paper; flip.cpp derives each
// step and states where it chooses what the paper leaves open.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.hpp"
#include "image/metrics.hpp"

namespace image {

// Where the viewer sits: a monitor `monitor_width_m` wide showing `monitor_width_px` pixels
// across, seen from `distance_m`. The defaults are the paper's (a 0.7 m wide 4K monitor at
// 0.7 m): 67.02 pixels per degree.
struct FlipViewing {
  double monitor_width_m = 0.7;
  double monitor_width_px = 3840;
  double distance_m = 0.7;

  // distance * (px / width) * pi / 180: the pixels one degree of visual angle spans at the
  // screen's centre.
  double pixels_per_degree() const;
};

// The per-pixel FLIP of a test image against a reference, row 0 = top.
struct FlipMap {
  std::uint32_t width = 0, height = 0;
  std::vector<float> values;  // width * height, each in [0, 1]; 0 where the images agree
};

// Alpha is ignored. Throws std::invalid_argument naming both sizes when they differ, or when
// a pixel buffer is not width * height * 4 bytes, or when the viewing gives no positive finite
// pixels per degree.
FlipMap flip_map(const Rgba8Image& test, const Rgba8Image& reference, const FlipViewing& viewing = {});

// The mean of the map over the masked pixels (Mask as in metrics.hpp: empty = every pixel);
// 0 when no pixel is masked. Throws std::invalid_argument when a non-empty mask is not one
// byte per pixel.
double mean_flip(const FlipMap& map, const Mask& mask = {});

// The map in heat_colour (heatmap.hpp) on the fixed scale 0..1, opaque; pixels outside a
// non-empty mask are kHeatmapMaskedOut.
Rgba8Image flip_heatmap(const FlipMap& map, const Mask& mask = {});

// The map as a linear image, the value in R, G and B and alpha 1: for a PFM of exact values.
RgbaF32Image flip_image(const FlipMap& map);

}  // namespace image
