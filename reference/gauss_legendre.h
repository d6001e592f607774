// Composite 4-point Gauss–Legendre quadrature (Abramowitz & Stegun, Table 25.4: nodes
// ±0.3399810435848563, ±0.8611363115940526 on [−1, 1], exact for polynomials of degree
// 7), on equal panels: what the reference uses inside heterogeneous media, where the
// integrand is piecewise smooth at a scale finer than any cut it could place.
#pragma once

#include <algorithm>
#include <cmath>

namespace volgraph::reference {

constexpr double kMaxGaussPanels = 1e5;  // a piece of a ray far longer than its panels

// ∫_a^b f on ceil((b − a) / panel) equal panels (1 … kMaxGaussPanels); `zero` is f's
// additive identity (0 or a zero vector), `add(x, y)` and `scale(x, s)` its arithmetic.
template <typename Value, typename F, typename Add, typename Scale>
Value gauss_legendre(double a, double b, double panel, const Value& zero, F&& f, Add&& add, Scale&& scale) {
  constexpr double kNodes[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  constexpr double kWeights[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  const double panels = std::clamp(std::ceil((b - a) / panel), 1.0, kMaxGaussPanels);
  const double width = (b - a) / panels;
  Value sum = zero;
  for (double k = 0; k < panels; ++k) {
    const double centre = a + (k + 0.5) * width;
    for (int n = 0; n < 4; ++n) sum = add(sum, scale(f(centre + 0.5 * width * kNodes[n]), kWeights[n]));
  }
  return scale(sum, 0.5 * width);
}

}  // namespace volgraph::reference
