#version 450
#extension GL_GOOGLE_include_directive : require
// sky_cube: the sky in the direction of each texel's centre of each face of a cube around
// the camera (include/cube_face.h's faces and directions), as the sky pass draws it behind
// the scene (include/atmosphere_sky_toward.glsl: one text). Faces are the layers of a 2D
// array view (passes/atmosphere/sky_cube.cpp).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

#include "include/atmosphere_sky_frame.glsl"
#include "include/cube_face.h"

layout(set = 0, binding = 0) uniform Atmosphere { AtmosphereParameters a; } atmosphere;
layout(set = 0, binding = 1) uniform Frame { SkyPassFrame f; } frame;
layout(set = 0, binding = 2) uniform texture2D transmittance;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4) uniform sampler linear;
layout(set = 0, binding = 5) uniform texture2D sky_view;
layout(set = 0, binding = 6) uniform texture2D multiscattering;  // the sky-view LUT when not wired (camera.y = 0: not read)
layout(set = 0, binding = 7, rgba16f) uniform writeonly image2DArray cube;

#include "include/atmosphere_sky_toward.glsl"

void main() {
  const ivec3 texel = ivec3(gl_GlobalInvocationID);
  const ivec3 size = imageSize(cube);
  if (any(greaterThanEqual(texel, size))) return;
  const vec3 direction = cube_texel_direction(texel.z, texel.xy, size.x);
  const vec3 radiance = frame.f.sun.w < 0.5 ? vec3(0.0) : sky_radiance_toward(direction);
  imageStore(cube, texel, vec4(radiance, 1.0));
}
