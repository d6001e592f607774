#include "reference/media.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "physics/media.h"
#include "physics/phase.h"
#include "reference/gauss_legendre.h"

namespace volgraph::reference {
namespace {

using physics::add;
using physics::Mat4;
using physics::scaled;
using physics::times;
using physics::over;

constexpr double kInfiniteDepth = 1e300;
// A volume's chord is integrated on at most this many panels and a camera ray cut at most
// this many times through it: noise finer than that is under-resolved (under_resolved()
// says so) rather than making a pixel take minutes.
constexpr double kMaxPanelsPerChord = 256;
constexpr double kMaxSegmentsPerChord = 64;
// A chord whose finest noise has more cells than kMaxPanelsPerChord is under-resolved
// whatever it spends, so it spends less: this many panels and segments. Each camera
// sample integrates the chord toward the light too, so a ray's cost grows with the
// product of the two chords' panels; at the caps above a ray of fine noise took about
// 0.2 s, 64 times what this costs.
constexpr double kUnderResolvedPanelsPerChord = 32;
constexpr double kUnderResolvedSegmentsPerChord = 8;
// e^(−this) is below double's resolution of 1: height fog beyond it adds nothing.
constexpr double kNegligibleExponent = 50;
Vec3 transform_vector(const Mat4& m, const Vec3& v) { return physics::to_vec3(glm::dmat3(m) * physics::vec(v)); }


Vec3 sigma_t(const Medium& m) { return add(m.sigma_s, m.sigma_a); }

Mat4 unit_shape_to_volume(const MediumVolume& v) { return glm::scale(Mat4(1), physics::vec(physics::unit_shape_scale(v))); }

// Where the density reaches 1 inside the edge fade (MediaField's inside distance ≥ fade),
// as a scale of the unit shape: the box's edges less the fade on each side, the sphere's
// radius less the fade, the ellipsoid's radii by 1 − fade / smallest radius. 0: no core.
Vec3 core_scale(const MediumVolume& v) {
  const double fade = v.noise.edge_fade;
  const Vec3 size = physics::unit_shape_scale(v);
  if (fade == 0 || std::min({size[0], size[1], size[2]}) <= 0) return {1, 1, 1};
  if (v.shape == Shape::box) {
    const Vec3 s{1 - 2 * fade / size[0], 1 - 2 * fade / size[1], 1 - 2 * fade / size[2]};
    return std::min({s[0], s[1], s[2]}) > 0 ? s : Vec3{0, 0, 0};
  }
  const double s = 1 - fade / std::min({size[0], size[1], size[2]});
  return s > 0 ? Vec3{s, s, s} : Vec3{0, 0, 0};
}

// The pieces of [t0, t1] cut at the core's ends.
std::vector<Interval> pieces(double t0, double t1, const std::optional<Interval>& core) {
  if (!core || core->exit <= t0 || core->enter >= t1) return {{t0, t1}};
  std::vector<Interval> out;
  const double a = std::max(t0, core->enter), b = std::min(t1, core->exit);
  if (a > t0) out.push_back({t0, a});
  out.push_back({a, b});
  if (b < t1) out.push_back({b, t1});
  return out;
}

}  // namespace

Vec3 transmittance_of(const Vec3& optical_depth) {
  return {physics::transmittance(optical_depth[0], 1.0), physics::transmittance(optical_depth[1], 1.0),
          physics::transmittance(optical_depth[2], 1.0)};
}

SceneMedia::SceneMedia(const Media& media, const MediaQuadrature& quadrature) : field_(media), quadrature_(quadrature) {
  for (const MediumVolume& v : media.volumes) {
    const Mat4 model = physics::model_matrix(v.transform) * unit_shape_to_volume(v);
    const bool uniform = v.noise.edge_fade == 0 && v.noise.octaves == 0;
    const Vec3 size = physics::unit_shape_scale(v);
    const bool flat = std::min({size[0], size[1], size[2]}) <= 0;  // no inside: nothing along any ray
    volumes_.push_back({v.shape, flat ? Mat4(1) : physics::inverse_affine(model), core_scale(v), uniform, flat});
  }
}

std::string SceneMedia::under_resolved() const {
  const Media& media = field_.media();
  for (size_t i = 0; i < media.volumes.size(); ++i) {
    const MediumVolume& v = media.volumes[i];
    if (v.noise.octaves == 0 || volumes_[i].flat) continue;
    // The longest chord, in local units: the box's diagonal, twice the largest radius.
    const Vec3 size = physics::unit_shape_scale(v);
    const double longest = v.shape == Shape::box ? std::sqrt(physics::dot(size, size)) : 2 * std::max({size[0], size[1], size[2]});
    const double cells = longest / (v.noise.scale / std::ldexp(1.0, v.noise.octaves - 1));
    if (cells * quadrature_.panels_per_noise_cell > kMaxPanelsPerChord) {
      return "volume " + std::to_string(i) + ": its finest noise octave has up to " + std::to_string(int64_t(cells)) +
             " cells along a ray, more than the reference integrates (" + std::to_string(int(kMaxPanelsPerChord)) +
             " panels a chord): the noise is under-resolved there (integrated on " +
             std::to_string(int(kUnderResolvedPanelsPerChord)) + " panels a chord where it is)";
    }
  }
  return "";
}

bool SceneMedia::empty() const {
  const Media& m = field_.media();
  return !m.fog && !m.height_fog && m.volumes.empty();
}

Vec3 SceneMedia::scattering(const Vec3& p, double cos_theta) const {
  Vec3 out{0, 0, 0};
  field_.visit(p, [&](const Medium& m, double density) {
    const double phase = m.g == 0 ? physics::phase_isotropic<double>() : physics::phase_hg(m.g, cos_theta);
    out = add(out, scaled(m.sigma_s, density * phase));
  });
  return out;
}

std::optional<SceneMedia::VolumeChord> SceneMedia::chord(size_t i, const Vec3& origin, const Vec3& direction) const {
  const Volume& v = volumes_[i];
  if (v.flat) return std::nullopt;
  const Vec3 o = physics::transform_point(v.inverse, origin), d = transform_vector(v.inverse, direction);
  const std::optional<Interval> shape = physics::unit_shape_interval(v.shape, o, d);
  if (!shape) return std::nullopt;
  VolumeChord c{*shape, std::nullopt, 0, 0};
  if (v.uniform) return c;
  if (v.core_scale[0] > 0) c.core = physics::unit_shape_interval(v.shape, over(o, v.core_scale), over(d, v.core_scale));
  // Lengths in the volume's local units become metres along the ray: a local unit is
  // 1 / |d_local| m, d_local the direction in local units.
  const MediumVolume& volume = field_.media().volumes[i];
  const Vec3 d_local = times(d, physics::unit_shape_scale(volume));
  const double metres_per_local = 1 / std::sqrt(physics::dot(d_local, d_local));
  c.panel = std::numeric_limits<double>::infinity();
  if (volume.noise.edge_fade > 0) c.panel = volume.noise.edge_fade * metres_per_local / quadrature_.panels_per_edge_fade;
  const double length = c.shape.exit - c.shape.enter;
  bool under_resolved = false;
  if (volume.noise.octaves > 0) {
    const double cell = volume.noise.scale / std::ldexp(1.0, volume.noise.octaves - 1) * metres_per_local;
    c.panel = std::min(c.panel, cell / quadrature_.panels_per_noise_cell);
    c.segment = cell / quadrature_.segments_per_noise_cell;
    under_resolved = length * quadrature_.panels_per_noise_cell / cell > kMaxPanelsPerChord;
  }
  const double panels = under_resolved ? kUnderResolvedPanelsPerChord : kMaxPanelsPerChord;
  const double segments = under_resolved ? kUnderResolvedSegmentsPerChord : kMaxSegmentsPerChord;
  c.panel = std::max(c.panel, length / panels);
  if (c.segment > 0) c.segment = std::max(c.segment, length / segments);
  return c;
}

std::vector<double> SceneMedia::boundaries(const Vec3& origin, const Vec3& direction, double t0, double t1) const {
  std::vector<double> out;
  auto add_cut = [&](double t) {
    if (t > t0 && t < t1) out.push_back(t);
  };
  for (size_t i = 0; i < volumes_.size(); ++i) {
    const std::optional<VolumeChord> c = chord(i, origin, direction);
    if (!c) continue;
    add_cut(c->shape.enter);
    add_cut(c->shape.exit);
    if (c->core) {
      add_cut(c->core->enter);
      add_cut(c->core->exit);
    }
    if (c->segment == 0) continue;
    const double a = std::max(t0, c->shape.enter), b = std::min(t1, c->shape.exit);
    const double cuts = std::min(std::ceil((b - a) / c->segment), kMaxGaussPanels);
    for (double k = 1; k < cuts; ++k) add_cut(a + (b - a) * k / cuts);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double SceneMedia::density_integral(size_t i, const Vec3& origin, const Vec3& direction, double t0, double t1,
                                    double panel) const {
  return gauss_legendre(
      t0, t1, panel, 0.0, [&](double t) { return field_.volume_density(i, add(origin, scaled(direction, t))); },
      [](double x, double y) { return x + y; }, [](double x, double s) { return x * s; });
}

double SceneMedia::noisy_panel(const Vec3& origin, const Vec3& direction, double t0, double t1) const {
  double panel = 0;
  for (size_t i = 0; i < volumes_.size(); ++i) {
    if (field_.media().volumes[i].noise.octaves == 0) continue;
    const std::optional<VolumeChord> c = chord(i, origin, direction);
    if (!c || c->shape.exit <= t0 || c->shape.enter >= t1) continue;
    panel = panel == 0 ? c->panel : std::min(panel, c->panel);
  }
  return panel;
}

Vec3 SceneMedia::volume_optical_depth(size_t i, const VolumeChord& c, const Vec3& origin, const Vec3& direction,
                                      double t0, double t1) const {
  const double a = std::max(t0, c.shape.enter), b = std::min(t1, c.shape.exit);
  if (!(b > a)) return {0, 0, 0};
  const MediumVolume& volume = field_.media().volumes[i];
  double length = 0;  // ∫ density dt
  for (const Interval& piece : pieces(a, b, c.core)) {
    const bool full = c.panel == 0 || (c.core && volume.noise.octaves == 0 && piece.enter >= c.core->enter &&
                                       piece.exit <= c.core->exit);
    length += full ? piece.exit - piece.enter : density_integral(i, origin, direction, piece.enter, piece.exit, c.panel);
  }
  return scaled(sigma_t(volume.medium), length);
}

Vec3 SceneMedia::volumes_optical_depth(const Vec3& origin, const Vec3& direction, double t0, double t1) const {
  Vec3 depth{0, 0, 0};
  for (size_t i = 0; i < volumes_.size(); ++i) {
    const std::optional<VolumeChord> c = chord(i, origin, direction);
    if (c) depth = add(depth, volume_optical_depth(i, *c, origin, direction, t0, t1));
  }
  return depth;
}

Vec3 SceneMedia::height_fog_optical_depth(double origin_y, double direction_y, double length) const {
  const std::optional<HeightFog>& fog = field_.media().height_fog;
  if (!fog) return {0, 0, 0};
  const Vec3 base = sigma_t(fog->medium);
  Vec3 depth;
  for (size_t c = 0; c < 3; ++c) {
    depth[c] = physics::height_fog_optical_depth(base[c], fog->falloff, fog->base_height, origin_y, direction_y, length);
  }
  return depth;
}

Vec3 SceneMedia::optical_depth(const Vec3& origin, const Vec3& direction, double t0, double t1) const {
  if (!(t1 > t0)) return {0, 0, 0};
  Vec3 depth = volumes_optical_depth(origin, direction, t0, t1);
  if (const std::optional<Medium>& fog = field_.media().fog) depth = add(depth, scaled(sigma_t(*fog), t1 - t0));
  return add(depth, height_fog_optical_depth(origin[1] + t0 * direction[1], direction[1], t1 - t0));
}

Vec3 SceneMedia::optical_depth_to_infinity(const Vec3& origin, const Vec3& direction) const {
  Vec3 depth = volumes_optical_depth(origin, direction, 0, std::numeric_limits<double>::infinity());
  const std::optional<HeightFog>& fog = field_.media().height_fog;
  if (!fog) return depth;
  const Vec3 base = sigma_t(fog->medium);
  if (direction[1] <= 0) {  // down (or level) forever through ever denser fog
    for (size_t c = 0; c < 3; ++c) depth[c] += base[c] > 0 ? kInfiniteDepth : 0;
    return depth;
  }
  // Far enough that the rest is below e^(−kNegligibleExponent) of what came before.
  const double length = kNegligibleExponent / (fog->falloff * direction[1]);
  return add(depth, height_fog_optical_depth(origin[1], direction[1], length));
}

}  // namespace volgraph::reference
