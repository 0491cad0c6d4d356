// Dynamic rendering into freshly cleared targets, as the raster passes (shadow maps, RSMs,
// G-buffer) use it: the layout transitions before and after, the attachments, the viewport.
#pragma once

#include "vkx/device.hpp"
#include "vkx/resources.hpp"

#include <span>

namespace vkx {

// Colour images to COLOR_ATTACHMENT_OPTIMAL and the depth image (if any) to
// DEPTH_STENCIL_ATTACHMENT_OPTIMAL, their old contents discarded.
void prepare_attachments(VkCommandBuffer cmd, std::span<const Image* const> colors, const Image* depth);

// After rendering: colour images to GENERAL for compute passes to read.
void colors_to_compute(VkCommandBuffer cmd, std::span<const Image* const> colors);

// Colour images not drawn this frame to GENERAL, their contents undefined: for compute passes
// that bind them without reading them (descriptors need a valid layout all the same).
void undrawn_to_compute(VkCommandBuffer cmd, std::span<const Image* const> colors);

// Which colour attachments begin_cleared_rendering clears: all, or only the first, when its
// w = 0 marks "nothing drawn here" and the others are read only where it is set (clearing
// them would be memory traffic nobody reads: half a millisecond of the G-buffer at 512^2).
enum class ClearColors { all, first };

// Begins rendering over `extent` into `colors` (cleared to (0, 0, 0, clear_alpha) as `clear`
// says, the others' contents undefined) and `depth` (cleared to 1; stored only if
// `store_depth`), and sets the scissor to the whole extent and the viewport to `viewport`, or
// to the whole extent when it is null.
void begin_cleared_rendering(const Device& device, VkCommandBuffer cmd, std::span<const VkImageView> colors,
                             VkImageView depth, VkExtent2D extent, bool store_depth,
                             ClearColors clear = ClearColors::all, float clear_alpha = 0.0f,
                             const VkViewport* viewport = nullptr);

}  // namespace vkx
