#include "reference/single_scattering.h"

#include <algorithm>
#include <cmath>

#include "reference/gauss_legendre.h"

namespace volgraph::reference {
namespace {

using physics::add;
using physics::scaled;
using physics::times;
using physics::largest;

constexpr uint32_t kBisectionSteps = 60;  // for where the transmittance reaches its floor
constexpr double kRoundOff = 1e-13;       // refinement below this relative change only chases rounding

double max_abs(const Vec3& v) { return std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])}); }

// Simpson's rule on [a, b] from f(a), f(m), f(b).
Vec3 simpson(double a, double b, const Vec3& fa, const Vec3& fm, const Vec3& fb) {
  return scaled(add(add(fa, scaled(fm, 4)), fb), (b - a) / 6);
}

// One segment [a, b] in which the media change smoothly: f(t) = T(0,a)·e^(−τ(a,t))·J(t).
class Segment {
 public:
  Segment(const SceneMedia& media, const Vec3& origin, const Vec3& direction, double a, const Vec3& transmittance_a,
          const std::function<Vec3(const Vec3&)>& source, const IntegrationSettings& settings)
      : media_(media), origin_(origin), direction_(direction), a_(a), t_a_(transmittance_a), source_(source), settings_(settings) {}

  Vec3 transmittance(double t) const {
    return times(t_a_, transmittance_of(media_.optical_depth(origin_, direction_, a_, t)));
  }

  Vec3 integrand(double t) const {
    ++evaluations_;
    const Vec3 x = add(origin_, scaled(direction_, t));
    return times(transmittance(t), source_(x));
  }

  // Where in [a, b] the transmittance's largest channel falls to `floor` (it does by b).
  double where_transmittance_reaches(double b, double floor) const {
    double lo = a_, hi = b;
    for (uint32_t i = 0; i < kBisectionSteps; ++i) {
      const double mid = (lo + hi) / 2;
      (largest(transmittance(mid)) < floor ? hi : lo) = mid;
    }
    return hi;
  }

  // ∫ f over [a, end] on Gauss–Legendre panels of at most `panel` m (noisy media).
  Vec3 integrate_on_panels(double end, double panel) const {
    if (!(end > a_)) return {0, 0, 0};
    return gauss_legendre(a_, end, panel, Vec3{0, 0, 0}, [&](double t) { return integrand(t); },
                          [](const Vec3& x, const Vec3& y) { return add(x, y); }, [](const Vec3& x, double s) { return scaled(x, s); });
  }

  Vec3 integrate(double end) const {
    const double length = end - a_;
    if (!(length > 0)) return {0, 0, 0};
    const std::vector<double> cuts = panel_cuts(end);
    struct Panel {
      double a, b;
      Vec3 fa, fm, fb, whole;
    };
    std::vector<Panel> grid(cuts.size() - 1);
    Vec3 coarse{0, 0, 0};
    Vec3 f_left = integrand(a_);
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
      Panel& p = grid[i];
      p.a = cuts[i];
      p.b = cuts[i + 1];
      p.fa = f_left;
      p.fm = integrand((p.a + p.b) / 2);
      p.fb = integrand(p.b);
      p.whole = simpson(p.a, p.b, p.fa, p.fm, p.fb);
      f_left = p.fb;
      coarse = add(coarse, p.whole);
    }
    const double tolerance = settings_.relative_tolerance * max_abs(coarse);
    Vec3 sum{0, 0, 0};
    for (const Panel& p : grid) {
      sum = add(sum, refine(p.a, p.b, p.fa, p.fm, p.fb, p.whole, tolerance * (p.b - p.a) / length, 0));
    }
    return sum;
  }

 private:
  // The initial panels' ends from a_ to `end`: each at most max_initial_panel long or
  // initial_panel_per_distance of its start's distance; where that makes fewer than two
  // or more than max_initial_panels, that many equal panels instead.
  std::vector<double> panel_cuts(double end) const {
    std::vector<double> cuts{a_};
    while (cuts.back() < end && cuts.size() <= settings_.max_initial_panels) {
      const double t = cuts.back();
      cuts.push_back(t + std::max(settings_.max_initial_panel, settings_.initial_panel_per_distance * t));
    }
    if (cuts.size() > settings_.max_initial_panels + 1 || cuts.size() < 3) {  // too many or too few: equal panels
      const size_t n = std::clamp<size_t>(cuts.size() - 1, 2, settings_.max_initial_panels);
      cuts.resize(n + 1);
      for (size_t i = 0; i <= n; ++i) cuts[i] = a_ + (end - a_) * double(i) / double(n);
    }
    cuts.back() = end;
    return cuts;
  }

  Vec3 refine(double a, double b, const Vec3& fa, const Vec3& fm, const Vec3& fb, const Vec3& whole, double tolerance,
              uint32_t depth) const {
    const double m = (a + b) / 2;
    const Vec3 flm = integrand((a + m) / 2), frm = integrand((m + b) / 2);
    const Vec3 left = simpson(a, m, fa, flm, fm), right = simpson(m, b, fm, frm, fb);
    const Vec3 halves = add(left, right);
    const Vec3 change = add(halves, scaled(whole, -1));
    const double error = max_abs(change);
    if (!std::isfinite(error)) return halves;  // no error estimate to extrapolate with
    const bool at_floor = depth >= settings_.max_depth || evaluations_ >= settings_.max_evaluations;
    if (at_floor || error <= 15 * tolerance || error <= kRoundOff * max_abs(halves)) {
      return add(halves, scaled(change, 1.0 / 15));  // Richardson extrapolation
    }
    return add(refine(a, m, fa, flm, fm, left, tolerance / 2, depth + 1), refine(m, b, fm, frm, fb, right, tolerance / 2, depth + 1));
  }

  const SceneMedia& media_;
  Vec3 origin_, direction_;
  double a_;
  Vec3 t_a_;
  const std::function<Vec3(const Vec3&)>& source_;
  const IntegrationSettings& settings_;
  mutable uint64_t evaluations_ = 0;  // integrand calls so far (IntegrationSettings::max_evaluations)
};

}  // namespace

RayScattering integrate_single_scattering(const SceneMedia& media, const Vec3& origin, const Vec3& direction,
                                          double length, std::vector<double> breaks,
                                          const std::function<Vec3(const Vec3&)>& source,
                                          const IntegrationSettings& settings) {
  RayScattering out;
  if (!(length > 0)) return out;
  for (double t : media.boundaries(origin, direction, 0, length)) breaks.push_back(t);
  breaks.erase(std::remove_if(breaks.begin(), breaks.end(), [&](double t) { return !(t > 0 && t < length); }), breaks.end());
  breaks.push_back(0);
  breaks.push_back(length);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  bool gathering = true;  // until the transmittance reaches its floor
  for (size_t s = 0; s + 1 < breaks.size(); ++s) {
    const double a = breaks[s], b = breaks[s + 1];
    const Segment segment(media, origin, direction, a, out.transmittance, source, settings);
    const Vec3 t_b = segment.transmittance(b);
    if (gathering) {
      const bool falls_below = largest(t_b) < settings.min_transmittance;
      const double end = falls_below ? segment.where_transmittance_reaches(b, settings.min_transmittance) : b;
      const double panel = media.noisy_panel(origin, direction, a, end);
      out.radiance = add(out.radiance, panel > 0 ? segment.integrate_on_panels(end, panel) : segment.integrate(end));
      gathering = !falls_below;
    }
    out.transmittance = t_b;
  }
  return out;
}

}  // namespace volgraph::reference
