// The reference tests' scenes: shipped configs loaded as the command line loads them, and
// small scenes built in code for closed forms.
#pragma once

#include <string>

#include "graph/config/config.h"
#include "passes/passes.h"

namespace volgraph::reference {

// configs/<relative> at width × height.
inline LoadedConfig load_shipped(const std::string& relative, uint32_t width, uint32_t height) {
  PassRegistry registry;
  register_builtin_passes(registry);
  Overrides o;
  o.size = Extent{width, height, 1};
  return load_config(std::string(VOLGRAPH_SOURCE_DIR) + "/configs/" + relative, registry, o);
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

}  // namespace volgraph::reference
