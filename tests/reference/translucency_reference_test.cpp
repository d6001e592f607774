// The reference renderer's translucent surfaces against closed forms: Beer–Lambert through
// a solid slab, Fresnel's two interfaces, coverage over an emissive wall, an invisible
// object, a translucent shadow caster, the displacement of refraction through a tilted
// view, total internal reflection seen from inside glass, and finite light everywhere in
// extreme materials and views.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/camera.h"
#include "physics/lighting.h"
#include "physics/translucency.h"
#include "reference/image_render.h"
#include "passes/plumbing/gltf.h"
#include "reference/renderer.h"
#include "reference/scene_triangles.h"
#include "tests/reference/test_scenes.h"
#include "tools/image_io.h"
#include "physics/tonemap.h"
#include "tests/support/source_dir.h"

namespace volgraph::reference {
namespace {

constexpr uint32_t kTranslucentWidth = 24, kTranslucentHeight = 16;

// An emissive wall of radiance `wall` (black albedo) in y = 0, seen from (0, 3, 0) straight
// down; nothing lit.
Scene wall_scene(const Vec3& wall) {
  Scene s;
  s.camera.position = {0, 3, 0};
  s.camera.target = {0, 0, 0};
  s.camera.up = {0, 0, -1};
  s.camera.fov_y_deg = 60;
  s.materials.push_back({.name = "wall", .albedo = {0, 0, 0}, .emissive = wall});
  s.objects.push_back({.name = "wall", .shape = Shape::plane, .size = {100, 1, 100}, .material = "wall"});
  return s;
}

Material glass(const std::string& name, double ior, VolumeKind volume) {
  Material m{.name = name, .albedo = {1, 1, 1}};
  m.translucency.transmission = 1;
  m.translucency.ior = ior;
  m.translucency.volume = volume;
  return m;
}

// A box of edges (20, thickness, 20) centred at height y, of material `material`.
Object slab(const std::string& material, double y, double thickness) {
  Object o{.name = "slab", .shape = Shape::box, .size = {20, thickness, 20}, .material = material};
  o.transform.translate = {0, y, 0};
  return o;
}

Vec3 ray_of(const Scene& s, uint32_t i, uint32_t j) { return physics::pixel_ray(s.camera, kTranslucentWidth, kTranslucentHeight, i, j); }

// A horizontal sheet 100 m wide at height `y`, of material "sheet".
Object sheet_at(double y) {
  Object o{.name = "sheet", .shape = Shape::plane, .size = {100, 1, 100}, .material = "sheet"};
  o.transform.translate = {0, y, 0};
  return o;
}

ReferenceImage render(const Scene& s, const IntegrationSettings& settings = {}) {
  const Renderer renderer(s, settings);
  return render_image(renderer, {.width = kTranslucentWidth, .height = kTranslucentHeight, .threads = 2});
}

TEST(TranslucencyReference, SolidSlabIsBeerLambertAlongTheChord) {
  Scene s = wall_scene({1, 1, 1});
  const double d = 0.5;
  const Vec3 c{0.5, 0.25, 0.8};
  Material m = glass("slab", 1, VolumeKind::solid);
  m.translucency.attenuation_color = c;
  m.translucency.attenuation_distance = d;
  s.materials.push_back(m);
  s.objects.push_back(slab("slab", 1, d));
  const Renderer renderer(s);
  double worst = 0;
  for (uint32_t j = 0; j < kTranslucentHeight; ++j) {
    for (uint32_t i = 0; i < kTranslucentWidth; ++i) {
      const Vec3 ray = ray_of(s, i, j);
      const Vec3 got = renderer.camera_ray_radiance(ray);
      for (size_t k = 0; k < 3; ++k) {
        const double sigma_t = -std::log(c[k]) / d;  // RTR4 eq. 14.23
        const double expected = std::exp(-sigma_t * d / std::abs(ray[1]));
        worst = std::max(worst, std::abs(got[k] - expected));
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
  std::printf("solid slab: largest |pixel − e^(−σt·d/|cos θ|)| = %.3g\n", worst);
}

TEST(TranslucencyReference, GlassReflectsFresnelAndPassesTheRestOnce) {
  const Vec3 wall{2, 1, 0.5};
  Scene s = wall_scene(wall);
  s.background = {0.3, 0.6, 0.9};  // L_env
  s.materials.push_back(glass("glass", 1.5, VolumeKind::solid));
  s.objects.push_back(slab("glass", 1, 0.5));
  const Renderer renderer(s);
  EXPECT_DOUBLE_EQ(physics::interface_reflectance(1.5, 1.0), 0.04);
  // Normal incidence: the ray straight down the view axis.
  const Vec3 centre = renderer.camera_ray_radiance({0, -1, 0});
  const double f = physics::interface_reflectance(1.5, 1.0);
  for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(centre[k], f * s.background[k] + (1 - f) * wall[k], 1e-15);  // one interface (KHR_materials_volume)
  double worst = 0;
  for (uint32_t j = 0; j < kTranslucentHeight; ++j) {
    for (uint32_t i = 0; i < kTranslucentWidth; ++i) {
      const Vec3 ray = ray_of(s, i, j);
      const Vec3 got = renderer.camera_ray_radiance(ray);
      const double fi = physics::interface_reflectance(1.5, std::abs(ray[1]));
      for (size_t k = 0; k < 3; ++k) worst = std::max(worst, std::abs(got[k] - (fi * s.background[k] + (1 - fi) * wall[k])));
    }
  }
  EXPECT_LT(worst, 1e-14);
}

// A scene with a lit floor, fog, a sheet and a solid: the objects given `material`.
Scene lit_scene_with(const std::optional<Material>& material) {
  Scene s;
  s.camera.position = {0.3, 3, 2.5};
  s.camera.target = {0, 0, 0};
  s.camera.fov_y_deg = 60;
  s.background = {0.1, 0.2, 0.3};
  s.materials.push_back({.name = "floor", .albedo = {0.5, 0.6, 0.7}});
  s.objects.push_back({.name = "floor", .shape = Shape::plane, .size = {100, 1, 100}, .material = "floor"});
  Light sun;
  sun.direction = physics::normalize(Vec3{0.3, -1, -0.2});
  sun.irradiance = {3, 3, 3};
  s.lights.push_back(sun);
  s.media.fog = Medium{.sigma_s = {0.02, 0.025, 0.03}, .sigma_a = {0.005, 0.005, 0.005}, .g = 0.3};
  if (material) {
    Material sheet = *material, solid = *material;
    sheet.name = "sheet";
    solid.name = "solid";
    sheet.translucency.volume = VolumeKind::thin_walled;
    solid.translucency.volume = VolumeKind::solid;
    s.materials.push_back(sheet);
    s.materials.push_back(solid);
    Object a{.name = "sheet", .shape = Shape::plane, .size = {2, 1, 2}, .material = "sheet"};
    a.transform.translate = {-0.5, 1.2, 0};
    Object b{.name = "solid", .shape = Shape::box, .size = {1, 1, 1}, .material = "solid"};
    b.transform.translate = {0.6, 0.6, 0.3};
    s.objects.push_back(a);
    s.objects.push_back(b);
  }
  return s;
}

TEST(TranslucencyReference, AnInvisibleObjectChangesNoBit) {
  Material clear = glass("clear", 1, VolumeKind::thin_walled);
  const ReferenceImage with = render(lit_scene_with(clear));
  const ReferenceImage without = render(lit_scene_with(std::nullopt));
  EXPECT_EQ(with.rgb, without.rgb);
}

TEST(TranslucencyReference, CoverageBlendsTheSheetOverTheWall) {
  const Vec3 wall{1, 0.5, 2};
  Scene s = wall_scene(wall);
  Material sheet{.name = "sheet", .albedo = {1, 1, 1}};
  sheet.translucency.alpha = 0.25;
  sheet.translucency.alpha_mode = AlphaMode::blend;
  sheet.translucency.ior = 1;
  s.materials.push_back(sheet);
  s.objects.push_back(sheet_at(1));
  Light sun;
  sun.direction = {0, -1, 0};
  sun.irradiance = {M_PI, M_PI, M_PI};
  s.lights.push_back(sun);
  const ReferenceImage image = render(s);
  for (uint32_t j = 0; j < kTranslucentHeight; ++j) {
    for (uint32_t i = 0; i < kTranslucentWidth; ++i) {
      for (size_t k = 0; k < 3; ++k) ASSERT_NEAR(image.at(i, j)[k], 0.75 * wall[k] + 0.25, 1e-15);
    }
  }
}

// Each layer is seen through the media in front of it: in an absorbing fog (σa, no
// scattering) a glowing sheet of coverage α at distance t₁ over the wall at t₂ is
// e^(−σa t₁)·α·L + (1 − α)·e^(−σa t₂)·wall.
TEST(TranslucencyReference, LayersAreSeenThroughTheMediaInFrontOfThem) {
  const Vec3 wall{1, 0.5, 2};
  Scene s = wall_scene(wall);
  const double sigma_a = 0.3;
  s.media.fog = Medium{.sigma_s = {0, 0, 0}, .sigma_a = {sigma_a, sigma_a, sigma_a}, .g = 0};
  Material sheet{.name = "sheet", .albedo = {0, 0, 0}, .emissive = {4, 4, 4}};
  sheet.translucency.alpha = 0.25;
  sheet.translucency.alpha_mode = AlphaMode::blend;
  s.materials.push_back(sheet);
  s.objects.push_back(sheet_at(1));
  const Renderer renderer(s);
  double worst = 0;
  for (uint32_t j = 0; j < kTranslucentHeight; ++j) {
    for (uint32_t i = 0; i < kTranslucentWidth; ++i) {
      const Vec3 ray = ray_of(s, i, j);
      const double t1 = 2 / -ray[1], t2 = 3 / -ray[1];
      const Vec3 got = renderer.camera_ray_radiance(ray);
      for (size_t k = 0; k < 3; ++k) {
        const double expected = std::exp(-sigma_a * t1) * 0.25 * 4 + 0.75 * std::exp(-sigma_a * t2) * wall[k];
        worst = std::max(worst, std::abs(got[k] - expected) / expected);
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
  std::printf("layers in fog: largest relative error %.3g\n", worst);
}

// In a scattering fog lit by a point light, the layered ray equals the segments integrated
// one by one: S(0, t₁) + T(0, t₁)[L₁ + τ₁(S(t₁, t₂) + T(t₁, t₂)·wall)] (fogged_layer's
// identity), to the integration's tolerance.
TEST(TranslucencyReference, FoggedLayersEqualTheSegmentsIntegratedApart) {
  const Vec3 wall{1, 0.5, 2};
  Scene s = wall_scene(wall);
  s.media.fog = Medium{.sigma_s = {0.2, 0.25, 0.3}, .sigma_a = {0.05, 0.05, 0.05}, .g = 0.3};
  Light lamp;
  lamp.type = LightType::point;
  lamp.position = {0.4, 2, 0.3};
  lamp.intensity = {3, 3, 3};
  lamp.cast_shadows = false;
  s.lights.push_back(lamp);
  Material sheet{.name = "sheet", .albedo = {0.5, 0.5, 0.5}, .emissive = {0.5, 0.5, 0.5}};
  sheet.translucency.alpha = 0.4;
  sheet.translucency.alpha_mode = AlphaMode::blend;
  sheet.translucency.ior = 1;
  s.materials.push_back(sheet);
  s.objects.push_back(sheet_at(1));
  IntegrationSettings settings;
  settings.relative_tolerance = 1e-9;
  const Renderer renderer(s, settings);
  const auto segment = [&](const Vec3& from, const Vec3& d, double length) {
    std::vector<double> breaks{physics::dot(physics::sub(lamp.position, from), d)};
    return integrate_single_scattering(renderer.media(), from, d, length, breaks,
                                       [&](const Vec3& x) { return renderer.in_scattering(x, d); }, settings);
  };
  double worst = 0;
  for (uint32_t j = 0; j < kTranslucentHeight; j += 3) {
    for (uint32_t i = 0; i < kTranslucentWidth; i += 3) {
      const Vec3 d = ray_of(s, i, j);
      const double t1 = 2 / -d[1], t2 = 3 / -d[1];
      const Vec3 at_sheet = physics::add(s.camera.position, physics::scaled(d, t1));
      const RayScattering front = segment(s.camera.position, d, t1), back = segment(at_sheet, d, t2 - t1);
      const std::optional<SurfaceHit> hit = renderer.surface_hit(d);
      const Vec3 e = renderer.surface_irradiance(hit->position, hit->normal);
      const Vec3 got = renderer.camera_ray_radiance(d);
      for (size_t k = 0; k < 3; ++k) {
        const double layer = 0.4 * (0.5 / M_PI * e[k] + 0.5);
        const double behind = back.radiance[k] + back.transmittance[k] * wall[k];
        const double expected = front.radiance[k] + front.transmittance[k] * (layer + 0.6 * behind);
        worst = std::max(worst, std::abs(got[k] - expected) / expected);
      }
    }
  }
  EXPECT_LT(worst, 1e-7);
  std::printf("fogged layers against segments apart: largest relative difference %.3g\n", worst);
}

TEST(TranslucencyReference, MaskedHolesAreSeenThrough) {
  const Vec3 wall{1, 0.5, 2};
  Scene s = wall_scene(wall);
  Material sheet{.name = "sheet", .albedo = {1, 1, 1}};
  sheet.translucency.alpha = 0.4;
  sheet.translucency.alpha_mode = AlphaMode::mask;  // below the cutoff 0.5: a hole
  s.materials.push_back(sheet);
  s.objects.push_back(sheet_at(1));
  EXPECT_EQ(render(s).at(5, 5), wall);
  s.materials[1].translucency.alpha = 0.6;  // above it: an opaque black-lit sheet
  EXPECT_EQ(render(s).at(5, 5), (Vec3{0, 0, 0}));
}

TEST(TranslucencyReference, CoverageIsAlphaTimesTheTexturesAlpha) {
  SceneTriangles scene;
  scene.images.push_back({2, 1, {1, 1, 1, 1, 1, 1}, {0, 1}});  // alpha 0 on the left texel, 1 on the right
  SurfaceMaterial m;
  m.base_color_image = 0;
  m.translucency.alpha = 0.8;
  m.translucency.alpha_mode = AlphaMode::mask;
  EXPECT_EQ(coverage_at(scene, m, 0.25, 0.5), 0.0);
  EXPECT_NEAR(coverage_at(scene, m, 0.75, 0.5), 0.8, 1e-7);
  EXPECT_NEAR(coverage_at(scene, m, 0.5, 0.5), 0.4, 1e-7);  // bilinear between the texels
  EXPECT_TRUE(is_hole(scene, m, 0.25, 0.5));
  EXPECT_FALSE(is_hole(scene, m, 0.75, 0.5));
  EXPECT_EQ(layer_coverage(scene, m, 0.75, 0.5), 1.0);  // only a blended layer is partly covered
  m.translucency.alpha_mode = AlphaMode::blend;
  EXPECT_NEAR(layer_coverage(scene, m, 0.75, 0.5), 0.8, 1e-7);
}

TEST(TranslucencyReference, ATranslucentSheetDimsTheLightByItsTransmittance) {
  Scene s = lit_scene_with(std::nullopt);
  s.media = {};
  Material sheet = glass("sheet", 1, VolumeKind::thin_walled);
  sheet.albedo = {0.6, 0.5, 0.4};
  s.materials.push_back(sheet);
  s.objects.push_back(sheet_at(2));
  const Renderer renderer(s);
  const Vec3 point{0.2, 0, -0.3}, up{0, 1, 0};
  const Vec3 unshadowed = physics::irradiance(s.lights[0], point, up);
  EXPECT_EQ(renderer.light_transmittance(s.lights[0], point), sheet.albedo);
  const Vec3 e = renderer.light_arrival(s.lights[0], point, up);
  for (size_t k = 0; k < 3; ++k) EXPECT_EQ(e[k], unshadowed[k] * sheet.albedo[k]);
  // Glass: (1 − F) at the shadow ray's angle; a solid: Beer–Lambert over the chord too.
  Scene g = s;
  g.materials.back().translucency.ior = 1.5;
  const double cos_light = -g.lights[0].direction[1];
  const double f = physics::interface_reflectance(1.5, cos_light);
  const Vec3 tg = Renderer(g).light_transmittance(g.lights[0], point);
  for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(tg[k], (1 - f) * sheet.albedo[k], 1e-15);
  Scene b = s;
  b.objects.back() = slab("sheet", 2, 0.5);
  b.materials.back().translucency.volume = VolumeKind::solid;
  b.materials.back().translucency.attenuation_color = {0.5, 0.5, 0.5};
  b.materials.back().translucency.attenuation_distance = 0.5;
  const Vec3 tb = Renderer(b).light_transmittance(b.lights[0], point);
  for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(tb[k], sheet.albedo[k] * std::exp(std::log(0.5) / cos_light), 1e-14);
}

// Refracted mode. The edge x = 0 of an emissive half-plane y = 0 (x < 0) seen from
// (2, 3, 0) through a horizontal glass slab y ∈ [1, 1.5]: found by bisection on the ray's
// angle θ from the vertical, it lies where the refracted path lands on x = 0, shifted by
// the slab d·(tan θ − tan θt) along the floor — a lateral displacement d·sin(θ − θt)/cos θt.
Scene edge_scene(double ior) {
  Scene s;
  s.camera.position = {2, 3, 0};
  s.camera.target = {0, 0, 0};
  s.camera.fov_y_deg = 60;
  s.materials.push_back({.name = "wall", .albedo = {0, 0, 0}, .emissive = {1, 1, 1}});
  Object wall{.name = "wall", .shape = Shape::plane, .size = {50, 1, 50}, .material = "wall"};
  wall.transform.translate = {-25, 0, 0};
  s.objects.push_back(wall);
  s.materials.push_back(glass("glass", ior, VolumeKind::solid));
  s.objects.push_back(slab("glass", 1.25, 0.5));
  return s;
}

Vec3 edge_ray(double theta) { return {-std::sin(theta), -std::cos(theta), 0}; }

// The angle where `lit(θ)` turns from false to true in [lo, hi].
template <typename Lit>
double bisect(double lo, double hi, Lit lit) {
  for (int k = 0; k < 80; ++k) {
    const double mid = (lo + hi) / 2;
    (lit(mid) ? hi : lo) = mid;
  }
  return (lo + hi) / 2;
}

TEST(TranslucencyReference, RefractionDisplacesTheEdgeBehindASlab) {
  const double ior = 1.5, d = 0.5;
  IntegrationSettings refracted;
  refracted.translucency = TranslucencyMode::refracted;
  const Scene s = edge_scene(ior);
  const Renderer renderer(s, refracted);
  const double seen = bisect(0.3, 0.9, [&](double th) { return renderer.camera_ray_radiance(edge_ray(th))[0] > 0.5; });
  // Where the refracted path lands: 2 − 2.5 tan θ − d tan θt = 0 (1.5 m above and 1 m
  // below the slab in air).
  const auto landing = [&](double th) {
    const double st = std::sin(th) / ior, tt = st / std::sqrt(1 - st * st);
    return 2 - 2.5 * std::tan(th) - d * tt;
  };
  const double expected = bisect(0.3, 0.9, [&](double th) { return landing(th) < 0; });
  EXPECT_NEAR(seen, expected, 1e-12);
  const double straight = std::atan(2.0 / 3.0);
  const double theta_t = std::asin(std::sin(seen) / ior);
  const double lateral = d * std::sin(seen - theta_t) / std::cos(theta_t);
  // The straight ray at the seen angle lands past the edge by the lateral displacement
  // over cos θ.
  const double straight_landing = 2 - 3 * std::tan(seen);
  EXPECT_NEAR(-straight_landing * std::cos(seen), lateral, 1e-11);
  // And in pixels: the edge is a horizontal line of the image (x runs up it); its row
  // along the middle column, straight and refracted (rows above it see the wall).
  const Renderer straight_renderer(s);
  const auto edge_row = [&](const Renderer& r) {
    return bisect(0, kTranslucentHeight, [&](double y) {
      return r.camera_ray_radiance(physics::pixel_ray(s.camera, kTranslucentWidth, kTranslucentHeight, kTranslucentWidth / 2.0 - 0.5, y - 0.5))[0] < 0.5;
    });
  };
  const double shift = edge_row(renderer) - edge_row(straight_renderer);
  std::printf("refraction: edge at θ = %.12f (straight %.12f), lateral displacement %.9f m, %.4f pixels at %u×%u\n", seen, straight,
              lateral, shift, kTranslucentWidth, kTranslucentHeight);
  // The shift the angles give: the rows from the centre are tan(angle off the axis) over tan 30°, times 8.
  const double rows_per_tangent = kTranslucentHeight / (2 * std::tan(M_PI / 6));  // at the view's centre (fov 60°)
  EXPECT_NEAR(shift, -std::tan(seen - straight) * rows_per_tangent, 1e-9);
  EXPECT_GT(std::abs(shift), 0.4);
}

// Refracted mode at normal incidence through a slab of ior 1.5, transmittance T across it:
// the reflections inside add up to the closed form of two parallel interfaces,
//   F·L_env + (1 − F)² T (wall + F T L_env) / (1 − F² T²),
// with every branch traced (no weight cut) to 64 interfaces.
TEST(TranslucencyReference, RefractedSlabSumsItsInternalReflections) {
  const Vec3 wall{2, 1, 0.5};
  Scene s = wall_scene(wall);
  s.background = {0.3, 0.6, 0.9};
  Material m = glass("glass", 1.5, VolumeKind::solid);
  m.translucency.attenuation_color = {1, 0.5, 0.25};
  m.translucency.attenuation_distance = 0.5;
  s.materials.push_back(m);
  s.objects.push_back(slab("glass", 1, 0.5));
  IntegrationSettings refracted;
  refracted.translucency = TranslucencyMode::refracted;
  refracted.min_branch_weight = 0;
  refracted.max_bounces = 64;
  const Renderer renderer(s, refracted);
  const Vec3 got = renderer.camera_ray_radiance({0, -1, 0});
  const double f = physics::interface_reflectance(1.5, 1.0);
  for (size_t k = 0; k < 3; ++k) {
    const double t = m.translucency.attenuation_color[k];  // across d = attenuation_distance
    const double l = s.background[k];
    EXPECT_NEAR(got[k], f * l + (1 - f) * (1 - f) * t * (wall[k] + f * t * l) / (1 - f * f * t * t), 1e-14) << k;
  }
}

// Dispersion (KHR_materials_dispersion) in refracted mode: each channel is traced on its
// own at its IOR, so a dispersive slab's image is, channel by channel, exactly the plain
// images at ior − halfSpread (red), ior (green) and ior + halfSpread (blue).
TEST(TranslucencyReference, DispersionTracesEachChannelAtItsOwnIor) {
  IntegrationSettings refracted;
  refracted.translucency = TranslucencyMode::refracted;
  Scene dispersive = edge_scene(1.5);
  dispersive.materials.back().translucency.dispersion = 4;  // V_d = 5: strong, so the channels part visibly
  const Vec3 iors = physics::dispersed_iors(1.5, 4.0);
  EXPECT_EQ(iors[0], 1.5 - 0.5 * 0.025 * 4);
  EXPECT_EQ(iors[2], 1.5 + 0.5 * 0.025 * 4);
  const ReferenceImage got = render(dispersive, refracted);
  const ReferenceImage plain = render(edge_scene(1.5), refracted);
  for (size_t c = 0; c < 3; ++c) {
    const ReferenceImage at = render(edge_scene(iors[c]), refracted);
    if (c != 1) ASSERT_NE(at.rgb, plain.rgb) << c;  // else the identity below could not fail
    for (size_t p = c; p < got.rgb.size(); p += 3) ASSERT_EQ(got.rgb[p], at.rgb[p]) << "channel " << c << ", value " << p / 3;
  }
  // Dispersion 0 is the one IOR, bit for bit.
  dispersive.materials.back().translucency.dispersion = 0;
  EXPECT_EQ(render(dispersive, refracted).rgb, plain.rgb);
}

TEST(TranslucencyReference, RefractedEqualsStraightAtIorOne) {
  Material m = glass("clearish", 1, VolumeKind::thin_walled);
  m.albedo = {0.9, 0.7, 0.5};
  m.translucency.transmission = 0.6;
  m.translucency.attenuation_color = {0.5, 0.6, 0.7};
  m.translucency.attenuation_distance = 0.8;
  Scene s = lit_scene_with(m);
  s.media = {};
  IntegrationSettings refracted;
  refracted.translucency = TranslucencyMode::refracted;
  EXPECT_EQ(render(s, refracted).rgb, render(s).rgb);
}

// The camera inside a flat glass box (ior 1.5, 20 × 4 × 20 m) looking down at its floor
// face, an emissive wall just below that face: rays beyond the critical angle 41.8° are
// totally reflected (their |cos| to every face is kept by the box's reflections, so they
// never leave through the floor) and see nothing of the wall; those inside it see it.
TEST(TranslucencyReference, TotalInternalReflectionHidesTheOutside) {
  Scene s;
  s.camera.position = {0, 0, 0};
  s.camera.target = {0, -1, 0};
  s.camera.up = {0, 0, -1};
  s.camera.fov_y_deg = 120;
  s.materials.push_back({.name = "wall", .albedo = {0, 0, 0}, .emissive = {1, 1, 1}});
  Object wall{.name = "wall", .shape = Shape::plane, .size = {20, 1, 20}, .material = "wall"};
  wall.transform.translate = {0, -2.5, 0};
  s.objects.push_back(wall);
  s.materials.push_back(glass("glass", 1.5, VolumeKind::solid));
  s.objects.push_back({.name = "glass", .shape = Shape::box, .size = {20, 4, 20}, .material = "glass"});
  IntegrationSettings refracted;
  refracted.translucency = TranslucencyMode::refracted;
  const Renderer renderer(s, refracted);
  const double critical = std::sqrt(1 - 1 / (1.5 * 1.5));  // cos of the critical angle (41.8°)
  size_t beyond = 0, within = 0;
  for (uint32_t j = 0; j < kTranslucentHeight; ++j) {
    for (uint32_t i = 0; i < kTranslucentWidth; ++i) {
      const Vec3 d = ray_of(s, i, j);
      const double to_floor = 2 / -d[1];
      if (std::abs(d[0] * to_floor) >= 10 || std::abs(d[2] * to_floor) >= 10) continue;  // meets a side first
      const Vec3 got = renderer.camera_ray_radiance(d);
      if (-d[1] < critical - 1e-9) {
        ++beyond;
        for (double v : got) ASSERT_EQ(v, 0.0) << i << ", " << j;
      } else if (-d[1] > critical + 1e-9) {
        ++within;
        for (double v : got) ASSERT_GT(v, 0.5) << i << ", " << j;
      }
    }
  }
  EXPECT_GT(beyond, 20u);
  EXPECT_GT(within, 20u);
  std::printf("total internal reflection: %zu pixels beyond the critical angle see 0, %zu within see the wall\n", beyond, within);
}

TEST(TranslucencyReference, ExtremeMaterialsAndViewsStayFinite) {
  for (const TranslucencyMode mode : {TranslucencyMode::straight, TranslucencyMode::refracted}) {
    Material m = glass("extreme", 4, VolumeKind::shell);
    m.translucency.attenuation_color = {0, 0, 0};
    m.translucency.attenuation_distance = 0;
    m.translucency.thickness = 0;
    Scene s = lit_scene_with(m);
    s.materials[1].translucency.volume = VolumeKind::shell;  // the sheet: a shell of thickness 0
    s.materials.back().translucency.thickness = 1e-3;        // the solid: opaque inside
    s.materials.back().translucency.attenuation_distance = 1e-9;
    Light point;
    point.type = LightType::point;
    point.position = {0.6, 0.6, 0.3};  // inside the solid
    point.intensity = {5, 5, 5};
    s.lights.push_back(point);
    IntegrationSettings settings;
    settings.translucency = mode;
    for (const Vec3& eye : {Vec3{0.3, 3, 2.5}, Vec3{3, 1.2000001, 0}, Vec3{0.6, 0.6, 0.3}}) {  // above, grazing the sheet, inside the solid
      s.camera.position = eye;
      s.camera.target = eye[1] < 1 ? Vec3{0.6, 0, 0.3} : Vec3{0, 1.2, 0};
      s.camera.up = eye[1] < 1 ? Vec3{0, 0, -1} : Vec3{0, 1, 0};
      if (eye[1] > 2) s.camera.target = {0, 0, 0};
      const ReferenceImage image = render(s, settings);
      for (double v : image.rgb) ASSERT_TRUE(std::isfinite(v) && v >= 0) << v;
    }
  }
}

}  // namespace
}  // namespace volgraph::reference

namespace volgraph::reference {
namespace {

// The shipped translucency demos (what `volgraph reference` renders through the same
// Renderer): finite and non-negative in both modes.
TEST(TranslucencyReference, ShippedDemosRenderInBothModes) {
  for (const char* config : {"demo_water_slab.json", "demo_transmission_test.json", "demo_attenuation_test.json", "demo_glass_vase_fog.json"}) {
    const LoadedConfig loaded = load_shipped(config, 12, 8);
    for (const TranslucencyMode mode : {TranslucencyMode::straight, TranslucencyMode::refracted}) {
      IntegrationSettings settings;
      settings.translucency = mode;
      settings.relative_tolerance = 1e-3;
      const Renderer renderer(loaded.config.scene, settings);
      const ReferenceImage image = render_image(renderer, {.width = 12, .height = 8, .threads = 2});
      for (double v : image.rgb) ASSERT_TRUE(std::isfinite(v) && v >= 0) << config << ": " << v;
    }
  }
}

}  // namespace
}  // namespace volgraph::reference

namespace volgraph::reference {
namespace {

// The straight mode against the GPU's goldens of the translucency demos (64×36, ACES as
// their composite), over the pixels whose 3×3 neighbourhood's first hits are one object:
// figures printed, and those of the pixels that see a translucent surface first (masked
// ones left out: the GPU's translucent pass cuts no holes, the reference does). The GPU's
// translucent surfaces cast no shadows: neither do they here. (Elsewhere the figures hold
// more than translucency: the GPU's mipmapped textures, which the reference samples at
// level 0 — the transmission test's backdrop seen through its spheres, too — and its
// shadow map's bias, which loses thin casters' shadows.)
TEST(TranslucencyReference, StraightModeAgainstTheGpuGoldens) {
  const uint32_t w = 64, h = 36;
  for (const char* name : {"demo_water_slab", "demo_attenuation_test", "demo_transmission_test"}) {
    LoadedConfig loaded = load_shipped(std::string(name) + ".json", w, h);
    const Scene& scene = loaded.config.scene;
    IntegrationSettings like_the_gpu;
    like_the_gpu.translucent_shadows = false;
    const Renderer renderer(scene, like_the_gpu);
    const ReferenceImage image = render_image(renderer, {.width = w, .height = h, .threads = 2});
    const Image golden = read_pfm(std::string(::volgraph::testing::source_dir()) + "/tests/golden/" + name + ".pfm");
    ASSERT_EQ(golden.width, w);
    std::vector<int> first(size_t(w) * h, -1);
    for (uint32_t j = 0; j < h; ++j) {
      for (uint32_t i = 0; i < w; ++i) {
        const std::optional<SurfaceHit> hit = renderer.surface_hit(physics::pixel_ray(scene.camera, w, h, i, j));
        if (hit) first[size_t(j) * w + i] = int(hit->triangle);
      }
    }
    double sum = 0, worst = 0, glass_sum = 0, glass_worst = 0;
    size_t compared = 0, glass = 0;
    for (uint32_t j = 1; j + 1 < h; ++j) {
      for (uint32_t i = 1; i + 1 < w; ++i) {
        const int object = first[size_t(j) * w + i] < 0 ? -1 : int(renderer.triangles().attributes[size_t(first[size_t(j) * w + i])].object);
        bool interior = true;
        for (uint32_t y = j - 1; y <= j + 1; ++y) {
          for (uint32_t x = i - 1; x <= i + 1; ++x) {
            const int t = first[size_t(y) * w + x];
            interior = interior && (t < 0 ? -1 : int(renderer.triangles().attributes[size_t(t)].object)) == object;
          }
        }
        if (!interior) continue;
        const physics::Rgb mapped = physics::tone_map(image.at(i, j), 0, physics::ToneMap::aces);
        const SurfaceMaterial* seen = first[size_t(j) * w + i] < 0 ? nullptr
            : &renderer.triangles().materials[renderer.triangles().attributes[size_t(first[size_t(j) * w + i])].material];
        const bool through_glass = seen && is_translucent(*seen) && seen->translucency.alpha_mode != AlphaMode::mask;
        for (size_t c = 0; c < 3; ++c) {
          const double e = std::abs(mapped[c] - golden.rgba[(size_t(j) * w + i) * 4 + c]);
          worst = std::max(worst, e);
          sum += e;
          if (through_glass) {
            glass_worst = std::max(glass_worst, e);
            glass_sum += e;
          }
        }
        glass += through_glass ? 1 : 0;
        ++compared;
      }
    }
    std::printf("straight reference vs GPU golden, %s 64x36: %zu pixels, mean abs error %.2e, max %.2e; the %zu seeing an unmasked "
                "translucent surface first: mean %.2e, max %.2e (tone-mapped)\n",
                name, compared, sum / double(3 * std::max<size_t>(compared, 1)), worst, glass, glass_sum / double(3 * std::max<size_t>(glass, 1)),
                glass_worst);
    EXPECT_GT(compared, 0u);
  }
}

}  // namespace
}  // namespace volgraph::reference

namespace volgraph::reference {
namespace {

// glTF's transmission texture in the reference: stored linear (no sRGB decode), its red
// channel × the factor at a texel centre, exactly as stored (TransmissionTest's textured
// spheres; the GPU reads the same bytes as rgba8 unorm).
TEST(TranslucencyReference, TheTransmissionTextureIsReadAsStoredData) {
  const LoadedConfig loaded = load_shipped("demo_transmission_test.json", 12, 8);
  const SceneTriangles triangles = scene_triangles(loaded.config.scene);
  int textured = 0;
  for (const SurfaceMaterial& m : triangles.materials) {
    if (m.transmission_image < 0) continue;
    ++textured;
    const LinearImage& image = triangles.images[size_t(m.transmission_image)];
    const plumbing::GltfModel model = plumbing::load_gltf(std::string(::volgraph::testing::source_dir()) +
                                                          "/../shared/assets/gltf/TransmissionTest/TransmissionTest.glb");
    // The texel (3, 5)'s centre.
    const double u = (3 + 0.5) / image.width, v = (5 + 0.5) / image.height;
    const double stored = image.rgb[(size_t(5) * image.width + 3) * 3];
    EXPECT_NEAR(transmission_at(triangles, m, u, v), m.translucency.transmission * stored, 1e-9);
    bool found = false;  // the value is a stored byte / 255, not an sRGB decode of it
    for (const plumbing::GltfPrimitive& p : model.primitives) {
      if (!p.transmission_texture) continue;
      const plumbing::Rgba8Image bytes = model.images[size_t(p.transmission_texture.image)].decode();
      if (bytes.width != image.width || bytes.height != image.height) continue;
      found |= std::abs(stored - bytes.texels[(size_t(5) * bytes.width + 3) * 4] / 255.0) < 1e-7;
    }
    EXPECT_TRUE(found);
  }
  EXPECT_GT(textured, 0) << "TransmissionTest has textured transmission";
}

}  // namespace
}  // namespace volgraph::reference
