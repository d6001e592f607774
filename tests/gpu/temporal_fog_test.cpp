// Temporal accumulation (froxel_temporal, pixel_temporal) on both backends, frames run
// one after another under validation (history pairs swapped every frame). Metric where
// not exact: relative mean absolute error Σ|a − ref| / Σ|ref| over RGB
// (tests/support/image_compare.h).
// - the first frame is this frame's value, bit for bit (so --frames 1 changes nothing);
// - the blend follows its CPU twin (physics/temporal.h) frame by frame on a still
//   camera: with jitter off every frame is the same and so is the blend, and the first
//   frames' weights 1, 1/2, 1/3 … give equal averages;
// - a still camera converges: the froxel in-scattering blended over N jittered frames
//   (froxel_voxelize's Halton jitter) follows the running mean of those frames and comes
//   closer to the average of 128 jittered frames, far below a single jittered frame's
//   error; the same for raymarch_fog's per-pixel jittered steps against the average of a
//   full cycle of its noise;
// - reprojection: after the camera moves (the test moves the scene's camera between
//   frames), the history read where the last frame saw each point lands on the fresh
//   volume or images at the new camera — exactly where the medium varies smoothly (height
//   fog, the camera rising), up to resampling on a sharp feature (a hard-edged sphere, a
//   box's edges); read at the same texel instead (reproject off) it does not;
// - stress scenes over several frames, the camera moving: no NaN or Inf in the history.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/rhi/device_error.h"
#include "passes/passes.h"
#include "physics/temporal.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/fog_scenes.h"
#include "tests/gpu/shipped_configs.h"
#include "tests/support/fog_accuracy.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kTemporalFogWidth = 64, kTemporalFogHeight = 48;

// A hard-edged fog sphere lit by a point light beside it: in-scattering that changes
// sharply inside a froxel (the sphere's edge, the light's 1/d²), where jitter matters.
const char* kSphereMedia = R"({ "volumes": [ { "shape": "sphere", "size": [3, 3, 3], "sigma_s": [0.8, 0.8, 0.8],
                                              "sigma_a": [0.05, 0.05, 0.05], "transform": { "translate": [0, 1, -5] } } ] })";
const char* kPointLight = R"([ { "type": "point", "position": [1.6, 2.2, -3.5], "intensity": [20, 20, 20] } ])";

std::string camera_at(double x) {
  std::ostringstream o;
  o << R"({ "position": [)" << x << R"(, 1, 0], "target": [)" << x << R"(, 1, -1], "fov_y_deg": 50, "near": 0.1, "far": 100 })";
  return o.str();
}

struct FroxelCase {
  std::string media = kSphereMedia;
  std::string lights = kPointLight;
  std::string grid = R"({ "tile": 4, "slices": 32, "near": 0.5, "far": 12, "distribution": "linear", "jitter": true })";
  std::string temporal = "{}";
};

// froxel_voxelize → froxel_scatter → froxel_temporal; outputs: the blended volume (0)
// and this frame's (1). The volumes' march toward the lights is off (shadow_steps 0): these
// cases measure the blend of voxelize's jitter alone, which the march's own would mix into.
std::string froxel_config(const FroxelCase& c) {
  std::ostringstream o;
  o << R"({ "output": { "size": [)" << kTemporalFogWidth << ", " << kTemporalFogHeight << R"(] },
  "scene": { "camera": )" << camera_at(0) << R"(, "lights": )" << c.lights << R"(, "media": )" << c.media << R"( },
  "graph": { "passes": [
    { "name": "fog_media", "type": "froxel_voxelize", "params": )" << c.grid << R"( },
    { "name": "fog_light", "type": "froxel_scatter", "variant": "isotropic", "params": { "shadow_steps": 0 },
      "inputs": { "media_scattering": "fog_media.media_scattering", "media_emission": "fog_media.media_emission", "frame": "fog_media.frame" } },
    { "name": "fog_temporal", "type": "froxel_temporal", "params": )" << c.temporal << R"(,
      "inputs": { "in_scatter": "fog_light.in_scatter", "frame": "fog_media.frame" } } ],
    "outputs": ["fog_temporal.accumulated", "fog_light.in_scatter"] } })";
  return o.str();
}

struct PixelCase {
  std::string march = R"({ "steps": 8, "max_distance": 12, "jitter": true })";
  std::string temporal = "{}";
  std::string lights = kPointLight;
  std::string objects = R"([ { "name": "ground", "shape": "plane", "size": [40, 1, 40], "material": "grey" },
                             { "name": "box", "shape": "box", "size": [1, 1.5, 1], "material": "grey",
                               "transform": { "translate": [-1.2, 0.75, -4] } } ])";
  std::string media = R"({ "height_fog": { "sigma_s": [0.3, 0.3, 0.3], "sigma_a": [0.02, 0.02, 0.02], "base_height": 0, "falloff": 0.8 },
                           "volumes": [ { "shape": "sphere", "size": [2, 2, 2], "sigma_s": [1, 1, 1], "sigma_a": [0, 0, 0],
                                          "transform": { "translate": [1, 1.2, -6] } } ] })";
};

// scene → raymarch_fog → pixel_temporal; outputs: the blended in-scattering (0) and
// transmittance (1), this frame's (2, 3).
std::string pixel_config(const PixelCase& c) {
  std::ostringstream o;
  o << R"({ "output": { "size": [)" << kTemporalFogWidth << ", " << kTemporalFogHeight << R"(] },
  "scene": { "camera": )" << camera_at(0) << R"(, "lights": )" << c.lights << R"(,
             "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } }, "objects": )" << c.objects << R"(, "media": )" << c.media << R"( },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "fog_march", "type": "raymarch_fog", "params": )" << c.march << R"(, "inputs": { "depth": "lit.depth" } },
    { "name": "fog_temporal", "type": "pixel_temporal", "params": )" << c.temporal << R"(,
      "inputs": { "depth": "lit.depth", "fog_scattering": "fog_march.fog_scattering", "fog_transmittance": "fog_march.fog_transmittance" } } ],
    "outputs": ["fog_temporal.scattering", "fog_temporal.transmittance", "fog_march.fog_scattering", "fog_march.fog_transmittance"] } })";
  return o.str();
}

double error(const Texels& a, const Texels& reference) { return compare_images(a.rgba, reference.rgba).relative_mean_error; }

// The graph's outputs, in order, after each frame.
class Frames {
 public:
  Frames(rhi::Device& device, LoadedConfig& config) : config_(config), executor_(device, config.graph, &config.config.scene, {}) {
    for (uint32_t o = 0; o < config.graph.outputs.size(); ++o) outputs_.push_back(config.graph.outputs[o].resource);
  }
  std::vector<Texels> next() {
    std::vector<Texels> out;
    for (Readback& r : executor_.run_frame_and_read(outputs_)) out.push_back(std::move(r.texels));
    return out;
  }
  Camera& camera() { return config_.config.scene.camera; }  // the executor reads it every frame
  const Plan& plan() const { return executor_.plan(); }

 private:
  LoadedConfig& config_;
  Executor executor_;
  std::vector<uint32_t> outputs_;
};

// Errors against `reference` of single frames (their mean) and of the blend at each
// checkpoint, printed on one line after `what`.
struct Convergence {
  double single = 0;
  std::vector<double> blended;
};

Convergence convergence(const char* what, const std::vector<Texels>& single, const std::vector<Texels>& blended,
                        const std::vector<int>& checkpoints, const Texels& reference) {
  Convergence c;
  for (const Texels& s : single) c.single += error(s, reference) / double(single.size());
  std::printf("%s: one jittered frame %.4f (mean of %zu)", what, c.single, single.size());
  for (size_t i = 0; i < blended.size(); ++i) {
    c.blended.push_back(error(blended[i], reference));
    std::printf(", %d frames %.4f", checkpoints[i], c.blended.back());
  }
  std::printf("\n");
  return c;
}

class TemporalFog : public OnEachBackend<> {
 public:
  LoadedConfig load(const std::string& text) { return load_config_text("temporal.json", text, registry_); }
  using OnEachBackend::device;

 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  PassRegistry registry_;
};

TEST_P(TemporalFog, TheHistoryPairIsPersistentOwnMemoryAndTheFirstFrameIsThisFramesValue) {
  LoadedConfig config = load(froxel_config({}));
  Frames frames(device(), config);
  uint32_t pairs = 0;
  for (uint32_t r = 0; r < config.graph.resources.size(); ++r) {
    const GraphResource& res = config.graph.resources[r];
    if (res.previous == kNone && res.previous_of == kNone) continue;
    ++pairs;
    EXPECT_TRUE(res.desc.persistent) << res.desc.name;
    EXPECT_EQ(frames.plan().placements[r].heap, kNone) << res.desc.name;
  }
  EXPECT_EQ(pairs, 2u);
  const std::vector<Texels> first = frames.next();
  EXPECT_TRUE(first[0].rgba.size() == first[1].rgba.size());
  for (size_t k = 0; k < first[0].rgba.size(); k += 4) {
    for (size_t ch = 0; ch < 3; ++ch) ASSERT_EQ(first[0].rgba[k + ch], first[1].rgba[k + ch]) << "texel " << k / 4;
    ASSERT_EQ(first[0].rgba[k + 3], 1.0f) << "one frame";
  }
}

// Jitter off: every frame's volume is the same, so the blend must stay that volume
// (to fp16) while the frame count climbs 1, 2, … to the cap ⌈1/alpha⌉ = 4 and stays.
TEST_P(TemporalFog, AStillCameraWithoutJitterKeepsTheValueWhileTheCountFollowsTheTwin) {
  FroxelCase c;
  c.grid = R"({ "tile": 8, "slices": 16, "near": 0.5, "far": 12, "distribution": "linear", "jitter": false })";
  c.temporal = R"({ "alpha": 0.25 })";
  LoadedConfig config = load(froxel_config(c));
  Frames frames(device(), config);
  physics::Accumulated<float> twin{};
  for (int f = 0; f < 6; ++f) {
    const std::vector<Texels> t = frames.next();
    twin = physics::temporal_blend(1.0f, twin, f > 0, 0.25f);
    ASSERT_EQ(twin.value, 1.0f);
    EXPECT_LE(error(t[0], t[1]), 1e-3) << "frame " << f;
    for (size_t k = 3; k < t[0].rgba.size(); k += 4) ASSERT_EQ(t[0].rgba[k], twin.frames) << "frame " << f << " texel " << k / 4;
  }
  EXPECT_EQ(twin.frames, 4.0f);
}

// The froxel in-scattering of frames 0 … 127 (Halton jitter) averaged is the reference;
// alpha 1/64 makes the blend an equal average of the first 64 frames: it must follow
// the running mean of the frames it has seen (to fp16 rounding, which accumulates) and
// come closer to the reference with frames. Halton points do not converge monotonically
// (measured: 16 frames are a little farther than 4 here), so the trend is checked from
// 1 to 4 to 64, and 16 frames against one jittered frame.
TEST_P(TemporalFog, AStillCameraConvergesToTheAverageOfManyJitteredFroxelSamples) {
  FroxelCase c;
  c.temporal = R"({ "alpha": 0.015625 })";
  LoadedConfig config = load(froxel_config(c));
  Frames frames(device(), config);
  const int kFrames = 128;
  const std::vector<int> checkpoints = {1, 4, 16, 64};
  std::vector<Texels> blended, single;
  Texels mean, running;
  for (int f = 0; f < kFrames; ++f) {
    std::vector<Texels> t = frames.next();
    if (f == 0) {
      mean = running = t[1];
      std::fill(mean.rgba.begin(), mean.rgba.end(), 0.0f);
      std::fill(running.rgba.begin(), running.rgba.end(), 0.0f);
    }
    for (size_t k = 0; k < mean.rgba.size(); ++k) {
      mean.rgba[k] += t[1].rgba[k] / kFrames;
      running.rgba[k] += (t[1].rgba[k] - running.rgba[k]) / float(f + 1);
    }
    if (std::find(checkpoints.begin(), checkpoints.end(), f + 1) != checkpoints.end()) {
      blended.push_back(t[0]);
      EXPECT_LT(error(t[0], running), f < 16 ? 5e-3 : 2e-2) << "the blend of " << f + 1 << " frames against their mean";
    }
    if (f >= 1 && f <= 8) single.push_back(t[1]);
  }
  const Convergence measured = convergence("froxel in-scattering vs the 128-frame average", single, blended, checkpoints, mean);
  const std::vector<double>& errors = measured.blended;
  EXPECT_LT(errors[1], 0.8 * errors[0]) << "4 frames against 1 (the unjittered centre)";
  EXPECT_LT(errors[3], 0.5 * errors[1]) << "64 frames against 4";
  EXPECT_LT(errors[2], 0.35 * measured.single) << "16 frames against one jittered frame";
  EXPECT_LT(errors[3], 0.15 * measured.single) << "64 frames against one jittered frame";
}

// With the default alpha (0.1) the blend of 16 frames is also well below one frame.
TEST_P(TemporalFog, TheDefaultBlendOf16FramesBeatsOneJitteredFrame) {
  LoadedConfig config = load(froxel_config({}));
  Frames frames(device(), config);
  std::vector<std::vector<Texels>> all;
  Texels mean;
  const int kFrames = 64;
  for (int f = 0; f < kFrames; ++f) {
    std::vector<Texels> t = frames.next();
    if (f == 0) {
      mean = t[1];
      std::fill(mean.rgba.begin(), mean.rgba.end(), 0.0f);
    }
    for (size_t k = 0; k < mean.rgba.size(); ++k) mean.rgba[k] += t[1].rgba[k] / kFrames;
    if (f == 15) all.push_back(t);
  }
  const double one = error(all[0][1], mean), sixteen = error(all[0][0], mean);
  std::printf("default alpha: frame 15 alone %.4f, blended over 16 frames %.4f\n", one, sixteen);
  EXPECT_LT(sixteen, 0.5 * one);
}

// The whole froxel chain (configs/graphs/froxel_fog.json: froxel_temporal before
// scatter_integrate and froxel_apply) on the oracle fog sphere (configs/tests/) against
// the CPU reference (tests/support/fog_accuracy.h metric: every pixel sees fog only
// here). With jitter on and alpha 1/64, 16 blended frames average each froxel's
// footprint: far closer than one jittered frame alone (measured 8.4 % against 24.2 % at
// frame 15 with alpha 1, no accumulation). Frame 0's centre rays are closer still (6.8 %):
// froxel_voxelize averages the sphere's chord along each ray exactly, so what jitter adds
// on this hard-edged sphere is the footprint's lateral average, a column-wide blur of its
// silhouette under the bilinear lookup.
TEST_P(TemporalFog, TheFroxelChainOverFramesComesCloserToTheCpuReference) {
  Overrides o;
  o.sets = {"fog_media.jitter=true", "fog_temporal.alpha=0.015625"};
  LoadedConfig config = accuracy::load_linear(config_path("tests/oracle_fog_sphere.json"), registry_, o);
  const reference::ReferenceImage reference = accuracy::render_reference(config);
  const std::vector<bool> fog_only = accuracy::fog_only_pixels(config.config.scene, config.config.output_size.width,
                                                               config.config.output_size.height);
  Frames frames(device(), config);
  const double one = accuracy::compare_fog(frames.next()[0], reference, fog_only).difference.relative_mean_error;
  for (int f = 1; f < 15; ++f) frames.next();
  const double sixteen = accuracy::compare_fog(frames.next()[0], reference, fog_only).difference.relative_mean_error;
  o.sets.back() = "fog_temporal.alpha=1";
  LoadedConfig unblended = accuracy::load_linear(config_path("tests/oracle_fog_sphere.json"), registry_, o);
  Frames alone(device(), unblended);
  for (int f = 0; f < 15; ++f) alone.next();
  const double jittered = accuracy::compare_fog(alone.next()[0], reference, fog_only).difference.relative_mean_error;
  std::printf("froxel chain vs the CPU reference (oracle fog sphere): 1 frame %.4f, 16 jittered frames blended %.4f, frame 15 alone %.4f\n",
              one, sixteen, jittered);
  EXPECT_LT(sixteen, 0.5 * jittered);
  EXPECT_LT(sixteen, 0.1);
}

// Ten frames at one camera, then one after the camera moved: the result is 0.9 × the
// history read where the last frame saw each froxel's centre + 0.1 × this frame's (the
// blend holds ten frames, the cap at alpha 0.1). Jitter off, so the history is exactly
// the last camera's volume; compared with the fresh volume at the new camera.
std::array<double, 2> froxel_move_errors(TemporalFog& test, FroxelCase c, const Vec3& move) {
  std::array<double, 2> errors{};
  for (const bool reproject : {true, false}) {
    c.temporal = std::string(R"({ "reproject": )") + (reproject ? "true" : "false") + " }";
    LoadedConfig config = test.load(froxel_config(c));
    Frames frames(test.device(), config);
    for (int f = 0; f < 10; ++f) frames.next();
    for (size_t i = 0; i < 3; ++i) {
      frames.camera().position[i] += move[i];
      frames.camera().target[i] += move[i];
    }
    const std::vector<Texels> moved = frames.next();
    errors[reproject ? 0 : 1] = error(moved[0], moved[1]);
  }
  return errors;
}

// Height fog (σs ∝ e^(−0.3·y)) under a directional light: in-scattering depends on the
// height alone, nearly linearly across a froxel. The camera rises 0.5 m: reprojected,
// each froxel reads the history at its own height (what remains is the exponential's
// curvature across a froxel and fp16: measured 0.26 %); read at the same froxel, 0.5 m
// lower (measured 14.5 %).
TEST_P(TemporalFog, AfterTheCameraRisesTheReprojectedFroxelHistoryIsThatOfTheSameHeight) {
  FroxelCase c;
  c.media = R"({ "height_fog": { "sigma_s": [0.3, 0.3, 0.3], "sigma_a": [0.02, 0.02, 0.02], "base_height": 0, "falloff": 0.3 } })";
  c.lights = R"([ { "type": "directional", "direction": [0.3, -1, 0.2], "irradiance": [3, 3, 3], "cast_shadows": false } ])";
  c.grid = R"({ "tile": 4, "slices": 32, "near": 0.5, "far": 12, "distribution": "linear", "jitter": false })";
  const std::array<double, 2> e = froxel_move_errors(*this, c, {0, 0.5, 0});
  std::printf("froxel history after a 0.5 m rise (height fog): reprojected %.5f, not reprojected %.5f\n", e[0], e[1]);
  EXPECT_LT(e[0], 5e-3);
  EXPECT_GT(e[1], 20 * e[0]);
}

// The sharp feature: the hard-edged sphere and the point light's 1/d² peak, after a
// 0.9 m move sideways (32×24×32 froxels). Reprojected, the history lands; what remains
// is trilinear resampling of the sphere's edge (measured 4.3 %; 16 % at 16×12 froxels).
// Read at the same froxel, the old view is shifted by several froxels (measured 104 %).
TEST_P(TemporalFog, AfterTheCameraMovesTheReprojectedFroxelHistoryLandsOnASharpFeature) {
  FroxelCase c;
  c.grid = R"({ "tile": 2, "slices": 32, "near": 0.5, "far": 12, "distribution": "linear", "jitter": false })";
  const std::array<double, 2> e = froxel_move_errors(*this, c, {0.9, 0, 0});
  std::printf("froxel history after a 0.9 m move (fog sphere): reprojected %.4f, not reprojected %.4f\n", e[0], e[1]);
  EXPECT_LT(e[0], 0.07);
  EXPECT_LT(e[0], 0.1 * e[1]);
}

// pixel_temporal: a homogeneous fog under a directional light, where each image depends
// on the distance to the surface alone (Hillaire's step is exact at any step count), over
// a box in front of a wall. The camera moves 0.3 m sideways (the box ~4 pixels, the wall
// ~2): reprojected by the depth, the history lands on the box's edges, and the wall it
// uncovers starts afresh (the history's depth disagrees) — measured 0.20 % (in-scattering)
// and 1.8 % (transmittance: the ray to a point changes length with the camera, e^(−σt·Δd));
// read at the same pixel, the edges are where they were: 1.5 % and 12.7 %.
TEST_P(TemporalFog, AfterTheCameraMovesTheReprojectedPixelHistoryLandsOnTheEdges) {
  std::array<double, 2> scattering{}, transmittance{};
  for (const bool reproject : {true, false}) {
    PixelCase c;
    c.march = R"({ "steps": 16, "max_distance": 12, "jitter": false })";
    c.temporal = std::string(R"({ "reproject": )") + (reproject ? "true" : "false") + " }";
    c.lights = R"([ { "type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3], "cast_shadows": false } ])";
    c.media = R"({ "fog": { "sigma_s": [0.25, 0.25, 0.25], "sigma_a": [0.05, 0.05, 0.05] } })";
    c.objects = R"([ { "name": "box", "shape": "box", "size": [1, 1.5, 1], "material": "grey", "transform": { "translate": [-0.3, 1, -4] } },
                     { "name": "wall", "shape": "box", "size": [30, 30, 0.2], "material": "grey", "transform": { "translate": [0, 0, -8] } } ])";
    LoadedConfig config = load(pixel_config(c));
    Frames frames(device(), config);
    for (int f = 0; f < 10; ++f) frames.next();
    frames.camera().position[0] = frames.camera().target[0] = 0.3;
    const std::vector<Texels> moved = frames.next();
    scattering[reproject ? 0 : 1] = error(moved[0], moved[2]);
    transmittance[reproject ? 0 : 1] = error(moved[1], moved[3]);
  }
  std::printf("pixel history after a 0.3 m move (box before a wall): in-scattering reprojected %.4f, not %.4f; "
              "transmittance reprojected %.4f, not %.4f\n", scattering[0], scattering[1], transmittance[0], transmittance[1]);
  EXPECT_LT(scattering[0], 5e-3);
  EXPECT_LT(scattering[0], 0.25 * scattering[1]);
  EXPECT_LT(transmittance[0], 0.03);
  EXPECT_LT(transmittance[0], 0.25 * transmittance[1]);
}

// raymarch_fog with 8 jittered steps (interleaved gradient noise, scrolled every frame,
// a cycle of 64 frames): the average of one cycle of raw frames is the reference (the
// jittered march's expected value); blended over frames (alpha 1/64) the error falls.
TEST_P(TemporalFog, AStillCameraConvergesForThePerPixelMarch) {
  PixelCase c;
  c.temporal = R"({ "alpha": 0.015625 })";
  LoadedConfig config = load(pixel_config(c));
  Frames frames(device(), config);
  const int kFrames = 64;
  const std::vector<int> checkpoints = {1, 4, 16, 64};
  std::vector<Texels> blended, single;
  Texels mean;
  for (int f = 0; f < kFrames; ++f) {
    std::vector<Texels> t = frames.next();
    if (f == 0) {
      mean = t[2];
      std::fill(mean.rgba.begin(), mean.rgba.end(), 0.0f);
    }
    for (size_t k = 0; k < mean.rgba.size(); ++k) mean.rgba[k] += t[2].rgba[k] / kFrames;
    if (std::find(checkpoints.begin(), checkpoints.end(), f + 1) != checkpoints.end()) blended.push_back(t[0]);
    if (f < 8) single.push_back(t[2]);
  }
  const Convergence measured = convergence("raymarch, 8 jittered steps, vs the 64-frame average", single, blended, checkpoints, mean);
  const std::vector<double>& errors = measured.blended;
  for (size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], 0.6 * errors[i - 1]) << checkpoints[i] << " frames";
  EXPECT_LT(errors[2], 0.35 * measured.single) << "16 frames against one frame";
  EXPECT_LT(errors[3], 0.02) << "the 64-frame blend is the 64-frame average, to fp16";
}

// Stress media over twelve frames with jitter, the camera moving each frame: no NaN or
// Inf in the blended volume or images, which are also the next frame's histories.
TEST_P(TemporalFog, StressScenesLeaveNoNanOrInfInTheHistoryOverManyFrames) {
  for (const char* m : kStressMedia) {
    FroxelCase froxels;
    froxels.media = m;
    froxels.lights = kStressLights;
    froxels.grid = R"({ "tile": 8, "slices": 16, "near": 0.001, "far": 100000, "distribution": "exponential", "jitter": true })";
    PixelCase pixels;
    pixels.media = m;
    pixels.lights = kStressLights;
    pixels.march = R"({ "steps": 8, "max_distance": 100000, "jitter": true })";
    for (const std::string& text : {froxel_config(froxels), pixel_config(pixels)}) {
      LoadedConfig config = load(text);
      Frames frames(device(), config);
      for (int f = 0; f < 12; ++f) {
        frames.camera().position[2] = frames.camera().target[2] = -0.1 * f;
        const std::vector<Texels> t = frames.next();
        for (size_t o = 0; o < 2; ++o) {
          for (size_t k = 0; k < t[o].rgba.size(); ++k) {
            ASSERT_TRUE(std::isfinite(t[o].rgba[k])) << "frame " << f << " output " << o << " value " << k << " of " << m;
          }
        }
      }
    }
  }
}

// With alpha 1 the blend is this frame's value exactly, so a pass reading the blended
// output must see what a twin pass reading this frame's value directly sees — on every
// frame, also the odd ones, where the history pairs' objects are the other way round
// (a pass that kept frame 0's bind group would read last frame's). scatter_integrate
// after froxel_temporal, and fog_apply after pixel_temporal, with jitter on.
TEST_P(TemporalFog, PassesAfterATemporalPassReadThisFramesObjectOfTheHistoryPair) {
  const std::string froxels = R"({ "output": { "size": [32, 24] },
  "scene": { "camera": )" + camera_at(0) + R"(, "lights": )" + kPointLight + R"(, "media": )" + kSphereMedia + R"( },
  "graph": { "passes": [
    { "name": "fog_media", "type": "froxel_voxelize", "params": { "slices": 16, "near": 0.5, "far": 12, "jitter": true } },
    { "name": "fog_light", "type": "froxel_scatter",
      "inputs": { "media_scattering": "fog_media.media_scattering", "media_emission": "fog_media.media_emission", "frame": "fog_media.frame" } },
    { "name": "fog_temporal", "type": "froxel_temporal", "params": { "alpha": 1 },
      "inputs": { "in_scatter": "fog_light.in_scatter", "frame": "fog_media.frame" } },
    { "name": "through", "type": "scatter_integrate",
      "inputs": { "in_scatter": "fog_temporal.accumulated", "media_scattering": "fog_media.media_scattering",
                  "media_absorption": "fog_media.media_absorption", "frame": "fog_media.frame" } },
    { "name": "direct", "type": "scatter_integrate",
      "inputs": { "in_scatter": "fog_light.in_scatter", "media_scattering": "fog_media.media_scattering",
                  "media_absorption": "fog_media.media_absorption", "frame": "fog_media.frame" } } ],
    "outputs": ["through.integrated_scattering", "direct.integrated_scattering"] } })";
  PixelCase pixel_case;
  const std::string pixels = R"({ "output": { "size": [32, 24] },
  "scene": { "camera": )" + camera_at(0) + R"(, "lights": )" + kPointLight + R"(,
             "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } }, "objects": )" + pixel_case.objects + R"(, "media": )" + pixel_case.media + R"( },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "lit_too", "type": "scene" },
    { "name": "fog_march", "type": "raymarch_fog", "params": { "steps": 8, "max_distance": 12 }, "inputs": { "depth": "lit.depth" } },
    { "name": "fog_temporal", "type": "pixel_temporal", "params": { "alpha": 1 },
      "inputs": { "depth": "lit.depth", "fog_scattering": "fog_march.fog_scattering", "fog_transmittance": "fog_march.fog_transmittance" } },
    { "name": "through", "type": "fog_apply",
      "inputs": { "color": "lit.color", "fog_scattering": "fog_temporal.scattering", "fog_transmittance": "fog_temporal.transmittance" } },
    { "name": "direct", "type": "fog_apply",
      "inputs": { "color": "lit_too.color", "fog_scattering": "fog_march.fog_scattering", "fog_transmittance": "fog_march.fog_transmittance" } } ],
    "outputs": ["through.color", "direct.color"] } })";
  for (const std::string& text : {froxels, pixels}) {
    LoadedConfig config = load(text);
    Frames frames(device(), config);
    for (int f = 0; f < 4; ++f) {
      const std::vector<Texels> t = frames.next();
      ASSERT_TRUE(t[0].rgba == t[1].rgba) << "frame " << f << " of " << config.graph.passes.back().decl->name;
    }
  }
}

// A pass that binds a history pair's output (composite reading pixel_temporal's
// `scattering`, whose object swaps with its history every frame) sees this frame's object
// every frame: its bind groups come from the device's cache by content, so on odd frames
// it gets the group of the other object. Composite `none` copies its input exactly, so
// each frame's output equals that frame's scattering; had it kept frame 0's group it
// would show the last frame's (the camera moves, so the two differ).
TEST_P(TemporalFog, APassReadingAHistoryPairSeesThisFramesObject) {
  const std::string text = R"({ "output": { "size": [32, 24] },
  "scene": { "camera": )" + camera_at(0) + R"(, "media": { "fog": { "sigma_s": [0.1, 0.1, 0.1], "sigma_a": [0, 0, 0] } },
             "lights": [ { "type": "point", "position": [0, 2, -3], "intensity": [20, 20, 20] } ] },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "fog_march", "type": "raymarch_fog", "inputs": { "depth": "lit.depth" } },
    { "name": "fog_temporal", "type": "pixel_temporal",
      "inputs": { "depth": "lit.depth", "fog_scattering": "fog_march.fog_scattering", "fog_transmittance": "fog_march.fog_transmittance" } },
    { "name": "out", "type": "composite", "variant": "none", "inputs": { "color": "fog_temporal.scattering" } } ],
    "outputs": ["out.output", "fog_temporal.scattering"] } })";
  LoadedConfig config = load(text);
  Frames frames(device(), config);
  std::vector<float> last_frame;
  for (int f = 0; f < 4; ++f) {
    frames.camera().position[0] = 0.3 * f;
    frames.camera().target[0] = 0.3 * f;
    const std::vector<Texels> out = frames.next();
    ASSERT_EQ(out[0].rgba.size(), out[1].rgba.size());
    for (size_t i = 0; i < out[0].rgba.size(); i += 4) {
      for (size_t k = 0; k < 3; ++k) ASSERT_EQ(out[0].rgba[i + k], out[1].rgba[i + k]) << "frame " << f << " texel " << i / 4;
    }
    EXPECT_NE(out[1].rgba, last_frame) << "frame " << f << " repeats the last: the test would not see a stale group";
    last_frame = out[1].rgba;
  }
}

// The shipped fog demos (their graphs now accumulate over frames) at the GPU tests' size,
// six frames with the camera moving: validation silent (TearDown), histories swapped and
// read by scatter_integrate and fog_apply through bind groups from the device's cache, and the
// output finite.
TEST_P(TemporalFog, TheFogDemosRunFrameAfterFrameWithAMovingCamera) {
  for (const char* demo : {"demo_fog.json", "demo_godrays.json", "demo_raymarch_fog.json"}) {
    Overrides o;
    o.size = kConfigTestSize;
    LoadedConfig config = load_config(config_path(demo), registry_, o);
    Frames frames(device(), config);
    for (int f = 0; f < 6; ++f) {
      frames.camera().position[0] += 0.05;
      const Texels t = frames.next()[0];
      for (size_t k = 0; k < t.rgba.size(); ++k) ASSERT_TRUE(std::isfinite(t.rgba[k])) << demo << " frame " << f;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, TemporalFog, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
