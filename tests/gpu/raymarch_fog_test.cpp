// raymarch_fog (→ fog_apply) on both backends, where physics or the CPU reference gives
// the answer:
// - no lights, no absorption, no emission: nothing appears (exactly 0);
// - a pure absorber: the background through Beer–Lambert, e^(−σa·d), d the length of each
//   pixel's ray to view depth max_distance (fp16 images: 2e-3 relative);
// - a homogeneous medium under an unshadowed directional light with g = 0 has constant
//   in-scattering S = σs·E/4π, so the radiance is S(1 − e^(−σt·d))/σt exactly: Hillaire's
//   step with jittered samples gets it to fp16 precision at any step count, at full and
//   half resolution, with or without volumetric shadows (the global fog does not shadow a
//   directional light);
// - jitter: the same frame gives the same image, the next frame another;
// - volumetric shadows: a dense absorbing box between a directional light and a thin fog
//   layer scales the layer's in-scattering behind it by e^(−σa·chord) with shadow_steps > 0
//   and leaves it unchanged with 0;
// - convergence: against the CPU reference (reference/) on height fog, a fog sphere and a
//   point light, the relative mean absolute error falls as steps grow 8 → 32 → 128;
// - stress (σt 0 and 1e4, g = ±0.999, a light at the camera, max_distance 1e5): no NaN or
//   Inf in either image or the frame, transmittance in [0, 1];
// - the phase variants (hg, isotropic, rayleigh, schlick, dual_hg: in_scattering.glsl,
//   shared with froxel_scatter): in homogeneous fog around a point light, raymarch_fog and
//   the froxel chain each within a stated bound of the single-scattering integral computed
//   here from the CPU twin (physics/in_scattering.h), itself checked against the CPU
//   reference for HG.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/camera.h"
#include "physics/in_scattering.h"
#include "physics/light_transmittance.h"
#include "reference/image_render.h"
#include "reference/renderer.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/froxel_chain_json.h"
#include "tests/support/adaptive_simpson.h"
#include "tests/gpu/fog_scenes.h"
#include "shaders/include/phase_codes.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kRaymarchFogWidth = 48, kRaymarchFogHeight = 32;

struct MarchCase {
  std::string media = R"({ "fog": { "sigma_s": [0.2, 0.2, 0.2], "sigma_a": [0, 0, 0] } })";
  std::string lights = "[]";
  std::string background = "[0, 0, 0]";
  std::string camera = R"({ "position": [0, 1, 0], "target": [0, 1, -1], "fov_y_deg": 50, "near": 0.1, "far": 1000 })";
  std::string march = R"({ "steps": 16, "max_distance": 20 })";
  std::string objects = "[]";
  std::string apply_variant = "bilinear";
  std::string march_variant = "hg";
};

// scene → raymarch_fog → fog_apply → composite (linear); the march's two images are
// outputs 1 (scattering) and 2 (transmittance).
std::string config_text(const MarchCase& c) {
  std::ostringstream o;
  o << R"({ "output": { "size": [)" << kRaymarchFogWidth << ", " << kRaymarchFogHeight << R"(] },
  "scene": { "camera": )" << c.camera << R"(, "background": { "radiance": )" << c.background << R"( },
             "objects": )" << c.objects << R"(, "lights": )" << c.lights << R"(, "media": )" << c.media << R"( },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "fog_march", "type": "raymarch_fog", "variant": ")" << c.march_variant << R"(", "params": )" << c.march << R"(,
      "inputs": { "depth": "lit.depth" } },
    { "name": "fog_apply", "type": "fog_apply", "variant": ")" << c.apply_variant << R"(",
      "inputs": { "color": "lit.color", "depth": "lit.depth", "fog_scattering": "fog_march.fog_scattering",
                  "fog_transmittance": "fog_march.fog_transmittance" } },
    { "name": "out", "type": "composite", "variant": "none", "inputs": { "color": "fog_apply.color" } } ],
    "outputs": ["out.output", "fog_march.fog_scattering", "fog_march.fog_transmittance"] } })";
  return o.str();
}

// Length of the camera ray through the centre of texel (i, j) of a w × h image, per unit
// of view depth.
double ray_length(const Camera& camera, uint32_t i, uint32_t j, uint32_t w, uint32_t h) {
  const physics::ViewRays rays = physics::view_rays(camera, double(kRaymarchFogWidth) / kRaymarchFogHeight);
  const Vec3 r = physics::view_ray(rays, (i + 0.5) / w * 2 - 1, 1 - (j + 0.5) / h * 2);
  return std::sqrt(physics::dot(r, r));
}

float channel(const Texels& t, uint32_t i, uint32_t j, size_t ch) { return t.rgba[4 * (size_t(j) * t.width + i) + ch]; }

class RaymarchFog : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(const MarchCase& c) { return load_config_text("march.json", config_text(c), registry_); }
  // The three outputs after `frames` frames.
  std::vector<Texels> render(const LoadedConfig& c, int frames = 1) {
    Executor executor(device(), c.graph, &c.config.scene, {});
    for (int f = 0; f < frames; ++f) executor.run_frame();
    return {executor.read_output(0), executor.read_output(1), executor.read_output(2)};
  }
  double homogeneous_error(int steps, const std::string& resolution, int shadow_steps);
  double reference_error(int steps);
  PassRegistry registry_;
};

TEST_P(RaymarchFog, NothingAppearsWithoutLightsAbsorptionOrEmission) {
  const std::vector<Texels> t = render(load(MarchCase{}));
  for (size_t i = 0; i < t[0].rgba.size(); i += 4) {
    for (size_t ch = 0; ch < 3; ++ch) {
      ASSERT_EQ(t[0].rgba[i + ch], 0.0f) << "texel " << i / 4;
      ASSERT_EQ(t[1].rgba[i + ch], 0.0f) << "texel " << i / 4;
    }
  }
}

TEST_P(RaymarchFog, APureAbsorberAttenuatesTheBackgroundByBeerLambert) {
  MarchCase c;
  c.media = R"({ "fog": { "sigma_s": [0, 0, 0], "sigma_a": [0.02, 0.05, 0.1] } })";
  c.background = "[1, 1, 1]";
  const LoadedConfig config = load(c);
  const Texels t = render(config)[0];
  const double sigma_a[3] = {0.02, 0.05, 0.1}, depth = 20;
  for (uint32_t j = 0; j < kRaymarchFogHeight; ++j) {
    for (uint32_t i = 0; i < kRaymarchFogWidth; ++i) {
      const double d = depth * ray_length(config.config.scene.camera, i, j, kRaymarchFogWidth, kRaymarchFogHeight);
      for (size_t ch = 0; ch < 3; ++ch) {
        const double want = std::exp(-sigma_a[ch] * d);
        ASSERT_NEAR(channel(t, i, j, ch), want, 2e-3 * want) << i << ", " << j << " ch " << ch;
      }
    }
  }
}

// Largest relative error of the march's in-scattering image against S(1 − e^(−σt d))/σt,
// each texel against its own ray (at half resolution the image is 24×16).
double RaymarchFog::homogeneous_error(int steps, const std::string& resolution, int shadow_steps) {
  MarchCase c;
  const double sigma_s = 0.4, sigma_a = 0.1, e = 3.0;
  c.media = R"({ "fog": { "sigma_s": [0.4, 0.4, 0.4], "sigma_a": [0.1, 0.1, 0.1] } })";
  c.lights = R"([ { "type": "directional", "direction": [0.3, -1, 0.2], "irradiance": [3, 3, 3], "cast_shadows": false } ])";
  c.march = R"({ "steps": )" + std::to_string(steps) + R"(, "shadow_steps": )" + std::to_string(shadow_steps) +
            R"(, "max_distance": 20, "resolution": ")" + resolution + R"(", "jitter": true })";
  const LoadedConfig config = load(c);
  const Texels t = render(config, 2)[1];  // frame 1: a jitter other than frame 0's
  const uint32_t w = resolution == "half" ? kRaymarchFogWidth / 2 : kRaymarchFogWidth, h = resolution == "half" ? kRaymarchFogHeight / 2 : kRaymarchFogHeight;
  EXPECT_EQ(t.width, w);
  EXPECT_EQ(t.height, h);
  const double s = sigma_s * e / (4 * M_PI), sigma_t = sigma_s + sigma_a;
  double worst = 0;
  for (uint32_t j = 0; j < h; ++j) {
    for (uint32_t i = 0; i < w; ++i) {
      const double d = 20 * ray_length(config.config.scene.camera, i, j, w, h);
      const double want = s * (1 - std::exp(-sigma_t * d)) / sigma_t;
      worst = std::max(worst, std::abs(channel(t, i, j, 0) - want) / want);
    }
  }
  return worst;
}

TEST_P(RaymarchFog, HillaireIsExactForAHomogeneousMediumAtAnyStepCountDespiteTheJitter) {
  for (int steps : {1, 3, 16, 64}) EXPECT_LT(homogeneous_error(steps, "full", 0), 2e-3) << steps << " steps";
  EXPECT_LT(homogeneous_error(7, "half", 0), 2e-3) << "half resolution";
  EXPECT_LT(homogeneous_error(7, "full", 4), 2e-3) << "with volumetric shadows";
}

// A fog sphere inside height fog lit by a point light: heterogeneous along every ray.
MarchCase heterogeneous_case(int steps) {
  MarchCase c;
  c.camera = R"({ "position": [0, 1, 6], "target": [0, 1, 0], "fov_y_deg": 50, "near": 0.1, "far": 20 })";
  c.background = "[0.1, 0.1, 0.15]";
  c.media = R"({ "height_fog": { "sigma_s": [0.08, 0.08, 0.08], "sigma_a": [0.02, 0.02, 0.02], "g": 0.3, "base_height": 0, "falloff": 0.5 },
                 "volumes": [ { "shape": "sphere", "size": [1.5, 1.5, 1.5], "sigma_s": [0.6, 0.5, 0.4], "sigma_a": [0.1, 0.1, 0.1], "g": 0.3,
                                "transform": { "translate": [0.5, 1.2, 0] } } ] })";
  c.lights = R"([ { "type": "point", "position": [-1.5, 2.5, 1], "intensity": [20, 18, 16], "cast_shadows": false } ])";
  c.march = R"({ "steps": )" + std::to_string(steps) + R"(, "shadow_steps": )" + std::to_string(steps) + R"(, "max_distance": 20 })";
  return c;
}

TEST_P(RaymarchFog, JitterIsTheSameForAFrameAndMovesBetweenFrames) {
  const LoadedConfig config = load(heterogeneous_case(8));
  const std::vector<Texels> once = render(config, 1), again = render(config, 1), next = render(config, 2);
  EXPECT_TRUE(once[1].rgba == again[1].rgba);
  EXPECT_FALSE(once[1].rgba == next[1].rgba);
}

// Relative mean absolute error of the frame against the CPU reference's radiance:
// Σ|gpu − reference| / Σ|reference| over every pixel and channel.
double RaymarchFog::reference_error(int steps) {
  const LoadedConfig config = load(heterogeneous_case(steps));
  const Texels t = render(config)[0];
  const reference::Renderer renderer(config.config.scene);
  const reference::ReferenceImage truth = reference::render_image(renderer, {.width = kRaymarchFogWidth, .height = kRaymarchFogHeight, .threads = 2});
  double difference = 0, total = 0;
  for (uint32_t j = 0; j < kRaymarchFogHeight; ++j) {
    for (uint32_t i = 0; i < kRaymarchFogWidth; ++i) {
      for (size_t ch = 0; ch < 3; ++ch) {
        difference += std::abs(channel(t, i, j, ch) - truth.at(i, j)[ch]);
        total += std::abs(truth.at(i, j)[ch]);
      }
    }
  }
  return difference / total;
}

TEST_P(RaymarchFog, ConvergesToTheCpuReferenceAsStepsGrow) {
  const double e8 = reference_error(8), e32 = reference_error(32), e128 = reference_error(128);
  std::printf("raymarch_fog vs CPU reference (relative mean absolute error): 8 steps %.2e, 32 steps %.2e, 128 steps %.2e\n", e8,
              e32, e128);
  // Measured: 0.149, 0.024, 0.012 (and 1.6e-3 at 512 steps); the point light's peak along
  // the rays passing near it is what 128 jittered steps still resolve coarsely.
  EXPECT_LT(e32, 0.5 * e8);
  EXPECT_LT(e128, 0.75 * e32);
  EXPECT_LT(e128, 2e-2);
}

// The dense box's chord toward the light is 10 m of σa = 0.1 (optical depth 1); the fog
// layer under it is lit through it.
MarchCase shadow_case(bool box, int shadow_steps) {
  MarchCase c;
  c.camera = kCameraAtTheLayer;
  c.media = layer_under_box_media(box);
  c.lights = kLightFromAbove;
  c.march = R"({ "steps": 32, "shadow_steps": )" + std::to_string(shadow_steps) + R"(, "max_distance": 30, "shadow_distance": 20 })";
  return c;
}

TEST_P(RaymarchFog, ADenseBoxCastsAVolumetricShadowOnlyWithShadowSteps) {
  // The layer shadows itself too (toward its top): each render is compared with the same
  // march without the box.
  const Texels open = render(load(shadow_case(false, 64)))[1];
  const Texels shadowed = render(load(shadow_case(true, 64)))[1];
  const Texels open_without_shadows = render(load(shadow_case(false, 0)))[1];
  const Texels without_shadows = render(load(shadow_case(true, 0)))[1];
  const double box_transmittance = std::exp(-0.1 * 10.0);
  double brightest = 0;
  for (size_t k = 0; k < open.rgba.size(); k += 4) brightest = std::max(brightest, double(open.rgba[k]));
  ASSERT_GT(brightest, 0.0);
  size_t under_box = 0, beside_box = 0;
  for (uint32_t j = 0; j < kRaymarchFogHeight; ++j) {
    for (uint32_t i = 0; i < kRaymarchFogWidth; ++i) {
      const double lit = channel(open, i, j, 0);
      if (lit < 1e-2 * brightest) continue;  // the ray misses the layer
      // Pixels left of centre look at x < 0 all along: under the box.
      const double want = i < kRaymarchFogWidth / 2 ? box_transmittance : 1.0;
      (i < kRaymarchFogWidth / 2 ? under_box : beside_box)++;
      EXPECT_NEAR(channel(shadowed, i, j, 0) / lit, want, 5e-3 * want) << i << ", " << j;
      EXPECT_EQ(channel(without_shadows, i, j, 0), channel(open_without_shadows, i, j, 0)) << i << ", " << j;
    }
  }
  EXPECT_GT(under_box, 50u);
  EXPECT_GT(beside_box, 50u);
  // The CPU twin of the secondary march gives the same closed form under the box.
  const LoadedConfig config = load(shadow_case(true, 64));
  const Scene& scene = config.config.scene;
  for (double jitter : {0.0, 0.3, 0.9}) {
    Media box_only = scene.media;
    box_only.volumes.erase(box_only.volumes.begin());  // the layer's own part of the march
    const Vec3 t = physics::transmittance_to_light(box_only, scene.lights[0], {-1, 1.3, -2}, 64, 20, jitter);
    EXPECT_NEAR(t[0], box_transmittance, 1e-9) << "jitter " << jitter;
  }
}

TEST_P(RaymarchFog, StressLimitsLeaveNoNanOrInfAndTransmittanceInZeroOne) {
  const char* media[] = {
      R"({ "fog": { "sigma_s": [1e4, 1e4, 1e4], "sigma_a": [0, 0, 0], "g": 0.999 } })",
      R"({ "fog": { "sigma_s": [0, 0, 0], "sigma_a": [0, 0, 0], "emission": [1, 1, 1], "g": -0.999 },
          "volumes": [ { "shape": "sphere", "size": [0, 0, 0], "sigma_s": [5, 5, 5] } ] })",
      R"({ "fog": { "sigma_s": [1e-7, 1e-7, 1e-7], "sigma_a": [0, 0, 0], "g": -0.999 } })",
      R"({ "height_fog": { "sigma_s": [1, 1, 1], "sigma_a": [1e4, 1e4, 1e4], "g": 0.999, "base_height": -1000, "falloff": 1000 } })",
  };
  for (const char* m : media) {
    MarchCase c;
    c.media = m;
    c.lights = R"([ { "type": "point", "position": [0, 1, 0], "intensity": [1e4, 1e4, 1e4] },
                    { "type": "directional", "direction": [0, 0, -1], "irradiance": [10, 10, 10] } ])";
    c.background = "[1, 1, 1]";
    c.march = R"({ "steps": 16, "shadow_steps": 4, "max_distance": 100000, "shadow_distance": 100000 })";
    const std::vector<Texels> t = render(load(c));
    for (const Texels& image : t) {
      for (size_t k = 0; k < image.rgba.size(); ++k) ASSERT_TRUE(std::isfinite(image.rgba[k])) << "value " << k << " of " << m;
    }
    for (size_t k = 0; k < t[2].rgba.size(); k += 4) {
      for (size_t ch = 0; ch < 3; ++ch) {
        ASSERT_GE(t[2].rgba[k + ch], 0.0f) << m;
        ASSERT_LE(t[2].rgba[k + ch], 1.0f) << m;
      }
    }
  }
}

// Depth-aware upsampling: a black box 3–5 m away covers the left of a view into lit fog
// that reaches 20 m, so the fog in front of the box is a fraction of the fog beside it.
// Marched at half resolution, each texel covers 2×2 pixels; along the box's silhouette
// bilinear reading blends fog from both sides, while fog_apply's depth_aware variant
// weights each texel by how close its depth is to the pixel's. Against the same march at
// full resolution, over the pixels whose 3×3 neighbourhood straddles the silhouette, the
// mean absolute error must be under a tenth of bilinear's (measured: 9.5e-5 against
// 0.054), and over the whole image no larger.
TEST_P(RaymarchFog, DepthAwareUpsamplingKeepsTheFogOnItsSideOfASilhouette) {
  MarchCase c;
  c.media = R"({ "fog": { "sigma_s": [0.1, 0.1, 0.1], "sigma_a": [0, 0, 0] } })";
  c.lights = R"([ { "type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3], "cast_shadows": false } ])";
  c.objects = R"([ { "name": "wall", "shape": "box", "size": [2, 4, 2], "material": "black", "transform": { "translate": [-1.1, 1, -4] } } ])";
  c.march = R"({ "steps": 32, "max_distance": 20, "jitter": false, "resolution": "full" })";
  auto text_with_black = [&](const MarchCase& m) {
    std::string t = config_text(m);
    t.replace(t.find(R"("scene": {)"), 10, R"("scene": { "materials": { "black": { "albedo": [0, 0, 0] } },)");
    return t;
  };
  auto final_image = [&](const MarchCase& m) {
    const LoadedConfig loaded = load_config_text("march.json", text_with_black(m), registry_);
    return render(loaded)[0];
  };
  const Texels full = final_image(c);
  c.march = R"({ "steps": 32, "max_distance": 20, "jitter": false, "resolution": "half" })";
  const Texels bilinear = final_image(c);
  c.apply_variant = "depth_aware";
  const Texels depth_aware = final_image(c);
  // Silhouette pixels: the 3×3 neighbourhood has both the box (its fog is dimmer) and the background.
  auto on_box = [&](int i, int j) { return channel(full, uint32_t(i), uint32_t(j), 0) < 0.5 * channel(full, kRaymarchFogWidth - 1, uint32_t(j), 0); };
  double edge_error[2] = {0, 0}, all_error[2] = {0, 0};
  size_t edge_pixels = 0;
  for (int j = 0; j < int(kRaymarchFogHeight); ++j) {
    for (int i = 0; i < int(kRaymarchFogWidth); ++i) {
      bool box = false, open = false;
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          const int x = std::clamp(i + di, 0, int(kRaymarchFogWidth) - 1), y = std::clamp(j + dj, 0, int(kRaymarchFogHeight) - 1);
          (on_box(x, y) ? box : open) = true;
        }
      }
      const double want = channel(full, uint32_t(i), uint32_t(j), 0);
      const double errors[2] = {std::abs(channel(bilinear, uint32_t(i), uint32_t(j), 0) - want),
                                std::abs(channel(depth_aware, uint32_t(i), uint32_t(j), 0) - want)};
      for (int v = 0; v < 2; ++v) all_error[v] += errors[v];
      if (!(box && open)) continue;
      ++edge_pixels;
      for (int v = 0; v < 2; ++v) edge_error[v] += errors[v];
    }
  }
  ASSERT_GT(edge_pixels, 20u);
  std::printf("  silhouette (%zu px): bilinear %.4g, depth_aware %.4g; whole image: %.4g, %.4g (mean absolute error)\n", edge_pixels,
              edge_error[0] / edge_pixels, edge_error[1] / edge_pixels, all_error[0] / (kRaymarchFogWidth * kRaymarchFogHeight), all_error[1] / (kRaymarchFogWidth * kRaymarchFogHeight));
  EXPECT_LT(edge_error[1], 0.1 * edge_error[0]);
  EXPECT_LE(all_error[1], all_error[0]);
}

// The phase variants, each in both techniques. The scene: homogeneous global fog (σs 0.1,
// σa 0.02, g 0.5) around a point light (20, 18, 15 W/sr at (1.5, 2, −6), unshadowed) in
// the view, no surfaces, black background, view depth 20 m (the camera's far plane, the
// march's max_distance, the grid's far). raymarch_fog: 256 unjittered steps; the froxel
// chain: a froxel a pixel (tile 1), 256 linear slices from 0.01 m. Both march toward the
// light (1 step: exact in homogeneous fog). The answer: per pixel
// L = ∫₀^D e^(−σt·t)·S(t) dt, S from physics/in_scattering.h, by adaptive Simpson (1e-9);
// for HG it matches the CPU reference (reference/, its own integrator) to 1e-5 (measured 1.4e-7).
// Metric: relative mean absolute error, Σ|gpu − L| / Σ|L| over every pixel and channel.
// Measured (both backends alike) for hg, isotropic, rayleigh, schlick, dual_hg — raymarch_fog:
// 3.6e-4, 3.6e-4, 3.3e-4, 3.4e-4, 3.5e-4; froxel chain: 5.4e-4, 4.8e-4, 4.3e-4, 5.5e-4, 3.8e-4
// (fp16 images; the steps and slices across the light's glow on the rays that pass near it).
// Bound: 1.5e-3 for either. The variants' images differ from each other by more than 4× that
// (the closest: hg and Schlick's approximation of it, 1.2e-2 apart).
struct PhaseVariant {
  const char* name;
  int code;
};
const PhaseVariant kPhaseVariants[] = {{"hg", PHASE_HG}, {"isotropic", PHASE_ISOTROPIC}, {"rayleigh", PHASE_RAYLEIGH},
                                       {"schlick", PHASE_SCHLICK}, {"dual_hg", PHASE_DUAL_HG}};
const char* kPointFogCamera = R"({ "position": [0, 1, 0], "target": [0, 1.2, -1], "fov_y_deg": 50, "near": 0.01, "far": 20 })";
const char* kPointFogMedia = R"({ "fog": { "sigma_s": [0.1, 0.1, 0.1], "sigma_a": [0.02, 0.02, 0.02], "g": 0.5 } })";
const char* kPointFogLight = R"([ { "type": "point", "position": [1.5, 2.0, -6.0], "intensity": [20, 18, 15], "cast_shadows": false } ])";
const char* kDualLobes = R"("g_back": -0.4, "w_forward": 0.6)";

// scene → froxel_voxelize → froxel_scatter (`variant`) → scatter_integrate → froxel_apply → composite.
std::string point_fog_froxel_chain(const std::string& variant) {
  std::ostringstream o;
  o << R"({ "output": { "size": [)" << kRaymarchFogWidth << ", " << kRaymarchFogHeight << R"(] },
  "scene": { "camera": )" << kPointFogCamera << R"(, "background": { "radiance": [0, 0, 0] }, "objects": [],
             "lights": )" << kPointFogLight << R"(, "media": )" << kPointFogMedia << R"( },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "fog_media", "type": "froxel_voxelize", "params": { "tile": 1, "slices": 256, "near": 0.01, "far": 20, "distribution": "linear", "jitter": false } },
    { "name": "fog_light", "type": "froxel_scatter", "variant": ")" << variant << R"(", "params": { "shadow_steps": 1, )" << kDualLobes << R"( },
      "inputs": { "media_scattering": "fog_media.media_scattering", "media_emission": "fog_media.media_emission", "frame": "fog_media.frame" } },
    { "name": "fog_integral", "type": "scatter_integrate", "variant": "hillaire",)" << kFroxelChainEnd;
  return o.str();
}

MarchCase point_fog_march(const std::string& variant) {
  MarchCase c;
  c.camera = kPointFogCamera;
  c.media = kPointFogMedia;
  c.lights = kPointFogLight;
  c.march_variant = variant;
  c.march = std::string(R"({ "steps": 256, "shadow_steps": 1, "max_distance": 20, "jitter": false, )") + kDualLobes + " }";
  return c;
}

// The radiance of each pixel (rgb, row 0 at the top) by single scattering along its ray
// to view depth 20, the in-scattering from physics::in_scattering with `phase`.
std::vector<Vec3> single_scattering_image(const Scene& scene, const physics::PhaseChoice& phase) {
  const physics::ViewRays rays = physics::view_rays(scene.camera, double(kRaymarchFogWidth) / kRaymarchFogHeight);
  const Medium& fog = *scene.media.fog;
  const Vec3 sigma_t = physics::add(fog.sigma_s, fog.sigma_a);
  const physics::MediaSample sample{.sigma_s = fog.sigma_s, .sigma_a = fog.sigma_a, .g = fog.g};
  const physics::LightMarch march{.steps = 1};
  std::vector<Vec3> image;
  for (uint32_t j = 0; j < kRaymarchFogHeight; ++j) {
    for (uint32_t i = 0; i < kRaymarchFogWidth; ++i) {
      const Vec3 r = physics::view_ray(rays, (i + 0.5) / kRaymarchFogWidth * 2 - 1, 1 - (j + 0.5) / kRaymarchFogHeight * 2);
      const double length = std::sqrt(physics::dot(r, r));
      const Vec3 direction = physics::scaled(r, 1 / length), to_camera = physics::scaled(direction, -1);
      Vec3 pixel;
      for (size_t ch = 0; ch < 3; ++ch) {
        const auto f = [&](double t) {
          const Vec3 p = physics::add(rays.position, physics::scaled(direction, t));
          const Vec3 s = physics::in_scattering(sample, p, to_camera, phase, scene.lights, {0, 0, 0}, scene.media, march, true);
          return std::exp(-sigma_t[ch] * t) * s[ch];
        };
        pixel[ch] = test::adaptive_simpson(f, 0, 20 * length, 1e-9, 40);
      }
      image.push_back(pixel);
    }
  }
  return image;
}

double relative_mean_error(const Texels& t, const std::vector<Vec3>& want) {
  double difference = 0, total = 0;
  for (uint32_t j = 0; j < kRaymarchFogHeight; ++j) {
    for (uint32_t i = 0; i < kRaymarchFogWidth; ++i) {
      for (size_t ch = 0; ch < 3; ++ch) {
        difference += std::abs(channel(t, i, j, ch) - want[j * kRaymarchFogWidth + i][ch]);
        total += std::abs(want[j * kRaymarchFogWidth + i][ch]);
      }
    }
  }
  return difference / total;
}

TEST_P(RaymarchFog, EveryPhaseVariantAgreesWithTheFroxelChainAndTheSingleScatteringIntegral) {
  std::vector<std::vector<Vec3>> answers;
  for (const PhaseVariant& v : kPhaseVariants) {
    const LoadedConfig march = load(point_fog_march(v.name));
    const Scene& scene = march.config.scene;
    const std::vector<Vec3> want = single_scattering_image(scene, physics::PhaseChoice{v.code, -0.4, 0.6});
    if (v.code == PHASE_HG) {  // the integral here against the reference's own (HG with the medium's g)
      const reference::Renderer renderer(scene);
      const reference::ReferenceImage truth = reference::render_image(renderer, {.width = kRaymarchFogWidth, .height = kRaymarchFogHeight, .threads = 2});
      double difference = 0, total = 0;
      for (uint32_t k = 0; k < kRaymarchFogWidth * kRaymarchFogHeight; ++k) {
        for (size_t ch = 0; ch < 3; ++ch) {
          difference += std::abs(want[k][ch] - truth.at(k % kRaymarchFogWidth, k / kRaymarchFogWidth)[ch]);
          total += std::abs(truth.at(k % kRaymarchFogWidth, k / kRaymarchFogWidth)[ch]);
        }
      }
      std::printf("  single-scattering integral (in_scattering.h) vs the CPU reference, hg: %.2e\n", difference / total);
      EXPECT_LT(difference / total, 1e-5);
    }
    const double marched = relative_mean_error(render(march)[0], want);
    const LoadedConfig froxels = load_config_text("froxels.json", point_fog_froxel_chain(v.name), registry_);
    Executor executor(device(), froxels.graph, &froxels.config.scene, {});
    executor.run_frame();
    const double froxel = relative_mean_error(executor.read_output(0), want);
    std::printf("  phase %-9s vs the integral (relative mean absolute error): raymarch_fog %.2e, froxel chain %.2e\n", v.name, marched,
                froxel);
    EXPECT_LT(marched, 1.5e-3) << v.name;
    EXPECT_LT(froxel, 1.5e-3) << v.name;
    answers.push_back(want);
  }
  // The variants are told apart: each image differs from every other's by more than 4× the bound.
  double closest = 1e9;
  size_t closest_pair[2] = {0, 0};
  for (size_t a = 0; a < answers.size(); ++a) {
    for (size_t b = a + 1; b < answers.size(); ++b) {
      double difference = 0, total = 0;
      for (size_t k = 0; k < answers[a].size(); ++k) {
        for (size_t ch = 0; ch < 3; ++ch) {
          difference += std::abs(answers[a][k][ch] - answers[b][k][ch]);
          total += std::abs(answers[b][k][ch]);
        }
      }
      EXPECT_GT(difference / total, 6e-3) << kPhaseVariants[a].name << " against " << kPhaseVariants[b].name;
      if (difference / total < closest) {
        closest = difference / total;
        closest_pair[0] = a;
        closest_pair[1] = b;
      }
    }
  }
  std::printf("  the closest two variants' images: %s and %s, %.2e apart\n", kPhaseVariants[closest_pair[0]].name,
              kPhaseVariants[closest_pair[1]].name, closest);
}

INSTANTIATE_TEST_SUITE_P(Backends, RaymarchFog, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
