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

// How a material's coverage α is used (glTF 2.0 alphaMode): ignored, cut at a threshold
// (texels below it are holes, in the shadow maps too), or blended.
enum class AlphaMode : uint8_t { opaque, mask, blend };

// What lies beneath a transmitting surface (KHR_materials_volume's thickness): nothing
// (thin-walled: the light is tinted at the surface alone), a shell `thickness` m thick
// crossed at the refracted angle, or a solid object whose path is measured along the
// ray (to its back faces, or to an opaque surface inside it).
enum class VolumeKind : uint8_t { thin_walled, shell, solid };

// How a surface passes light (RTR4 §14.5; glTF 2.0 alphaMode, KHR_materials_transmission,
// _ior and _volume): coverage α, and a dielectric interface of index `ior` through which
// a fraction `transmission` of the light not reflected passes, tinted by the albedo and
// attenuated inside by Beer–Lambert with σt per channel = −ln(attenuation_color) /
// attenuation_distance (RTR4 eq. 14.23). A surface is translucent (drawn by the
// translucency passes, not the opaque scene) when it blends or transmits.
struct Translucency {
  double alpha = 1;  // coverage, 0–1
  AlphaMode alpha_mode = AlphaMode::opaque;
  double alpha_cutoff = 0.5;  // mask: coverage below it is a hole
  double transmission = 0;    // 0–1 of the light the interface does not reflect
  double ior = 1.5;
  double dispersion = 0;  // KHR_materials_dispersion: 20/V_d (Abbe number), 0 = one IOR for all channels
  Vec3 attenuation_color{1, 1, 1};     // transmittance after attenuation_distance inside
  double attenuation_distance = 1e30;  // m (1e30: no absorption)
  VolumeKind volume = VolumeKind::thin_walled;
  double thickness = 0;  // m: the shell's; solid: the path where no back faces are measured
  double roughness = 0;  // the interface's (glTF's roughnessFactor, 0–1): blurs what a solid refracts (a mip chain behind it)
  bool translucent() const { return alpha_mode == AlphaMode::blend || transmission > 0; }
};

// A surface's material: Lambertian reflection of albedo ρ, emission, and how it passes light.
struct Material {
  std::string name;
  Vec3 albedo{0.8, 0.8, 0.8};
  std::string albedo_texture;  // path as resolved against the config's folder; "" for none
  Vec3 emissive{0, 0, 0};      // radiance
  Translucency translucency;
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
  // gltf: whether any primitive's material is translucent (filled in after the scene is
  // read by the registry's scene annotator, passes/plumbing/gltf.h: graph/ reads no glTF).
  bool translucent_in_file = false;
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

// One layer of an atmosphere's density profile (Bruneton 2017, DensityProfileLayer): at
// altitude h (m) inside the layer, density = exp_term · e^(exp_scale · h) + linear_term · h
// + constant_term, clamped to [0, 1].
struct DensityLayer {
  double width = 0;  // m: the layer's thickness (the upper layer's is ignored: it goes to the top)
  double exp_term = 0;
  double exp_scale = 0;      // 1/m
  double linear_term = 0;    // 1/m
  double constant_term = 0;
};

// Two layers: `lower` from the ground to its width, `upper` above it (Bruneton 2017).
struct DensityProfile {
  DensityLayer lower, upper;
};

enum class MiePhase : uint8_t { henyey_greenstein, cornette_shanks };

// A planet's atmosphere (Bruneton 2017's model, as Hillaire 2020 uses it): a spherical
// ground of `bottom_radius`, air up to `top_radius`, Rayleigh scattering, Mie scattering
// and absorption, and an absorbing (ozone) layer, each a coefficient at density 1 times its
// profile. Its sun is the scene's directional light `sun_light`: that light's direction,
// and its irradiance as it arrives at the top of the atmosphere. The scene's y = 0 is
// `origin_altitude` above the ground, straight above the planet's centre: the camera's
// altitude is origin_altitude + its y. The defaults are the `earth` preset (Bruneton 2017's
// demo constants, which Hillaire 2020 uses).
struct Atmosphere {
  std::string preset = "earth";  // "earth", "mars" or "custom": what the values started from
  double bottom_radius = 6360e3;  // m
  double top_radius = 6420e3;     // m
  Vec3 rayleigh_scattering{5.802e-6, 13.558e-6, 33.1e-6};  // 1/m at density 1
  DensityProfile rayleigh_density{{}, {0, 1, -1.0 / 8000, 0, 0}};  // e^(−h / 8 km)
  Vec3 mie_scattering{3.996e-6, 3.996e-6, 3.996e-6};  // 1/m
  Vec3 mie_extinction{4.44e-6, 4.44e-6, 4.44e-6};     // 1/m (scattering + absorption)
  DensityProfile mie_density{{}, {0, 1, -1.0 / 1200, 0, 0}};  // e^(−h / 1.2 km)
  double mie_g = 0.8;
  MiePhase mie_phase = MiePhase::cornette_shanks;
  Vec3 absorption_extinction{0.650e-6, 1.881e-6, 0.085e-6};  // 1/m (ozone)
  DensityProfile absorption_density{{25e3, 0, 0, 1.0 / 15e3, -2.0 / 3}, {0, 0, 0, -1.0 / 15e3, 8.0 / 3}};  // tent 10–25–40 km
  Vec3 ground_albedo{0.3, 0.3, 0.3};
  double origin_altitude = 0;        // m: the scene's y = 0 above the ground
  int sun_light = -1;                // index into Scene::lights (a directional light); -1: none
  double sun_angular_radius = 0.004675;  // rad
  Where where;
};

// A weather map over the cloud layer (Schneider & Vos 2015): an image tiled over the ground
// plane, r the coverage multiplier (coverage here = the layer's coverage × r), g the cloud
// type where the image has colour channels (a grey image: the layer's type everywhere).
struct CloudWeatherMap {
  std::string image;                   // path as resolved against the config's folder
  double size = 20000;                 // m: the ground the image spans (it tiles)
  std::array<double, 2> offset{0, 0};  // m: added to (x, z) before the lookup
  Where where;                         // where the config gives the map
};

// A layer of clouds between two altitudes above the ground (Schneider & Vos 2015; RTR4
// 14.4.2), on the atmosphere's spherical planet (Earth's 6360 km without one). Its density
// is the base shape × the height signal of `type` × `coverage`, eroded by the detail noise;
// its medium scatters without absorbing (albedo 1: σs = σt), σt = `extinction` × density.
struct CloudLayer {
  double bottom_altitude = 1500;  // m above the ground
  double top_altitude = 4000;     // m above the ground
  double coverage = 0.5;          // [0, 1]: the sky's fraction the layer covers
  double type = 0.5;              // [0, 1]: 0 stratus, 0.5 cumulus, 1 cumulonimbus (the height signal)
  double extinction = 0.08;       // 1/m at density 1 (measured: stratus 0.04–0.06, cumulus 0.05–0.12)
  double shape_scale = 20000;     // m: the shape noise's tile, horizontally and vertically
  double detail_scale = 2000;     // m: the detail noise's tile
  Vec3 wind{10, 0, 0};            // m/s: the noise's drift with time
  std::optional<CloudWeatherMap> weather_map;  // none: one coverage and type everywhere
  Where where;                    // where the config gives the layer
};

// A scalar volume file for volume_file (scene.volume_data; RTR4 14.3.1): a NRRD file, or a
// headerless .raw file whose layout `raw_*` gives. The samples map to [0, 1] through
// `window` (low, high) when set, else the sample type's range.
struct VolumeData {
  std::string file;                          // resolved against the config's folder
  std::optional<std::array<double, 2>> window;
  bool raw = false;                          // a .raw file: the layout below
  std::string raw_type = "uchar";            // uchar, ushort, short, float
  std::array<int64_t, 3> raw_sizes{1, 1, 1};
  std::array<double, 3> raw_spacing{1, 1, 1};
  bool raw_big_endian = false;
  std::string transfer_2d;                   // a 2D transfer table's image (transfer_table), resolved; "" none
  Where where;                               // where the config gives it
};

struct Scene {
  Camera camera;
  Vec3 background{0, 0, 0};  // radiance
  std::vector<Material> materials;
  std::vector<Object> objects;
  std::vector<Light> lights;
  Media media;
  std::optional<Atmosphere> atmosphere;  // none: no sky, no aerial perspective
  std::optional<CloudLayer> clouds;      // none: no cloud passes, no cloud noise
  std::optional<VolumeData> volume_data; // none: no volume file for volume_file

  SceneFeatures features() const;
  // A hash of the parts named (every value in them): equal scenes give equal hashes, and
  // a change to any value in a part changes it (but for collisions, 1 in 2^64).
  uint64_t hash(ScenePartMask parts) const;
  const Material* find_material(const std::string& name) const;
  // The sun: the atmosphere's sun light, else the first directional light; none: −1.
  int sun_light() const;
};

}  // namespace volgraph
