// Adaptive Simpson quadrature of a smooth scalar function on [a, b] (Kuncir 1962, with
// Richardson's correction), for tests that need an independent integral: `tolerance` is
// absolute, `depth` bounds the recursion.
#pragma once

#include <cmath>
#include <functional>

namespace volgraph::test {

inline double adaptive_simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm, double fb,
                               double whole, double tolerance, int depth) {
  const double m = (a + b) / 2, lm = (a + m) / 2, rm = (m + b) / 2;
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15 * tolerance) return left + right + (left + right - whole) / 15;
  return adaptive_simpson(f, a, m, fa, flm, fm, left, tolerance / 2, depth - 1) +
         adaptive_simpson(f, m, b, fm, frm, fb, right, tolerance / 2, depth - 1);
}

// ∫ₐᵇ f, starting from the whole interval.
inline double adaptive_simpson(const std::function<double(double)>& f, double a, double b, double tolerance, int depth) {
  const double fa = f(a), fm = f((a + b) / 2), fb = f(b);
  return adaptive_simpson(f, a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), tolerance, depth);
}

}  // namespace volgraph::test
