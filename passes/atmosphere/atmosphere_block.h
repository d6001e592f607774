// What every atmosphere pass binds: the atmosphere's uniform block (physics::GpuAtmosphere,
// packed from the scene each time the pass records) and the camera's place in the planet's
// frame (its zenith and radius, the direction toward the sun and its zenith cosine).
#pragma once

#include <string>

#include "graph/execute/pass_execution.h"
#include "passes/plumbing/programs.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_sky.h"

namespace volgraph::atmosphere {

// The uniform buffer of binding (0, 0), checked against the program at setup.
class AtmosphereBlock {
 public:
  template <class Program>  // plumbing::ComputeProgram or RenderProgram
  void setup(PassSetup& s, const Program& program) {
    plumbing::check_wrapped_uniform_mirror<physics::GpuAtmosphere>(program, 0, 0, s.name() + " atmosphere");
    create(s);
  }
  // Packs the scene's atmosphere into the buffer and returns it for the bind group.
  rhi::BufferId write(PassContext& c) const;

 private:
  void create(PassSetup& s);
  rhi::BufferId buffer_;
};

// planet_up = (the camera's zenith, its radius clamped to the top), toward_sun = (toward the
// sun, its zenith cosine at the camera): the vec4 pair the sky, aerial-perspective and
// sky-view shaders take (include/atmosphere_sky_lookup.glsl SkyFrame).
struct PlanetFrame {
  float planet_up[4];
  float toward_sun[4];
  float sun[4];  // rgb: the sun's E at the top of the atmosphere, w: 1 when there is a sun (all 0 without)
  bool has_sun;
};
PlanetFrame planet_frame(const Scene& scene);

}  // namespace volgraph::atmosphere
