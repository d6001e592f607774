// Lorenz–Mie scattering by a homogeneous sphere (Bohren & Huffman 1983, appendix A: BHMIE)
// and the phase function of a cloud's water droplets: the modified gamma size distribution
// of Hansen & Travis 1974 (eq. 2.56) weighted by each size's scattering cross-section, per
// colour channel, tabulated in shaders/include/cloud_phase_table.h's parameterisation.
#pragma once

#include <array>
#include <complex>
#include <cstdint>
#include <vector>

namespace volgraph::physics {

// One sphere's efficiencies and amplitudes (Bohren & Huffman 1983, §4.4, eqs. 4.61, 4.74).
struct MieSphere {
  double q_ext = 0;                           // extinction efficiency C_ext / πr²
  double q_sca = 0;                           // scattering efficiency C_sca / πr²
  double g = 0;                               // asymmetry parameter <cos θ>
  std::vector<std::complex<double>> s1, s2;   // amplitude functions at the requested cos θ
};

// BHMIE: size parameter x = 2πr/λ, relative refractive index m, the amplitudes at each
// cos θ of `cos_thetas` (Bohren & Huffman 1983, appendix A; series to x + 4x^(1/3) + 2).
MieSphere mie_sphere(double x, std::complex<double> m, const std::vector<double>& cos_thetas);

// One sphere's phase function (1/sr): (|S1|² + |S2|²) / (2π x² Q_sca) (B&H eq. 3.16, 4.77).
std::vector<double> mie_phase(const MieSphere& sphere, double x);

// Water's refractive index in the visible (Hale & Querry 1973: 1.333, absorption negligible).
inline constexpr double kWaterRefractiveIndex = 1.333;

// The wavelengths (µm) of the r, g, b channels: the atmosphere's (physics/atmosphere_sky.cpp,
// Hillaire 2016's limb darkening at 680, 550 and 440 nm).
inline constexpr std::array<double, 3> kChannelWavelengthsUm = {0.680, 0.550, 0.440};

// A water cloud's droplets: Hansen & Travis 1974's modified gamma distribution
// n(r) ∝ r^((1 − 3v)/v) e^(−r/(r_eff v)) (eq. 2.56), r_eff and v_eff its effective radius
// and variance (eqs. 2.53, 2.54). Defaults: Hansen & Travis's water cloud (r_eff 10 µm, v_eff 0.1).
struct DropletDistribution {
  double effective_radius_um = 10.0;
  double effective_variance = 0.1;
};

// A phase table: texel i of N holds p(θ_i) per channel (rgb, 1/sr) at
// θ_i = π u_i², u_i = (i + ½)/N (shaders/include/cloud_phase_table.h), and g per channel.
struct CloudPhaseTable {
  std::vector<std::array<float, 3>> texels;
  std::array<double, 3> g{};  // the distribution's mean cosine per channel
};

// The droplets' phase per channel, weighted by πr² Q_sca(r) n(r):
// p(θ) = ∫ n πr² Q_sca p_r(θ) dr / ∫ n πr² Q_sca dr, N texels.
CloudPhaseTable cloud_droplet_phase_table(const DropletDistribution& droplets, uint32_t n);

// A table of one Henyey–Greenstein lobe (the same p in every channel): for comparing the
// tabulated phase with the analytic one.
CloudPhaseTable henyey_greenstein_phase_table(double g, uint32_t n);

// The table's p at cos θ, linear between texel centres (cloud_phase_table.h's lookup, the GPU's).
std::array<float, 3> cloud_phase_table_at(const CloudPhaseTable& table, float cos_theta);

// ∫ p dω of the table's channel c by the midpoint rule over its texels (dω = 2π sin θ · 2πu du).
double cloud_phase_table_integral(const CloudPhaseTable& table, int channel);

}  // namespace volgraph::physics
