// The froxel chain (froxel_voxelize → froxel_scatter → scatter_integrate → froxel_apply)
// on both backends, where physics gives the answer:
// - no lights, no absorption, no emission: nothing appears (exactly 0);
// - a pure absorber: the background through Beer–Lambert, e^(−σa·d), d the grid's depth
//   along each pixel's ray (fp16 volumes: 2e-3 relative);
// - a homogeneous medium under an unshadowed directional light with isotropic phase has
//   constant in-scattering S = σs·E/4π, so the radiance is S(1 − e^(−σt·d))/σt exactly:
//   Hillaire's step gets it to fp16 precision at any slice count, Wronski's errs and
//   converges as slices grow;
// - stress (σt up to 1e4, g = ±0.999, a light at the camera, a zero-size volume, a grid
//   from 1 mm to 100 km, an opacity shadow map over a zero-size volume): no NaN or Inf in
//   any intermediate volume, transmittance in [0, 1];
// - volumetric self-shadowing: a dense box between a light and a fog layer dims the layer
//   under it by the box's transmittance, only with shadow_steps;
// - without a medium the four passes are culled and the image is the scene's own.
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/camera.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/fog_scenes.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kFroxelFogWidth = 48, kFroxelFogHeight = 32;

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
const char* kOpacityShadowPasses = R"(
    { "name": "sun_shadow", "type": "shadow_map", "params": { "resolution": 256 } },
    { "name": "media_shadow", "type": "opacity_shadow_map", "params": { "resolution": 64, "layers": 64 },
      "inputs": { "light_view": "sun_shadow.light_view" } },)";
const char* kOpacityShadowInputs =
    R"(, "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view", "media_shadow": "media_shadow.optical_depth")";

std::string config_text(const FogCase& c) {
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
    { "name": "fog_integral", "type": "scatter_integrate", "variant": ")" << c.integrate_variant << R"(",
      "inputs": { "in_scatter": "fog_light.in_scatter", "media_scattering": "fog_media.media_scattering",
                  "media_absorption": "fog_media.media_absorption", "frame": "fog_media.frame" } },
    { "name": "fog_apply", "type": "froxel_apply",
      "inputs": { "color": "lit.color", "depth": "lit.depth", "integrated_scattering": "fog_integral.integrated_scattering",
                  "integrated_transmittance": "fog_integral.integrated_transmittance", "frame": "fog_media.frame" } },
    { "name": "out", "type": "composite", "variant": "none", "inputs": { "color": "fog_apply.color" } } ],
    "outputs": ["out.output"] } })";
  return o.str();
}

class FroxelFog : public OnEachBackend<> {
 protected:
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
  double homogeneous_error(const std::string& variant, int slices);
  PassRegistry registry_;
};

TEST_P(FroxelFog, NothingAppearsWithoutLightsAbsorptionOrEmission) {
  const Texels t = render(load(FogCase{}));
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    for (size_t ch = 0; ch < 3; ++ch) ASSERT_EQ(t.rgba[i + ch], 0.0f) << "texel " << i / 4;
  }
}

// The froxel grid resolves one value per column (8×8 pixels here); a pixel reads the
// bilinear blend of the columns around it (clamped at the edges). So the expected image
// is that blend of each column's exact e^(−σa·d_column).
double column_blend(const Camera& camera, uint32_t i, uint32_t j, const std::function<double(double)>& of_ray_length) {
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

TEST_P(FroxelFog, APureAbsorberAttenuatesTheBackgroundByBeerLambert) {
  FogCase c;
  c.media = R"({ "fog": { "sigma_s": [0, 0, 0], "sigma_a": [0.02, 0.05, 0.1] } })";
  c.background = "[1, 1, 1]";
  const LoadedConfig config = load(c);
  const Texels t = render(config);
  const double sigma_a[3] = {0.02, 0.05, 0.1}, depth = 20 - 0.1;
  for (uint32_t j = 0; j < kFroxelFogHeight; ++j) {
    for (uint32_t i = 0; i < kFroxelFogWidth; ++i) {
      for (size_t ch = 0; ch < 3; ++ch) {
        const double want = column_blend(config.config.scene.camera, i, j, [&](double length) { return std::exp(-sigma_a[ch] * depth * length); });
        ASSERT_NEAR(t.rgba[4 * (j * kFroxelFogWidth + i) + ch], want, 2e-3 * want) << i << ", " << j << " ch " << ch;
      }
    }
  }
}

// Largest relative error of the in-scattered radiance against S(1 − e^(−σt d))/σt.
double FroxelFog::homogeneous_error(const std::string& variant, int slices) {
  FogCase c;
  const double sigma_s = 0.4, sigma_a = 0.1, e = 3.0;
  c.media = R"({ "fog": { "sigma_s": [0.4, 0.4, 0.4], "sigma_a": [0.1, 0.1, 0.1] } })";
  c.lights = R"([ { "type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3], "cast_shadows": false } ])";
  c.scatter_variant = "isotropic";
  c.integrate_variant = variant;
  c.grid = R"({ "slices": )" + std::to_string(slices) + R"(, "near": 0.1, "far": 20, "distribution": "linear", "jitter": false })";
  const LoadedConfig config = load(c);
  const Texels t = render(config);
  const double s = sigma_s * e / (4 * M_PI), sigma_t = sigma_s + sigma_a;
  double worst = 0;
  for (uint32_t j = 0; j < kFroxelFogHeight; ++j) {
    for (uint32_t i = 0; i < kFroxelFogWidth; ++i) {
      const double want = column_blend(config.config.scene.camera, i, j, [&](double length) {
        return s * (1 - std::exp(-sigma_t * (20 - 0.1) * length)) / sigma_t;
      });
      worst = std::max(worst, std::abs(t.rgba[4 * (j * kFroxelFogWidth + i)] - want) / want);
    }
  }
  return worst;
}

TEST_P(FroxelFog, HillaireIsExactForAHomogeneousMediumAndWronskiConverges) {
  EXPECT_LT(homogeneous_error("hillaire", 16), 3e-3);
  double previous = 1e9;
  for (int slices : {8, 16, 32, 64}) {
    const double wronski = homogeneous_error("wronski", slices);
    EXPECT_GT(wronski, 3e-3) << slices << " slices";  // optical depth 10: each slice is dense
    EXPECT_LT(wronski, previous) << slices << " slices";
    previous = wronski;
  }
}

TEST_P(FroxelFog, StressLimitsLeaveNoNanOrInfInAnyVolume) {
  for (const char* m : kStressMedia) {
    FogCase c;
    c.media = m;
    c.lights = kStressLights;
    c.background = "[1, 1, 1]";
    c.opacity_shadow_map = true;  // the directional light's volumetric shadows by the map, the point light's by no march
    c.grid = R"({ "slices": 16, "near": 0.001, "far": 100000, "distribution": "exponential", "jitter": false })";
    LoadedConfig config = load(c);
    for (uint32_t r = 0; r < config.graph.resources.size(); ++r) {  // keep every volume to read it back (as --dump does)
      const GraphResource& resource = config.graph.resources[r];
      if (resource.desc.kind == ResourceKind::texture3d) config.graph.outputs.push_back({r, uint32_t(resource.version_writers.size() - 1)});
    }
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    for (uint32_t r = 0; r < config.graph.resources.size(); ++r) {
      const ResourceDesc& d = config.graph.resources[r].desc;
      if (d.kind != ResourceKind::texture3d && d.name != "out.output") continue;
      const Texels t = executor.read_texture(r);
      for (size_t k = 0; k < t.rgba.size(); ++k) ASSERT_TRUE(std::isfinite(t.rgba[k])) << d.name << " value " << k << " of " << m;
      if (d.name != "fog_integral.integrated_transmittance") continue;
      for (size_t k = 0; k < t.rgba.size(); k += 4) {
        for (size_t ch = 0; ch < 3; ++ch) {
          ASSERT_GE(t.rgba[k + ch], 0.0f) << m;
          ASSERT_LE(t.rgba[k + ch], 1.0f) << m;
        }
      }
    }
  }
}

TEST_P(FroxelFog, WithoutAMediumTheFogPassesAreCulledAndTheSceneIsUntouched) {
  FogCase with;
  with.media = R"({ "fog": { "sigma_s": [0, 0, 0], "sigma_a": [0, 0, 0] } })";  // no medium at all
  with.background = "[0.25, 0.5, 1]";
  const LoadedConfig config = load(with);
  Executor executor(device(), config.graph, &config.config.scene, {});
  EXPECT_EQ(executor.plan().culled.size(), 4u);
  for (const CulledPass& culled : executor.plan().culled) EXPECT_EQ(culled.reason, CullReason::scene_lacks);
  executor.run_frame();
  const Texels t = executor.read_output(0);
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    ASSERT_EQ(t.rgba[i], 0.25f);
    ASSERT_EQ(t.rgba[i + 2], 1.0f);
  }
}

// Volumetric self-shadowing: a fog layer (y 0–2) lit from straight above, a dense absorbing
// box (σa 0.1, 10 m tall, over x < 0) between it and the light. With shadow_steps the
// layer's in-scattering under the box drops by the box's transmittance e^(−1) — its exact
// chord, plus fp16: 2 % allowed — and beside it stays; with shadow_steps 0, the box changes
// nothing.
FogCase layer_under_box(bool box, int shadow_steps) {
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
void expect_box_shadow(const Texels& open, const Texels& shadowed, const std::function<void(size_t k)>& also = {},
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

TEST_P(FroxelFog, ADenseBoxShadowsTheFogUnderItOnlyWithShadowSteps) {
  expect_box_shadow(render(load(layer_under_box(false, 256))), render(load(layer_under_box(true, 256))));
  const Texels open_unshadowed = render(load(layer_under_box(false, 0)));
  const Texels unshadowed = render(load(layer_under_box(true, 0)));
  for (size_t k = 0; k < open_unshadowed.rgba.size(); ++k) ASSERT_EQ(unshadowed.rgba[k], open_unshadowed.rgba[k]) << k;
}

// At froxel_scatter's defaults the box shadows the layer too, exactly: a volume without edge
// fade or noise dims the light by e^(−σt·chord) (each volume's chord toward the light,
// light_transmittance.glsl), so under the box the in-scattering is e^(−1) of the open
// layer's (1 with the volumes ignored) and beside it 1, within 2 % (fp16).
TEST_P(FroxelFog, ADenseBoxShadowsTheFogUnderItAtTheDefaults) {
  FogCase open = layer_under_box(false, 0), shadowed = layer_under_box(true, 0);
  open.scatter_params = shadowed.scatter_params = "{}";
  expect_box_shadow(render(load(open)), render(load(shadowed)));
}

// Skipping the light loop in froxels without scattering (the default) is exact: the image
// is bit-identical with skip_empty off, on media confined to local volumes.
TEST_P(FroxelFog, SkippingEmptyFroxelsChangesNothing) {
  FogCase skipping = layer_under_box(true, 16);
  FogCase lighting_all = skipping;
  lighting_all.scatter_params = R"({ "shadow_steps": 16, "shadow_distance": 20, "skip_empty": false })";
  const Texels a = render(load(skipping)), b = render(load(lighting_all));
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  for (size_t k = 0; k < a.rgba.size(); ++k) ASSERT_EQ(a.rgba[k], b.rgba[k]) << k;
}

// The same shadow by the other volumetric-shadow variant: light 0 casts shadows, its
// shadow map's view holds the media volumes, and an opacity shadow map of 64 layers over
// it replaces the march (shadow_steps 0). The layer's own optical depth toward the light
// is linear in height (trilinear lookups reproduce it) and the box's is whole below it:
// the ratio is e^(−1) as before, to 3 %: the march of 2 steps a layer and fp16 τ, and the
// froxels that the layer's bottom face cuts — they hold its medium in part (froxel_voxelize
// averages it over the froxel) and are lit at their centre, which may lie below the layer,
// outside the media the map was fitted to (where those centres fall moves the ratio:
// measured −2.2 % at 64 slices, +2.4 % at 256). The image agrees with the 256-step
// march's to 3 % wherever the layer is lit.
FogCase layer_under_box_by_opacity_map(bool box) {
  FogCase c = layer_under_box(box, 0);
  c.lights = R"([ { "type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3] } ])";
  c.opacity_shadow_map = true;
  return c;
}

TEST_P(FroxelFog, ADenseBoxShadowsTheFogUnderItThroughAnOpacityShadowMap) {
  const Texels shadowed = render(load(layer_under_box_by_opacity_map(true)));
  const Texels marched = render(load(layer_under_box(true, 256)));
  expect_box_shadow(render(load(layer_under_box_by_opacity_map(false))), shadowed,
                    [&](size_t k) { EXPECT_NEAR(shadowed.rgba[k], marched.rgba[k], 3e-2 * marched.rgba[k]) << k / 4; }, 3e-2);
}

// Surfaces too: a floor (ρ 0.5, y = −0.5) under the fog layer (τ 1 straight up, over
// −4 < z < 0) and the box (τ 1, over −10 < x < 0) receives E·e^(−τ) from the light
// overhead, so its radiance is ρ/π·3·e^(−τ) — read where the floor is at least 0.5 m from
// the media's edges (the map's texels blend across them). 1 %: fp16 τ, and 8 march steps a
// layer (0.21 m layers here) put each of the layer's edges within ±0.013 m (τ ±0.007).
// The graph renders the lit scene alone (no fog in front of the floor).
TEST_P(FroxelFog, TheOpacityShadowMapDimsSurfacesUnderTheMedia) {
  std::ostringstream text;
  text << R"({ "output": { "size": [)" << kFroxelFogWidth << ", " << kFroxelFogHeight << R"(] },
  "scene": { "camera": )" << kCameraAtTheLayer << R"(, "media": )" << layer_under_box_media(true) << R"(,
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "objects": [ { "name": "floor", "shape": "plane", "size": [40, 1, 40], "material": "grey", "transform": { "translate": [0, -0.5, 0] } } ],
    "lights": [ { "type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3] } ] },
  "graph": { "passes": [
    { "name": "sun_shadow", "type": "shadow_map", "params": { "resolution": 256 } },
    { "name": "media_shadow", "type": "opacity_shadow_map", "params": { "resolution": 64, "layers": 64, "steps_per_layer": 8 },
      "inputs": { "light_view": "sun_shadow.light_view" } },
    { "name": "lit", "type": "scene", "inputs": { )" << (kOpacityShadowInputs + 2) << R"( } },
    { "name": "out", "type": "composite", "variant": "none", "inputs": { "color": "lit.color" } } ],
    "outputs": ["out.output"] } })";
  const LoadedConfig config = load_config_text("floor.json", text.str(), registry_);
  const Texels t = render(config);
  const physics::ViewRays rays = physics::view_rays(config.config.scene.camera, double(kFroxelFogWidth) / kFroxelFogHeight);
  size_t checked[2] = {0, 0};
  for (uint32_t j = 0; j < kFroxelFogHeight; ++j) {
    for (uint32_t i = 0; i < kFroxelFogWidth; ++i) {
      const Vec3 d = physics::view_ray(rays, (i + 0.5) / kFroxelFogWidth * 2 - 1, 1 - (j + 0.5) / kFroxelFogHeight * 2);
      if (d[1] >= 0) continue;
      const double t_floor = (-0.5 - rays.position[1]) / d[1];
      const double x = rays.position[0] + t_floor * d[0], z = rays.position[2] + t_floor * d[2];
      const bool under_layer = z > -4 && z < 0, under_box = x > -10 && x < 0;
      if (std::abs(x) < 0.5 || std::abs(x + 10) < 0.5 || std::abs(z) < 0.5 || std::abs(z + 4) < 0.5 || z < -15) continue;
      const double want = 0.5 / M_PI * 3 * std::exp(-(under_layer ? 1.0 : 0.0) - (under_box ? 1.0 : 0.0));
      ++checked[under_layer];
      EXPECT_NEAR(t.rgba[4 * (j * kFroxelFogWidth + i)], want, 1e-2 * want) << i << ", " << j << " x " << x << " z " << z;
    }
  }
  EXPECT_GT(checked[0], 20u);
  EXPECT_GT(checked[1], 20u);
}

INSTANTIATE_TEST_SUITE_P(Backends, FroxelFog, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
