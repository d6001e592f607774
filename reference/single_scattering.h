// Single scattering along one ray through the scene's media (the volume rendering
// equation without multiple scattering): L = ∫₀^D T(0,t)·J(t) dt, with J the radiance
// per metre scattered or emitted toward the viewer at distance t and T(0,t) the exact
// transmittance (closed-form optical depth between the media's boundaries). The integral
// is taken segment by segment between media boundaries and any breaks the caller adds
// (where J peaks, e.g. a point light's closest approach), each segment by adaptive
// Simpson quadrature (Lyness 1969, "Notes on the adaptive Simpson quadrature routine")
// from a grid of initial panels — or, through noisy volumes, by Gauss–Legendre on the
// fixed panels SceneMedia::noisy_panel gives.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "reference/clouds.h"
#include "reference/media.h"

namespace volgraph::reference {

// How the camera ray crosses translucent surfaces (reference/renderer.h): straight on
// through each layer (what the GPU's translucency pass models), or bent at each interface
// of a solid by Snell's law (the two-interface ground truth of the refraction variants).
enum class TranslucencyMode { straight, refracted };

struct IntegrationSettings {
  // Each segment's estimated error (Richardson: |S₂ − S₁|/15, max over channels) is held
  // below this fraction of the segment's integral.
  double relative_tolerance = 1e-5;
  // Integration stops where T(0,t) (its largest channel) falls below this: what lies
  // beyond adds at most this fraction of the radiance it would add unattenuated.
  double min_transmittance = 1e-6;
  // Initial panels are at most this long (m), or this fraction of their distance from the
  // camera where that is longer (a feature far away subtends less), so that features
  // narrower than the whole segment (shafts of light between shadows) are seen before
  // refinement…
  double max_initial_panel = 0.5;
  double initial_panel_per_distance = 0.05;
  // …but no more than this many per segment.
  uint32_t max_initial_panels = 256;
  uint32_t max_depth = 30;  // bisections of an initial panel
  // Integrand evaluations one segment's refinement may spend: the floor under it where
  // the integrand never settles (a point light on the surface a ray ends at: 1/d²
  // growth and shadow-ray visibility flickering at every scale), so that such a pixel
  // takes at most this many evaluations; panels refined after it is spent keep their
  // Richardson estimate. Converging segments use a small fraction of it.
  uint64_t max_evaluations = uint64_t{1} << 14;
  TranslucencyMode translucency = TranslucencyMode::straight;
  // The cloud layer's reference (reference/clouds.h): cloud_noise's and cloud_march's defaults.
  CloudReferenceSettings clouds;
  // Layers a ray composes (straight mode) or translucent surfaces a shadow ray crosses:
  // beyond them the camera ray sees the background, the light is taken as blocked.
  uint32_t max_layers = 64;
  // Refracted mode: interfaces one camera path crosses or reflects at before it is cut
  // (its light then 0); reflected branches inside a solid whose weight falls below
  // min_branch_weight are cut too.
  uint32_t max_bounces = 16;
  // Whether translucent surfaces shadow (by their transmittance); false: they cast none,
  // as on the GPU (for comparisons with it), masked holes and opaque casters still do.
  bool translucent_shadows = true;
  // Whether a translucent surface's reflection sees what a ray leaving toward the mirrored
  // direction sees (the sky, or the background), as the translucency pass does with an
  // environment cube wired; false: the uniform L_env (the background, or under an
  // atmosphere the sky's ambient radiance), as it does without one.
  bool directional_environment = false;
  double min_branch_weight = 1e-4;
};

struct RayScattering {
  Vec3 radiance{0, 0, 0};       // ∫ T·J, the light the media add
  Vec3 transmittance{1, 1, 1};  // T(0, D), exact, for what lies at D
};

// `source(x)`: J at point x (W/(m²·sr·m) per channel). `direction` is unit.
RayScattering integrate_single_scattering(const SceneMedia& media, const Vec3& origin, const Vec3& direction,
                                          double length, std::vector<double> breaks,
                                          const std::function<Vec3(const Vec3&)>& source,
                                          const IntegrationSettings& settings);

}  // namespace volgraph::reference
