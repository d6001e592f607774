// The CPU twin of the light's transmittance through the local volumes
// (physics/light_transmittance.h), against closed forms and brute force:
// - a box without edge fade or noise dims a point light by e^(−σt·chord) exactly (the chord
//   of the segment to the light, known for an axis-aligned box), whatever the samples, and a
//   light the box does not lie toward is not dimmed;
// - a directional light sees the box only within `max_distance`;
// - a noisy, faded volume's optical depth, averaged over a sweep of jitters, is the midpoint
//   rule's of MediaField's point density over the segment (1e5 points) to 1e-3 relative;
// - 0 samples: no volume shadows.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/light_transmittance.h"
#include "physics/media_field.h"

namespace volgraph::physics {
namespace {

Media one_box(double edge_fade, int octaves) {
  Media media;
  MediumVolume box{.shape = Shape::box, .size = {2, 4, 2}};
  box.transform.translate = {0, 5, 0};  // y from 3 to 7
  box.medium = {.sigma_s = {0.2, 0.1, 0.05}, .sigma_a = {0.1, 0.2, 0.3}};
  box.noise = {.octaves = octaves, .scale = 0.7, .coverage = 0.8, .edge_fade = edge_fade};
  media.volumes.push_back(box);
  return media;
}

Light point_light_at(const Vec3& p) {
  Light l;
  l.type = LightType::point;
  l.position = p;
  l.intensity = {1, 1, 1};
  return l;
}

TEST(LightTransmittance, AUniformBoxDimsByItsExactChord) {
  const Media media = one_box(0, 0);
  const Light above = point_light_at({0.3, 10, -0.2});
  for (int samples : {1, 8, 64}) {
    const Vec3 t = transmittance_to_light(media, above, {0.3, 0, -0.2}, samples, 50, 0.5);
    const double chord = 4;  // straight up through y 3 … 7
    EXPECT_NEAR(t[0], std::exp(-0.3 * chord), 1e-12) << samples;
    EXPECT_NEAR(t[1], std::exp(-0.3 * chord), 1e-12) << samples;
    EXPECT_NEAR(t[2], std::exp(-0.35 * chord), 1e-12) << samples;
  }
  const Vec3 beside = transmittance_to_light(media, point_light_at({3, 10, 0}), {3, 0, 0}, 8, 50, 0.5);
  EXPECT_EQ(beside[0], 1.0);
  const Vec3 off = transmittance_to_light(media, above, {0.3, 0, -0.2}, 0, 50, 0.5);
  EXPECT_EQ(off[0], 1.0);
}

TEST(LightTransmittance, ADirectionalLightSeesTheBoxWithinMaxDistance) {
  const Media media = one_box(0, 0);
  Light sun;
  sun.type = LightType::directional;
  sun.direction = {0, -1, 0};
  sun.irradiance = {1, 1, 1};
  EXPECT_NEAR(transmittance_to_light(media, sun, {0, 0, 0}, 8, 50, 0.5)[0], std::exp(-0.3 * 4), 1e-12);
  EXPECT_NEAR(transmittance_to_light(media, sun, {0, 0, 0}, 8, 5, 0.5)[0], std::exp(-0.3 * 2), 1e-12);  // y 3 … 5 only
  EXPECT_EQ(transmittance_to_light(media, sun, {0, 0, 0}, 8, 2, 0.5)[0], 1.0);
}

TEST(LightTransmittance, ANoisyVolumesDepthOverJittersIsThePointDensitysIntegral) {
  const Media media = one_box(0.3, 4);
  const MediaField field(media);
  const Vec3 p{0.2, 1, 0.1}, light_at{-0.4, 9, 0.5};
  const glm::dvec3 d = vec(light_at) - vec(p);
  const double length = glm::length(d);
  double integral = 0;
  const int n = 100000;
  for (int k = 0; k < n; ++k) {
    const Vec3 x = to_vec3(vec(p) + d * ((k + 0.5) / n));
    integral += field.sample(x).sigma_a[0] + field.sample(x).sigma_s[0];
  }
  integral *= length / n;
  ASSERT_GT(integral, 0.1);
  double mean = 0;
  const int jitters = 64;
  for (int j = 0; j < jitters; ++j) {
    const double jitter = (j + 0.5) / jitters;
    mean += -std::log(transmittance_to_light(media, point_light_at(light_at), p, 8, 50, jitter)[0]) / jitters;
  }
  EXPECT_NEAR(mean, integral, 1e-3 * integral);
}

}  // namespace
}  // namespace volgraph::physics
