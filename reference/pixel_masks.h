// Which pixels a comparison with the reference looks at, decided by the reference's
// own exact visibility: the pixels that see only the media (the background through the
// fog), or only surfaces, each with its 3×3 neighbourhood so that rasterised
// silhouettes (where the GPU's and the reference's edges differ) are left out of both.
#pragma once

#include <cstdint>
#include <vector>

#include "graph/scene/scene.h"

namespace volgraph::reference {

// Per pixel (row-major): true where the pixel and its 3×3 neighbourhood see no surface.
std::vector<bool> fog_only_pixels(const Scene& scene, uint32_t width, uint32_t height);
// Per pixel (row-major): true where the pixel and its 3×3 neighbourhood all see a surface
// (the frame's edge pixels, whose neighbourhood is cut, never).
std::vector<bool> surface_only_pixels(const Scene& scene, uint32_t width, uint32_t height);

}  // namespace volgraph::reference
