// Temporal accumulation's shared fixture (froxel_temporal_test.cpp, pixel_temporal_test.cpp,
// temporal_fog_test.cpp): frames run one after another under validation, the froxel graph
// (froxel_voxelize → froxel_scatter → froxel_temporal) and the per-pixel one (scene →
// raymarch_fog → pixel_temporal) with their cases, the error metric and the convergence
// record. Helpers are the fixture's members, so the files a unity build batches together
// share no namespace-scope names.
#pragma once

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {

class TemporalFogFixture : public OnEachBackend<> {
 public:
  static constexpr uint32_t kTemporalFogWidth = 64, kTemporalFogHeight = 48;

  // A hard-edged fog sphere lit by a point light beside it: in-scattering that changes
  // sharply inside a froxel (the sphere's edge, the light's 1/d²), where jitter matters.
  static constexpr const char* kSphereMedia = R"({ "volumes": [ { "shape": "sphere", "size": [3, 3, 3], "sigma_s": [0.8, 0.8, 0.8],
                                                "sigma_a": [0.05, 0.05, 0.05], "transform": { "translate": [0, 1, -5] } } ] })";
  static constexpr const char* kPointLight = R"([ { "type": "point", "position": [1.6, 2.2, -3.5], "intensity": [20, 20, 20] } ])";

  static std::string camera_at(double x) {
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
  static std::string froxel_config(const FroxelCase& c) {
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
  static std::string pixel_config(const PixelCase& c) {
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

  static double error(const Texels& a, const Texels& reference) { return compare_images(a.rgba, reference.rgba).relative_mean_error; }

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

  static Convergence convergence(const char* what, const std::vector<Texels>& single, const std::vector<Texels>& blended,
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

}  // namespace volgraph::testing
