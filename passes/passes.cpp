#include "passes/passes.h"

#include "passes/atmosphere/atmosphere_passes.h"
#include "passes/clouds/cloud_passes.h"
#include "passes/fog/fog_passes.h"
#include "passes/plumbing/gltf.h"
#include "passes/translucency/translucency_passes.h"

namespace volgraph {

void register_builtin_passes(PassRegistry& registry) {
  registry.add(shadow_map_pass());
  registry.add(scene_pass());
  registry.add(composite_pass());
  registry.add(clear_pass());
  registry.add(copy_pass());
  registry.add(vignette_pass());
  registry.add(froxel_voxelize_pass());
  registry.add(froxel_scatter_pass());
  registry.add(froxel_temporal_pass());
  registry.add(scatter_integrate_pass());
  registry.add(froxel_apply_pass());
  registry.add(fog_apply_pass());
  registry.add(raymarch_fog_pass());
  registry.add(pixel_temporal_pass());
  registry.add(depth_fog_pass());
  registry.add(height_fog_pass());
  registry.add(analytic_fog_pass());
  registry.add(opacity_shadow_map_pass());
  registry.add(light_volume_pass());
  registry.add(atmosphere_transmittance_lut_pass());
  registry.add(atmosphere_multiscattering_lut_pass());
  registry.add(atmosphere_skyview_lut_pass());
  registry.add(atmosphere_aerial_perspective_pass());
  registry.add(atmosphere_bruneton_tables_pass());
  registry.add(sky_pass());
  registry.add(translucency_pass());
  registry.add(aerial_perspective_apply_pass());
  registry.add(cloud_noise_pass());
  // glTF objects with translucent materials need the translucency pass (graph/ reads no glTF).
  registry.set_scene_annotator(plumbing::mark_translucent_gltf_objects);
}

}  // namespace volgraph
