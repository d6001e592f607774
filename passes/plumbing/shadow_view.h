// The shadow_map pass's light_view buffer: gpu::ShadowView, written once for GLSL and C++
// (shaders/include/shadow_view.h), the one member of its readers' shadow block.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include "shaders/include/shadow_view.h"

namespace volgraph::plumbing {

using ShadowViewBlock = gpu::ShadowView;  // written once for GLSL and C++: shaders/include/shadow_view.h
static_assert(sizeof(ShadowViewBlock) == 160);

}  // namespace volgraph::plumbing
