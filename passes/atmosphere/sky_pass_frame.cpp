#include "passes/atmosphere/sky_pass_frame.h"

#include "graph/scene/scene.h"
#include "passes/atmosphere/atmosphere_block.h"
#include "passes/fog/fog_frame.h"
#include "physics/atmosphere_sky.h"

namespace volgraph::atmosphere {

gpu::SkyPassFrame sky_pass_frame(const Scene& scene, Extent view_extent, const SkyLook& look) {
  const Atmosphere& a = *scene.atmosphere;
  const PlanetFrame planet = planet_frame(scene);
  gpu::SkyPassFrame f{};
  f.view = fog::pack_view_rays(scene.camera, view_extent);
  f.planet_up = gpu::vec4_of(planet.planet_up);
  f.toward_sun = gpu::vec4_of(planet.toward_sun);
  f.sun = gpu::vec4_of(planet.sun);
  f.sun_disk[0] = float(a.sun_angular_radius);
  f.sun_disk[1] = look.sun_disk ? 1.0f : 0.0f;
  f.sun_disk[2] = look.limb_darkening ? 1.0f : 0.0f;
  f.sun_disk[3] = look.ground ? 1.0f : 0.0f;
  f.camera[0] = float(physics::atmosphere_view(scene).r);
  f.camera[1] = look.multiscattering ? 1.0f : 0.0f;
  f.sampling[0] = float(look.min_samples);
  f.sampling[1] = float(look.max_samples);
  f.sampling[2] = 100e3f;  // Hillaire 2020: rays of 100 km and longer take the max
  f.sampling[3] = float(look.sample_offset);
  return f;
}

}  // namespace volgraph::atmosphere
