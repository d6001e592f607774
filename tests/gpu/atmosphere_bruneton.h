// Bruneton 2017's tables' shared fixture (atmosphere_bruneton_tables_test.cpp,
// atmosphere_bruneton_test.cpp): the transmittance LUT and atmosphere_bruneton_tables on each
// backend, small table sizes, and the tables read back as the CPU twin takes them. Helpers
// are the fixture's members, so the files a unity build batches together share no
// namespace-scope names.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_bruneton.h"
#include "tests/gpu/backends.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {

class AtmosphereBrunetonFixture : public OnEachBackend<> {
 public:  // the constants and helpers: also for the configs a file builds outside the fixture
  // Small tables: 4 × 8 × 32 × 8 (nu, mu_s, mu, r), irradiance 16 × 8.
  static constexpr const char* kSmall = R"("nu": 4, "nu_mu_s": 32, "mu": 32, "r": 8, "irradiance_width": 16, "irradiance_height": 8)";
  static inline const physics::BrunetonTableSize kSmallSize{4, 8, 32, 8, 16, 8};

  static std::string tables_config(int orders, const std::string& sizes, const std::string& camera_y = "1") {
    return R"({ "output": { "size": [16, 16] },
    "scene": { "camera": { "position": [0, )" + camera_y + R"(, 5], "target": [0, )" + camera_y + R"(, 0] },
               "lights": [ { "name": "sun", "type": "directional", "direction": [0, -1, -1.7320508], "irradiance": [1, 1, 1] } ],
               "atmosphere": { "preset": "earth" } },
    "graph": { "passes": [ { "name": "lut", "type": "atmosphere_transmittance_lut" },
                           { "name": "tables", "type": "atmosphere_bruneton_tables", "params": { "orders": )" +
           std::to_string(orders) + ", " + sizes + R"( },
                             "inputs": { "transmittance": "lut.transmittance" } } ],
               "outputs": ["tables.scattering", "tables.irradiance", "lut.transmittance", "tables.single_mie_scattering"] } })";
  }

  static physics::BrunetonTable table_of(const Texels& t) { return {int(t.width), int(t.height), int(t.depth), t.rgba}; }

  static physics::TransmittanceToTop exact_transmittance(const Atmosphere& a) {
    return [a](double r, double mu) { return physics::transmittance_to_top(a, r, mu); };
  }

 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(int orders, const std::string& sizes = kSmall) {
    return load_config_text("atmosphere_bruneton.json", tables_config(orders, sizes), registry_);
  }

  PassRegistry registry_;
};

}  // namespace volgraph::testing
