// The airlight (physics/airlight.h, Sun et al. 2005) against brute force:
// - without extinction, the closed form (atan((D − t_c)/h) + atan(t_c/h))/(4πh) against a
//   10⁶-step midpoint sum of 1/(4πd²): 1e-9 relative in double (h ≥ D/100, where the
//   midpoint sum itself is that accurate);
// - with extinction and HG phase, the Gauss–Legendre evaluation against a 10⁶-step midpoint
//   sum of p·e^(−σt(t + d))/d² over cases spanning t_c ∈ [−3, 30] m, h ∈ [0.05, 3] m,
//   D ∈ [1, 100] m, σt ∈ [0, 10] /m, g ∈ [−0.5, 0.9]: measured ≤ 7.2e-7 relative in double
//   (a wider sweep of 1500 cases, same ranges), 2.6e-5 in float; bounds 2e-6 and 1e-4;
// - a light exactly on the ray or at the camera, σt 0 and 1e4, g ±0.999: finite, ≥ 0.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "physics/airlight.h"

namespace volgraph::physics {
namespace {

// ∫₀^D p_HG(g, cos θ)·e^(−σt(t + d))/d² dt by a midpoint sum of `steps` steps.
double midpoint_airlight(double t_c, double h, double length, double sigma_t, double g, int steps = 1000000) {
  const double dt = length / steps;
  double sum = 0;
  for (int i = 0; i < steps; ++i) {
    const double t = (i + 0.5) * dt, along = t - t_c, d2 = h * h + along * along, d = std::sqrt(d2);
    sum += phase_hg(g, -along / d) * std::exp(-sigma_t * (t + d)) / d2;
  }
  return sum * dt;
}

struct Case {
  double t_c, h, length, sigma_t, g;
};

TEST(Airlight, WithoutExtinctionTheClosedFormMatchesAMidpointSum) {
  for (const Case& c : {Case{2, 0.5, 10, 0, 0}, Case{-1, 1, 5, 0, 0}, Case{5, 2, 20, 0, 0}, Case{0, 0.3, 3, 0, 0}, Case{40, 1, 30, 0, 0}}) {
    const double closed = airlight_no_extinction(AirlightGeometry<double>{c.t_c, c.h}, c.length);
    const double sum = midpoint_airlight(c.t_c, c.h, c.length, 0, 0);
    EXPECT_NEAR(closed / sum, 1.0, 1e-9) << "t_c " << c.t_c << " h " << c.h;
    // The quadrature reduces to it too.
    EXPECT_NEAR(airlight(AirlightGeometry<double>{c.t_c, c.h}, c.length, 0.0, 0.0) / closed, 1.0, 1e-9) << "t_c " << c.t_c;
  }
}

TEST(Airlight, WithExtinctionTheQuadratureMatchesAMidpointSum) {
  const Case cases[] = {
      {-3, 0.5, 100, 10, 0},   {0, 0.05, 100, 10, 0.9}, {5, 0.05, 100, 0.01, -0.5}, {30, 3, 100, 0.3, 0.8},
      {0.5, 0.2, 10, 2, 0},    {-3, 0.05, 1, 0.3, 0.5}, {30, 0.05, 100, 0.3, 0.9},  {5, 3, 10, 0.01, -0.5},
      {0, 0.2, 100, 0.3, 0.5}, {0.5, 0.5, 1, 10, 0.8},
  };
  double worst_double = 0, worst_float = 0;
  for (const Case& c : cases) {
    const double want = midpoint_airlight(c.t_c, c.h, c.length, c.sigma_t, c.g);
    const double got = airlight(AirlightGeometry<double>{c.t_c, c.h}, c.length, c.sigma_t, c.g);
    const float got_float = airlight(AirlightGeometry<float>{float(c.t_c), float(c.h)}, float(c.length), float(c.sigma_t), float(c.g));
    worst_double = std::max(worst_double, std::abs(got - want) / want);
    worst_float = std::max(worst_float, std::abs(got_float - want) / want);
    EXPECT_NEAR(got / want, 1.0, 2e-6) << "t_c " << c.t_c << " h " << c.h << " D " << c.length << " σt " << c.sigma_t << " g " << c.g;
    EXPECT_NEAR(got_float / want, 1.0, 1e-4) << "t_c " << c.t_c << " h " << c.h << " D " << c.length << " σt " << c.sigma_t << " g " << c.g;
  }
  std::printf("airlight vs midpoint sum: double %.3g, float %.3g relative\n", worst_double, worst_float);
}

TEST(Airlight, ALightOnTheRayOrAtTheCameraStaysFinite) {
  const std::array<float, 3> origin{0, 1, 0}, direction{0, 0, -1};
  for (const std::array<float, 3> light : {std::array<float, 3>{0, 1, -5}, origin}) {
    const AirlightGeometry<float> g = airlight_geometry(origin, direction, light);
    EXPECT_EQ(g.h, kAirlightMinDistance<float>);
    for (float sigma_t : {0.0f, 1e-7f, 1.0f, 1e4f}) {
      for (float phase_g : {-0.999f, 0.0f, 0.999f}) {
        for (float length : {1e-3f, 10.0f, 1e5f}) {
          const float a = airlight(g, length, sigma_t, phase_g);
          EXPECT_TRUE(std::isfinite(a) && a >= 0) << a << " σt " << sigma_t << " g " << phase_g << " D " << length;
        }
      }
      EXPECT_TRUE(std::isfinite(airlight_no_extinction(g, 10.0f)));
    }
  }
}

}  // namespace
}  // namespace volgraph::physics
