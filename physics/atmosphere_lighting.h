// How the atmosphere lights the scene beneath it. Its sun is the scene's directional light
// `Atmosphere::sun_light`, whose irradiance E is given at the top of the atmosphere; the
// scene (metres around its origin, `origin_altitude` above the ground) is small beside
// the air's scale heights, so every point of it takes the values at the scene's origin:
// - the sun arrives as E × T_sun(r_origin, mu_s): coloured and dimmed at sunset, its disk
//   cut by the horizon (physics::sun_transmittance, Bruneton 2017 GetTransmittanceToSun);
// - the sky lights it as an isotropic ambient radiance L_sky = E × Ψ_ms(r_origin, mu_s),
//   Hillaire 2020's multiple-scattering term (§5.5: the light scattered at least once,
//   averaged over the sphere with the ground's bounce, times 1/(1 − f_ms) for the orders
//   past it) — media scatter σs·L_sky, a surface facing any way receives π·L_sky.
// The passes, the reference and the tests all light the scene through these two
// functions, so a technique's error is measured against the same light.
#pragma once

#include <vector>

#include "graph/scene/scene.h"

namespace volgraph::physics {

// The scene's lights as they arrive at the scene: the atmosphere's sun dimmed by the air
// above the scene's origin (none left once its disk has set), the other lights as they
// are. Without an atmosphere, the scene's lights unchanged.
std::vector<Light> lights_through_atmosphere(const Scene& scene);

// The sky's isotropic radiance at the scene's origin (W/(m²·sr) per channel); 0 without
// an atmosphere or its sun.
Vec3 sky_ambient_radiance(const Scene& scene);

// The light at `altitude` metres above the ground (a cloud layer's: kilometres up, where
// the scene-origin values above would not hold), the sun's zenith cosine taken at the
// origin's zenith (+y): the sun's irradiance E × T_sun(r, mu_s) and the sky's isotropic
// radiance E × Ψ_ms(r, mu_s). Without an atmosphere or its sun: has_sun false, both 0.
struct LightAtAltitude {
  bool has_sun = false;
  Vec3 sun_irradiance{0, 0, 0};
  Vec3 sky_radiance{0, 0, 0};
};
LightAtAltitude atmosphere_light_at_altitude(const Scene& scene, double altitude);

// Where a cloud layer takes the atmosphere's light: its middle altitude (one value for the
// whole layer, as the scene takes its origin's), for cloud_march and its reference alike.
inline double cloud_light_altitude(const CloudLayer& layer) { return 0.5 * (layer.bottom_altitude + layer.top_altitude); }

}  // namespace volgraph::physics
