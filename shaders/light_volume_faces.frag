#version 450
#extension GL_GOOGLE_include_directive : require
// light_volume, the shadow volume's faces (Billeter, Sintorn, Assarsson 2010, eq. 2–3):
// along a camera ray the shadowed light's in-scattering over a shadowed segment [t0, t1]
// is I(t1) − I(t0), I(t) the unshadowed integral from the camera (shaders/include/
// light_volume_integral.glsl). Each face the ray crosses adds ±σs·E·I(min(t, t_end)) to the
// unshadowed sum: + where the ray enters the shadow (a face whose outside faces the
// camera), − where it leaves. Faces behind the scene's surface all add I(t_end) (from
// `ends`, no quadrature): what they add sums to −I(t_end) where the surface is shadowed
// and to 0 where it is lit. t is the fragment's view depth (1/gl_FragCoord.w: the camera
// clip's w is the view depth) times the ray's length per unit depth.
#include "include/light_volume.glsl"
#include "include/light_volume_integral.glsl"

layout(set = 0, binding = 0) uniform Params { LightVolumeParams p; } params;
layout(set = 0, binding = 2) uniform texture2D light_frame;
layout(set = 0, binding = 3) uniform sampler nearest;
layout(set = 0, binding = 4) uniform Frame { FogFrame f; } frame;
layout(set = 0, binding = 5) uniform texture2D ends;
layout(location = 0) out vec4 added;

void main() {
  const vec4 end = texelFetch(sampler2D(ends, nearest), ivec2(gl_FragCoord.xy), 0);
  const vec2 uv = gl_FragCoord.xy / vec2(params.p.sizes.zw);
  const vec3 through = view_ray(frame.f.view, vec2(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0));
  const float ray_scale = length(through);
  const float t = ray_scale / gl_FragCoord.w;
  vec3 scattered = end.rgb;
  if (t < end.a) {
    const vec4 frame_texel = texelFetch(sampler2D(light_frame, nearest), ivec2(LIGHT_FRAME_TEXELS - 1, 0), 0);
    const Light light = frame.f.light_list.lights[int(frame_texel.y)];
    const MediumCoefficients fog = frame.f.media.fog;
    const vec3 sigma_t = fog.sigma_s_g.rgb + fog.sigma_a.rgb;
    scattered = min(fog.sigma_s_g.rgb * light.power_cos_inner.rgb *
                        light_scattering_to(light, frame.f.view.position.xyz, through / ray_scale, t, sigma_t, fog.sigma_s_g.w),
                    vec3(1e30));
  }
  const float orientation = texelFetch(sampler2D(light_frame, nearest), ivec2(LIGHT_FRAME_TEXELS - 1, 0), 0).x;
  const bool enters_shadow = gl_FrontFacing == (orientation > 0.0);
  added = vec4(enters_shadow ? scattered : -scattered, 0.0);
}
