// The scene a config describes (DESIGN.md units: metres, Y up, linear radiance).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "graph/diagnostics.h"
#include "graph/scene_features.h"

namespace volgraph {

using Vec3 = std::array<double, 3>;

struct Transform {
  Vec3 translate{0, 0, 0};
  Vec3 rotate_deg{0, 0, 0};  // applied X, then Y, then Z
  Vec3 scale{1, 1, 1};
};

struct Camera {
  Vec3 position{0, 1, 5};
  Vec3 target{0, 0, 0};
  Vec3 up{0, 1, 0};
  double fov_y_deg = 45;
  double near = 0.1;
  double far = 1000;
};

struct Material {
  std::string name;
  Vec3 albedo{0.8, 0.8, 0.8};
  std::string albedo_texture;  // path as resolved against the config's folder; "" for none
  Vec3 emissive{0, 0, 0};      // radiance
  double transmission = 0;     // > 0: translucent
  double ior = 1.5;
  Where where;
};

enum class Shape : uint8_t { plane, box, sphere, ellipsoid, gltf };

struct Object {
  std::string name;
  Shape shape = Shape::box;
  Vec3 size{1, 1, 1};        // plane: x and z extent; box: edges; sphere: radius in size[0]
  std::string file;          // gltf: path resolved against the config's folder
  std::string material;      // "" for a glTF's own materials
  Transform transform;
  bool cast_shadows = true;
  Where where;
};

enum class LightType : uint8_t { directional, point, spot };

struct Light {
  std::string name;
  LightType type = LightType::directional;
  Vec3 direction{0, -1, 0};  // directional, spot: where the light travels
  Vec3 position{0, 0, 0};    // point, spot
  Vec3 irradiance{0, 0, 0};  // directional: W/m² per channel on a surface facing it
  Vec3 intensity{0, 0, 0};   // point, spot: W/sr per channel
  double inner_cone_deg = 20;
  double outer_cone_deg = 30;
  bool cast_shadows = true;
  Where where;
};

struct Medium {  // σs and σa per channel, 1/m; g for Henyey-Greenstein
  Vec3 sigma_s{0, 0, 0};
  Vec3 sigma_a{0, 0, 0};
  double g = 0;
  Vec3 emission{0, 0, 0};
};

struct HeightFog {
  Medium medium;             // at base_height
  double base_height = 0;    // m
  double falloff = 0.1;      // 1/m: density × exp(−falloff · (y − base_height))
};

// Procedural density inside a local volume: fractal gradient noise (octaves summed at
// doubling frequency and halving amplitude, physics/noise.h defines it exactly)
// mapped to a density multiplier in [0, 1] by `coverage`, times the edge fade; the
// multiplier scales the medium's σs, σa and emission alike. The noise lives in the
// volume's local space (it moves, turns and scales with the volume's transform).
struct Noise {
  int octaves = 0;         // 0: no noise (uniform density); else 1 … 8
  double scale = 1;        // local units (m without a transform scale): the size of the largest features
  double coverage = 1;     // (0, 1]: 1 keeps the whole fBm range; less empties the thin parts
  double edge_fade = 0;    // m: density ramps from 0 at the surface to full this far inside
};

struct MediumVolume {
  Shape shape = Shape::box;  // box, sphere, ellipsoid
  Vec3 size{1, 1, 1};        // box: edges; sphere: radius (first value); ellipsoid: radii
  Transform transform;
  Medium medium;
  Noise noise;
  Where where;
};

struct Media {
  std::optional<Medium> fog;  // global homogeneous
  std::optional<HeightFog> height_fog;
  std::vector<MediumVolume> volumes;
};

struct Scene {
  Camera camera;
  Vec3 background{0, 0, 0};  // radiance
  std::vector<Material> materials;
  std::vector<Object> objects;
  std::vector<Light> lights;
  Media media;

  SceneFeatures features() const;
  // A hash of the parts named (every value in them): equal scenes give equal hashes, and
  // a change to any value in a part changes it (but for collisions, 1 in 2^64).
  uint64_t hash(ScenePartMask parts) const;
  const Material* find_material(const std::string& name) const;
};

}  // namespace volgraph
