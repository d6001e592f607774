// The end of the froxel chain's graph as the GPU fog tests write it, after fog_integral's
// type and variant: its inputs, froxel_apply over lit's colour and depth, a composite
// without tone mapping to out.output, and the config's closing brackets.
#pragma once

namespace volgraph::testing {

inline constexpr const char* kFroxelChainEnd = R"(
      "inputs": { "in_scatter": "fog_light.in_scatter", "media_scattering": "fog_media.media_scattering",
                  "media_absorption": "fog_media.media_absorption", "frame": "fog_media.frame" } },
    { "name": "fog_apply", "type": "froxel_apply",
      "inputs": { "color": "lit.color", "depth": "lit.depth", "integrated_scattering": "fog_integral.integrated_scattering",
                  "integrated_transmittance": "fog_integral.integrated_transmittance", "frame": "fog_media.frame" } },
    { "name": "out", "type": "composite", "variant": "none", "inputs": { "color": "fog_apply.color" } } ],
    "outputs": ["out.output"] } })";

}  // namespace volgraph::testing
