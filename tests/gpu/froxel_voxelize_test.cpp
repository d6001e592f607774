// froxel_voxelize averages the media over each froxel (shaders/include/media_average.glsl
// ↔ physics/media_average.h), on both backends, where physics gives the answer:
// - an absorbing slab seen face-on (its faces at constant view depth, neither on a slice
//   boundary at 64, 128 or 256 slices), through the froxel chain (voxelize → scatter →
//   integrate → apply) with one froxel per pixel, so each pixel reads its own column:
//   the background behind it is e^(−σa·L·|ray|) exactly, L the thickness and |ray| the
//   pixel ray's length per metre of view depth. Each froxel holds σa times the fraction
//   of its depth range inside the slab, so the chain's optical depth is the exact one at
//   every slice count; what is left is rgba16f storage (transmittance and colour, 2^−11
//   relative each): largest relative error over the image ≤ 2e-3 at 64, 128 and 256
//   slices (measured 8.1e-4, 9.0e-4, 9.0e-4). Exact at each count, the error has no
//   discretisation left to fall: the bound holds at every count instead. Point-sampled
//   froxels (full or empty by their centre) moved each face to a slice boundary: 6.5 %
//   and 6.2 % off at 64 and 128 slices, 9.0e-4 at 256 where the two faces' errors cancel.
// - a noise volume (3 octaves, features of 0.5 to 2 m in froxels 1 m deep): the mean of
//   froxel_voxelize's σs over 1, 4, 16 and 64 jittered frames (the jitter moves each
//   froxel's ray across it and its depth sub-samples along it; froxel_temporal blends the
//   frames so) against each froxel's exact average — the density integrated over its
//   footprint and depth range on the CPU (physics/media_field.h; 3 × 3 rays × 64 steps,
//   1.5e-3 from 6 × 6 × 128). Metric: relative mean absolute error Σ|a − ref| / Σ|ref| over
//   the volume's rgb: measured 1.5 %, 2.4 %, 1.2 %, 0.52 % (frame 0's centred strata are a
//   midpoint rule, better than the first few jittered frames; from 4 frames on it falls);
//   centre samples gave 21.6 %, 12.9 %, 4.8 %, 2.2 %.
#include <cmath>
#include <cstdio>
#include <sstream>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/camera.h"
#include "physics/froxel.h"
#include "physics/media_field.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/froxel_chain_json.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

const char* kCamera = R"({ "position": [0, 1, 0], "target": [0, 1, -1], "fov_y_deg": 50, "near": 0.1, "far": 1000 })";

// The slab: faces at view depths 4.55 and 10.6125 m, in a linear grid from 0.5 to 16.5 m
// (slice boundaries every 0.25 m at 64 slices: the faces at 0.2 and 0.45 of a slice, at
// 0.4 and 0.9 at 128, at 0.8 and 0.8 at 256). σa is exact in fp16.
constexpr double kSlabNear = 4.55, kSlabFar = 10.6125;
constexpr double kSlabSigmaA[3] = {0.25, 0.5, 0.75};
constexpr uint32_t kSlabWidth = 32, kSlabHeight = 18;

std::string slab_config(int slices) {
  std::ostringstream o;
  o << R"({ "output": { "size": [)" << kSlabWidth << ", " << kSlabHeight << R"(] },
  "scene": { "camera": )" << kCamera << R"(, "background": { "radiance": [1, 1, 1] },
    "media": { "volumes": [ { "shape": "box", "size": [400, 400, )" << kSlabFar - kSlabNear << R"(],
      "sigma_s": [0, 0, 0], "sigma_a": [)" << kSlabSigmaA[0] << ", " << kSlabSigmaA[1] << ", " << kSlabSigmaA[2] << R"(],
      "transform": { "translate": [0, 1, )" << -(kSlabNear + kSlabFar) / 2 << R"(] } } ] } },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "fog_media", "type": "froxel_voxelize",
      "params": { "tile": 1, "slices": )" << slices << R"(, "near": 0.5, "far": 16.5, "distribution": "linear", "jitter": false } },
    { "name": "fog_light", "type": "froxel_scatter", "variant": "isotropic",
      "inputs": { "media_scattering": "fog_media.media_scattering", "media_emission": "fog_media.media_emission", "frame": "fog_media.frame" } },
    { "name": "fog_integral", "type": "scatter_integrate", "variant": "hillaire",)" << kFroxelChainEnd;
  return o.str();
}

// The noise volume: froxels of one pixel (0.12 m across at 6 m) and 1 m deep, so the
// noise (features 0.5 to 2 m) varies most along each froxel's depth.
constexpr uint32_t kNoiseWidth = 48, kNoiseHeight = 36, kNoiseTile = 1, kNoiseSlices = 8;
constexpr double kNoiseGridNear = 2, kNoiseGridFar = 10, kNoiseSigmaS = 0.8;
const char* kNoiseMedia = R"({ "volumes": [ { "shape": "box", "size": [6, 4, 4], "sigma_s": [0.8, 0.8, 0.8], "sigma_a": [0, 0, 0],
    "noise": { "octaves": 3, "scale": 2, "coverage": 0.7 }, "transform": { "translate": [0, 1, -6] } } ] })";

std::string noise_config() {
  std::ostringstream o;
  o << R"({ "output": { "size": [)" << kNoiseWidth << ", " << kNoiseHeight << R"(] },
  "scene": { "camera": )" << kCamera << R"(, "media": )" << kNoiseMedia << R"( },
  "graph": { "passes": [
    { "name": "fog_media", "type": "froxel_voxelize",
      "params": { "tile": )" << kNoiseTile << R"(, "slices": )" << kNoiseSlices << R"(, "near": )" << kNoiseGridNear << R"(, "far": )"
    << kNoiseGridFar << R"(, "distribution": "linear", "jitter": true } } ],
    "outputs": ["fog_media.media_scattering"] } })";
  return o.str();
}

// Each froxel's σs averaged over its footprint (rays × rays stratified across the column,
// uniform in NDC as the jitter is) and its depth range along each ray (`steps` midpoints,
// uniform in view depth as the sub-samples are): the value the jittered frames converge
// to. rgba like the media_scattering volume (rgb σs, a unused).
std::vector<float> exact_noise_froxels(const Scene& scene, int rays, int steps) {
  const physics::MediaField field(scene.media);
  const physics::ViewRays view = physics::view_rays(scene.camera, double(kNoiseWidth) / kNoiseHeight);
  const uint32_t columns_x = kNoiseWidth / kNoiseTile, columns_y = kNoiseHeight / kNoiseTile;
  const physics::FroxelRange range{kNoiseGridNear, kNoiseGridFar, physics::FroxelDistribution::linear};
  std::vector<float> out;
  for (uint32_t k = 0; k < kNoiseSlices; ++k) {
    const double t0 = physics::froxel_depth(range, double(k) / kNoiseSlices), t1 = physics::froxel_depth(range, double(k + 1) / kNoiseSlices);
    for (uint32_t y = 0; y < columns_y; ++y) {
      for (uint32_t x = 0; x < columns_x; ++x) {
        double sum = 0;
        for (int a = 0; a < rays; ++a) {
          for (int b = 0; b < rays; ++b) {
            const double u = (x + (a + 0.5) / rays) / columns_x, v = (y + (b + 0.5) / rays) / columns_y;
            const glm::dvec3 ray = physics::vec(physics::view_ray(view, u * 2 - 1, 1 - v * 2));
            for (int s = 0; s < steps; ++s) {
              const double t = t0 + (t1 - t0) * (s + 0.5) / steps;
              sum += field.volume_density(0, physics::to_vec3(physics::vec(view.position) + t * ray));
            }
          }
        }
        const float sigma_s = float(kNoiseSigmaS * sum / (double(rays) * rays * steps));
        out.insert(out.end(), {sigma_s, sigma_s, sigma_s, 0.0f});
      }
    }
  }
  return out;
}

// The relative mean absolute error of the rgb of `got` against `want`.
double rgb_error(const std::vector<float>& got, const std::vector<float>& want) {
  double difference = 0, total = 0;
  for (size_t i = 0; i < want.size(); ++i) {
    if (i % 4 == 3) continue;
    difference += std::abs(double(got[i]) - want[i]);
    total += std::abs(double(want[i]));
  }
  return difference / total;
}

class FroxelVoxelize : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(const std::string& text) { return load_config_text("voxelize.json", text, registry_); }
  PassRegistry registry_;
};

// Largest relative error of the background seen through the slab, against Beer–Lambert.
double slab_error(const LoadedConfig& config, const Texels& t) {
  const physics::ViewRays view = physics::view_rays(config.config.scene.camera, double(kSlabWidth) / kSlabHeight);
  double worst = 0;
  for (uint32_t j = 0; j < kSlabHeight; ++j) {
    for (uint32_t i = 0; i < kSlabWidth; ++i) {
      const Vec3 ray = physics::view_ray(view, (i + 0.5) / kSlabWidth * 2 - 1, 1 - (j + 0.5) / kSlabHeight * 2);
      const double length = (kSlabFar - kSlabNear) * std::sqrt(physics::dot(ray, ray));
      for (size_t ch = 0; ch < 3; ++ch) {
        const double want = std::exp(-kSlabSigmaA[ch] * length);
        worst = std::max(worst, std::abs(t.rgba[4 * (j * kSlabWidth + i) + ch] - want) / want);
      }
    }
  }
  return worst;
}

TEST_P(FroxelVoxelize, AnAbsorbingSlabSeenFaceOnTransmitsExactlyAtEverySliceCount) {
  for (int slices : {64, 128, 256}) {
    const LoadedConfig config = load(slab_config(slices));
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    const double error = slab_error(config, executor.read_output(0));
    std::printf("absorbing slab, %d slices: largest relative error %.2e\n", slices, error);
    EXPECT_LE(error, 2e-3) << slices << " slices";
  }
}

// The mean of the frames' σs volumes, as froxel_temporal's blend holds it on a still
// camera while its first frames weigh equally (its rgba16f history is left out here).
TEST_P(FroxelVoxelize, JitteredFramesConvergeToTheFroxelAverageOfANoiseVolume) {
  LoadedConfig config = load(noise_config());
  const std::vector<float> exact = exact_noise_froxels(config.config.scene, 3, 64);
  Executor executor(device(), config.graph, &config.config.scene, {});
  std::vector<double> sum(exact.size(), 0.0);
  std::vector<double> errors;
  for (int frame = 1; frame <= 64; ++frame) {
    executor.run_frame();
    const Texels t = executor.read_output(0);
    ASSERT_EQ(t.rgba.size(), exact.size());
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += t.rgba[i];
    if (frame != 1 && frame != 4 && frame != 16 && frame != 64) continue;
    std::vector<float> mean(sum.size());
    for (size_t i = 0; i < sum.size(); ++i) mean[i] = float(sum[i] / frame);
    errors.push_back(rgb_error(mean, exact));
    std::printf("noise volume, %d frames: relative mean error %.4f\n", frame, errors.back());
  }
  // Bounds about twice the measured errors; centre samples miss every one of them.
  EXPECT_LT(errors[0], 0.03);  // frame 0: the centre ray, each stratum's centre
  EXPECT_LT(errors[1], 0.04);
  EXPECT_LT(errors[2], errors[1]);
  EXPECT_LT(errors[3], errors[2]);
  EXPECT_LT(errors[3], 0.01);
}

INSTANTIATE_TEST_SUITE_P(Backends, FroxelVoxelize, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
