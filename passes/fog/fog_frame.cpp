#include "passes/fog/fog_frame.h"

#include "graph/scene/scene.h"
#include "physics/camera.h"

namespace volgraph::fog {
namespace {

// The radical inverse of n in `base` (Halton 1960).
double radical_inverse(uint64_t n, uint64_t base) {
  double inverse = 0, scale = 1.0 / double(base);
  for (; n > 0; n /= base, scale /= double(base)) inverse += double(n % base) * scale;
  return inverse;
}

template <typename Vector4>  // float[4] or gpu::vec4
void put(Vector4& out, const Vec3& v, double w) {
  for (int i = 0; i < 3; ++i) out[i] = float(v[size_t(i)]);
  out[3] = float(w);
}

}  // namespace

std::array<double, 3> froxel_jitter(uint64_t frame) {
  if (frame == 0) return {0, 0, 0};
  return {radical_inverse(frame, 2) - 0.5, radical_inverse(frame, 3) - 0.5, radical_inverse(frame, 5) - 0.5};
}

gpu::ViewRays pack_view_rays(const Camera& camera, Extent output) {
  const physics::ViewRays rays = physics::view_rays(camera, double(output.width) / double(output.height));
  gpu::ViewRays v{};
  put(v.position, rays.position, camera.near);
  put(v.forward, rays.forward, camera.far);
  put(v.right, rays.right, 0);
  put(v.up, rays.up, 0);
  return v;
}

gpu::FogFrame make_fog_frame(const PassSetup& s, uint64_t frame, const FogFrameInputs& inputs, plumbing::SceneLighting& lighting) {
  const Scene& scene = *s.scene;
  gpu::FogFrame f{};
  f.view = pack_view_rays(scene.camera, s.frame_size());
  f.grid.size[0] = inputs.grid.width;
  f.grid.size[1] = inputs.grid.height;
  f.grid.size[2] = inputs.grid.depth;
  f.grid.range[0] = float(inputs.range.near);
  f.grid.range[1] = float(inputs.range.far);
  f.grid.range[2] = inputs.range.distribution == physics::FroxelDistribution::linear ? 0.0f : 1.0f;
  const std::array<double, 3> jitter = inputs.jitter ? froxel_jitter(frame) : std::array<double, 3>{0, 0, 0};
  put(f.jitter, {jitter[0], jitter[1], jitter[2]}, double(frame));
  const Vec3 sky = lighting.sky_ambient_radiance(scene);
  put(f.ambient, {inputs.ambient_radiance[0] + sky[0], inputs.ambient_radiance[1] + sky[1], inputs.ambient_radiance[2] + sky[2]}, 0);
  f.light_list = plumbing::pack_lights(lighting.lights(scene));
  f.media = physics::pack_media(scene.media);
  return f;
}

std::vector<ParamProblem> media_fit_problems(const Scene& scene, const std::string& what) {
  if (scene.media.volumes.size() <= size_t(physics::kMaxMediumVolumes)) return {};
  return {{"", "at most " + std::to_string(physics::kMaxMediumVolumes) + " media volumes are " + what + ", the scene has " +
                   std::to_string(scene.media.volumes.size())}};
}

}  // namespace volgraph::fog
