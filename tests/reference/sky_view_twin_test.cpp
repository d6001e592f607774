// The sky pass's double twin (physics/atmosphere_sky.h marched_sky_radiance,
// limb_darkening) against the CPU reference (reference/atmosphere_reference.h sky(), single
// scattering: adaptive Simpson, its ground's sun term, the disk) on the rays the sky pass
// draws — from the ground, from 3 km down onto the ground, from space through the limb and
// onto the lit ground, from space past the atmosphere — and the limb darkening's
// normalisation: the darkened disk's irradiance is E. Measured: the twin within 3.4e-3 of the
// reference on these rays (the ground's 10° ray, the march's 40 samples), 4e-4 through the limb.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "physics/atmosphere.h"
#include "physics/atmosphere_sky.h"
#include "reference/atmosphere_reference.h"

namespace volgraph {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ∫ over the disk of L cos θ dω per unit E = Σ over rings of ρ = sin θ / sin α: the
// projected solid angle of a ring is π sin²α · 2ρ dρ exactly (midpoint rule, 20000 rings).
TEST(SkyViewTwin, TheLimbDarkenedDiskKeepsItsIrradiance) {
  const double alpha = 0.004675, scale = physics::sun_disk_radiance_scale(alpha);
  Vec3 irradiance{0, 0, 0};
  const int rings = 20000;
  for (int k = 0; k < rings; ++k) {
    const double rho = (k + 0.5) / rings;
    const Vec3 limb = physics::limb_darkening(rho);
    for (size_t c = 0; c < 3; ++c) irradiance[c] += scale * limb[c] * kPi * std::sin(alpha) * std::sin(alpha) * 2 * rho / rings;
  }
  for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(irradiance[c], 1.0, 1e-6) << "channel " << c;
  // Darker at the limb than at the centre, bluer darker (a grows toward the blue).
  EXPECT_GT(physics::limb_darkening(0)[0], physics::limb_darkening(0.9)[0]);
  EXPECT_LT(physics::limb_darkening(0.9)[2], physics::limb_darkening(0.9)[0]);
  EXPECT_EQ(physics::limb_darkening(1.01)[1], 0.0);
}

struct Ray {
  const char* what;
  double altitude;  // m
  Vec3 direction;   // world (the camera straight above the planet's centre)
};

// Relative error of the twin (40 midpoint samples, E = 1) per ray, largest channel.
TEST(SkyViewTwin, MarchedSkyMatchesTheReferenceAtSingleScattering) {
  const Atmosphere a = *physics::atmosphere_preset("earth");
  const Vec3 toward_sun = physics::normalize(Vec3{0, 0.3, -1});
  reference::AtmosphereReferenceSettings settings;
  settings.samples = 0;
  settings.relative_tolerance = 1e-6;
  const reference::AtmosphereReference ref(a, {toward_sun, {1, 1, 1}, a.sun_angular_radius}, settings);
  const Ray rays[] = {
      {"from the ground, 10 degrees up", 0, physics::normalize(Vec3{0, 0.18, -1})},
      {"from 3 km onto the ground", 3000, physics::normalize(Vec3{0.2, -0.5, -1})},
      {"from 400 km through the limb", 400e3, physics::normalize(Vec3{0, -0.345, -1})},
      {"from 400 km onto the lit ground", 400e3, physics::normalize(Vec3{0.1, -1, -0.4})},
      {"from 400 km past the atmosphere", 400e3, physics::normalize(Vec3{0, 0.1, -1})},
  };
  for (const Ray& ray : rays) {
    physics::AtmosphereView view;
    view.r = a.bottom_radius + ray.altitude;
    view.up = {0, 1, 0};
    view.toward_sun = toward_sun;
    view.mu_s = toward_sun[1];
    view.has_sun = true;
    const Vec3 twin = physics::marched_sky_radiance(a, view, ray.direction);
    const reference::SkySample want = ref.sky({0, view.r, 0}, ray.direction, 0);
    double worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      const double scale = std::max(want.radiance[c], 1e-30);
      worst = std::max(worst, std::abs(twin[c] - want.radiance[c]) / scale);
      if (want.radiance[c] == 0) EXPECT_EQ(twin[c], 0.0) << ray.what;
    }
    std::printf("%s: twin %.4g %.4g %.4g, reference %.4g %.4g %.4g, relative error %.3g\n", ray.what, twin[0], twin[1], twin[2],
                want.radiance[0], want.radiance[1], want.radiance[2], worst);
    EXPECT_LT(worst, 1e-2) << ray.what;
  }
}

}  // namespace
}  // namespace volgraph
