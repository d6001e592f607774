// The CPU twins of froxel_voxelize's average (physics/shape_interval.h,
// physics/media_average.h) against closed forms and brute force:
// - the unit box and ball: intervals of axis rays known exactly; rays that miss, graze or
//   start inside; a transformed volume's interval ends lie on its surface (inside distance
//   0, physics/media_field.h) with the inside between them;
// - a uniform volume's mean density is the fraction of the segment inside: against a
//   midpoint rule of MediaField's point density (1e4 points: ±1e-4 of a fraction, a
//   point's half-width at each surface);
// - the height fog's mean density against adaptive Simpson quadrature (1e-9 relative),
//   and on a segment of no length the density there;
// - a faded or noisy volume's sub-samples: at the strata's centres (jitter 0) near the
//   mean, and averaged over a sweep of jitters (equally spaced in (−½, ½)) the mean itself
//   to the sweep's resolution;
// - the media summed: coefficients × mean densities, g weighted by σs.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/media.h"
#include "physics/media_average.h"
#include "physics/media_field.h"
#include "physics/shape_interval.h"
#include "tests/support/adaptive_simpson.h"

namespace volgraph::physics {
namespace {

TEST(ShapeInterval, AxisRaysThroughTheUnitShapesAreExact) {
  const std::optional<RayInterval> box = unit_box_interval({-2, 0.1, -0.2}, {1, 0, 0});
  ASSERT_TRUE(box);
  EXPECT_DOUBLE_EQ(box->enter, 1.5);
  EXPECT_DOUBLE_EQ(box->exit, 2.5);
  const std::optional<RayInterval> ball = unit_ball_interval({0, 0, 3}, {0, 0, -2});  // a ray of length 2
  ASSERT_TRUE(ball);
  EXPECT_DOUBLE_EQ(ball->enter, 1.0);
  EXPECT_DOUBLE_EQ(ball->exit, 2.0);
  const std::optional<RayInterval> from_inside = unit_ball_interval({0, 0.6, 0}, {0, 1, 0});
  ASSERT_TRUE(from_inside);
  EXPECT_DOUBLE_EQ(from_inside->enter, -1.6);
  EXPECT_DOUBLE_EQ(from_inside->exit, 0.4);
}

TEST(ShapeInterval, RaysThatMissHaveNone) {
  EXPECT_FALSE(unit_box_interval({-2, 0.6, 0}, {1, 0, 0}));   // parallel to a slab, outside it
  EXPECT_FALSE(unit_box_interval({-2, 0, 0}, {1, 2, 0}));     // crosses x's slab where y's is behind
  EXPECT_FALSE(unit_ball_interval({-2, 1.01, 0}, {1, 0, 0}));
  EXPECT_FALSE(unit_ball_interval({0, 0, 0}, {0, 0, 0}));     // no direction
  const std::optional<RayInterval> grazing = unit_ball_interval({-2, 1, 0}, {1, 0, 0});
  ASSERT_TRUE(grazing);
  EXPECT_NEAR(grazing->enter, 2.0, 1e-7);
  EXPECT_NEAR(grazing->exit, 2.0, 1e-7);
}

Media three_volumes(double fade, int octaves) {
  Media media;
  const Shape shapes[] = {Shape::box, Shape::sphere, Shape::ellipsoid};
  for (size_t i = 0; i < 3; ++i) {
    MediumVolume v{.shape = shapes[i], .size = {2.0, 1.5, 1.2}};
    v.transform.translate = {-3.0 + 3.0 * double(i), 1.0, -6.0};
    v.transform.rotate_deg = {20.0 * double(i), 35, 10};
    v.transform.scale = {1, 1.0 + 0.3 * double(i), 0.8};
    v.medium = {.sigma_s = {2, 3, 4}, .sigma_a = {1, 0.5, 0.25}, .g = 0.6, .emission = {0.5, 0.25, 0.125}};
    v.noise = {.octaves = octaves, .scale = 0.4, .coverage = 0.8, .edge_fade = fade};
    media.volumes.push_back(v);
  }
  return media;
}

// Camera-like rays from (0, 1, 0) toward the volumes, of forward component 1 (view depth
// t): a 9 × 7 fan, or every other one of it.
std::vector<Vec3> rays_toward_the_volumes(int every = 1) {
  std::vector<Vec3> rays;
  for (int i = 0; i < 9; i += every) {
    for (int j = 0; j < 7; j += every) rays.push_back({-0.8 + 0.2 * i, -0.3 + 0.1 * j, -1});
  }
  return rays;
}

const Vec3 kOrigin{0, 1, 0};

Vec3 at(const Vec3& origin, const Vec3& ray, double t) { return to_vec3(vec(origin) + t * vec(ray)); }

TEST(ShapeInterval, AVolumesIntervalEndsLieOnItsSurface) {
  const MediaField field(three_volumes(0, 0));
  size_t hits = 0;
  for (const Vec3& ray : rays_toward_the_volumes()) {
    for (size_t i = 0; i < 3; ++i) {
      const std::optional<RayInterval> chord = volume_interval(field, i, kOrigin, ray);
      if (!chord) {  // no point of a fine march along the ray is inside
        for (double t = 0; t < 20; t += 1e-3) ASSERT_LT(field.inside_distance(i, at(kOrigin, ray, t)), 1e-9) << "volume " << i;
        continue;
      }
      ++hits;
      EXPECT_NEAR(field.inside_distance(i, at(kOrigin, ray, chord->enter)), 0.0, 1e-12) << "volume " << i;
      EXPECT_NEAR(field.inside_distance(i, at(kOrigin, ray, chord->exit)), 0.0, 1e-12) << "volume " << i;
      if (chord->exit - chord->enter < 1e-6) continue;
      EXPECT_GT(field.inside_distance(i, at(kOrigin, ray, (chord->enter + chord->exit) / 2)), 0.0) << "volume " << i;
    }
  }
  EXPECT_GT(hits, 30u);  // of 189 ray–volume pairs
}

// The mean of `density` over t ∈ [t0, t1] by the midpoint rule on n points.
template <typename Density>
double midpoint_mean(const Density& density, double t0, double t1, int n) {
  double sum = 0;
  for (int k = 0; k < n; ++k) sum += density(t0 + (t1 - t0) * (k + 0.5) / n);
  return sum / n;
}

TEST(MediaAverage, AUniformVolumeHoldsTheFractionOfTheSegmentInside) {
  const MediaField field(three_volumes(0, 0));
  size_t partial = 0;
  for (const Vec3& ray : rays_toward_the_volumes(2)) {
    for (double t0 = 3.5; t0 < 8.5; t0 += 0.37) {
      const RaySegment s{kOrigin, ray, t0, t0 + 0.29};
      for (size_t i = 0; i < 3; ++i) {
        const double want = midpoint_mean([&](double t) { return field.volume_density(i, at(kOrigin, ray, t)); }, s.t0, s.t1, 10000);
        const double got = volume_mean_density(field, i, s, 0.0);
        EXPECT_NEAR(got, want, 1e-4) << "volume " << i << " t0 " << t0;
        partial += got > 0.01 && got < 0.99;
      }
    }
  }
  EXPECT_GT(partial, 10u);  // segments across the surfaces, not only whole or empty ones
}

TEST(MediaAverage, TheHeightFogsMeanMatchesQuadrature) {
  const HeightFog fog{.medium = {.sigma_s = {0.1, 0.1, 0.1}}, .base_height = 0.5, .falloff = 0.7};
  Media media;
  media.height_fog = fog;
  const MediaField field(media);
  for (const Vec3& ray : rays_toward_the_volumes()) {
    for (double t0 : {0.1, 2.0, 9.0}) {
      const RaySegment s{kOrigin, {ray[0], 3 * ray[1], ray[2]}, t0, t0 * 1.3 + 0.5};
      const auto density = [&](double t) { return field.height_fog_density(at(s.origin, s.ray, t)); };
      const double want = test::adaptive_simpson(density, s.t0, s.t1, 1e-13, 40) / (s.t1 - s.t0);
      EXPECT_NEAR(height_fog_mean_density(fog, s), want, 1e-9 * want) << "t0 " << t0;
    }
  }
  // A segment of no length (a froxel whose depth range rounds to nothing): the density there.
  const RaySegment point{kOrigin, {0.2, -0.1, -1}, 3.0, 3.0};
  const double there = field.height_fog_density(at(point.origin, point.ray, 3.0));
  EXPECT_NEAR(height_fog_mean_density(fog, point), there, 1e-12 * there);
}

TEST(MediaAverage, SubSamplesOfFadedOrNoisyVolumesConvergeOverJitters) {
  for (const auto& [fade, octaves] : {std::pair{0.3, 0}, std::pair{0.0, 3}, std::pair{0.2, 2}}) {
    const MediaField field(three_volumes(fade, octaves));
    double worst_centres = 0, worst_sweep = 0;
    for (const Vec3& ray : rays_toward_the_volumes(2)) {
      for (double t0 = 3.5; t0 < 8.5; t0 += 0.61) {
        const RaySegment s{kOrigin, ray, t0, t0 + 0.47};
        for (size_t i = 0; i < 3; ++i) {
          const double want = midpoint_mean([&](double t) { return field.volume_density(i, at(kOrigin, ray, t)); }, s.t0, s.t1, 4000);
          constexpr int kJitters = 64;
          double sweep = 0;
          for (int j = 0; j < kJitters; ++j) sweep += volume_mean_density(field, i, s, (j + 0.5) / kJitters - 0.5) / kJitters;
          worst_centres = std::max(worst_centres, std::abs(volume_mean_density(field, i, s, 0.0) - want));
          worst_sweep = std::max(worst_sweep, std::abs(sweep - want));
        }
      }
    }
    // The sweep is a midpoint rule of 4 × 64 points over the part inside (the noise's
    // finest cells, 0.1 local units, span about 20 of them): ≤ 1e-3.
    EXPECT_LT(worst_sweep, 1e-3) << "fade " << fade << " octaves " << octaves;
    EXPECT_LT(worst_sweep, worst_centres / 10) << "fade " << fade << " octaves " << octaves;
  }
}

TEST(MediaAverage, TheMediaSumTheirCoefficientsTimesTheirMeanDensities) {
  Media media = three_volumes(0, 0);
  media.fog = Medium{.sigma_s = {0.02, 0.03, 0.04}, .sigma_a = {0.01, 0.01, 0.01}, .g = 0.2};
  media.height_fog = HeightFog{.medium = {.sigma_s = {0.05, 0.05, 0.05}, .g = -0.3}, .base_height = 0, .falloff = 0.3};
  const MediaField field(media);
  const RaySegment s{kOrigin, {0.1, -0.05, -1}, 5.5, 6.5};
  const double h = height_fog_mean_density(*media.height_fog, s);
  const double v = volume_mean_density(field, 1, s, 0.0);
  ASSERT_GT(v, 0.0);
  ASSERT_EQ(volume_mean_density(field, 0, s, 0.0), 0.0);
  ASSERT_EQ(volume_mean_density(field, 2, s, 0.0), 0.0);
  const MediaSample got = average_media(field, s, 0.0);
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_DOUBLE_EQ(got.sigma_s[c], media.fog->sigma_s[c] + h * media.height_fog->medium.sigma_s[c] + v * media.volumes[1].medium.sigma_s[c]);
    EXPECT_DOUBLE_EQ(got.sigma_a[c], media.fog->sigma_a[c] + v * media.volumes[1].medium.sigma_a[c]);
    EXPECT_DOUBLE_EQ(got.emission[c], v * media.volumes[1].medium.emission[c]);
  }
  const double w_fog = 0.09, w_height = 0.15 * h, w_volume = 9 * v;
  EXPECT_NEAR(got.g, (0.2 * w_fog - 0.3 * w_height + 0.6 * w_volume) / (w_fog + w_height + w_volume), 1e-12);
}

}  // namespace
}  // namespace volgraph::physics
