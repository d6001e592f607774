// The reference renderer's media against closed forms and brute force (DESIGN.md units):
// Beer–Lambert through a slab and a ball of absorbing fog; a non-absorbing medium without
// lights gives exactly the attenuated background; homogeneous emission; the analytic
// single-scattering integral of a point light (no extinction) and, with extinction, a
// 10⁶-step midpoint sum; height fog's closed-form optical depth against quadrature; a
// volume's shadow on a lit wall; an edge fade's closed form along a diameter; noisy
// volumes' optical depth and transmittance against brute-force sums of the GPU's twin.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "physics/camera.h"
#include "physics/media_field.h"
#include "physics/phase.h"
#include "reference/renderer.h"
#include "tests/reference/test_scenes.h"
#include "tests/support/random_graph.h"

namespace volgraph::reference {
namespace {

using physics::add;
using physics::dot;
using physics::scaled;
using physics::sub;

constexpr uint32_t kW = 12, kH = 8;

double relative_error(double got, double expected) { return std::abs(got - expected) / std::abs(expected); }

// A camera at the origin looking down −Z, nothing else.
Scene empty_scene(double far = 1000) {
  Scene s;
  s.camera.position = {0, 0, 0};
  s.camera.target = {0, 0, -1};
  s.camera.fov_y_deg = 40;
  s.camera.far = far;
  s.background = {0.3, 0.6, 0.9};
  return s;
}

// A wall of albedo `albedo` facing the camera at z = −distance.
void add_wall(Scene& s, double distance, double albedo) {
  s.materials.push_back({.name = "wall", .albedo = {albedo, albedo, albedo}});
  Object wall{.name = "wall", .shape = Shape::plane, .size = {100, 1, 100}, .material = "wall"};
  wall.transform.translate = {0, 0, -distance};
  wall.transform.rotate_deg = {90, 0, 0};  // normal +Y turned to +Z, toward the camera
  s.objects.push_back(wall);
}

Light point_light(const Vec3& position, const Vec3& intensity) {
  Light l;
  l.type = LightType::point;
  l.position = position;
  l.intensity = intensity;
  return l;
}

IntegrationSettings precise() {
  IntegrationSettings s;
  s.relative_tolerance = 1e-10;
  return s;
}

template <typename PixelCheck>
void for_each_pixel(const Scene& scene, PixelCheck check) {
  for (uint32_t j = 0; j < kH; ++j) {
    for (uint32_t i = 0; i < kW; ++i) check(i, j, physics::pixel_ray(scene.camera, kW, kH, i, j));
  }
}

TEST(ReferenceMedia, BeerLambertThroughASlab) {
  Scene scene = empty_scene();
  MediumVolume slab{.shape = Shape::box};
  slab.transform.translate = {0, 0, -5};
  slab.size = {40, 40, 2};  // z from −6 to −4
  slab.medium.sigma_a = {0.3, 0.5, 0.7};
  scene.media.volumes.push_back(slab);
  const Renderer renderer(scene, precise());
  double worst = 0;
  for_each_pixel(scene, [&](uint32_t i, uint32_t j, const Vec3& d) {
    const double chord = 2 / std::abs(d[2]);
    const Vec3 got = renderer.pixel_radiance(i, j, kW, kH);
    for (size_t c = 0; c < 3; ++c) worst = std::max(worst, relative_error(got[c], scene.background[c] * std::exp(-slab.medium.sigma_a[c] * chord)));
  });
  EXPECT_LT(worst, 1e-9) << "largest relative error";
}

TEST(ReferenceMedia, BeerLambertThroughAnEllipsoid) {
  Scene scene = empty_scene();
  MediumVolume ball{.shape = Shape::ellipsoid};
  ball.transform.translate = {0.2, -0.1, -5};
  ball.size = {1.5, 1.5, 0.75};  // radii, then stretched by the transform: semi-axes 1.5, 1.5, 3
  ball.transform.scale = {1, 1, 4};
  ball.medium.sigma_a = {0.4, 0.2, 0.1};
  ball.medium.sigma_s = {0.2, 0, 0};  // scatters, but there is no light
  scene.media.volumes.push_back(ball);
  const Renderer renderer(scene, precise());
  double worst = 0;
  size_t through = 0;
  for_each_pixel(scene, [&](uint32_t i, uint32_t j, const Vec3& d) {
    // The chord in the ellipsoid's unit-ball space, where t is the same parameter.
    const Vec3 o{-0.2 / 1.5, 0.1 / 1.5, 5 / 3.0}, dl{d[0] / 1.5, d[1] / 1.5, d[2] / 3};
    const double a = dot(dl, dl), b = dot(o, dl), c = dot(o, o) - 1, disc = b * b - a * c;
    const double chord = disc > 0 ? 2 * std::sqrt(disc) / a : 0;
    through += chord > 0;
    const Vec3 got = renderer.pixel_radiance(i, j, kW, kH);
    for (size_t k = 0; k < 3; ++k) {
      const double sigma_t = ball.medium.sigma_a[k] + ball.medium.sigma_s[k];
      worst = std::max(worst, relative_error(got[k], scene.background[k] * std::exp(-sigma_t * chord)));
    }
  });
  EXPECT_GT(through, 10u);
  EXPECT_LT(worst, 1e-9) << "largest relative error";
}

TEST(ReferenceMedia, WithoutAbsorptionLightsOrEmissionTheBackgroundIsOnlyAttenuated) {
  Scene scene = empty_scene(50);
  scene.media.fog = Medium{.sigma_s = {0.05, 0.02, 0.01}, .g = 0.6};
  const Renderer renderer(scene, precise());
  const Vec3 forward{0, 0, -1};
  double worst = 0;
  for_each_pixel(scene, [&](uint32_t i, uint32_t j, const Vec3& d) {
    const double length = scene.camera.far / dot(d, forward);  // to the far plane
    const Vec3 got = renderer.pixel_radiance(i, j, kW, kH);
    for (size_t c = 0; c < 3; ++c) worst = std::max(worst, relative_error(got[c], scene.background[c] * std::exp(-scene.media.fog->sigma_s[c] * length)));
  });
  EXPECT_LT(worst, 1e-12) << "largest relative error";
}

TEST(ReferenceMedia, HomogeneousEmission) {
  Scene scene = empty_scene();
  add_wall(scene, 8, 0);
  scene.media.fog = Medium{.sigma_s = {0.1, 0, 0}, .sigma_a = {0.1, 0.3, 0}, .emission = {0.5, 0.25, 2}};
  const Renderer renderer(scene, precise());
  double worst = 0;
  for_each_pixel(scene, [&](uint32_t i, uint32_t j, const Vec3& d) {
    const double length = 8 / std::abs(d[2]);
    const Vec3 got = renderer.pixel_radiance(i, j, kW, kH);
    for (size_t c = 0; c < 3; ++c) {
      const double sigma_t = scene.media.fog->sigma_s[c] + scene.media.fog->sigma_a[c];
      // ∫₀^D e^(−σt t)·ε dt; ε·D where σt = 0.
      const double expected = sigma_t > 0 ? scene.media.fog->emission[c] / sigma_t * (1 - std::exp(-sigma_t * length))
                                          : scene.media.fog->emission[c] * length;
      worst = std::max(worst, relative_error(got[c], expected));
    }
  });
  EXPECT_LT(worst, 1e-9) << "largest relative error";
}

// Without extinction, ∫₀^D σs/(4π)·I/(h² + (t − t_c)²) dt in closed form.
double point_light_integral(double sigma_s, double intensity, double length, double t_c, double h) {
  return sigma_s * intensity / (4 * M_PI) * (std::atan((length - t_c) / h) + std::atan(t_c / h)) / h;
}

TEST(ReferenceMedia, PointLightIntegralWithoutExtinction) {
  Scene scene = empty_scene();
  add_wall(scene, 6, 0);  // black: only the medium adds light
  const double sigma_s = 1e-10;  // extinction e^(−σs·12 m) changes the answer by ~1e-9 relative
  scene.media.fog = Medium{.sigma_s = {sigma_s, sigma_s, sigma_s}};
  const Light light = point_light({0.3, 0.5, -2}, {5, 4, 3});
  scene.lights.push_back(light);
  const Renderer renderer(scene, precise());
  double worst = 0;
  for_each_pixel(scene, [&](uint32_t i, uint32_t j, const Vec3& d) {
    const double length = 6 / std::abs(d[2]);
    const double t_c = dot(light.position, d);
    const double h = std::sqrt(dot(sub(light.position, scaled(d, t_c)), sub(light.position, scaled(d, t_c))));
    const Vec3 got = renderer.pixel_radiance(i, j, kW, kH);
    for (size_t c = 0; c < 3; ++c) worst = std::max(worst, relative_error(got[c], point_light_integral(sigma_s, light.intensity[c], length, t_c, h)));
  });
  std::printf("point light, no extinction: largest relative error %.2e\n", worst);
  EXPECT_LT(worst, 1e-9) << "largest relative error (measured 4.3e-10 at tolerance 1e-10)";
}

TEST(ReferenceMedia, PointLightWithExtinctionMatchesAMillionStepMidpointSum) {
  Scene scene = empty_scene();
  add_wall(scene, 6, 0);
  const Medium fog{.sigma_s = {0.3, 0.2, 0.1}, .sigma_a = {0.2, 0.1, 0.3}, .g = 0.5};
  scene.media.fog = fog;
  const Light light = point_light({0.3, 0.2, -2.5}, {5, 4, 3});
  scene.lights.push_back(light);
  const Renderer renderer(scene, precise());
  for (const auto& [i, j] : {std::pair{0u, 0u}, {6u, 4u}, {9u, 2u}}) {
    const Vec3 d = physics::pixel_ray(scene.camera, kW, kH, i, j);
    const double length = 6 / std::abs(d[2]);
    const size_t steps = 1000000;
    const double dt = length / steps;
    Vec3 sum{0, 0, 0};
    for (size_t k = 0; k < steps; ++k) {
      const double t = (k + 0.5) * dt;
      const Vec3 to_light = sub(light.position, scaled(d, t));
      const double d2 = dot(to_light, to_light), dl = std::sqrt(d2);
      const double cos_theta = -dot(scaled(to_light, -1 / dl), d);  // travel · (toward the viewer)
      for (size_t c = 0; c < 3; ++c) {
        const double sigma_t = fog.sigma_s[c] + fog.sigma_a[c];
        sum[c] += std::exp(-sigma_t * t) * fog.sigma_s[c] * physics::phase_hg(fog.g, cos_theta) * light.intensity[c] / d2 *
                  std::exp(-sigma_t * dl) * dt;
      }
    }
    const Vec3 got = renderer.pixel_radiance(i, j, kW, kH);
    for (size_t c = 0; c < 3; ++c) {
      std::printf("point light with extinction, pixel %u,%u channel %zu: relative error %.2e\n", i, j, c, relative_error(got[c], sum[c]));
      EXPECT_LT(relative_error(got[c], sum[c]), 1e-12) << "pixel " << i << ", " << j << " channel " << c << " (measured 2.3e-13 at most)";
    }
  }
}

TEST(ReferenceMedia, HeightFogOpticalDepthMatchesQuadrature) {
  Media media;
  media.height_fog = HeightFog{.medium = {.sigma_s = {0.04, 0.03, 0.02}, .sigma_a = {0.01, 0.01, 0.05}}, .base_height = 0.5, .falloff = 0.3};
  const SceneMedia scene_media(media);
  test::Rng rng(7);
  for (int r = 0; r < 20; ++r) {
    const Vec3 origin{rng.unit() * 10 - 5, rng.unit() * 6 - 2, rng.unit() * 10 - 5};
    const Vec3 direction = physics::normalize({rng.unit() * 2 - 1, rng.unit() * 2 - 1, rng.unit() * 2 - 1});
    const double length = 1 + rng.unit() * 40;
    const Vec3 closed = scene_media.optical_depth(origin, direction, 0, length);
    // Composite Simpson with 20 000 panels: error ~ (L/n)⁴·σ'''' ≪ 1e-10 relative here.
    const int n = 20000;
    Vec3 quadrature{0, 0, 0};
    for (int k = 0; k <= 2 * n; ++k) {
      const double w = k == 0 || k == 2 * n ? 1 : k % 2 ? 4 : 2;
      quadrature = add(quadrature, scaled(scene_media.at(add(origin, scaled(direction, length * k / (2 * n)))).sigma_t(), w));
    }
    quadrature = scaled(quadrature, length / (6 * n));
    for (size_t c = 0; c < 3; ++c) EXPECT_LT(relative_error(closed[c], quadrature[c]), 1e-10) << "ray " << r << " channel " << c;
  }
}

TEST(ReferenceMedia, HeightFogTowardTheSunIsTheIntegralToInfinity) {
  Media media;
  media.height_fog = HeightFog{.medium = {.sigma_a = {0.05, 0.05, 0.05}}, .base_height = 0, .falloff = 0.5};
  const SceneMedia scene_media(media);
  const Vec3 up = physics::normalize({0.3, 0.8, 0.1});
  // ∫₀^∞ σ e^(−f(y₀ + t·d_y)) dt = σ e^(−f y₀)/(f d_y).
  const double expected = 0.05 * std::exp(-0.5 * 1.5) / (0.5 * up[1]);
  EXPECT_LT(relative_error(scene_media.optical_depth_to_infinity({0, 1.5, 0}, up)[0], expected), 1e-12);
  EXPECT_GT(scene_media.optical_depth_to_infinity({0, 1.5, 0}, {1, 0, 0})[0], 1e100);  // level: forever in fog
}

TEST(ReferenceMedia, AVolumeShadowsALitWall) {
  // A floor lit from straight above through a slab of absorbing fog that covers x < 0.
  Scene scene = plane_scene({0, 4, 0.001}, 0.5);
  Light sun;
  sun.direction = {0, -1, 0};
  sun.irradiance = {2, 2, 2};
  scene.lights.push_back(sun);
  MediumVolume slab{.shape = Shape::box};
  slab.transform.translate = {-50, 2, 0};
  slab.size = {100, 0.5, 100};  // y from 1.75 to 2.25, beneath the camera
  slab.medium.sigma_a = {0.4, 0.8, 1.6};
  scene.media.volumes.push_back(slab);
  const Renderer renderer(scene, precise());
  for (const auto& [x, under_slab] : {std::pair{-1.0, true}, {1.0, false}}) {
    const Vec3 p{x, 0, 0.3};
    const Vec3 e = renderer.light_arrival(sun, p, {0, 1, 0});
    for (size_t c = 0; c < 3; ++c) {
      const double through = under_slab ? std::exp(-slab.medium.sigma_a[c] * 0.5) : 1.0;
      EXPECT_NEAR(e[c], 2 * through, 2e-15) << "x " << x << " channel " << c;
    }
  }
}

// Along a diameter of a sphere of radius R whose density ramps from 0 at the surface to
// 1 at depth f (the edge fade), ∫ density = 2(R − f) + 2·f/2 = 2R − f; along the x axis
// of a box (edges ≥ 2f) the same holds with R the half edge.
TEST(ReferenceMedia, EdgeFadeOpticalDepthIsClosedFormAlongADiameter) {
  Media media;
  MediumVolume ball{.shape = Shape::sphere, .size = {1.5, 0, 0}};
  ball.transform.translate = {0.2, -0.1, -4};
  ball.medium.sigma_a = {0.2, 0.4, 0.8};
  ball.noise.edge_fade = 0.6;
  media.volumes.push_back(ball);
  MediumVolume box{.shape = Shape::box, .size = {3, 2, 2}};
  box.transform.translate = {0, 10, 0};
  box.medium.sigma_s = {1, 1, 1};
  box.noise.edge_fade = 0.4;
  media.volumes.push_back(box);
  const SceneMedia scene_media(media);
  const Vec3 ball_depth = scene_media.optical_depth({0.2, -0.1, 0}, {0, 0, -1}, 0, 10);
  for (size_t c = 0; c < 3; ++c) EXPECT_LT(relative_error(ball_depth[c], ball.medium.sigma_a[c] * (2 * 1.5 - 0.6)), 1e-12) << c;
  const Vec3 box_depth = scene_media.optical_depth({-5, 10, 0}, {1, 0, 0}, 0, 10);
  EXPECT_LT(relative_error(box_depth[0], 3 - 0.4), 1e-12);
}

// A noisy volume (fBm, coverage, edge fade, turned and scaled by its transform).
MediumVolume noisy_volume(Shape shape) {
  MediumVolume v{.shape = shape, .size = {1.2, 0.8, 1.0}};
  v.transform.translate = {0.3, 0.1, -3};
  v.transform.rotate_deg = {20, 35, 0};
  v.transform.scale = {1.5, 1, 1};
  v.medium.sigma_s = {0.8, 0.9, 1.0};
  v.medium.sigma_a = {0.4, 0.2, 0.1};
  v.noise = {.octaves = 5, .scale = 0.7, .coverage = 0.7, .edge_fade = 0.2};
  return v;
}

// The twin's σt summed by the midpoint rule, n points over [0, length].
Vec3 brute_force_optical_depth(const physics::MediaField& field, const Vec3& origin, const Vec3& direction, double length,
                               int n) {
  Vec3 sum{0, 0, 0};
  for (int k = 0; k < n; ++k) sum = add(sum, field.sample(add(origin, scaled(direction, length * (k + 0.5) / n))).sigma_t());
  return scaled(sum, length / n);
}

// The reference's optical depth through noisy volumes (4-point Gauss–Legendre, a panel
// per cell of the finest octave, MediaQuadrature) against a 10⁵-point midpoint sum of the
// GPU's CPU twin, on random rays through each shape: within 5e-4 relative (measured
// 2.5e-4 at worst, the box: the kinks of its edge fade's ridges and of the coverage
// clamp fall inside panels), and 8× finer panels agree with the sum as closely.
TEST(ReferenceMedia, NoisyOpticalDepthMatchesABruteForceSumOfTheTwin) {
  for (Shape shape : {Shape::box, Shape::sphere, Shape::ellipsoid}) {
    Media media;
    media.volumes.push_back(noisy_volume(shape));
    const SceneMedia scene_media(media);
    const SceneMedia finer(media, {.panels_per_noise_cell = 8, .panels_per_edge_fade = 32});
    const physics::MediaField field(media);
    test::Rng rng(11);
    double worst = 0, worst_finer = 0;
    for (int r = 0; r < 12; ++r) {
      const Vec3 origin{rng.unit() - 0.5, rng.unit() - 0.5, 0};
      const Vec3 target{0.3 + rng.unit() - 0.5, 0.1 + rng.unit() - 0.5, -3 + rng.unit() - 0.5};
      const Vec3 direction = physics::normalize(sub(target, origin));
      const Vec3 got = scene_media.optical_depth(origin, direction, 0, 6);
      const Vec3 brute = brute_force_optical_depth(field, origin, direction, 6, 100000);
      const Vec3 fine = finer.optical_depth(origin, direction, 0, 6);
      ASSERT_GT(brute[0], 0.01) << "ray " << r << " misses the volume";
      for (size_t c = 0; c < 3; ++c) {
        worst = std::max(worst, relative_error(got[c], brute[c]));
        worst_finer = std::max(worst_finer, relative_error(got[c], fine[c]));
      }
    }
    std::printf("shape %d: optical depth vs brute force %.2e, vs 8x finer panels %.2e (relative, worst of 12 rays)\n",
                int(shape), worst, worst_finer);
    EXPECT_LT(worst, 5e-4) << "shape " << int(shape);
    EXPECT_LT(worst_finer, 5e-4) << "shape " << int(shape);
  }
}

// Noise far finer than the volume (1 mm, 8 octaves, in a 2 m box) is integrated on a
// bounded number of panels, and the reference says it under-resolves it; a volume of size
// 0 has no inside.
TEST(ReferenceMedia, FineNoiseIsUnderResolvedInBoundedTimeAndFlatVolumesAreEmpty) {
  Media media;
  media.volumes.push_back(noisy_volume(Shape::box));
  EXPECT_EQ(SceneMedia(media).under_resolved(), "");
  media.volumes[0].noise = {.octaves = 8, .scale = 1e-3, .coverage = 1, .edge_fade = 0};
  const SceneMedia fine(media);
  EXPECT_NE(fine.under_resolved().find("volume 0"), std::string::npos);
  const Vec3 depth = fine.optical_depth({0.3, 0.1, 0}, {0, 0, -1}, 0, 10);
  EXPECT_TRUE(std::isfinite(depth[0]) && depth[0] > 0);
  media.volumes[0].size = {0, 1, 1};
  media.volumes[0].noise.edge_fade = 0.2;
  EXPECT_EQ(SceneMedia(media).optical_depth({0.3, 0.1, 0}, {0, 0, -1}, 0, 10), (Vec3{0, 0, 0}));
}

// Seen through a noisy absorber (no lights), the background arrives × e^(−τ) with τ the
// brute-force sum of the twin's σt: the camera ray's segments and transmittance agree.
TEST(ReferenceMedia, ANoisyAbsorberAttenuatesTheBackgroundByTheTwinsOpticalDepth) {
  Scene scene = empty_scene(20);
  MediumVolume v = noisy_volume(Shape::ellipsoid);
  v.medium.sigma_s = {0, 0, 0};
  scene.media.volumes.push_back(v);
  const Renderer renderer(scene);
  const physics::MediaField field(scene.media);
  for (const auto& [i, j] : {std::pair{6u, 4u}, {5u, 3u}, {7u, 5u}, {4u, 4u}}) {
    const Vec3 direction = physics::pixel_ray(scene.camera, kW, kH, i, j);
    const Vec3 tau = brute_force_optical_depth(field, scene.camera.position, direction, 20 / -direction[2], 200000);
    const Vec3 got = renderer.pixel_radiance(i, j, kW, kH);
    for (size_t c = 0; c < 3; ++c) {
      EXPECT_LT(relative_error(got[c], scene.background[c] * std::exp(-tau[c])), 1e-4) << "pixel " << i << ", " << j << " channel " << c;
    }
  }
}

// The reference's media at a point are the twin's: σs, σt and emission, and with g = 0
// its phase-weighted scattering is σs/4π, inside a noisy volume.
TEST(ReferenceMedia, PointsAreTheTwinsSamples) {
  Media media;
  media.volumes.push_back(noisy_volume(Shape::sphere));
  media.volumes.back().medium.emission = {0.1, 0.2, 0.3};
  media.fog = Medium{.sigma_s = {0.01, 0.01, 0.01}};
  const SceneMedia scene_media(media);
  const physics::MediaField field(media);
  test::Rng rng(3);
  int inside = 0;
  for (int k = 0; k < 200; ++k) {
    const Vec3 p{0.3 + 2 * rng.unit() - 1, 0.1 + 2 * rng.unit() - 1, -3 + 2 * rng.unit() - 1};
    const physics::MediaSample got = scene_media.at(p), want = field.sample(p);
    EXPECT_EQ(got.sigma_s, want.sigma_s);
    EXPECT_EQ(got.sigma_a, want.sigma_a);
    EXPECT_EQ(got.emission, want.emission);
    const Vec3 s = scene_media.scattering(p, 0.3);
    for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(s[c], want.sigma_s[c] * physics::phase_isotropic<double>(), 1e-15);
    inside += want.sigma_a[0] > 0;
  }
  EXPECT_GT(inside, 20) << "points inside the volume's medium";
}

}  // namespace
}  // namespace volgraph::reference
