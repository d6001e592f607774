// Every fog technique against the CPU reference on the oracle scenes
// (configs/tests/oracle_*.json: media and lights, no surfaces, so only the fog is
// compared — tests/support/fog_accuracy.h states the metric and the exclusions), on
// Vulkan (lavapipe) under the validation layer:
// - each technique within its stated bound of relative mean error per oracle scene;
// - the froxel chain converges toward the reference as its grid grows: more slices, and
//   more columns (a larger frame);
// - on dense fog (optical depth 8.75) Hillaire's integration step errs less than
//   Wronski's at equal slices;
// - a negative control: a sun 5 % dimmer on the GPU fails the global fog's bound.
// - a heterogeneous (noisy) volume: raymarch_fog and the froxel chain against the reference.
// A technique is one row of kTechniques (its graph and its bound per scene; the closed
// forms only on the scenes they model); the oracle scenes are the rows of kOracles.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "passes/passes.h"
#include "tests/accuracy/vulkan_accuracy_test.h"
#include "tests/gpu/backends.h"
#include "tests/support/fog_accuracy.h"
#include "tests/support/source_dir.h"

namespace volgraph::testing {
namespace {

const std::string kTestConfigs = std::string(::volgraph::testing::source_dir()) + "/configs/tests/";

const char* const kOracles[] = {"oracle_global_fog.json", "oracle_height_fog.json", "oracle_fog_sphere.json",
                                "oracle_dense_fog.json", "oracle_point_fog.json", "oracle_shadowed_fog.json"};
constexpr size_t kOracleCount = std::size(kOracles);

constexpr double kNotApplicable = -1;  // a technique's bound on a scene it cannot render

// A fog technique as the harness renders it: the graph fragment included after the
// oracle scene ("" keeps the froxel chain the oracles include), the overrides that pick
// its variants and settings, and the bound on its relative mean error per oracle scene
// (kOracles order), with why the bound is what it is.
struct Technique {
  std::string name;
  std::string graph;
  Overrides overrides;
  double bound[kOracleCount];
  std::string why;
};

const Technique kTechniques[] = {
    {"froxel_hillaire", "", {.variants = {"fog_integral=hillaire"}}, {0.02, 0.05, 0.2, 0.02, 0.2, 0.25},
     "x, y: one froxel column per 8×8 pixels, blended bilinearly — smooth in homogeneous fog (the phase function "
     "varies across a column), coarse where the height fog's density changes with the ray's elevation, coarsest at "
     "the hard-edged sphere's silhouette and across the point light's glow, which peaks inside a column (12×8 columns "
     "there: 10 %) and across the spot's shadow shaft (13 %: the shaft is about a column wide); z: 64 slices, exact per homogeneous slice; "
     "fp16 volumes"},
    {"raymarch_fog", "../graphs/raymarch_fog.json",
     {.sets = {"fog_march.resolution=full", "fog_march.steps=256", "fog_march.shadow_steps=64", "fog_march.max_distance=1000",
               "fog_march.jitter=false"}},
     {0.005, 0.005, 0.02, 0.005, 0.01, 0.02},
     "256 midpoint steps to the far plane per pixel, 64 toward the light: the reference's adaptive integral to "
     "quadrature error, except across the sphere's hard edges (a step straddles them) and the point light's peak; "
     "fp16 outputs; with shadows, the 2048² shadow map against exact rays (0.6 %)"},
    {"analytic_fog", "../graphs/analytic_fog.json", {}, {0.005, kNotApplicable, kNotApplicable, 0.005, 0.005, kNotApplicable},
     "closed form for a directional light in homogeneous fog (exact); the point light's airlight integral by "
     "Gauss–Legendre quadrature (8 panels × 8 nodes); fp16 outputs. Needs a global fog"},
    {"light_volume", "../graphs/light_volume_fog.json", {}, {0.01, kNotApplicable, kNotApplicable, 0.01, 0.01, 0.005},
     "without shadows no volume is drawn: each pixel's closed-form (directional) or Gauss–Legendre (point, spot) "
     "integral to the far plane; with the spot's shadow, the 512² hard shadow map against exact rays (0.14 %); fp16 "
     "outputs. Needs a homogeneous global fog"},
    {"height_fog", "../graphs/height_fog.json", {}, {kNotApplicable, 0.005, kNotApplicable, kNotApplicable, kNotApplicable, kNotApplicable},
     "closed-form optical depth along the view ray and in-scattering with the sun dimmed by the fog above each point "
     "(as the reference), exact; fp16 outputs (measured 0.035 %). Needs height fog"},
};

// The oracle config, with the technique's graph included after it when it has one.
LoadedConfig load_oracle(const std::string& oracle, const Technique& technique, const PassRegistry& registry) {
  if (technique.graph.empty()) return accuracy::load_linear(kTestConfigs + oracle, registry, technique.overrides);
  const std::string text = R"({ "include": [")" + oracle + R"(", ")" + technique.graph + R"("] })";
  return accuracy::load_linear_text(kTestConfigs + "accuracy_" + technique.name + ".json", text, registry,
                                    technique.overrides);
}

// The reference side of a comparison, computed once per scene and size.
struct Reference {
  reference::ReferenceImage image;
  std::vector<bool> fog_only;
};

Reference reference_of(const LoadedConfig& loaded) {
  const Extent size = loaded.config.output_size;
  return {accuracy::render_reference(loaded), accuracy::fog_only_pixels(loaded.config.scene, size.width, size.height)};
}

Overrides froxel_overrides(int slices, const std::string& variant, std::optional<Extent> size = std::nullopt) {
  return {.size = size, .sets = {"fog_media.slices=" + std::to_string(slices)}, .variants = {"fog_integral=" + variant}};
}

class FogAccuracy : public VulkanAccuracyTest {
 protected:

  LoadedConfig froxel_oracle(const std::string& oracle, const Overrides& overrides) {
    return load_oracle(oracle, {"froxel", "", overrides}, registry_);
  }
  // `loaded` rendered on the GPU against the reference over its fog-only pixels.
  accuracy::FogComparison compare(const LoadedConfig& loaded, const Reference& ref) {
    return accuracy::compare_fog(accuracy::render_gpu(gpu_->device(), loaded), ref.image, ref.fog_only);
  }
  // Relative mean error of `loaded`, printed with what it was.
  double error_of(const LoadedConfig& loaded, const Reference& ref, const std::string& what) {
    const accuracy::FogComparison c = compare(loaded, ref);
    std::printf("  %s: %s\n", what.c_str(), c.describe().c_str());
    return c.difference.relative_mean_error;
  }

};

TEST_F(FogAccuracy, EveryTechniqueIsWithinItsBoundOnEveryOracleScene) {
  for (const Technique& technique : kTechniques) {
    for (size_t s = 0; s < kOracleCount; ++s) {
      if (technique.bound[s] == kNotApplicable) continue;
      const LoadedConfig loaded = load_oracle(kOracles[s], technique, registry_);
      const accuracy::FogComparison c = compare(loaded, reference_of(loaded));
      std::printf("  %s on %s: %s (bound %.3g)\n", technique.name.c_str(), kOracles[s], c.describe().c_str(), technique.bound[s]);
      EXPECT_EQ(c.compared_pixels, c.pixels) << kOracles[s] << ": an oracle scene has no surfaces";
      EXPECT_EQ(c.difference.non_finite, 0u) << technique.name << " on " << kOracles[s];
      EXPECT_LE(c.difference.relative_mean_error, technique.bound[s])
          << technique.name << " on " << kOracles[s] << ": relative mean error over the fog-only pixels (" << technique.why << ")";
    }
  }
}

// Depth resolution: on the fog sphere (hard edges along every ray through it) the
// error must fall at every doubling of the slices from 16 to 128. froxel_voxelize holds
// the exact fraction of each froxel's depth inside the sphere, so its edges cost no
// slices; what depth leaves is the light's variation across a froxel (lit at its centre).
// One froxel per pixel, so that the columns' footprint (the next test) does not hide it.
TEST_F(FogAccuracy, FroxelChainConvergesTowardTheReferenceAsSlicesGrow) {
  const Reference ref = reference_of(froxel_oracle("oracle_fog_sphere.json", {}));
  double previous = 0;
  for (int slices : {16, 32, 64, 128}) {
    Overrides o = froxel_overrides(slices, "hillaire");
    o.sets.push_back("fog_media.tile=1");
    const LoadedConfig loaded = froxel_oracle("oracle_fog_sphere.json", o);
    const double error = error_of(loaded, ref, "fog sphere, hillaire, " + std::to_string(slices) + " slices");
    if (slices > 16) EXPECT_LT(error, previous) << slices << " slices: relative mean error must fall as slices double";
    previous = error;
  }
}

// Screen resolution: the grid's columns are 1/8 of the output in x and y (there is no
// parameter for it), so the grid grows in x and y with the frame: 6×4, 12×8, 24×16
// columns. Each pixel is compared, so the error must fall as the columns shrink.
TEST_F(FogAccuracy, FroxelChainConvergesTowardTheReferenceAsColumnsShrink) {
  double previous = 0;
  for (uint32_t width : {48u, 96u, 192u}) {
    const Extent size{width, width * 2 / 3, 1};
    const LoadedConfig loaded = froxel_oracle("oracle_fog_sphere.json", froxel_overrides(64, "hillaire", size));
    const double error = error_of(loaded, reference_of(loaded), "fog sphere, 64 slices, " + std::to_string(width / 8) + " columns across");
    if (width > 48) EXPECT_LT(error, previous) << width / 8 << " columns across: relative mean error must fall as columns shrink";
    previous = error;
  }
}

TEST_F(FogAccuracy, HillaireErrsLessThanWronskiAtEqualSlicesOnDenseFog) {
  const Reference ref = reference_of(froxel_oracle("oracle_dense_fog.json", {}));
  for (int slices : {16, 32, 64}) {
    const std::string at = ", " + std::to_string(slices) + " slices";
    const double hillaire = error_of(froxel_oracle("oracle_dense_fog.json", froxel_overrides(slices, "hillaire")), ref, "dense fog, hillaire" + at);
    const double wronski = error_of(froxel_oracle("oracle_dense_fog.json", froxel_overrides(slices, "wronski")), ref, "dense fog, wronski" + at);
    EXPECT_LT(hillaire, wronski) << slices << " slices: relative mean error, dense fog (optical depth 8.75)";
  }
}

// The metric and bound can fail: the GPU renders the global fog oracle under a sun 5 %
// dimmer than the reference's, which must exceed the froxel chain's bound there.
TEST_F(FogAccuracy, ASunFivePercentDimmerOnTheGpuFailsTheBound) {
  const Technique& froxel = kTechniques[0];
  const LoadedConfig truth = load_oracle(kOracles[0], froxel, registry_);
  LoadedConfig dimmer = load_oracle(kOracles[0], froxel, registry_);
  for (double& e : dimmer.config.scene.lights.at(0).irradiance) e *= 0.95;
  const double error = error_of(dimmer, reference_of(truth), "global fog, sun 5 % dimmer on the GPU");
  EXPECT_GT(error, froxel.bound[0]);
}

// A heterogeneous medium (oracle_noise_volume: fBm noise with coverage and an edge fade,
// scattering, absorbing and emitting, the light attenuated through it): the noise reaches
// every technique through media_field.glsl, the reference through its CPU twin.
// - raymarch_fog, full resolution, 256 unjittered steps (3.5 cm, a third of the finest
//   octave's cell), 64 steps toward the light: within 0.5 % (measured 0.04 %);
// - the froxel chain (128 linear slices of 3.9 cm, 64 shadow steps) converges as its
//   columns shrink — 4, 2, 1 pixels a column (measured 9.4 %, 3.2 %, 0.09 %; 256 slices
//   change none of them: each column blends the medium trilinearly across the volume's
//   silhouette and the noise's features, which is what limits it) — within 5 % at 2 pixels
//   and 0.5 % at 1;
// - negative control: the volume without its noise on the GPU is far off (measured 42 %).
TEST_F(FogAccuracy, NoisyVolumeRaymarchedAndFroxelizedAgainstTheReference) {
  const Reference ref = reference_of(froxel_oracle("oracle_noise_volume.json", {}));
  const Technique raymarch{"raymarch_noise", "../graphs/raymarch_fog.json",
                           {.sets = {"fog_march.steps=256", "fog_march.shadow_steps=64", "fog_march.max_distance=9",
                                     "fog_march.shadow_distance=5", "fog_march.jitter=false", "fog_march.resolution=full"}},
                           {}, "per-pixel march"};
  const double raymarch_error = error_of(load_oracle("oracle_noise_volume.json", raymarch, registry_), ref,
                                         "noisy volume, raymarch_fog 256 steps");
  EXPECT_LT(raymarch_error, 0.005) << "raymarch_fog on the noisy volume: relative mean error";

  double previous = 1;
  for (const auto& [tile, bound] : {std::pair{4, 1.0}, {2, 0.05}, {1, 0.005}}) {
    const Overrides overrides{.sets = {"fog_media.tile=" + std::to_string(tile)}};
    const double error = error_of(froxel_oracle("oracle_noise_volume.json", overrides), ref,
                                  "noisy volume, froxel chain, " + std::to_string(tile) + "-pixel columns");
    EXPECT_LT(error, previous) << tile << "-pixel columns: relative mean error must fall as columns shrink";
    EXPECT_LT(error, bound) << tile << "-pixel columns: relative mean error";
    previous = error;
  }

  LoadedConfig uniform = froxel_oracle("oracle_noise_volume.json", {});
  uniform.config.scene.media.volumes[0].noise.octaves = 0;
  EXPECT_GT(error_of(uniform, ref, "the volume without its noise on the GPU"), 0.2);
}

TEST(FogAccuracyHarness, PixelsSeeingASurfaceAndTheirNeighboursAreNotCompared) {
  PassRegistry registry;
  register_builtin_passes(registry);
  const LoadedConfig loaded = accuracy::load_linear(kTestConfigs + "lambert_plane.json", registry);
  const std::vector<bool> fog_only = accuracy::fog_only_pixels(loaded.config.scene, 8, 8);
  EXPECT_EQ(std::count(fog_only.begin(), fog_only.end(), true), 0) << "the plane fills the frame";
  Scene sky = loaded.config.scene;
  sky.objects.clear();
  const std::vector<bool> all = accuracy::fog_only_pixels(sky, 8, 8);
  EXPECT_EQ(std::count(all.begin(), all.end(), true), 64) << "nothing but background";
}

}  // namespace
}  // namespace volgraph::testing
