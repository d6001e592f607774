// The cloud layer's lighting on the CPU: shaders/include/cloud_lighting.h compiled as C++
// with GLM's types, as physics/cloud_density.h does; its HG lobe is physics/phase.h's
// phase_hg<float>, the twin of phase.glsl's that the shader uses.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "physics/phase.h"

namespace volgraph::physics::cloud_lighting {

using namespace glm;
using uint = uint32_t;

// phase.glsl's phase_hg, by its C++ twin.
inline float phase_hg(float g, float cos_theta) { return physics::phase_hg<float>(g, cos_theta); }
// phase.glsl's phase_isotropic, likewise.
inline float phase_isotropic() { return physics::phase_isotropic<float>(); }

#include "shaders/include/cloud_lighting.h"

}  // namespace volgraph::physics::cloud_lighting
