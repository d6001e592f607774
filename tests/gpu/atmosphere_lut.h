// The atmosphere LUT passes' shared fixture (atmosphere_transmittance_lut_test.cpp,
// atmosphere_multiscattering_lut_test.cpp, atmosphere_skyview_lut_test.cpp,
// atmosphere_aerial_perspective_test.cpp, atmosphere_lut_test.cpp): the four Hillaire 2020
// LUT passes in one graph on each backend, their tables its outputs 0–4. Helpers are the
// fixture's members, so the files a unity build batches together share no namespace-scope names.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_lut.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {

class AtmosphereLutFixture : public OnEachBackend<> {
 protected:
  static std::string lut_config(const std::string& atmosphere) {
    return R"({ "output": { "size": [16, 16] },
    "scene": { "camera": { "position": [0, 1, 5], "target": [0, 1, 0] },
               "lights": [ { "name": "sun", "type": "directional", "direction": [0, -1, -1], "irradiance": [1, 1, 1] } ],
               )" + atmosphere + R"( },
    "graph": { "passes": [ { "name": "lut", "type": "atmosphere_transmittance_lut" },
                           { "name": "ms", "type": "atmosphere_multiscattering_lut", "inputs": { "transmittance": "lut.transmittance" } },
                           { "name": "sky", "type": "atmosphere_skyview_lut",
                             "inputs": { "transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering" } },
                           { "name": "air", "type": "atmosphere_aerial_perspective",
                             "inputs": { "transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering" } } ],
               "outputs": ["lut.transmittance", "ms.multiscattering", "sky.sky_view", "air.aerial_scattering", "air.aerial_transmittance"] } })";
  }

  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(const std::string& atmosphere) { return load_config_text("atmosphere_lut.json", lut_config(atmosphere), registry_); }

  // The largest absolute error of each texel against the double-precision twin, over the
  // whole table and over the zenith (mu = 1: the first column) alone.
  struct LutErrors {
    double all = 0, zenith = 0;
  };

  static LutErrors transmittance_errors(const Texels& lut, const Atmosphere& atmosphere) {
    LutErrors e;
    const physics::TransmittanceLutSize size{int(lut.width), int(lut.height)};
    for (uint32_t j = 0; j < lut.height; ++j) {
      for (uint32_t i = 0; i < lut.width; ++i) {
        const physics::LutUv uv{(i + 0.5) / lut.width, (j + 0.5) / lut.height};
        const physics::RadiusAndMu rm = physics::transmittance_lut_r_mu(atmosphere, uv, size);
        const Vec3 want = physics::transmittance_to_top(atmosphere, rm.r, rm.mu);
        for (size_t c = 0; c < 3; ++c) {
          const double error = std::abs(lut.rgba[4 * (size_t(j) * lut.width + i) + c] - want[c]);
          e.all = std::max(e.all, error);
          if (i == 0) e.zenith = std::max(e.zenith, error);  // x_mu = 0: the distance to the top at its least, mu = 1
        }
      }
    }
    return e;
  }

  PassRegistry registry_;
};

}  // namespace volgraph::testing
