// pixel_temporal on both backends, frames run one after another under validation; the graph
// scene → raymarch_fog → pixel_temporal. After the camera moves the reprojected history lands
// on the edges (read at the same pixel instead it does not); a still camera converges: the
// march's per-pixel jittered steps blended over N frames come closer to the average of a full
// cycle of its noise. Fixture: temporal_fog.h.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "physics/temporal.h"
#include "tests/gpu/temporal_fog.h"

namespace volgraph::testing {
namespace {

class PixelTemporal : public TemporalFogFixture {};

// pixel_temporal: a homogeneous fog under a directional light, where each image depends
// on the distance to the surface alone (Hillaire's step is exact at any step count), over
// a box in front of a wall. The camera moves 0.3 m sideways (the box ~4 pixels, the wall
// ~2): reprojected by the depth, the history lands on the box's edges, and the wall it
// uncovers starts afresh (the history's depth disagrees) — measured 0.20 % (in-scattering)
// and 1.8 % (transmittance: the ray to a point changes length with the camera, e^(−σt·Δd));
// read at the same pixel, the edges are where they were: 1.5 % and 12.7 %.
TEST_P(PixelTemporal, AfterTheCameraMovesTheReprojectedPixelHistoryLandsOnTheEdges) {
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
TEST_P(PixelTemporal, AStillCameraConvergesForThePerPixelMarch) {
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

INSTANTIATE_TEST_SUITE_P(Backends, PixelTemporal, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
