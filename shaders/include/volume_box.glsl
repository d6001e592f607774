// volume_visualize's box and volume (passes/volume/volume_visualize.cpp), shared by its
// compute shader and its slices: the including shader declares `params`
// (VolumeVisualizeParams), `density` (texture3D) and `density_sampler` before this file.
#ifndef VOLGRAPH_VOLUME_BOX_GLSL
#define VOLGRAPH_VOLUME_BOX_GLSL

// The box's coordinates [0, 1]³ of world point p.
vec3 box_coordinates(vec3 p) { return (p - params.box_min.xyz) / (params.box_max.xyz - params.box_min.xyz); }

float density_at(vec3 p) { return textureLod(sampler3D(density, density_sampler), box_coordinates(p), 0.0).r; }

// The interval of view depth z (point = origin + z·ray) inside the box, by the slab method
// (Kay & Kajiya 1986); empty (x ≥ y) where the ray misses it.
vec2 box_interval(vec3 origin, vec3 ray) {
  const vec3 safe = mix(vec3(1e-20), ray, greaterThan(abs(ray), vec3(1e-20)));
  const vec3 to_min = (params.box_min.xyz - origin) / safe, to_max = (params.box_max.xyz - origin) / safe;
  const vec3 near = min(to_min, to_max), far = max(to_min, to_max);
  return vec2(max(max(near.x, near.y), near.z), min(min(far.x, far.y), far.z));
}

vec4 transfer(float d) { return volume_transfer_lookup(params.knot_density, params.knot_rgba, params.march.z, d); }

// The density's gradient at p by central differences one texel apart (in world units).
vec3 density_gradient(vec3 p) {
  const vec3 size = params.box_max.xyz - params.box_min.xyz;
  const vec3 h = size / vec3(textureSize(sampler3D(density, density_sampler), 0));
  return vec3(density_at(p + vec3(h.x, 0, 0)) - density_at(p - vec3(h.x, 0, 0)),
              density_at(p + vec3(0, h.y, 0)) - density_at(p - vec3(0, h.y, 0)),
              density_at(p + vec3(0, 0, h.z)) - density_at(p - vec3(0, 0, h.z))) / (2.0 * h);
}

#ifdef VOLUME_TRANSFER_TABLE
// The 2D table's colour and opacity at world point p: its density and gradient magnitude
// (six more lookups a sample) placed by volume_transfer_table_position, the four texels
// around fetched whole and mixed (texel centres: exact at the table's samples; the including
// shader declares `transfer_table` and `nearest`).
vec4 transfer_at(vec3 p) {
  const ivec2 size = textureSize(sampler2D(transfer_table, nearest), 0);
  const vec2 at = volume_transfer_table_position(density_at(p), length(density_gradient(p)), params.gradient.z, vec2(size));
  const ivec2 i0 = ivec2(floor(at)), i1 = min(i0 + 1, size - 1);
  return volume_transfer_table_mix(texelFetch(sampler2D(transfer_table, nearest), i0, 0),
                                   texelFetch(sampler2D(transfer_table, nearest), ivec2(i1.x, i0.y), 0),
                                   texelFetch(sampler2D(transfer_table, nearest), ivec2(i0.x, i1.y), 0),
                                   texelFetch(sampler2D(transfer_table, nearest), i1, 0), at - vec2(i0));
}
#else
// The transfer function's colour and opacity at world point p: the 1D table at its density,
// with the gradient ramp when on (volume_transfer_2d; six more lookups a sample).
vec4 transfer_at(vec3 p) {
  const vec4 from_table = transfer(density_at(p));
  if (!(params.gradient.y > 0.0)) return from_table;
  return volume_transfer_2d(from_table, length(density_gradient(p)), params.gradient.x, params.gradient.y);
}
#endif

#endif
