// What every pass interface header (shaders/shared/*_interface.h) starts with: in C++ the
// gpu namespace and its 32-bit uint, in GLSL nothing. A pass's binding numbers are LPV_BINDING
// constants and its push constants one struct, so the shader and the pass's C++ read the same
// definition (the pass lists its layout by these names; renderer/gpu_types.hpp checks sizes).
#ifndef LPV_PASS_INTERFACE_H
#define LPV_PASS_INTERFACE_H

#ifdef __cplusplus
#include <cstdint>
#define LPV_INTERFACE_BEGIN namespace gpu { using uint = std::uint32_t;
#define LPV_INTERFACE_END }
#define LPV_BINDING inline constexpr uint
#else
#define LPV_INTERFACE_BEGIN
#define LPV_INTERFACE_END
#define LPV_BINDING const uint
#endif

#endif
