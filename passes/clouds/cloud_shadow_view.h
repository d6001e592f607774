// Where cloud_shadow_map's square lies (one function for the writer, every reader and the
// tests): centred under the camera on the plane of the cloud layer's bottom, `extent` m a
// side, its centre snapped to whole texels (so the map does not shimmer as the camera
// moves), toward the scene's sun (cloud_march's: the atmosphere's sun light, else the first
// directional light). Texel (i, j) of a size × size map ↔ the plane's point
// centre + ((i + ½)/size − ½, (j + ½)/size − ½)·extent in (x, z).
#pragma once

#include <cmath>
#include <cstddef>

#include "graph/scene/scene.h"
#include "passes/clouds/cloud_layer.h"
#include "shaders/include/cloud_shadow_view.h"

namespace volgraph {

// The scene must have a cloud layer.
inline gpu::CloudShadowView cloud_shadow_view(const Scene& scene, double extent, int size) {
  const double texel = extent / size;
  const auto snapped = [&](double x) { return std::round(x / texel) * texel; };
  gpu::CloudShadowView v{};
  v.plane[0] = float(snapped(scene.camera.position[0]));
  v.plane[1] = float(scene.clouds->bottom_altitude - clouds::origin_altitude(scene));  // world y = 0 is at the origin's altitude
  v.plane[2] = float(snapped(scene.camera.position[2]));
  v.plane[3] = float(extent);
  v.to_sun[3] = -1;
  if (const int sun = clouds::sun_index(scene); sun >= 0) {
    const Vec3& d = scene.lights[size_t(sun)].direction;
    const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int i = 0; i < 3; ++i) v.to_sun[i] = float(-d[size_t(i)] / n);
    v.to_sun[3] = float(sun);
  }
  return v;
}

}  // namespace volgraph
