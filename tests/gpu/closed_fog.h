// The closed-form per-pixel fog techniques' shared fixture (depth_fog_test.cpp,
// height_fog_test.cpp, analytic_fog_test.cpp, closed_fog_test.cpp): one technique followed
// by fog_apply and composite over a scene on each backend, read back as the composed image,
// fog_scattering and fog_transmittance. Helpers are the fixture's members, so the files a
// unity build batches together share no namespace-scope names.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/camera.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {

class ClosedFogFixture : public OnEachBackend<> {
 protected:
  static constexpr uint32_t kClosedFogWidth = 48, kClosedFogHeight = 32;
  static constexpr double kFp16 = 1e-3;     // one fp16 rounding (4.9e-4) and the float maths
  static constexpr double kComposed = 2e-3;  // T, L_scat and the colour each rounded to fp16, then blended

  struct ClosedCase {
    std::string technique;  // each file names its own (a string here would label every file with it)
    std::string variant = "exponential";
    std::string params = "{}";
    std::string media = R"({ "fog": { "sigma_s": [0.1, 0.1, 0.1], "sigma_a": [0, 0, 0] } })";
    std::string lights = "[]";
    std::string objects = "[]";
    std::string background = "[0, 0, 0]";
    std::string camera = R"({ "position": [0, 1, 0], "target": [0, 1, -1], "fov_y_deg": 50, "near": 0.1, "far": 40 })";
  };

  // Outputs: 0 the composed linear image, 1 fog_scattering, 2 fog_transmittance.
  static std::string config_text(const ClosedCase& c) {
    std::ostringstream o;
    o << R"({ "output": { "size": [)" << kClosedFogWidth << ", " << kClosedFogHeight << R"(] },
  "scene": { "camera": )" << c.camera << R"(, "background": { "radiance": )" << c.background << R"( },
             "materials": { "glow": { "albedo": [0, 0, 0], "emissive": [0.5, 0.5, 0.5] } },
             "objects": )" << c.objects << R"(, "lights": )" << c.lights << R"(, "media": )" << c.media << R"( },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "fog", "type": ")" << c.technique << R"(", "variant": ")" << c.variant << R"(", "params": )" << c.params << R"(,
      "inputs": { "depth": "lit.depth" } },
    { "name": "fogged", "type": "fog_apply",
      "inputs": { "color": "lit.color", "fog_scattering": "fog.fog_scattering", "fog_transmittance": "fog.fog_transmittance" } },
    { "name": "out", "type": "composite", "variant": "none", "inputs": { "color": "fogged.color" } } ],
    "outputs": ["out.output", "fog.fog_scattering", "fog.fog_transmittance"] } })";
    return o.str();
  }

  struct Rendered {
    Texels image, scattering, transmittance;
    double at(const Texels& t, uint32_t i, uint32_t j, size_t ch) const { return t.rgba[4 * (j * t.width + i) + ch]; }
  };

  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(const ClosedCase& c) { return load_config_text("closed_fog.json", config_text(c), registry_); }
  Rendered render(const LoadedConfig& c) {
    Executor executor(device(), c.graph, &c.config.scene, {});
    executor.run_frame();
    return {executor.read_output(0), executor.read_output(1), executor.read_output(2)};
  }

  // The length of pixel (i, j)'s ray per metre of view depth.
  static double ray_scale(const Camera& camera, uint32_t i, uint32_t j) {
    const physics::ViewRays rays = physics::view_rays(camera, double(kClosedFogWidth) / kClosedFogHeight);
    const Vec3 r = physics::view_ray(rays, (i + 0.5) / kClosedFogWidth * 2 - 1, 1 - (j + 0.5) / kClosedFogHeight * 2);
    return std::sqrt(physics::dot(r, r));
  }

  static Vec3 closed_fog_pixel_direction(const Camera& camera, uint32_t i, uint32_t j) {
    const physics::ViewRays rays = physics::view_rays(camera, double(kClosedFogWidth) / kClosedFogHeight);
    return physics::normalize(physics::view_ray(rays, (i + 0.5) / kClosedFogWidth * 2 - 1, 1 - (j + 0.5) / kClosedFogHeight * 2));
  }

  static void expect_near_relative(double got, double want, const std::string& what, double relative = kFp16) {
    EXPECT_NEAR(got, want, relative * std::abs(want) + 1e-6) << what;
  }

  PassRegistry registry_;
};

}  // namespace volgraph::testing
