// The shared physics includes (shaders/include/phase.glsl, media.glsl, airlight.glsl,
// light_volume_integral.glsl; and temporal accumulation's view_rays.glsl, froxel.glsl,
// temporal_blend.glsl) on lavapipe, on each backend, against their CPU twins in float
// (physics/phase.h, media.h, airlight.h, light_volume_integral.h), over a table that
// covers the traps (g → ±1, x → 0, dense and empty media, huge distances): relative
// error ≤ 2e-5 (GLSL lets exp be off by 3 + 2|x| ULP; our twins use the same formulas).
// The noise (noise.glsl ↔ noise.h in float, same inputs) and the media field
// (media_field.glsl ↔ media_field.h in double, noisy volumes) at many points: bounds at
// NoiseAndMediaFieldMatchTheirCpuTwins. The in-scattering sum (in_scattering.glsl ↔
// in_scattering.h in double): bound at InScatteringMatchesItsCpuTwin.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <span>
#include <vector>


#include <gtest/gtest.h>

#include "graph/access.h"
#include "passes/fog/fog_frame.h"
#include "physics/airlight.h"
#include "physics/in_scattering.h"
#include "physics/light_volume_integral.h"
#include "physics/media_average.h"
#include "physics/media_field.h"
#include "physics/noise.h"
#include "physics/media.h"
#include "physics/phase.h"
#include "physics/temporal.h"
#include "physics/translucency.h"
#include "shaders/include/phase_codes.h"
#include "graph/rhi/spirv_reflect.h"
#include "tests/gpu/shaders/gpu_test_shaders.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/twin_shader.h"
#include "tests/support/random_graph.h"

namespace volgraph::testing {
namespace {

struct Case {
  float g, cos_theta, t_c, h;
  float x, sigma_t, dz, falloff;
  float origin_y, direction_y, length, air_sigma_t;
};

std::vector<Case> cases() {
  const float gs[] = {-0.999f, -0.5f, 0.0f, 0.3f, 0.9f, 0.99f, 0.999f};
  const float cosines[] = {-1.0f, -0.5f, 0.0f, 0.5f, 0.99f, 0.99999f, 1.0f};
  const float xs[] = {0.0f, 1e-9f, 1e-6f, 1e-3f, 0.00999f, 0.0101f, 0.3f, 5.0f, -3.0f, 1e4f};
  const float sigmas[] = {0.0f, 1e-7f, 1e-3f, 0.5f, 20.0f, 1e4f};
  const float dzs[] = {1e-3f, 0.25f, 3.0f, 1e3f, 1e5f};
  const float falloffs[] = {1e-6f, 0.05f, 0.5f, 3.0f};
  const float directions[] = {-1.0f, -0.3f, 0.0f, 0.2f, 1.0f};
  // Airlight geometry (t_c, h, length, σt), with σt·(t + d) ≤ ~10 so exp's ULPs stay small.
  const float t_cs[] = {-3.0f, 0.0f, 0.5f, 5.0f, 30.0f};
  const float hs[] = {1e-4f, 0.05f, 0.5f, 3.0f};
  const float lengths[] = {1.0f, 10.0f, 100.0f};
  const float air_sigmas[] = {0.0f, 0.01f, 0.1f};
  std::vector<Case> out;
  size_t i = 0;
  for (float g : gs) {
    for (float c : cosines) {
      out.push_back({g, c, t_cs[i % 5], hs[i % 4], xs[i % 10], sigmas[i % 6], dzs[i % 5], falloffs[i % 4], 2.0f - 0.5f * float(i % 7),
                     directions[i % 5], lengths[i % 3], air_sigmas[(i / 3) % 3]});
      ++i;
    }
  }
  return out;
}

// light_volume's I(t) for one case, as physics_twins.comp builds it.
float light_volume_integral(const Case& c) {
  physics::RayLight<float> spot;
  spot.type = physics::kLightTypeSpot;
  spot.position = {0, 3, 0};
  spot.direction = {0, -1, 0};
  spot.cos_outer = 0.8191520443f;
  spot.cos_inner = 0.9063077870f;
  const float y = 0.3f * c.direction_y, norm = std::sqrt(1 + y * y + 0.01f);
  return physics::light_scattering_to(spot, {-4.0f, c.origin_y, 0.0f}, {1 / norm, y / norm, 0.1f / norm}, c.length, c.air_sigma_t,
                                      std::clamp(c.g, -0.9f, 0.9f));
}

// The CPU twins' values for one case, in the shader's order.
std::array<float, 12> expected(const Case& c) {
  using namespace physics;
  ScatterAccumulator<float> a;
  integrate_hillaire(a, 1.0f, c.sigma_t, c.dz);
  const AirlightGeometry<float> air{c.t_c, c.h};
  return {phase_hg(c.g, c.cos_theta), phase_schlick(schlick_k(c.g), c.cos_theta), phase_dual_hg(c.g, -0.5f * c.g, 0.7f, c.cos_theta),
          phase_rayleigh(c.cos_theta), one_minus_exp_over_x(c.x), a.radiance, a.transmittance,
          height_fog_optical_depth(c.sigma_t, c.falloff, 0.0f, c.origin_y, c.direction_y, c.dz),
          airlight(air, c.length, c.air_sigma_t, std::clamp(c.g, -0.9f, 0.9f)), airlight_no_extinction(air, c.length),
          attenuated_length(c.sigma_t, c.dz), light_volume_integral(c)};
}

// The airlight's two columns get 1e-4: lavapipe's atan is off by up to ~2e-5 relative
// (Vulkan allows atan 4096 ULP), and the quadrature's panel width is a difference of two
// logs (asinh) that loses ~|w|·ε relative where the segment subtends a small angle far from
// the light. Measured: printed by the test.
// light_volume's I(t) (column 11) shares the airlight's quadrature in w, and lavapipe's
// sinh/cosh: the same 1e-4.
float tolerance(size_t column) { return column == 8 || column == 9 || column == 11 ? 1e-4f : 2e-5f; }

// Test shader `shader` over `table` (its binding 0, a storage buffer), three vec4 out per case.
template <typename Case>
std::vector<float> run_table_shader(rhi::Device& device, const char* shader, const std::vector<Case>& table) {
  const std::vector<std::byte> bytes = run_twin_shader(device, shader, {{std::as_bytes(std::span(table)), rhi::buffer_usage::storage}},
                                                       table.size(), table.size() * 48);
  std::vector<float> results(table.size() * 12);
  std::memcpy(results.data(), bytes.data(), results.size() * sizeof(float));
  return results;
}

class PhysicsTwins : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
};

TEST_P(PhysicsTwins, ShadersMatchTheirCpuTwins) {
  const std::vector<Case> table = cases();
  const std::vector<std::byte> bytes = run_twin_shader(device(), "physics_twins.comp",
                                                       {{std::as_bytes(std::span(table)), rhi::buffer_usage::storage}},
                                                       table.size(), table.size() * 48);
  const auto* results = reinterpret_cast<const float*>(bytes.data());
  const char* names[] = {"hg", "schlick", "dual hg", "rayleigh", "1-exp/x", "hillaire L", "hillaire T", "height depth", "airlight", "airlight σt=0", "attenuated length", "light_volume I"};
  float worst_airlight = 0;
  for (size_t i = 0; i < table.size(); ++i) {
    const std::array<float, 12> want = expected(table[i]);
    for (size_t k = 0; k < 12; ++k) {
      const float got = results[12 * i + k];
      ASSERT_TRUE(std::isfinite(got)) << names[k] << " case " << i;
      if (k == 8 || k == 9 || k == 11) worst_airlight = std::max(worst_airlight, std::abs(got - want[k]) / (std::abs(want[k]) + 1e-30f));
      EXPECT_NEAR(got, want[k], tolerance(k) * std::abs(want[k]) + 1e-30f) << names[k] << " case " << i << " g " << table[i].g
                                                                   << " cos " << table[i].cos_theta << " x " << table[i].x;
    }
  }
  std::printf("airlight and light_volume I(t) GPU vs CPU twin: %.3g relative at most\n", worst_airlight);
}

// std430 mirror of media_twins.comp's Point.
struct NoisePoint {
  float position[4];  // xyz, w octaves
  float noise[4];     // x coverage, y octave of the single gradient noise
};

// Media with every kind of medium and noisy volumes of each shape, turned and scaled.
Media noisy_media() {
  Media media;
  media.fog = Medium{.sigma_s = {0.02, 0.03, 0.04}, .sigma_a = {0.01, 0.01, 0.01}, .g = 0.2};
  media.height_fog = HeightFog{.medium = {.sigma_s = {0.05, 0.05, 0.05}, .g = -0.3}, .base_height = 0, .falloff = 0.3};
  const Shape shapes[] = {Shape::box, Shape::sphere, Shape::ellipsoid, Shape::box};
  for (size_t i = 0; i < std::size(shapes); ++i) {
    MediumVolume v{.shape = shapes[i], .size = {2.0, 1.5, 1.2}};
    v.transform.translate = {-3.0 + 2.0 * double(i), 1.0, -4.0};
    v.transform.rotate_deg = {15.0 * double(i), 30, 0};
    v.transform.scale = {1, 1.0 + 0.25 * double(i), 1};
    v.medium = {.sigma_s = {2, 3, 4}, .sigma_a = {1, 0.5, 0.25}, .g = 0.6, .emission = {0.5, 0.25, 0.125}};
    v.noise = {.octaves = int(2 * i + 1), .scale = 0.5 + 0.25 * double(i), .coverage = 1.0 - 0.2 * double(i), .edge_fade = 0.1 * double(i)};
    if (i == 3) v.noise.octaves = 0;  // an edge fade without noise
    media.volumes.push_back(v);
  }
  return media;
}

// Noise (noise.glsl against noise.h<float>, the same float inputs; values in about
// [−1, 1]): the hash is exact, so only rounding differs (the fade polynomial, the lerps,
// fused or not): |Δ| ≤ 2e-6 for the gradient noise and the fBm, 2e-6 / coverage for
// the density (the coverage remap divides by it). Lattice positions up to ±40 cells
// (×128 at the eighth octave) and past the ±2^30 clamp. On lavapipe (llvmpipe, either
// backend) the three are bit-identical to the twin's, as measured.
// Media field (media_field.glsl in float against media_field.h in double), at points in
// and around the volumes: |Δσ| ≤ 2e-5 × the σ of the media there at full density (the
// height fog's at max(its density, 1)), summed (the world-to-local transform in float moves the local point by ~1e-7 × |p|, and the
// fBm's slope, ~octaves / (scale · coverage), turns that into density); |Δg| ≤ 1e-4.
TEST_P(PhysicsTwins, NoiseAndMediaFieldMatchTheirCpuTwins) {
  const Media media = noisy_media();
  const gpu::MediaField packed = physics::pack_media(media);
  const physics::MediaField field(media);
  test::Rng rng(5);
  std::vector<NoisePoint> points;
  const float coverages[] = {1.0f, 0.7f, 0.3f, 0.01f};
  for (size_t i = 0; i < 4096; ++i) {
    const float spread = i % 512 == 7 ? 3e9f : 80.0f;
    NoisePoint p{};
    for (size_t k = 0; k < 3; ++k) p.position[k] = float(i % 2 ? (rng.unit() - 0.5) * spread : 0.0);
    if (i % 2 == 0) {  // around the volumes
      p.position[0] = float(-5.0 + 8.0 * rng.unit());
      p.position[1] = float(-0.5 + 3.0 * rng.unit());
      p.position[2] = float(-6.0 + 4.0 * rng.unit());
    }
    p.position[3] = float(1 + i % physics::kMaxNoiseOctaves);
    p.noise[0] = coverages[i % 4];
    p.noise[1] = float(i % 7);
    points.push_back(p);
  }
  const std::vector<std::byte> bytes =
      run_twin_shader(device(), "media_twins.comp",
                      {{std::as_bytes(std::span(&packed, 1)), rhi::buffer_usage::uniform},
                       {std::as_bytes(std::span(points)), rhi::buffer_usage::storage}},
                      points.size(), points.size() * 64);
  const auto* results = reinterpret_cast<const float*>(bytes.data());
  const bool on_llvmpipe = device().info().device.find("llvmpipe") != std::string::npos;
  float worst_noise = 0, worst_density = 0;
  double worst_sigma = 0, worst_g = 0;
  size_t inside_partial = 0, noise_away_from_zero = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const NoisePoint& q = points[i];
    const float* got = results + 16 * i;
    const int octaves = int(q.position[3]);
    const float px = q.position[0], py = q.position[1], pz = q.position[2], coverage = q.noise[0];
    const float noise = physics::gradient_noise(px, py, pz, uint32_t(q.noise[1]));
    const float fbm = physics::fbm(px, py, pz, octaves);
    const float density = physics::noise_density(px, py, pz, octaves, coverage);
    for (size_t k = 0; k < 16; ++k) ASSERT_TRUE(std::isfinite(got[k])) << "point " << i << " value " << k;
    EXPECT_NEAR(got[0], noise, 2e-6f) << "gradient noise at point " << i;
    EXPECT_NEAR(got[1], fbm, 2e-6f) << "fbm at point " << i << ", " << octaves << " octaves";
    EXPECT_NEAR(got[2], density, 2e-6f / coverage) << "noise density at point " << i << ", coverage " << coverage;
    if (on_llvmpipe) {  // measured bit-identical there (README "Heterogeneous media")
      EXPECT_EQ(got[0], noise) << "gradient noise at point " << i << " on llvmpipe";
      EXPECT_EQ(got[1], fbm) << "fbm at point " << i << " on llvmpipe";
      EXPECT_EQ(got[2], density) << "noise density at point " << i << " on llvmpipe";
    }
    noise_away_from_zero += std::abs(fbm) > 0.1f;
    worst_noise = std::max({worst_noise, std::abs(got[0] - noise), std::abs(got[1] - fbm)});
    worst_density = std::max(worst_density, std::abs(got[2] - density) * coverage);

    const Vec3 p{px, py, pz};
    const physics::MediaSample want = field.sample(p);
    Vec3 full_sigma_s{0, 0, 0}, full_sigma_a{0, 0, 0}, full_emission{0, 0, 0};
    field.visit(p, [&](const Medium& m, double density_there) {
      const double at_least_full = std::max(density_there, 1.0);  // the height fog's exceeds 1 below its base
      full_sigma_s = physics::add(full_sigma_s, physics::scaled(m.sigma_s, at_least_full));
      full_sigma_a = physics::add(full_sigma_a, physics::scaled(m.sigma_a, at_least_full));
      full_emission = physics::add(full_emission, physics::scaled(m.emission, at_least_full));
      inside_partial += density_there < 1 && m.g == 0.6;  // a volume, faded or noisy here
    });
    for (size_t c = 0; c < 3; ++c) {
      const double ds = std::abs(got[4 + c] - want.sigma_s[c]), da = std::abs(got[8 + c] - want.sigma_a[c]);
      const double de = std::abs(got[12 + c] - want.emission[c]);
      EXPECT_LE(ds, 2e-5 * full_sigma_s[c]) << "σs channel " << c << " at point " << i;
      EXPECT_LE(da, 2e-5 * full_sigma_a[c]) << "σa channel " << c << " at point " << i;
      EXPECT_LE(de, 2e-5 * full_emission[c]) << "emission channel " << c << " at point " << i;
      if (full_sigma_s[c] > 0) worst_sigma = std::max(worst_sigma, ds / full_sigma_s[c]);
    }
    EXPECT_NEAR(got[7], want.g, 1e-4) << "g at point " << i;
    worst_g = std::max(worst_g, std::abs(got[7] - want.g));
  }
  EXPECT_GT(noise_away_from_zero, points.size() / 4) << "the noise varies";
  EXPECT_GT(inside_partial, 500u) << "points where a volume's density is between 0 and 1";
  std::printf("noise GPU vs CPU twin (float): %.3g absolute at most, density %.3g × coverage; media field vs double twin: "
              "σ %.3g of the full σ, g %.3g (%zu points of partial density)\n",
              worst_noise, worst_density, worst_sigma, worst_g, inside_partial);
}

// The in-scattering sum S = σs·(Σ p(θ)·E·V·T_media + L_ambient) + emission of
// in_scattering.glsl (what froxel_scatter and raymarch_fog run) against physics/in_scattering.h
// in double: every phase variant (g from −0.5 to 0.85, the dual-lobe HG's g_back and
// w_forward), a point light (light 0, behind the cases' shadow map: V per channel, with or
// without the media's transmittance held in it), a directional and a spot light, media of
// global fog, height fog and a box (the march toward each light: 0 or 6 steps, jitter),
// points in and out of the media, σs zero or not with the skip on or off, ambient 0 or not.
// Relative error per channel ≤ 2e-5 (float against double: the light's I/d², the march's
// optical depth and exp, the phase; measured 2.8e-6, printed). The box's faces are hard: a
// march sample that lands on one (within float's rounding) is inside in one precision and
// outside in the other, so the points keep their samples off them.
struct InScatteringCase {
  float position[4];   // xyz: p; w: the phase code
  float to_camera[4];  // xyz; w: 1 skips the light loop where σs is zero
  float sigma_s[4];    // rgb; a: g
  float emission[4];
  float phase[4];      // g_back, w_forward
  float march[4];      // steps, max_distance, jitter
  float shadow[4];     // light 0's visibility (× 1, 0.5, 0.25); 1: it holds light 0's media transmittance
};

// The shader's hooks, for the CPU twin: light 0 behind the case's shadow map.
struct CaseShadows {
  double v = 1;
  bool mapped = false;
  Vec3 visibility(size_t light, const Vec3&) const { return light == 0 ? Vec3{v, v * 0.5, v * 0.25} : Vec3{1, 1, 1}; }
  bool media_shadow_mapped(size_t light) const { return mapped && light == 0; }
};

TEST_P(PhysicsTwins, InScatteringMatchesItsCpuTwin) {
  std::vector<Light> lights(3);
  lights[0].type = LightType::point;
  lights[0].position = {1.0, 2.5, -3.0};
  lights[0].intensity = {20, 16, 12};
  lights[1].type = LightType::directional;
  lights[1].direction = physics::normalize(Vec3{0.3, -1.0, 0.25});
  lights[1].irradiance = {3, 2.8, 2.4};
  lights[2].type = LightType::spot;
  lights[2].position = {-1.0, 4.0, -4.0};
  lights[2].direction = {0, -1, 0};
  lights[2].intensity = {40, 40, 40};
  lights[2].inner_cone_deg = 40;
  lights[2].outer_cone_deg = 60;
  Media media;
  media.fog = Medium{.sigma_s = {0.04, 0.05, 0.06}, .sigma_a = {0.01, 0.01, 0.02}, .g = 0.2};
  media.height_fog = HeightFog{.medium = {.sigma_s = {0.1, 0.1, 0.1}, .sigma_a = {0.02, 0.02, 0.02}, .g = 0.5}, .base_height = 0, .falloff = 0.4};
  MediumVolume box{.shape = Shape::box, .size = {2, 2, 2}};
  box.transform.translate = {0.5, 1.5, -3.5};
  box.medium = {.sigma_s = {0.6, 0.5, 0.4}, .sigma_a = {0.3, 0.3, 0.3}, .g = 0.6};
  media.volumes.push_back(box);

  const Vec3 camera{0, 1, 6};
  const Vec3 points[] = {{0.5, 1.5, -3.5}, {-2.0, 0.3, -1.0}, {1.2, 2.3, -2.7}, {-0.8, 3.0, -4.2}, {3.0, 0.8, 1.0}};
  const int codes[] = {PHASE_HG, PHASE_ISOTROPIC, PHASE_RAYLEIGH, PHASE_SCHLICK, PHASE_DUAL_HG};
  const float gs[] = {-0.5f, 0.0f, 0.3f, 0.85f};
  const float shadows[][2] = {{1, 0}, {0.6f, 0}, {0.6f, 1}, {0, 0}};
  std::vector<InScatteringCase> table;
  size_t n = 0;
  for (int code : codes) {
    for (float g : gs) {
      for (const Vec3& p : points) {
        for (const auto& shadow : shadows) {
          for (int steps : {0, 6}) {
            InScatteringCase c{};
            const Vec3 to_camera = physics::normalize(physics::sub(camera, p));
            for (size_t k = 0; k < 3; ++k) {
              c.position[k] = float(p[k]);
              c.to_camera[k] = float(to_camera[k]);
            }
            c.position[3] = float(code);
            c.to_camera[3] = n % 3 == 0 ? 0.0f : 1.0f;
            const bool empty = n % 7 == 3;
            for (size_t k = 0; k < 3; ++k) c.sigma_s[k] = empty ? 0.0f : 0.1f + 0.05f * float(k + n % 4);
            c.sigma_s[3] = g;
            if (n % 2) {
              c.emission[0] = 0.02f;
              c.emission[1] = 0.01f;
              c.emission[2] = 0.03f;
            }
            c.phase[0] = n % 5 == 0 ? 0.2f : -0.4f;
            c.phase[1] = n % 4 == 0 ? 0.3f : 0.75f;
            c.march[0] = float(steps);
            c.march[1] = 20.0f;
            c.march[2] = float(n % 8) / 8.0f;
            c.shadow[0] = shadow[0];
            c.shadow[1] = shadow[1];
            table.push_back(c);
            ++n;
          }
        }
      }
    }
  }

  double worst = 0;
  size_t lit = 0;
  for (const Vec3& ambient : {Vec3{0, 0, 0}, Vec3{0.05, 0.1, 0.2}}) {
    gpu::FogFrame frame{};
    frame.light_list = plumbing::pack_lights(lights);
    frame.media = physics::pack_media(media);
    for (size_t k = 0; k < 3; ++k) frame.ambient[k] = float(ambient[k]);
    const std::vector<std::byte> bytes = run_twin_shader(device(), "in_scattering_twins.comp",
                                                         {{std::as_bytes(std::span(&frame, 1)), rhi::buffer_usage::uniform},
                                                          {std::as_bytes(std::span(table)), rhi::buffer_usage::storage}},
                                                         table.size(), table.size() * 16);
    const auto* results = reinterpret_cast<const float*>(bytes.data());
    for (size_t i = 0; i < table.size(); ++i) {
      const InScatteringCase& c = table[i];
      const physics::MediaSample m{.sigma_s = {c.sigma_s[0], c.sigma_s[1], c.sigma_s[2]},
                                   .emission = {c.emission[0], c.emission[1], c.emission[2]},
                                   .g = c.sigma_s[3]};
      const physics::PhaseChoice phase{int(c.position[3]), c.phase[0], c.phase[1]};
      const physics::LightMarch march{int(c.march[0]), c.march[1], c.march[2]};
      const Vec3 want = physics::in_scattering(m, {c.position[0], c.position[1], c.position[2]},
                                               {c.to_camera[0], c.to_camera[1], c.to_camera[2]}, phase, lights, ambient, media, march,
                                               c.to_camera[3] > 0.5f, CaseShadows{c.shadow[0], c.shadow[1] > 0.5f});
      lit += want[0] > c.emission[0];
      for (size_t k = 0; k < 3; ++k) {
        const float got = results[4 * i + k];
        ASSERT_TRUE(std::isfinite(got)) << "case " << i;
        const double error = std::abs(got - want[k]) / (std::abs(want[k]) + 1e-30);
        worst = std::max(worst, error);
        EXPECT_NEAR(got, want[k], 2e-5 * std::abs(want[k]) + 1e-30)
            << "case " << i << " channel " << k << ": phase " << phase.code << " g " << m.g << " steps " << march.steps << " V "
            << c.shadow[0] << (c.shadow[1] > 0.5f ? " (holds T)" : "") << " ambient " << ambient[0];
      }
    }
  }
  EXPECT_GT(lit, table.size());  // most cases are lit (the rest: σs = 0)
  std::printf("in_scattering.glsl vs physics/in_scattering.h (double), %zu cases × 2 ambients: %.3g relative at most\n", table.size(),
              worst);
}

// Temporal accumulation's maths (view_rays.glsl view_uvz, froxel.glsl froxel_uvw,
// temporal_blend.glsl) against their twins (camera.h, froxel.h, temporal.h) over cameras
// (turned, 16:9 and 1:2), grids (linear, exponential) and points inside the frame, off
// its edges, behind the camera and outside [near, far]: 2e-5 absolute on u, v, w (texture
// coordinates) and relative on z and the blend; inside/outside the same. Points behind
// the camera compare only z (u and v mean nothing there).
struct ReprojectionCase {
  gpu::ViewRays view;
  gpu::FroxelGrid grid;
  float point[4];
  float blend[4];  // current, history value, history frames, alpha
  float valid[4];
};

std::vector<ReprojectionCase> reprojection_cases(std::vector<std::pair<physics::ViewRays, physics::FroxelRange>>& cpu) {
  Camera turned;
  turned.position = {1, 2, 3};
  turned.target = {-2, 1, -4};
  turned.fov_y_deg = 50;
  turned.near = 0.1;
  turned.far = 40;
  Camera tall = turned;
  tall.position = {-3, 0.5, 1};
  tall.target = {-3, 0.2, -6};
  tall.fov_y_deg = 75;
  const std::pair<Camera, Extent> views[] = {{turned, {160, 90, 1}}, {tall, {50, 100, 1}}};
  const float ndcs[] = {-1.3f, -0.97f, -0.4f, 0.0f, 0.31f, 0.96f, 1.25f};
  const double depths[] = {-2, 0.05, 0.7, 6, 39, 55};
  std::vector<ReprojectionCase> out;
  size_t n = 0;
  for (const auto& [camera, size] : views) {
    const physics::ViewRays rays = physics::view_rays(camera, double(size.width) / size.height);
    for (const physics::FroxelDistribution distribution : {physics::FroxelDistribution::linear, physics::FroxelDistribution::exponential}) {
      const physics::FroxelRange range{0.2, 40, distribution};
      for (float x : ndcs) {
        for (float y : ndcs) {
          for (double z : depths) {
            ReprojectionCase c{};
            c.view = fog::pack_view_rays(camera, size);
            c.grid = {{16, 8, 32, 0}, {float(range.near), float(range.far), distribution == physics::FroxelDistribution::linear ? 0.0f : 1.0f, 0}};
            const Vec3 p = physics::add(rays.position, physics::scaled(physics::view_ray(rays, x, y), z));
            for (size_t i = 0; i < 3; ++i) c.point[i] = float(p[i]);
            c.blend[0] = 0.5f + float(n % 7);
            c.blend[1] = 3.0f - float(n % 5);
            c.blend[2] = float(n % 12);
            c.blend[3] = n % 3 == 0 ? 0.1f : n % 3 == 1 ? 0.015625f : 1.0f;
            c.valid[0] = n % 4 == 0 ? 0.0f : 1.0f;
            out.push_back(c);
            cpu.emplace_back(rays, range);
            ++n;
          }
        }
      }
    }
  }
  return out;
}

TEST_P(PhysicsTwins, TemporalReprojectionAndBlendMatchTheirCpuTwins) {
  std::vector<std::pair<physics::ViewRays, physics::FroxelRange>> cpu;
  const std::vector<ReprojectionCase> table = reprojection_cases(cpu);
  const std::vector<float> computed = run_table_shader(device(), "reprojection_twins.comp", table);
  const float* got = computed.data();

  size_t inside = 0;
  for (size_t i = 0; i < table.size(); ++i) {
    const ReprojectionCase& c = table[i];
    const Vec3 p = {c.point[0], c.point[1], c.point[2]};
    const physics::ViewUvz uvz = physics::view_uvz(cpu[i].first, p);
    const physics::FroxelUvw uvw = physics::froxel_uvw(cpu[i].first, cpu[i].second, p);
    const float* r = got + 12 * i;
    EXPECT_NEAR(r[2], uvz.z, 2e-5 * std::max(1.0, std::abs(uvz.z))) << "z, case " << i;
    if (uvz.z > 1e-3) {
      EXPECT_NEAR(r[0], uvz.u, 2e-5) << "u, case " << i;
      EXPECT_NEAR(r[1], uvz.v, 2e-5) << "v, case " << i;
      EXPECT_NEAR(r[4], uvw.u, 2e-5) << "froxel u, case " << i;
      EXPECT_NEAR(r[5], uvw.v, 2e-5) << "froxel v, case " << i;
      EXPECT_NEAR(r[6], uvw.w, 2e-5) << "froxel w, case " << i;
    }
    EXPECT_EQ(r[7], uvw.inside ? 1.0f : 0.0f) << "inside, case " << i << " u " << uvw.u << " v " << uvw.v << " z " << uvz.z;
    inside += uvw.inside;
    const physics::Accumulated<float> want =
        physics::temporal_blend(c.blend[0], physics::Accumulated<float>{c.blend[1], c.blend[2]}, c.valid[0] > 0.5f, c.blend[3]);
    EXPECT_NEAR(r[8], want.value, 2e-5 * std::max(1.0f, std::abs(want.value))) << "blend, case " << i;
    EXPECT_EQ(r[9], want.frames) << "blend frames, case " << i;
  }
  EXPECT_GT(inside, table.size() / 5);
  EXPECT_LT(inside, table.size() / 2);
}

// froxel_voxelize's average (media_average.glsl, shape_interval.glsl in float) against
// physics/media_average.h in double, over camera-like ray segments through the four
// volumes of noisy_media() — the last made uniform (no fade, no noise: its mean is the
// exact fraction inside) — and its fog and height fog; jitters 0, ±0.3, 0.49. Where a
// ray crosses a volume (a chord over 2 cm) its interval ends agree to 5e-5 m (float
// transforms of points some metres away; measured 7e-6, printed); mean densities to 5e-5
// (the sub-samples sit where the chord's float ends put them, in noise of 0.5 m features
// and coverage remaps that divide by 0.4; measured 4e-6); the height fog's mean to 1e-5
// relative; the summed σ to 2e-5 of the media's full σ there (measured 9e-7) and g to 1e-4.
struct AverageSegment {
  float origin_t0[4], ray_t1[4], jitter[4];
};

TEST_P(PhysicsTwins, MediaAverageMatchesItsCpuTwin) {
  Media media = noisy_media();
  media.volumes[3].noise = {};
  const gpu::MediaField packed = physics::pack_media(media);
  const physics::MediaField field(media);
  std::vector<AverageSegment> segments;
  const float jitters[] = {0.0f, 0.3f, -0.3f, 0.49f};
  for (int i = 0; i < 24; ++i) {
    for (int j = 0; j < 8; ++j) {
      for (int k = 0; k < 6; ++k) {
        const float t0 = 2.0f + 0.83f * float(k), length = 0.05f + 0.29f * float((i + j + k) % 6);
        segments.push_back({{0.5f, 1.2f, 1.0f, t0}, {-0.9f + 0.075f * float(i), -0.3f + 0.07f * float(j), -1.0f, t0 + length},
                            {jitters[(i + 3 * j + k) % 4], 0, 0, 0}});
      }
    }
  }
  const std::vector<std::byte> bytes =
      run_twin_shader(device(), "media_average_twins.comp",
                      {{std::as_bytes(std::span(&packed, 1)), rhi::buffer_usage::uniform},
                       {std::as_bytes(std::span(segments)), rhi::buffer_usage::storage}},
                      segments.size(), segments.size() * 7 * 16);
  const auto* results = reinterpret_cast<const float*>(bytes.data());
  double worst_end = 0, worst_mean = 0, worst_sigma = 0;
  size_t chords = 0, partial = 0;
  for (size_t n = 0; n < segments.size(); ++n) {
    const AverageSegment& g = segments[n];
    const float* got = results + 28 * n;
    for (size_t k = 0; k < 28; ++k) ASSERT_TRUE(std::isfinite(got[k])) << "segment " << n << " value " << k;
    const physics::RaySegment s{{g.origin_t0[0], g.origin_t0[1], g.origin_t0[2]}, {g.ray_t1[0], g.ray_t1[1], g.ray_t1[2]}, g.origin_t0[3], g.ray_t1[3]};
    for (size_t v = 0; v < 4; ++v) {
      const std::optional<physics::RayInterval> want = physics::volume_interval(field, v, s.origin, s.ray);
      const float enter = got[2 * v], exit = got[2 * v + 1];
      if (want && want->exit - want->enter > 0.02) {
        ++chords;
        ASSERT_LE(enter, exit) << "segment " << n << " volume " << v << ": the shader misses";
        worst_end = std::max({worst_end, std::abs(enter - want->enter), std::abs(exit - want->exit)});
        EXPECT_NEAR(enter, want->enter, 5e-5) << "segment " << n << " volume " << v;
        EXPECT_NEAR(exit, want->exit, 5e-5) << "segment " << n << " volume " << v;
      }
      if (!want) EXPECT_LT(exit - enter, 1e-3f) << "segment " << n << " volume " << v << ": the CPU misses";
      const double mean = physics::volume_mean_density(field, v, s, g.jitter[0]);
      partial += mean > 0.01 && mean < 0.99;
      worst_mean = std::max(worst_mean, std::abs(got[8 + v] - mean));
      EXPECT_NEAR(got[8 + v], mean, 5e-5) << "segment " << n << " volume " << v;
    }
    const double height = physics::height_fog_mean_density(*media.height_fog, s);
    EXPECT_NEAR(got[12], height, 1e-5 * height) << "segment " << n;
    const physics::MediaSample want = physics::average_media(field, s, g.jitter[0]);
    Vec3 full{0, 0, 0};  // σs + σa of every medium at full density (the height fog's at its mean)
    auto add_full = [&](const Medium& m, double density) {
      full = physics::add(full, physics::scaled(physics::add(m.sigma_s, m.sigma_a), density));
    };
    add_full(*media.fog, 1);
    add_full(media.height_fog->medium, std::max(height, 1.0));
    for (const MediumVolume& v : media.volumes) add_full(v.medium, 1);
    for (size_t c = 0; c < 3; ++c) {
      const double ds = std::abs(got[16 + c] - want.sigma_s[c]), da = std::abs(got[20 + c] - want.sigma_a[c]);
      worst_sigma = std::max({worst_sigma, ds / full[c], da / full[c]});
      EXPECT_LE(ds, 2e-5 * full[c]) << "σs channel " << c << " of segment " << n;
      EXPECT_LE(da, 2e-5 * full[c]) << "σa channel " << c << " of segment " << n;
      EXPECT_NEAR(got[24 + c], want.emission[c], 2e-5 * full[c]) << "emission channel " << c << " of segment " << n;
    }
    EXPECT_NEAR(got[19], want.g, 1e-4) << "g of segment " << n;
  }
  EXPECT_GT(chords, 300u);
  EXPECT_GT(partial, 300u) << "segments a volume fills in part";
  std::printf("media average GPU vs CPU twin: chord ends %.3g m, mean densities %.3g, σ %.3g of the full σ (%zu chords, %zu partial means)\n",
              worst_end, worst_mean, worst_sigma, chords, partial);
}

// std430 mirror of translucency_twins.comp's Case.
struct TranslucencyCase {
  float ray[4];   // to_incident, eta (the normal +y)
  float slab[4];  // F0, cos θ, colour, distance
};

// translucency.glsl against physics/translucency.h in float: incidence from 0 to 89° for
// eta 1 (exactly straight on), air→glass, glass→air (past its critical angle: total
// internal reflection on both), water; Schlick, σt from a colour, the slab, F0. Within
// 4 float ulps relative (1e-6) on the vectors and 1e-5 on exp/log/pow of lavapipe and Dawn.
TEST_P(PhysicsTwins, TranslucencyMatchesItsCpuTwin) {
  std::vector<TranslucencyCase> table;
  for (const float eta : {1.0f, 1.0f / 1.5f, 1.5f, 1.0f / 1.33f}) {
    for (int k = 0; k < 90; k += 7) {
      const float theta = float(k) * float(M_PI) / 180.0f;
      table.push_back({{std::sin(theta), std::cos(theta), 0.0f, eta}, {0.04f, std::cos(theta), 0.05f + 0.01f * float(k), 0.1f}});
    }
  }
  const std::vector<std::byte> bytes = run_twin_shader(device(), "translucency_twins.comp",
                                                       {{std::as_bytes(std::span(table)), rhi::buffer_usage::storage}},
                                                       table.size(), table.size() * 32);
  const auto* got = reinterpret_cast<const float*>(bytes.data());
  int total_internal = 0;
  for (size_t i = 0; i < table.size(); ++i) {
    const TranslucencyCase& c = table[i];
    const std::optional<physics::Vec3Of<float>> t = physics::refract_bec<float>({c.ray[0], c.ray[1], c.ray[2]}, {0, 1, 0}, c.ray[3]);
    ASSERT_EQ(got[8 * i + 3] > 0.5f, bool(t)) << "case " << i << ": total internal reflection on one side only";
    total_internal += t ? 0 : 1;
    for (size_t k = 0; t && k < 3; ++k) EXPECT_NEAR(got[8 * i + k], (*t)[k], 1e-6f) << "case " << i;
    if (c.ray[3] == 1.0f && t) {
      for (size_t k = 0; k < 3; ++k) EXPECT_EQ(got[8 * i + k], -c.ray[k]) << "IOR 1 is straight on, exactly";
    }
    const float sigma_t = physics::sigma_t_from_color(c.slab[2], c.slab[3]);
    const float want[4] = {physics::fresnel_schlick(c.slab[0], c.slab[1]), sigma_t, physics::slab_transmittance(sigma_t, c.slab[3], c.slab[1]),
                           physics::fresnel_f0(1.0f, 1.0f / c.ray[3])};
    for (size_t k = 0; k < 4; ++k) EXPECT_NEAR(got[8 * i + 4 + k], want[k], 1e-5f * std::abs(want[k]) + 1e-7f) << "case " << i << " value " << k;
  }
  EXPECT_GT(total_internal, 0) << "the table reaches past glass's critical angle";
}

INSTANTIATE_TEST_SUITE_P(Backends, PhysicsTwins, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
