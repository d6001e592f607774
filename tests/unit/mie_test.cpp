// physics/mie (Bohren & Huffman 1983's BHMIE; Hansen & Travis 1974's droplet distribution)
// and the phase table's shared parameterisation (shaders/include/cloud_phase_table.h).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "physics/cloud_phase_table.h"
#include "physics/mie.h"
#include "physics/phase.h"

namespace volgraph::physics {
namespace {

constexpr double kMieTestPi = 3.14159265358979323846;

// Bohren & Huffman 1983, appendix A's test (CALLBHMIE: r 0.525 µm, λ 0.6328 µm, m 1.55):
// Q_ext = Q_sca = 3.10543, g = 0.63314 (the published output, as in Prahl's miepython tests).
TEST(Mie, BohrenHuffmanDielectricSphere) {
  const double x = 2 * kMieTestPi * 0.525 / 0.6328;
  const MieSphere s = mie_sphere(x, 1.55, {});
  EXPECT_NEAR(s.q_ext, 3.10543, 1e-5);
  EXPECT_NEAR(s.q_sca, 3.10543, 1e-5);
  EXPECT_NEAR(s.g, 0.63314, 1e-5);
}

// The same sphere absorbing, m = 1.55 + 0.1i (B&H's sign): Q_ext 2.86165188, Q_sca 1.66424912,
// g 0.80128973 (Prahl's miepython test of BHMIE, written there as 1.55 − 0.1i).
TEST(Mie, BohrenHuffmanAbsorbingSphere) {
  const double x = 2 * kMieTestPi * 0.525 / 0.6328;
  const MieSphere s = mie_sphere(x, {1.55, 0.1}, {});
  EXPECT_NEAR(s.q_ext, 2.86165188, 1e-7);
  EXPECT_NEAR(s.q_sca, 1.66424912, 1e-7);
  EXPECT_NEAR(s.g, 0.80128973, 1e-7);
}

// A sphere much smaller than the wavelength scatters as Rayleigh: p → (3/16π)(1 + cos²θ).
TEST(Mie, RayleighLimit) {
  const std::vector<double> mu = {1.0, 0.7, 0.3, 0.0, -0.4, -1.0};
  const MieSphere s = mie_sphere(0.01, kWaterRefractiveIndex, mu);
  const std::vector<double> p = mie_phase(s, 0.01);
  for (size_t i = 0; i < mu.size(); ++i)
    EXPECT_NEAR(p[i] / (3.0 / (16.0 * kMieTestPi) * (1.0 + mu[i] * mu[i])), 1.0, 1e-3) << "cos θ " << mu[i];
}

// The asymmetry from the series equals ∫ cos θ p dω of the phase from S1, S2 (x = 20, water).
TEST(Mie, AsymmetryMatchesThePhasesMeanCosine) {
  constexpr int n = 20000;
  std::vector<double> mu(n);
  for (int i = 0; i < n; ++i) mu[size_t(i)] = std::cos((i + 0.5) * kMieTestPi / n);
  const MieSphere s = mie_sphere(20.0, kWaterRefractiveIndex, mu);
  const std::vector<double> p = mie_phase(s, 20.0);
  double norm = 0, mean_cos = 0;
  for (int i = 0; i < n; ++i) {
    const double w = 2 * kMieTestPi * std::sin((i + 0.5) * kMieTestPi / n) * kMieTestPi / n;
    norm += p[size_t(i)] * w;
    mean_cos += p[size_t(i)] * mu[size_t(i)] * w;
  }
  EXPECT_NEAR(norm, 1.0, 1e-3);
  EXPECT_NEAR(mean_cos, s.g, 1e-3);
}

const CloudPhaseTable& default_cloud_table() {
  static const CloudPhaseTable table = cloud_droplet_phase_table({}, 512);
  return table;
}

// The default water cloud's table integrates to 1 over the sphere in every channel.
TEST(Mie, CloudTableIsNormalised) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(cloud_phase_table_integral(default_cloud_table(), c), 1.0, 1e-3) << "channel " << c;
}

// Hansen & Travis 1974's water cloud (r_eff ≈ 10 µm): g ≈ 0.85–0.87 at 550 nm; g grows
// toward the blue (x larger), and the forward peak dwarfs the back.
TEST(Mie, CloudTableAsymmetryIsHansenTravis) {
  const CloudPhaseTable& table = default_cloud_table();
  EXPECT_GT(table.g[1], 0.85);
  EXPECT_LT(table.g[1], 0.87);
  EXPECT_LT(table.g[0], table.g[2]);
  EXPECT_GT(table.texels.front()[1], 100.0f * table.texels.back()[1]);
}

// The shared lookup at a texel's centre returns that texel (cos θ in float: the first few
// texels are closer than float's cos resolution, so from texel 32 on; 1e-3 relative).
TEST(Mie, TableLookupIsExactAtTexelCentres) {
  const CloudPhaseTable& table = default_cloud_table();
  const int n = int(table.texels.size());
  for (int i = 32; i < n; i += 37) {
    const float mu = float(std::cos(cloud_phase_table::cloud_phase_table_angle(i, n)));
    EXPECT_NEAR(cloud_phase_table::cloud_phase_table_position(mu, n), float(i), 0.02f) << "texel " << i;
    const std::array<float, 3> p = cloud_phase_table_at(table, mu);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[size_t(c)] / table.texels[size_t(i)][size_t(c)], 1.0f, 1e-3f) << "texel " << i;
  }
  EXPECT_EQ(cloud_phase_table_at(table, 1.0f)[1], table.texels.front()[1]);
  EXPECT_EQ(cloud_phase_table_at(table, -1.0f)[1], table.texels.back()[1]);
}

// A Henyey–Greenstein table read back between texels is the analytic phase within the
// interpolation error (1 % relative at g = 0.8 for 512 texels).
TEST(Mie, HenyeyGreensteinTableInterpolates) {
  const CloudPhaseTable table = henyey_greenstein_phase_table(0.8, 512);
  for (const float mu : {0.999f, 0.9f, 0.5f, 0.0f, -0.7f})
    EXPECT_NEAR(cloud_phase_table_at(table, mu)[0] / phase_hg<double>(0.8, mu), 1.0, 1e-2) << "cos θ " << mu;
}

}  // namespace
}  // namespace volgraph::physics
