// The froxel chain's shared fixture (froxel_scatter_test.cpp, scatter_integrate_test.cpp,
// opacity_shadow_map_test.cpp, froxel_fog_test.cpp): froxel_voxelize → froxel_scatter →
// scatter_integrate → froxel_apply → composite over a scene on each backend (with
// shadow_map and opacity_shadow_map where a case asks), and the fog layer under a dense box
// that volumetric shadows are checked on. Helpers are the fixture's members, so the files a
// unity build batches together share no namespace-scope names.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/camera.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/froxel_chain_json.h"
#include "tests/gpu/fog_scenes.h"

namespace volgraph::testing {

class FroxelFogFixture : public OnEachBackend<> {
 protected:
  static constexpr uint32_t kFroxelFogWidth = 48, kFroxelFogHeight = 32;

  struct FogCase {
    std::string media = R"({ "fog": { "sigma_s": [0.2, 0.2, 0.2], "sigma_a": [0, 0, 0] } })";
    std::string lights = "[]";
    std::string background = "[0, 0, 0]";
    std::string scatter_variant = "hg";
    std::string integrate_variant = "hillaire";
    std::string camera = R"({ "position": [0, 1, 0], "target": [0, 1, -1], "fov_y_deg": 50, "near": 0.1, "far": 1000 })";
    std::string grid = R"({ "slices": 32, "near": 0.1, "far": 20, "distribution": "linear", "jitter": false })";
    std::string scatter_params = "{}";
    // Volumetric shadows of the shadow map's light by an opacity shadow map (the light must
    // cast shadows); the scene's colour then also holds the media's shadow on surfaces.
    bool opacity_shadow_map = false;
    std::string objects = "[]";
  };

  // The passes and froxel_scatter's inputs that shadow light 0 by a shadow map and an
  // opacity shadow map of the same view.
  static constexpr const char* kOpacityShadowPasses = R"(
      { "name": "sun_shadow", "type": "shadow_map", "params": { "resolution": 256 } },
      { "name": "media_shadow", "type": "opacity_shadow_map", "params": { "resolution": 64, "layers": 64 },
        "inputs": { "light_view": "sun_shadow.light_view" } },)";
  static constexpr const char* kOpacityShadowInputs =
      R"(, "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view", "media_shadow": "media_shadow.optical_depth")";

  static std::string config_text(const FogCase& c) {
    std::ostringstream o;
    o << R"({ "output": { "size": [)" << kFroxelFogWidth << ", " << kFroxelFogHeight << R"(] },
    "scene": { "camera": )" << c.camera << R"(, "background": { "radiance": )" << c.background << R"( },
               "objects": )" << c.objects << R"(, "lights": )" << c.lights << R"(, "media": )" << c.media << R"( },
    "graph": { "passes": [)" << (c.opacity_shadow_map ? kOpacityShadowPasses : "") << R"(
      { "name": "lit", "type": "scene")" << (c.opacity_shadow_map ? R"(, "inputs": { )" + std::string(kOpacityShadowInputs + 2) + " }" : "") << R"( },
      { "name": "fog_media", "type": "froxel_voxelize", "params": )" << c.grid << R"( },
      { "name": "fog_light", "type": "froxel_scatter", "variant": ")" << c.scatter_variant << R"(", "params": )" << c.scatter_params << R"(,
        "inputs": { "media_scattering": "fog_media.media_scattering", "media_emission": "fog_media.media_emission",
                    "frame": "fog_media.frame")" << (c.opacity_shadow_map ? kOpacityShadowInputs : "") << R"( } },
      { "name": "fog_integral", "type": "scatter_integrate", "variant": ")" << c.integrate_variant << R"(",)" << kFroxelChainEnd;
    return o.str();
  }

  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(const FogCase& c) { return load_config_text("fog.json", config_text(c), registry_); }
  Texels render(const LoadedConfig& c) {
    Executor executor(device(), c.graph, &c.config.scene, {});
    executor.run_frame();
    return executor.read_output(0);
  }

  // The froxel grid resolves one value per column (8×8 pixels here); a pixel reads the
  // bilinear blend of the columns around it (clamped at the edges). So the expected image
  // is that blend of each column's exact e^(−σa·d_column).
  static double column_blend(const Camera& camera, uint32_t i, uint32_t j, const std::function<double(double)>& of_ray_length) {
    const double columns_x = kFroxelFogWidth / 8.0, columns_y = kFroxelFogHeight / 8.0;
    const double u = std::clamp((i + 0.5) / kFroxelFogWidth * columns_x - 0.5, 0.0, columns_x - 1);
    const double v = std::clamp((j + 0.5) / kFroxelFogHeight * columns_y - 0.5, 0.0, columns_y - 1);
    const int x0 = int(u), y0 = int(v), x1 = std::min(x0 + 1, int(columns_x) - 1), y1 = std::min(y0 + 1, int(columns_y) - 1);
    auto at = [&](int x, int y) {  // the column's centre ray, as a pixel of a columns_x × columns_y frame
      const physics::ViewRays rays = physics::view_rays(camera, double(kFroxelFogWidth) / kFroxelFogHeight);
      const Vec3 r = physics::view_ray(rays, (x + 0.5) / columns_x * 2 - 1, 1 - (y + 0.5) / columns_y * 2);
      return of_ray_length(std::sqrt(physics::dot(r, r)));
    };
    const double fx = u - x0, fy = v - y0;
    return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) + fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
  }

  // Volumetric self-shadowing: a fog layer (y 0–2) lit from straight above, a dense absorbing
  // box (σa 0.1, 10 m tall, over x < 0) between it and the light. With shadow_steps the
  // layer's in-scattering under the box drops by the box's transmittance e^(−1) — its exact
  // chord, plus fp16: 2 % allowed — and beside it stays; with shadow_steps 0, the box changes
  // nothing.
  static FogCase layer_under_box(bool box, int shadow_steps) {
    FogCase c;
    c.camera = kCameraAtTheLayer;
    c.media = layer_under_box_media(box);
    c.lights = kLightFromAbove;
    c.scatter_params = R"({ "shadow_steps": )" + std::to_string(shadow_steps) + R"(, "shadow_distance": 20 })";
    c.grid = R"({ "slices": 64, "near": 0.1, "far": 20, "distribution": "linear", "jitter": false })";
    return c;
  }

  // shadowed/open is e^(−1) under the box and 1 beside it (to `tolerance`, relative) over
  // the layer's lit pixels, leaving out the columns whose blend crosses x = 0; `also(k)`
  // checks more at each pixel it compares.
  static void expect_box_shadow(const Texels& open, const Texels& shadowed, const std::function<void(size_t k)>& also = {},
                         double tolerance = 2e-2) {
    double brightest = 0;
    for (size_t k = 0; k < open.rgba.size(); k += 4) brightest = std::max(brightest, double(open.rgba[k]));
    ASSERT_GT(brightest, 0.0);
    size_t under = 0, beside = 0;
    for (uint32_t j = 0; j < kFroxelFogHeight; ++j) {
      for (uint32_t i = 0; i < kFroxelFogWidth; ++i) {
        const size_t k = 4 * (j * kFroxelFogWidth + i);
        if (open.rgba[k] < 1e-2 * brightest || (i + 8 > kFroxelFogWidth / 2 && i < kFroxelFogWidth / 2 + 8)) continue;
        const double want = i < kFroxelFogWidth / 2 ? std::exp(-1.0) : 1.0;
        (i < kFroxelFogWidth / 2 ? under : beside)++;
        EXPECT_NEAR(shadowed.rgba[k] / open.rgba[k], want, tolerance * want) << i << ", " << j;
        if (also) also(k);
      }
    }
    EXPECT_GT(under, 50u);
    EXPECT_GT(beside, 50u);
  }

  // layer_under_box with its light shadowed by an opacity shadow map instead of a march.
  static FogCase layer_under_box_by_opacity_map(bool box) {
    FogCase c = layer_under_box(box, 0);
    c.lights = R"([ { "type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3] } ])";
    c.opacity_shadow_map = true;
    return c;
  }

  PassRegistry registry_;
};

}  // namespace volgraph::testing
