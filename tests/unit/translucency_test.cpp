// physics/translucency.h against what optics gives exactly (RTR4 §14.5; double unless
// stated):
// - Fresnel at normal incidence for n = 1.5 is 0.04; Schlick's form equals F0 at normal
//   incidence and 1 at grazing, and rises monotonically between;
// - Bec's refraction obeys Snell's law (n₁ sin θi = n₂ sin θt) and gives a unit vector on the
//   far side, within 1e-12; IOR 1 leaves the direction exactly unchanged (float and double);
//   total internal reflection exactly beyond the critical angle asin(n₂/n₁);
// - a slab of σt = −ln(c)/d transmits c at normal incidence (to rounding) and e^(−σt d/cos θt)
//   at an angle; transmittance 0 and 1, thickness 0 and grazing rays give finite values;
// - a slab shifts a ray it passes by d sin(θ − θt)/cos θt across it (screen-space
//   refraction's exit point), exactly 0 at IOR 1 and at normal incidence.
#include <cmath>

#include <gtest/gtest.h>

#include "physics/translucency.h"

namespace volgraph::physics {
namespace {

using V = Vec3Of<double>;

double dot3(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The unit vector at angle `theta` from the +y normal, in the xy plane, toward +x.
V toward(double theta) { return {std::sin(theta), std::cos(theta), 0}; }

TEST(Translucency, FresnelAtNormalIncidenceForGlassIsFourPercent) {
  EXPECT_DOUBLE_EQ(fresnel_f0(1.0, 1.5), 0.04);
  EXPECT_DOUBLE_EQ(fresnel_f0(1.5, 1.0), 0.04);
  EXPECT_EQ(fresnel_f0(1.33, 1.33), 0.0);
  EXPECT_DOUBLE_EQ(fresnel_schlick(0.04, 1.0), 0.04);
  EXPECT_DOUBLE_EQ(fresnel_schlick(0.04, 0.0), 1.0);
  double previous = 0.04;
  for (double c = 0.95; c >= 0; c -= 0.05) {
    const double f = fresnel_schlick(0.04, c);
    EXPECT_GT(f, previous) << "cos " << c;
    previous = f;
  }
}

TEST(Translucency, BecsRefractionObeysSnellsLaw) {
  const V normal{0, 1, 0};
  for (const double eta : {1.0 / 1.5, 1.0 / 1.33, 1.5, 1.2}) {
    const double critical = eta > 1 ? std::asin(1 / eta) : M_PI / 2;
    for (double theta = 0; theta < M_PI / 2; theta += 0.01) {
      const std::optional<V> t = refract_bec(toward(theta), normal, eta);
      if (theta > critical + 1e-9) {
        EXPECT_FALSE(t) << "eta " << eta << " theta " << theta << ": beyond the critical angle";
        continue;
      }
      if (theta < critical - 1e-9) ASSERT_TRUE(t) << "eta " << eta << " theta " << theta;
      if (!t) continue;
      EXPECT_NEAR(dot3(*t, *t), 1, 1e-12);
      EXPECT_LE(dot3(*t, normal), 0) << "the transmitted ray goes into the far side";
      const double sin_t = std::sqrt((*t)[0] * (*t)[0] + (*t)[2] * (*t)[2]);
      EXPECT_NEAR(sin_t, eta * std::sin(theta), 1e-12) << "Snell: n₁ sin θi = n₂ sin θt";
      EXPECT_LE((*t)[0], 0) << "it continues across the normal, away from the incident side";
    }
  }
}

TEST(Translucency, IorOneLeavesTheDirectionExactlyUnchanged) {
  const V normal{0, 1, 0};
  for (double theta = 0; theta < 1.55; theta += 0.1) {
    const V l = toward(theta);
    const std::optional<V> t = refract_bec(l, normal, 1.0);
    ASSERT_TRUE(t);
    for (size_t i = 0; i < 3; ++i) EXPECT_EQ((*t)[i], -l[i]) << "theta " << theta;
    const Vec3Of<float> lf{float(l[0]), float(l[1]), float(l[2])};
    const std::optional<Vec3Of<float>> tf = refract_bec(lf, {0.0f, 1.0f, 0.0f}, 1.0f);
    ASSERT_TRUE(tf);
    for (size_t i = 0; i < 3; ++i) EXPECT_EQ((*tf)[i], -lf[i]) << "float, theta " << theta;
  }
}

TEST(Translucency, TotalInternalReflectionBeyondTheCriticalAngle) {
  const double eta = 1.5;  // glass to air
  const double critical = std::asin(1 / eta);
  EXPECT_TRUE(refract_bec(toward(critical - 1e-6), {0, 1, 0}, eta));
  EXPECT_FALSE(refract_bec(toward(critical + 1e-6), {0, 1, 0}, eta));
}

TEST(Translucency, ASlabTransmitsItsColourAtNormalIncidenceAndLessAtAnAngle) {
  for (const double color : {0.9, 0.5, 0.01}) {
    const double d = 0.03;
    const double sigma_t = sigma_t_from_color(color, d);
    EXPECT_NEAR(slab_transmittance(sigma_t, d, 1.0), color, 1e-15);
    const double cos_t = std::cos(0.6);
    EXPECT_NEAR(slab_transmittance(sigma_t, d, cos_t), std::pow(color, 1 / cos_t), 1e-15) << "the longer path at an angle";
  }
}

TEST(Translucency, LimitsStayFinite) {
  EXPECT_EQ(sigma_t_from_color(1.0, 0.1), 0.0);
  const double opaque = sigma_t_from_color(0.0, 0.1);
  EXPECT_TRUE(std::isfinite(opaque));
  EXPECT_LT(slab_transmittance(opaque, 0.1, 1.0), 1e-29);
  EXPECT_EQ(slab_transmittance(opaque, 0.0, 1.0), 1.0) << "thickness 0";
  EXPECT_EQ(slab_transmittance(opaque, 0.1, 0.0), 0.0) << "a grazing ray through an absorbing slab";
  EXPECT_EQ(slab_transmittance(0.0, 0.1, 0.0), 1.0) << "a grazing ray through a clear slab";
  EXPECT_TRUE(std::isfinite(sigma_t_from_color(0.0f, 0.1f)));
}

// A slab d thick (normal +y) seen at θ from its normal: the ray leaves it displaced across
// its own direction by d sin(θ − θt)/cos θt (Snell's law; the textbook lateral shift),
// perpendicular to the view ray, toward the normal's side; none at normal incidence or IOR 1.
TEST(Translucency, ASlabShiftsTheRayItPassesByTheLateralDisplacement) {
  const double d = 0.3, ior = 1.5;
  for (double theta : {0.1, 0.4, 0.8, 1.2, 1.5}) {
    const V l = toward(theta);                      // toward the viewer
    const double path = d / std::cos(theta);        // along the view ray, face to face
    const V offset = slab_exit_offset(l, V{0, 1, 0}, ior, path);
    const double theta_t = std::asin(std::sin(theta) / ior);
    EXPECT_NEAR(std::sqrt(dot3(offset, offset)), d * std::sin(theta - theta_t) / std::cos(theta_t), 1e-12) << theta;
    EXPECT_NEAR(dot3(offset, l), 0, 1e-12) << theta;  // across the view ray
    EXPECT_GT(offset[0], 0) << theta;                  // bent toward the normal: the exit lies on the viewer's side in x
  }
  const V head_on = slab_exit_offset(V{0, 1, 0}, V{0, 1, 0}, ior, d);
  EXPECT_EQ(dot3(head_on, head_on), 0);
  const V no_interface = slab_exit_offset(toward(0.7), V{0, 1, 0}, 1.0, d);
  EXPECT_EQ(no_interface, (V{0, 0, 0}));
  // Float (the GPU twin's precision) at θ = 36.87° (sin 0.6): within 1e-6 m of the double's.
  const float shift = slab_exit_offset(Vec3Of<float>{0.6f, 0.8f, 0}, Vec3Of<float>{0, 1, 0}, 1.5f, 0.5f)[0];
  EXPECT_NEAR(shift, slab_exit_offset(V{0.6, 0.8, 0}, V{0, 1, 0}, 1.5, 0.5)[0], 1e-6);
}

// The rough-refraction level: 0 where nothing blurs (smooth, IOR 1, nothing behind); log2
// of the cone's footprint in pixels otherwise — 2 α (1 − 1/η) path / (distance · pixel
// angle): roughness 0.5 at IOR 1.5 over 3 m behind, seen 6 m away at 0.01 rad a pixel, is
// 2 · 0.25 · (1/3) · 3 / 0.06 = 8.33 px; twice the path is one level more.
TEST(Translucency, TheRefractionBlurLevelIsTheConesFootprintInPixels) {
  EXPECT_EQ(refraction_blur_lod(0.0, 1.5, 3.0, 6.0, 0.01), 0.0);
  EXPECT_EQ(refraction_blur_lod(0.5, 1.0, 3.0, 6.0, 0.01), 0.0);
  EXPECT_EQ(refraction_blur_lod(0.5, 1.5, 0.0, 6.0, 0.01), 0.0);
  EXPECT_EQ(refraction_blur_lod(0.1, 1.5, 0.01, 6.0, 0.01), 0.0);  // under a pixel: level 0, never below
  EXPECT_NEAR(refraction_blur_lod(0.5, 1.5, 3.0, 6.0, 0.01), std::log2(2 * 0.25 * (1.0 / 3.0) * 3 / 0.06), 1e-12);
  EXPECT_NEAR(refraction_blur_lod(0.5, 1.5, 6.0, 6.0, 0.01) - refraction_blur_lod(0.5, 1.5, 3.0, 6.0, 0.01), 1.0, 1e-12);
  EXPECT_TRUE(std::isfinite(refraction_blur_lod(1.0f, 4.0f, 1e30f, 1e-30f, 1e-9f)));
}

}  // namespace
}  // namespace volgraph::physics

namespace volgraph::physics {
namespace {

using Vec3d = Vec3Of<double>;

Vec3d unit_of(const Vec3d& v) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}
double dot_of(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// A ball of radius 1 at the origin: a ray from `origin` along unit `d` enters it, is bent by
// Bec's form, meets the sphere again and leaves by Bec's form — the exact two interfaces —
// and sphere_exit, given only the entry, its normal and the chord along the view ray, finds
// the same exit point and direction (to double rounding) at IOR 1.2, 1.5 and 2.4.
TEST(Translucency, TheSphereModelLeavesABallWhereTheBallIsLeft) {
  for (const double ior : {1.2, 1.5, 2.4}) {
    for (const double height : {0.0, 0.3, 0.6, 0.9}) {
      const Vec3d origin{height, 0.2 * height, 5}, d{0, 0, -1};
      // Entry: |origin + t d| = 1, the nearer root; the chord along the view ray to the far root.
      const double b = dot_of(origin, d), c = dot_of(origin, origin) - 1, root = std::sqrt(b * b - c);
      const double t_in = -b - root, chord = 2 * root;
      const Vec3d entry{origin[0] + t_in * d[0], origin[1] + t_in * d[1], origin[2] + t_in * d[2]};
      const Vec3d to_incident{-d[0], -d[1], -d[2]};
      const Vec3d normal = unit_of(entry);
      const SphereExit<double> model = sphere_exit(to_incident, normal, ior, chord);
      // The exact path.
      const Vec3d inside = *refract_bec(to_incident, normal, 1 / ior);
      const double s = -2 * dot_of(entry, inside);  // the second root of |entry + s inside| = 1
      const Vec3d exit{entry[0] + s * inside[0], entry[1] + s * inside[1], entry[2] + s * inside[2]};
      const Vec3d exit_normal_inward{-exit[0], -exit[1], -exit[2]};
      const std::optional<Vec3d> out = refract_bec(Vec3d{-inside[0], -inside[1], -inside[2]}, exit_normal_inward, ior);
      ASSERT_TRUE(out);
      for (size_t k = 0; k < 3; ++k) {
        EXPECT_NEAR(entry[k] + model.offset[k], exit[k], 1e-12) << "ior " << ior << " height " << height;
        EXPECT_NEAR(model.direction[k], (*out)[k], 1e-12) << "ior " << ior << " height " << height;
      }
    }
  }
}

// Straight through where nothing bends it: IOR 1, no path, a grazing entry.
TEST(Translucency, TheSphereModelGoesStraightWithoutAnInterface) {
  const Vec3d to_incident{0, 0, 1}, normal = unit_of({0.3, 0, 1});
  for (const auto& [ior, path] : {std::pair{1.0, 0.7}, std::pair{1.5, 0.0}}) {
    const SphereExit<double> e = sphere_exit(to_incident, normal, ior, path);
    EXPECT_EQ(e.direction, (Vec3d{0, 0, -1}));
    EXPECT_EQ(e.offset, (Vec3d{0, 0, -path}));
  }
  const SphereExit<double> grazing = sphere_exit(to_incident, Vec3d{1, 0, 0}, 1.5, 0.5);
  EXPECT_EQ(grazing.direction, (Vec3d{0, 0, -1}));
}

}  // namespace
}  // namespace volgraph::physics

namespace volgraph::physics {
namespace {

// A lobe as wide as a level-0 texel (π/2 over the face) reads level 0; twice that, level 1;
// a sharp lobe and a huge one stay in [0, 16].
TEST(Translucency, TheEnvironmentLevelIsTheLobesWidthInTexels) {
  const double texel = 1.5707963 / 64;
  EXPECT_EQ(environment_lod(0.0, 64), 0.0);
  EXPECT_EQ(environment_lod(texel, 64), 0.0);
  EXPECT_NEAR(environment_lod(2 * texel, 64), 1.0, 1e-12);
  EXPECT_NEAR(environment_lod(8 * texel, 64), 3.0, 1e-12);
  EXPECT_EQ(environment_lod(1e9, 64), 16.0);
}

}  // namespace
}  // namespace volgraph::physics
