#version 450
#extension GL_GOOGLE_include_directive : require
// volume_visualize, variant half_angle, the light's draw of slice k (Kniss et al. 2003): each
// light-buffer texel whose light ray crosses the slice's plane inside the box writes 1 − α, the
// transfer function's opacity there corrected for the planes' spacing along the light
// (Δ / |l·s|), multiplied into the buffer's transmittance (BlendMode::multiply). Crossings
// outside the box by at most one texel take the box's nearest point's opacity: the eye's
// bilinear lookups beside a face parallel to the light then read the face's occlusion, not the
// unoccluded 1 beyond it (the cost: up to one texel more path where the light enters).
#include "include/volume_visualize_params.h"
#include "include/volume_transfer.h"

layout(set = 0, binding = 0) uniform VolumeVisualizeParamsBlock { VolumeVisualizeParams params; };
layout(set = 0, binding = 1) uniform texture3D density;
layout(set = 0, binding = 2) uniform sampler density_sampler;

#include "include/volume_box.glsl"
#include "include/volume_half_angle.glsl"

layout(location = 0) flat in int slice;
layout(location = 0) out vec4 transmitted;

void main() {
  const vec3 crossing = light_buffer_point(gl_FragCoord.xy / params.light_v.w, slice);
  const vec3 p = clamp(crossing, params.box_min.xyz, params.box_max.xyz);
  if (distance(p, crossing) > 2.0 * params.light_u.w / params.light_v.w) discard;
  const float spacing = params.surface.z / abs(dot(params.light_direction.xyz, params.half_axis.xyz));
  transmitted = vec4(1.0 - volume_step_opacity(transfer_at(p).a, spacing, params.surface.y));
}
