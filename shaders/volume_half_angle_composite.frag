#version 450
// volume_visualize, variant half_angle: the slices' premultiplied radiance and opacity (the
// eye buffer) over the scene (BlendMode::premultiplied_over: eye + scene × (1 − α)).
layout(set = 0, binding = 0) uniform texture2D eye;
layout(set = 0, binding = 1) uniform sampler nearest;
layout(location = 0) out vec4 over;

void main() { over = texelFetch(sampler2D(eye, nearest), ivec2(gl_FragCoord.xy), 0); }
