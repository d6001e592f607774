#include "passes/atmosphere/atmosphere_block.h"

#include <algorithm>

namespace volgraph::atmosphere {

void AtmosphereBlock::create(PassSetup& s) {
  buffer_ = s.device.create_buffer(
      {s.name() + " atmosphere", sizeof(physics::GpuAtmosphere), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
}

rhi::BufferId AtmosphereBlock::write(PassContext& c) const {
  const physics::GpuAtmosphere atmosphere = physics::pack_atmosphere(*c.scene->atmosphere);
  c.device.write_buffer(buffer_, 0, std::as_bytes(std::span(&atmosphere, 1)));
  return buffer_;
}

PlanetFrame planet_frame(const Scene& scene) {
  const physics::AtmosphereView view = physics::atmosphere_view(scene);
  PlanetFrame f{};
  for (size_t i = 0; i < 3; ++i) {
    f.planet_up[i] = float(view.up[i]);
    f.toward_sun[i] = float(view.toward_sun[i]);
  }
  f.planet_up[3] = float(std::min(view.r, scene.atmosphere->top_radius));
  f.toward_sun[3] = float(view.mu_s);
  f.has_sun = view.has_sun;
  if (!view.has_sun) return f;
  const Vec3& e = scene.lights[size_t(scene.atmosphere->sun_light)].irradiance;
  for (size_t i = 0; i < 3; ++i) f.sun[i] = float(e[i]);
  f.sun[3] = 1.0f;
  return f;
}

}  // namespace volgraph::atmosphere
