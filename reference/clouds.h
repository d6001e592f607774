// The cloud layer on the CPU (docs/clouds.md "CPU reference"): what cloud_march
// (shaders/cloud_march.comp) computes, from the SAME text, with only the quadrature changed.
// - The noise textures are made by the twin of shaders/include/cloud_noise.h at the
//   cloud_noise pass's sizes and stored as the GPU stores them (rgba8 unorm: each channel
//   rounded to the nearest of 255 steps), sampled as cloud_march's `noise` sampler does
//   (trilinear, repeat, level 0) with the same wind and curl offsets.
// - A weather map (scene.clouds.weather_map) is held as cloud_weather_map stores it (the
//   texels of passes/clouds/cloud_weather_map.h, rgba8) and sampled bilinearly with repeat
//   as cloud_layer.glsl does: coverage × r, type mix(the layer's, g, a).
// - The density is cloud_density.h's, the lighting cloud_lighting.h's (dual-lobe HG,
//   Wrenninge's octaves, powder off), the sun's optical depth over the same light_distance.
//   With cloud_phase_table wired into the march, the phase is the table's (the texels the
//   pass uploads, physics/mie), read by cloud_phase_table.h's lookup and cloud_octaves_tabulated.
// - The quadrature: the view segment in `view_steps` equal steps with no empty-space
//   skipping and no early termination, Hillaire's step on each (exact for a density constant
//   on the step); the light march in `light_steps` midpoint samples over light_distance.
//   Its own error: halving both steps changes a pixel by less than kCloudReferenceTolerance
//   (relative to the pixel's radiance, plus 1e-4 of the transmittance), tested by
//   tests/reference/cloud_reference_test.cpp.
// Geometry in double (the layer's spheres on the planet), the texel maths in float (the twin).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "graph/graph.h"
#include "graph/scene/scene.h"
#include "physics/mie.h"

namespace volgraph::reference {

// The reference's own stated error: halving its steps moves a pixel's radiance by less than
// this fraction (tests/reference/cloud_reference_test.cpp, CloudReference.Converges).
inline constexpr double kCloudReferenceTolerance = 2e-3;

// cloud_noise's and cloud_march's parameters the reference uses: their defaults
// (passes/clouds/*.cpp) unless taken from a config's graph (cloud_reference_settings).
struct CloudReferenceSettings {
  int shape_size = 128, detail_size = 32, curl_size = 128;
  uint32_t seed = 0;
  double light_distance = 2000, max_distance = 60000, curl_strength = 0.1;
  int octaves = 3;
  double a = 0.5, b = 0.5, c = 0.5, g_forward = 0.8, g_back = -0.3, back_weight = 0.2;
  Vec3 ambient{0, 0, 0};
  int weather_size = 128;  // cloud_weather_map's size: the weather texture's side (texels)
  // cloud_phase_table's texels when the march reads them (its phase_table input): the phase
  // per channel from the table instead of the dual-lobe HG.
  std::optional<physics::CloudPhaseTable> phase_table;
  double seconds = 0;  // the wind's clock: frame / 60 on the GPU; frame 0 here
  // The quadrature (not the GPU's): equal steps over the view segment and toward the sun.
  int view_steps = 2048, light_steps = 128;
};

// The settings a loaded graph gives: its first cloud_noise's sizes and seed and its first
// cloud_march's parameters (each pass's defaults where the graph has none), the table of the
// cloud_phase_table wired into that march's phase_table, the quadrature of `base`. `params` is LoadedConfig::params (per graph pass).
CloudReferenceSettings cloud_reference_settings(const Graph& graph, const std::vector<std::vector<ParamValue>>& params,
                                                CloudReferenceSettings base = {});

// An rgba8 unorm texture as the GPU holds it: channels quantised, sampled trilinearly with
// repeat wrap (level 0; compute shaders have no derivatives).
class CloudTexture {
 public:
  CloudTexture(int width, int height, int depth) : w_(width), h_(height), d_(depth), texels_(size_t(width) * height * depth) {}
  int width() const { return w_; }
  int height() const { return h_; }
  int depth() const { return d_; }
  // Stores v quantised to 8 bits a channel, as a unorm8 image store rounds.
  void store(int x, int y, int z, const std::array<float, 4>& v);
  const std::array<float, 4>& texel(int x, int y, int z) const { return texels_[index(x, y, z)]; }
  // Trilinear with repeat at normalised uvw (a 2D texture: depth 1, w ignored).
  std::array<float, 4> sample(double u, double v, double w) const;

 private:
  size_t index(int x, int y, int z) const { return (size_t(z) * h_ + size_t(y)) * w_ + size_t(x); }
  int w_, h_, d_;
  std::vector<std::array<float, 4>> texels_;
};

// One unorm8 channel as stored: round(clamp(v, 0, 1) · 255) / 255.
float quantise_unorm8(float v);

// The three cloud_noise textures at the given sizes and seed, texel centres as the shaders.
CloudTexture cloud_shape_texture(int size, uint32_t seed);
CloudTexture cloud_detail_texture(int size, uint32_t seed);
CloudTexture cloud_curl_texture(int size, uint32_t seed);

// What the layer does to a camera ray: C = radiance + transmittance · C_behind.
struct CloudSample {
  Vec3 radiance{0, 0, 0};
  double transmittance = 1;
};

class CloudReference {
 public:
  // The scene must have a cloud layer.
  CloudReference(const Scene& scene, const CloudReferenceSettings& settings = {});
  // The layer along the ray from the camera along unit `direction`, up to `surface` metres
  // (the opaque surface's distance; infinity where none), the first entry into the layer.
  CloudSample along(const Vec3& direction, double surface) const;
  // The layer's density at world point p (cloud_march.comp's density()).
  double density(const Vec3& p) const;
  // The segment [t_in, t_out] of the camera ray inside the layer, false where it misses.
  bool segment(const Vec3& origin, const Vec3& direction, double& t_in, double& t_out) const;
  const CloudTexture& shape() const { return shape_; }
  const CloudTexture& detail() const { return detail_; }
  const CloudTexture& curl() const { return curl_; }
  const CloudReferenceSettings& settings() const { return settings_; }
  // What the brute-force walk (reference/cloud_path_tracer.h) shares with this reference:
  // the layer, the camera, the sun (unit direction toward it, irradiance; `has_sun` false:
  // the ambient alone) and the ambient (the sky's added), and the ground test for the sun.
  const CloudLayer& layer() const { return layer_; }
  const Vec3& camera() const { return camera_; }
  bool has_sun() const { return has_sun_; }
  const Vec3& to_sun() const { return to_sun_; }
  const Vec3& sun_irradiance() const { return sun_irradiance_; }
  bool ground_hides_sun(const Vec3& p) const;

 private:
  double altitude(const Vec3& p) const;
  double sun_optical_depth(const Vec3& p) const;
  std::array<float, 2> coverage_and_type(const Vec3& noise_point) const;
  Vec3 source(const Vec3& p, double rho, double cos_theta) const;

  CloudLayer layer_;
  CloudReferenceSettings settings_;
  Vec3 camera_{0, 0, 0};
  double radius_ = 6360e3, origin_altitude_ = 0;
  bool has_sun_ = false;
  Vec3 to_sun_{0, 1, 0}, sun_irradiance_{0, 0, 0};
  CloudTexture shape_, detail_, curl_;
  std::optional<CloudTexture> weather_;  // cloud_weather_map's texture, when the layer has a weather map
};

}  // namespace volgraph::reference
