// The reference tests' scenes: shipped configs loaded as the command line loads them, and
// small scenes built in code for closed forms.
#pragma once

#include <string>

#include "graph/config/config.h"
#include "passes/passes.h"
#include "tests/support/source_dir.h"

namespace volgraph::reference {

// configs/<relative> at width × height.
inline LoadedConfig load_shipped(const std::string& relative, uint32_t width, uint32_t height) {
  PassRegistry registry;
  register_builtin_passes(registry);
  Overrides o;
  o.size = Extent{width, height, 1};
  return load_config(std::string(::volgraph::testing::source_dir()) + "/configs/" + relative, registry, o);
}

// A square plane of albedo `albedo` in y = 0 seen from above by a camera at `eye`
// looking at the origin.
inline Scene plane_scene(const Vec3& eye, double albedo, double size = 100) {
  Scene s;
  s.camera.position = eye;
  s.camera.target = {0, 0, 0};
  s.camera.up = {0, 0, -1};
  s.camera.fov_y_deg = 60;
  s.materials.push_back({.name = "grey", .albedo = {albedo, albedo, albedo}});
  s.objects.push_back({.name = "floor", .shape = Shape::plane, .size = {size, 1, size}, .material = "grey"});
  return s;
}

// demo_primitives with fog everywhere, denser near the ground, and a ball of thick fog.
inline void add_demo_fog(Scene& scene) {
  scene.media.fog = Medium{.sigma_s = {0.02, 0.025, 0.03}, .sigma_a = {0.005, 0.005, 0.005}, .g = 0.3};
  scene.media.height_fog = HeightFog{.medium = {.sigma_s = {0.1, 0.1, 0.1}, .sigma_a = {0.01, 0.01, 0.01}, .g = 0.5},
                                     .base_height = 0, .falloff = 1.5};
  MediumVolume ball{.shape = Shape::sphere, .medium = {.sigma_s = {0.6, 0.5, 0.4}, .sigma_a = {0.05, 0.05, 0.05}, .g = -0.2}};
  ball.transform.translate = {0, 1.8, 1};
  ball.size = {0.8, 0.8, 0.8};  // a sphere: radius size[0]
  scene.media.volumes.push_back(ball);
}

}  // namespace volgraph::reference
