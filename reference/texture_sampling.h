// Material textures as the reference renderer reads them: level 0 of the image, decoded
// from sRGB to linear light once, sampled bilinearly with the sampler's wrap modes (the
// GPU filters the same decoded texels; it also blends mip levels, which the reference,
// having no pixel footprint, does not).
#pragma once

#include <cstdint>
#include <vector>

#include "graph/scene/scene.h"
#include "passes/plumbing/textures.h"

namespace volgraph::reference {

struct LinearImage {
  uint32_t width = 0, height = 0;
  std::vector<float> rgb;  // linear, 3 floats a texel, row 0 at the top
  std::vector<float> alpha;  // coverage, 1 float a texel (stored linear, as glTF's alpha)
};

LinearImage linear_image(const plumbing::Rgba8Image& encoded);
// Data stored linear (glTF's transmission and thickness textures): the stored values / 255.
LinearImage data_image(const plumbing::Rgba8Image& stored);

// The image at texture coordinate (u, v) (0, 0 the top-left corner, texel centres at
// half-integers of the texel grid), bilinear between the four nearest texels.
Vec3 sample_bilinear(const LinearImage& image, plumbing::SamplerWrap wrap, double u, double v);
// The image's alpha at (u, v), bilinear as its colour; 1 for an image without alpha.
double sample_alpha_bilinear(const LinearImage& image, plumbing::SamplerWrap wrap, double u, double v);

}  // namespace volgraph::reference
