// The reference renderer draws a scene's atmosphere (reference/renderer.h), against closed
// forms of physics/atmosphere.h on a plain scene: a Lambertian wall of albedo ρ 100 m in
// front of a camera 2 m above the ground of the earth preset, lit by a noon sun 60° up
// behind the camera (cos θ = 1/2 on the wall), seen along the horizontal ray through the
// image's centre, where the air's density is that of the camera's altitude to 1e-6 (the
// ray rises 0.8 mm over 100 m) and T_sun that of the scene's origin to 2e-6:
//   L = (ρ/π)(E T_sun cos θ + π L_sky) T_air + S_air,
// T_air = e^(−σt d), S_air = J (1 − T_air)/σt, J = (σ_R P_R(ν) + σ_M P_M(ν)) E T_sun(2 m)
// (the air lit where it is; the scene's lights at its origin, physics/atmosphere_lighting.h), with the reference's Monte Carlo off (single scattering, exact to the quadrature's
// 1e-6); the same through an absorbing and scattering global fog integrated together with
// the air; a sky pixel against AtmosphereReference::sky; scenes without an atmosphere
// unchanged bit for bit.
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include <gtest/gtest.h>

#include "physics/atmosphere.h"
#include "physics/atmosphere_multiscattering.h"
#include "physics/camera.h"
#include "physics/phase.h"
#include "reference/atmosphere_reference.h"
#include "reference/image_render.h"
#include "reference/renderer.h"
#include "tests/reference/test_scenes.h"

namespace volgraph::reference {
namespace {

constexpr double kDistance = 100, kEyeHeight = 2, kAlbedo = 0.5;
const Vec3 kSunIrradiance{1.5, 1.6, 1.7};
const Vec3 kTowardSun{0, 0.8660254037844386, 0.5};  // 60° up, behind the camera

// FNV-1a (Fowler, Noll, Vo) over the image's doubles, bit patterns as they are.
uint64_t image_bits_hash(const ReferenceImage& image) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (double v : image.rgb) {
    const uint64_t bits = std::bit_cast<uint64_t>(v);
    for (int b = 0; b < 8; ++b) h = (h ^ ((bits >> (8 * b)) & 0xff)) * 0x100000001b3ull;
  }
  return h;
}

// The wall: a box whose face z = −kDistance looks at the camera, under the earth preset.
Scene wall_scene(double albedo) {
  Scene s;
  s.camera.position = {0, kEyeHeight, 0};
  s.camera.target = {0, kEyeHeight, -1};
  s.camera.fov_y_deg = 30;
  s.materials.push_back({.name = "wall", .albedo = {albedo, albedo, albedo}});
  Object wall{.name = "wall", .shape = Shape::box, .size = {100, 100, 1}, .material = "wall"};
  wall.transform.translate = {0, kEyeHeight, -kDistance - 0.5};
  s.objects.push_back(wall);
  Light sun;
  sun.type = LightType::directional;
  sun.direction = physics::scaled(kTowardSun, -1);
  sun.irradiance = kSunIrradiance;
  s.lights.push_back(sun);
  Atmosphere a = *physics::atmosphere_preset("earth");
  a.sun_light = 0;
  s.atmosphere = a;
  return s;
}

Vec3 times(const Vec3& a, const Vec3& b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }

// The closed form above, through a global fog of σs (isotropic) and σa (0: none): the
// fog's and the air's extinction add, the fog scatters σs (E T_sun/(4π) + L_sky) (a global
// fog does not dim a directional light), both dimmed by both.
Vec3 expected_wall(const Scene& scene, double albedo, double fog_sigma_s, double fog_sigma_a) {
  const Atmosphere& a = *scene.atmosphere;
  const double r = a.bottom_radius, h = kEyeHeight;
  const double mu_s = kTowardSun[1], nu = -kTowardSun[2];  // the view (0, 0, −1) against the sun
  const Vec3 t_sun = physics::sun_transmittance(a, r, mu_s);             // the scene's lights: at its origin
  const Vec3 t_sun_air = physics::sun_transmittance(a, r + h, mu_s);     // the air's: where it scatters
  const Vec3 l_sky = times(kSunIrradiance, physics::multiscattering(a, r, mu_s));
  const Vec3 sigma_t = physics::extinction_at(a, h);
  Vec3 out;
  for (size_t c = 0; c < 3; ++c) {
    const double e_sun = kSunIrradiance[c] * t_sun[c];
    const double j_air = (physics::rayleigh_scattering_at(a, h)[c] * physics::phase_rayleigh(nu) +
                          physics::mie_scattering_at(a, h)[c] * physics::mie_phase(a, nu)) * kSunIrradiance[c] * t_sun_air[c];
    const double j_fog = fog_sigma_s * (e_sun / (4 * M_PI) + l_sky[c]);
    const double extinction = sigma_t[c] + fog_sigma_s + fog_sigma_a, t = std::exp(-extinction * kDistance);
    const double surface = albedo / M_PI * (e_sun * 0.5 + M_PI * l_sky[c]);
    out[c] = surface * t + (j_air + j_fog) * (1 - t) / extinction;
  }
  return out;
}

// The reference along the ray through the centre of a 9×5 image, the Monte Carlo off.
Vec3 centre_radiance(const Scene& scene, uint32_t samples = 0) {
  AtmosphereReferenceSettings settings;
  settings.samples = samples;
  const Renderer renderer(scene, {}, settings);
  return renderer.pixel_radiance(4, 2, 9, 5);
}

void expect_relative(const Vec3& got, const Vec3& want, double tolerance, const char* what) {
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(got[c], want[c], tolerance * want[c]) << what << ", channel " << c;
    std::printf("%s, channel %zu: %.9g against %.9g (relative %.2g)\n", what, c, got[c], want[c], got[c] / want[c] - 1);
  }
}

TEST(ReferenceAtmosphere, LitWallThroughTheAirIsTheClosedForm) {
  const Scene scene = wall_scene(kAlbedo);
  expect_relative(centre_radiance(scene), expected_wall(scene, kAlbedo, 0, 0), 1e-5, "wall");
}

TEST(ReferenceAtmosphere, TheAirAloneInFrontOfABlackWallIsItsSingleScattering) {
  const Scene scene = wall_scene(0);
  expect_relative(centre_radiance(scene), expected_wall(scene, 0, 0, 0), 1e-5, "air in front of a black wall");
}

TEST(ReferenceAtmosphere, FogAndAirIntegratedTogetherAreTheClosedForm) {
  Scene scene = wall_scene(kAlbedo);
  scene.media.fog = Medium{.sigma_s = {0.004, 0.004, 0.004}, .sigma_a = {0.003, 0.003, 0.003}, .g = 0};
  expect_relative(centre_radiance(scene), expected_wall(scene, kAlbedo, 0.004, 0.003), 1e-4, "wall through fog and air");
}

// With the Monte Carlo on (64 paths), the pixel is the aerial perspective of its own
// ray's paths in front of the wall; the orders ≥ 2 add 1.3-1.6× single scattering
// (measured; the ground's bounce and the whole sky light this backward-looking ray), within
// 40 % of Hillaire 2020's isotropic estimate σs E Ψ_ms (1 − T_air)/σt.
TEST(ReferenceAtmosphere, HigherOrdersAreTheAerialPerspectiveOfTheRaysOwnPaths) {
  const Scene scene = wall_scene(0);
  const Renderer renderer(scene);
  const Vec3 d = physics::pixel_ray(scene.camera, 9, 5, 4, 2);
  const AtmosphereReference& air = *renderer.atmosphere();
  const SurfaceHit hit = *renderer.surface_hit(d);
  const AerialPerspectiveSample ap =
      air.aerial_perspective(planet_position(air.atmosphere(), scene.camera.position), d, hit.t, camera_ray_key(d));
  const Vec3 got = renderer.pixel_radiance(4, 2, 9, 5), single = expected_wall(scene, 0, 0, 0);
  const Atmosphere& a = *scene.atmosphere;
  const Vec3 psi = physics::multiscattering(a, a.bottom_radius + kEyeHeight, kTowardSun[1]);
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(got[c], ap.in_scattered[c]);
    const double multiple = got[c] - single[c];
    const double sigma_t = physics::extinction_at(a, kEyeHeight)[c];
    const double sigma_s = physics::rayleigh_scattering_at(a, kEyeHeight)[c] + physics::mie_scattering_at(a, kEyeHeight)[c];
    const double hillaire = sigma_s * kSunIrradiance[c] * psi[c] * -std::expm1(-sigma_t * kDistance) / sigma_t;
    std::printf("channel %zu: orders >= 2 add %.3g of single scattering (standard error of order 2 %.2g of it), %u orders; "
                "Hillaire's estimate %.3g of it\n",
                c, multiple / single[c], ap.scattering.standard_error[1][c] / single[c], ap.scattering.orders, hillaire / single[c]);
    EXPECT_NEAR(multiple, hillaire, 0.4 * hillaire);
  }
}

TEST(ReferenceAtmosphere, ASkyPixelIsTheAtmosphereReferencesSky) {
  Scene scene = wall_scene(kAlbedo);
  scene.camera.target = {0, kEyeHeight + 1, -1};  // 45° up: the top rows see the sky
  const Renderer renderer(scene);
  const AtmosphereReference& air = *renderer.atmosphere();
  const Vec3 eye = planet_position(air.atmosphere(), scene.camera.position);
  const Vec3 d = physics::pixel_ray(scene.camera, 9, 5, 4, 0);
  ASSERT_FALSE(renderer.surface_hit(d));
  const Vec3 got = renderer.pixel_radiance(4, 0, 9, 5), want = air.sky(eye, d, camera_ray_key(d)).radiance;
  for (size_t c = 0; c < 3; ++c) EXPECT_EQ(got[c], want[c]);
}

// With media in the scene the sky is integrated to the far plane, then seen from there:
// where the ray meets no fog that is the sky from the camera (single scattering: exact to
// the quadratures' tolerance).
TEST(ReferenceAtmosphere, ASkyPixelPastTheFarPlaneIsTheSkyFromTheCamera) {
  Scene scene = wall_scene(kAlbedo);
  scene.camera.target = {0, kEyeHeight + 1, -1};
  MediumVolume elsewhere{.shape = Shape::sphere, .medium = {.sigma_s = {0.5, 0.5, 0.5}}};
  elsewhere.transform.translate = {0, -50, 50};
  scene.media.volumes.push_back(elsewhere);
  AtmosphereReferenceSettings settings;
  settings.samples = 0;
  const Renderer renderer(scene, {}, settings);
  const AtmosphereReference& air = *renderer.atmosphere();
  const Vec3 d = physics::pixel_ray(scene.camera, 9, 5, 4, 0);
  const Vec3 want = air.sky(planet_position(air.atmosphere(), scene.camera.position), d, 0).radiance;
  expect_relative(renderer.pixel_radiance(4, 0, 9, 5), want, 1e-5, "sky past the far plane");
}

// Recorded from the renderer before it drew atmospheres (the project's compiler, x86-64):
// the foggy demo_primitives and atmosphere_earth's scene with its atmosphere removed. The
// foggy one re-recorded when HG's base for g < 0 became (1 + g)² − 2g(1 + cosθ)
// (physics::phase_hg_base: algebraically the same, other roundings; its ball's g is −0.2).
TEST(ReferenceAtmosphere, WithoutAnAtmosphereTheImageIsTheSameBitForBitAsBefore) {
  LoadedConfig foggy = load_shipped("demo_primitives.json", 16, 9);
  add_demo_fog(foggy.config.scene);
  LoadedConfig plain = load_shipped("tests/atmosphere_earth.json", 16, 9);
  plain.config.scene.atmosphere.reset();
  EXPECT_EQ(image_bits_hash(render_image(Renderer(foggy.config.scene), {.width = 16, .height = 9, .threads = 2})),
            0x0888dd127d339bcdull);
  EXPECT_EQ(image_bits_hash(render_image(Renderer(plain.config.scene), {.width = 16, .height = 9, .threads = 2})),
            0xe5fee58bcfbe55bcull);
}

// Thin air (docs/reference.md): the noon demo with a Rayleigh scale height of 1 mm (the
// loader's floor, `rayleigh_scale_height: 0.001`) at 16×9 on two threads. Before
// physics::optical_depth clipped the altitudes where a layer's density is negligible, each
// call ran 4096 panels: the image took 275 s (a 2×1 image had not finished after 60 s).
TEST(ReferenceAtmosphere, ThinAirRendersInSecondsWithFinitePixels) {
  LoadedConfig loaded = load_shipped("demo_atmosphere_noon.json", 16, 9);
  ASSERT_TRUE(loaded.config.scene.atmosphere.has_value());
  loaded.config.scene.atmosphere->rayleigh_density = DensityProfile{{}, {0, 1, -1 / 1e-3, 0, 0}};
  const auto start = std::chrono::steady_clock::now();
  const Renderer renderer(loaded.config.scene);
  const ReferenceImage image = render_image(renderer, {.width = 16, .height = 9, .threads = 2});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("thin air (H_R = 1 mm) 16x9, 2 threads: %.2f s\n", seconds);
  EXPECT_LT(seconds, 20.0);
  ASSERT_EQ(image.rgb.size(), size_t(16 * 9 * 3));
  for (double v : image.rgb) ASSERT_TRUE(std::isfinite(v) && v >= 0);
}

}  // namespace
}  // namespace volgraph::reference
