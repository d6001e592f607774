// Lorenz–Mie scattering (Bohren & Huffman 1983, appendix A: BHMIE) and the cloud droplets'
// tabulated phase (Hansen & Travis 1974's modified gamma distribution).
#include "physics/mie.h"

#include <algorithm>
#include <cmath>

#include "physics/cloud_phase_table.h"
#include "physics/phase.h"

namespace volgraph::physics {
namespace {

constexpr double kMiePi = 3.14159265358979323846;

// The logarithmic derivative D_n(mx) for n < count by downward recurrence from D = 0 far
// above (Bohren & Huffman 1983, eq. 4.89): stable for any m.
std::vector<std::complex<double>> log_derivatives(std::complex<double> y, int count) {
  std::vector<std::complex<double>> d(size_t(count) + 1, 0.0);
  for (int n = count; n >= 2; --n) {
    const std::complex<double> ny = double(n) / y;
    d[size_t(n) - 1] = ny - 1.0 / (d[size_t(n)] + ny);
  }
  return d;
}

// The series' length: x + 4x^(1/3) + 2 terms (Wiscombe 1980, as BHMIE).
int series_terms(double x) { return int(x + 4.0 * std::cbrt(x) + 2.0); }

// θ of each of the table's texels, as cos θ (cloud_phase_table.h's angles).
std::vector<double> table_cosines(uint32_t n) {
  std::vector<double> mu(n);
  for (uint32_t i = 0; i < n; ++i) {
    const double u = (i + 0.5) / n;
    mu[i] = std::cos(kMiePi * u * u);
  }
  return mu;
}

// One channel of the droplets' phase: midpoint quadrature over the radii that carry the
// area-weighted distribution r² n(r), a gamma law of mean r_eff and deviation r_eff √v
// (Hansen & Travis 1974, eqs. 2.53–2.56). Returns p at each cos θ and the mean cosine.
std::pair<std::vector<double>, double> droplet_phase(const DropletDistribution& droplets, double wavelength_um,
                                                     const std::vector<double>& mu) {
  constexpr int kRadii = 160;
  const double r_eff = droplets.effective_radius_um, v = droplets.effective_variance;
  const double deviation = r_eff * std::sqrt(v);
  const double r_lo = std::max(r_eff - 5.0 * deviation, 0.02 * r_eff), r_hi = r_eff + 8.0 * deviation;
  const double dr = (r_hi - r_lo) / kRadii;
  const double alpha = (1.0 - 3.0 * v) / v, scale = r_eff * v;  // n(r) ∝ r^α e^(−r/scale)
  const double k = 2.0 * kMiePi / wavelength_um;
  const double log_peak = alpha * std::log(std::max(alpha * scale, r_lo)) - std::max(alpha * scale, r_lo) / scale;
  std::vector<double> intensity(mu.size(), 0.0);
  double cross_section = 0, g_cross_section = 0;
  for (int j = 0; j < kRadii; ++j) {
    const double r = r_lo + (j + 0.5) * dr;
    const double weight = std::exp(alpha * std::log(r) - r / scale - log_peak) * dr;  // n(r) dr, up to a constant
    const double x = k * r;
    const MieSphere sphere = mie_sphere(x, kWaterRefractiveIndex, mu);
    const double c_sca = kMiePi * r * r * sphere.q_sca;
    cross_section += weight * c_sca;
    g_cross_section += weight * c_sca * sphere.g;
    for (size_t i = 0; i < mu.size(); ++i)  // dC_sca/dω = (|S1|² + |S2|²) / 2k² (B&H eq. 3.16)
      intensity[i] += weight * (std::norm(sphere.s1[i]) + std::norm(sphere.s2[i])) / (2.0 * k * k);
  }
  for (double& p : intensity) p /= cross_section;
  return {intensity, g_cross_section / cross_section};
}

}  // namespace

MieSphere mie_sphere(double x, std::complex<double> m, const std::vector<double>& cos_thetas) {
  MieSphere out;
  const int terms = series_terms(x);
  const std::complex<double> y = m * x;
  const int start = std::max(terms, int(std::abs(y))) + 15;
  const std::vector<std::complex<double>> d = log_derivatives(y, start);
  const size_t angles = cos_thetas.size();
  out.s1.assign(angles, 0.0);
  out.s2.assign(angles, 0.0);
  std::vector<double> pi_previous(angles, 0.0), pi_current(angles, 1.0);  // π_{n−1}, π_n (π_0 = 0, π_1 = 1)
  // Riccati–Bessel ψ_n(x), χ_n(x) by upward recurrence (B&H eq. 4.89), ξ = ψ − iχ.
  double psi0 = std::cos(x), psi1 = std::sin(x), chi0 = -std::sin(x), chi1 = std::cos(x);
  std::complex<double> xi1(psi1, -chi1), a_previous, b_previous;
  double q_sca = 0, q_ext = 0, g_sum = 0;
  for (int n = 1; n <= terms; ++n) {
    const double nn = n;
    const double psi = (2.0 * nn - 1.0) * psi1 / x - psi0;
    const double chi = (2.0 * nn - 1.0) * chi1 / x - chi0;
    const std::complex<double> xi(psi, -chi);
    // a_n, b_n through D_n (B&H eq. 4.88).
    const std::complex<double> da = d[size_t(n)] / m + nn / x, db = m * d[size_t(n)] + nn / x;
    const std::complex<double> a = (da * psi - psi1) / (da * xi - xi1);
    const std::complex<double> b = (db * psi - psi1) / (db * xi - xi1);
    q_sca += (2.0 * nn + 1.0) * (std::norm(a) + std::norm(b));
    q_ext += (2.0 * nn + 1.0) * (a + b).real();
    // g Q_sca (B&H eq. 4.62), the cross terms a_{n−1} a_n* added at n.
    g_sum += (2.0 * nn + 1.0) / (nn * (nn + 1.0)) * (a * std::conj(b)).real();
    if (n > 1) g_sum += (nn - 1.0) * (nn + 1.0) / nn * (a_previous * std::conj(a) + b_previous * std::conj(b)).real();
    // S1, S2 with π_n and τ_n = nμπ_n − (n + 1)π_{n−1} (B&H eqs. 4.46, 4.47, 4.74).
    const double f = (2.0 * nn + 1.0) / (nn * (nn + 1.0));
    for (size_t i = 0; i < angles; ++i) {
      const double mu = cos_thetas[i], pi = pi_current[i];
      const double tau = nn * mu * pi - (nn + 1.0) * pi_previous[i];
      out.s1[i] += f * (a * pi + b * tau);
      out.s2[i] += f * (a * tau + b * pi);
      pi_current[i] = ((2.0 * nn + 1.0) * mu * pi - (nn + 1.0) * pi_previous[i]) / nn;
      pi_previous[i] = pi;
    }
    a_previous = a, b_previous = b;
    psi0 = psi1, psi1 = psi, chi0 = chi1, chi1 = chi;
    xi1 = std::complex<double>(psi1, -chi1);
  }
  out.q_sca = 2.0 / (x * x) * q_sca;
  out.q_ext = 2.0 / (x * x) * q_ext;
  out.g = 4.0 / (x * x) * g_sum / out.q_sca;
  return out;
}

std::vector<double> mie_phase(const MieSphere& sphere, double x) {
  std::vector<double> p(sphere.s1.size());
  for (size_t i = 0; i < p.size(); ++i)
    p[i] = (std::norm(sphere.s1[i]) + std::norm(sphere.s2[i])) / (2.0 * kMiePi * x * x * sphere.q_sca);
  return p;
}

CloudPhaseTable cloud_droplet_phase_table(const DropletDistribution& droplets, uint32_t n) {
  const std::vector<double> mu = table_cosines(n);
  CloudPhaseTable table;
  table.texels.assign(n, {0, 0, 0});
  for (int c = 0; c < 3; ++c) {
    const auto [p, g] = droplet_phase(droplets, kChannelWavelengthsUm[size_t(c)], mu);
    for (uint32_t i = 0; i < n; ++i) table.texels[i][size_t(c)] = float(p[i]);
    table.g[size_t(c)] = g;
  }
  return table;
}

CloudPhaseTable henyey_greenstein_phase_table(double g, uint32_t n) {
  const std::vector<double> mu = table_cosines(n);
  CloudPhaseTable table;
  table.texels.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    const float p = float(phase_hg<double>(g, mu[i]));
    table.texels[i] = {p, p, p};
  }
  table.g = {g, g, g};
  return table;
}

std::array<float, 3> cloud_phase_table_at(const CloudPhaseTable& table, float cos_theta) {
  namespace shared = cloud_phase_table;
  const int n = int(table.texels.size());
  const float x = shared::cloud_phase_table_position(cos_theta, n);
  const auto texel = [&](int i) {
    const std::array<float, 3>& t = table.texels[size_t(i)];
    return glm::vec3(t[0], t[1], t[2]);
  };
  const glm::vec3 p = shared::cloud_phase_table_mix(texel(shared::cloud_phase_table_lower(x)), texel(shared::cloud_phase_table_upper(x, n)), x);
  return {p.x, p.y, p.z};
}

double cloud_phase_table_integral(const CloudPhaseTable& table, int channel) {
  const size_t n = table.texels.size();
  double sum = 0;
  for (size_t i = 0; i < n; ++i) {
    const double u = (i + 0.5) / n;
    sum += table.texels[i][size_t(channel)] * std::sin(kMiePi * u * u) * 2.0 * kMiePi * u / n;  // sin θ dθ, θ = πu²
  }
  return 2.0 * kMiePi * sum;
}

}  // namespace volgraph::physics
