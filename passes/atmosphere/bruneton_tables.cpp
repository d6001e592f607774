// atmosphere_bruneton_tables (Bruneton & Neyret 2008; Bruneton 2017, Precompute without
// COMBINED_SCATTERING_TEXTURES): the scattering table (r, mu, mu_s, nu → Rayleigh and the
// higher orders in rgb, for a sun of unit irradiance), the single Mie table beside it (rgb,
// the same shape: no extrapolation of green and blue from red) and the sky's irradiance
// table (r, mu_s), from the transmittance LUT, by iterated scattering orders. The pass runs
// as steps the graph orders and synchronises, each one dispatch:
//   direct_irradiance, single_scattering, then for each order n = 2 … kMaxOrders
//   density_<n>, indirect_irradiance_<n>, multiple_scattering_<n>,
// with the delta tables and the running sums as internal slots (the graph gives them memory
// and their barriers). The sums ping-pong between two internal slots; the last order's
// steps write the outputs. Orders past `orders` carry the sums on unchanged (their density
// step records nothing), so the step list is fixed and `orders` a parameter.
// Defaults: 8 × 64 × 128 × 64 texels (nu, mu_s, mu, r: a 512 × 128 × 64 texture), 200
// trapezoids for single scattering, irradiance 64 × 16, 4 orders. Bruneton 2017's 8 × 32 ×
// 128 × 32 at 50 trapezoids leaves 5.5 % beside the sun and 3.1 % at the sunset horizon at
// the worst pixel; these meet 0.5 % (tests/accuracy/atmosphere_sky_accuracy_test.cpp). Every table is rgba32f (read by texelFetch and
// blended in the shaders: include/atmosphere_bruneton.glsl). Cached on the atmosphere.
// Shaders: shaders/atmosphere_bruneton_*.comp.
#include <array>
#include <string>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/atmosphere/atmosphere_block.h"
#include "passes/register_pass.h"
#include "passes/atmosphere/bruneton_uniforms.h"
#include "passes/plumbing/programs.h"
#include "physics/atmosphere_bruneton.h"
#include "shaders/bindings/atmosphere_bruneton_direct_irradiance.comp.h"
#include "shaders/bindings/atmosphere_bruneton_single_scattering.comp.h"
#include "shaders/bindings/atmosphere_bruneton_scattering_density.comp.h"
#include "shaders/bindings/atmosphere_bruneton_indirect_irradiance.comp.h"
#include "shaders/bindings/atmosphere_bruneton_multiple_scattering.comp.h"

namespace volgraph {
namespace {

namespace bruneton_direct_irradiance_shader = shaders::atmosphere_bruneton_direct_irradiance_comp;
namespace bruneton_single_scattering_shader = shaders::atmosphere_bruneton_single_scattering_comp;
namespace bruneton_scattering_density_shader = shaders::atmosphere_bruneton_scattering_density_comp;
namespace bruneton_indirect_irradiance_shader = shaders::atmosphere_bruneton_indirect_irradiance_comp;
namespace bruneton_multiple_scattering_shader = shaders::atmosphere_bruneton_multiple_scattering_comp;

constexpr int kMaxOrders = 8;

std::vector<ParamProblem> check_table_shape(const PassDecl& decl, const Scene&, const std::vector<ParamValue>& values);

struct BrunetonTablesTable : PassTable {
  BrunetonTablesTable()
      : PassTable("atmosphere_bruneton_tables", PassKind::compute,
                  "Bruneton 2017's precomputed scattering (4D in 3D) and irradiance tables, by iterated scattering orders.") {
    decl.needs = feature_bit(SceneFeature::atmosphere);
    decl.cached = true;
    decl.frame_invariant = true;
    decl.reads_scene = part_bit(ScenePart::atmosphere);
    decl.check_scene = check_table_shape;
  }
  // Variants.
  VariantHandle iterated = variant("iterated_orders", "each order from the last by a density and an integral along the ray (Bruneton 2017)");
  // Parameters.
  ParamHandle<int64_t> orders = integer("orders", 4, 1, kMaxOrders, "", "scattering orders summed (1: single scattering)");
  ParamHandle<int64_t> samples = integer("samples", 50, 1, 4096, "", "trapezoids along each ray of the multiple scattering integrals (Bruneton 2017: 50)");
  ParamHandle<int64_t> single_samples = integer("single_samples", physics::kSingleScatteringSamples, 1, 4096, "", "trapezoids along each ray of the single scattering integral");
  ParamHandle<int64_t> nu = integer("nu", 8, 2, 64, "texels", "view–sun cosines (nu slices packed in x)");
  ParamHandle<int64_t> nu_mu_s = integer("nu_mu_s", 512, 4, 2048, "texels", "x: nu × the sun zenith cosines (mu_s) per slice");
  ParamHandle<int64_t> mu = integer("mu", 128, 4, 1024, "texels", "view zenith cosines, half below the horizon and half above");
  ParamHandle<int64_t> r = integer("r", 64, 2, 256, "texels", "altitudes");
  ParamHandle<int64_t> irradiance_width = integer("irradiance_width", 64, 2, 1024, "texels", "the irradiance table's sun zenith cosines");
  ParamHandle<int64_t> irradiance_height = integer("irradiance_height", 16, 2, 1024, "texels", "the irradiance table's altitudes");
  // Slots.
  SlotHandle transmittance = input("transmittance", ResourceKind::texture2d, Usage::sampled,
                                   "the transmittance LUT (atmosphere_transmittance_lut.transmittance)");
  SlotHandle scattering = output("scattering", ResourceKind::texture3d, Usage::storage_write, Format::rgba32_float, scattering_size(),
                                 "per (r, mu, mu_s, nu) for a sun of unit E: Rayleigh + orders ≥ 2 over p_R (rgb)");
  SlotHandle single_mie_scattering = output("single_mie_scattering", ResourceKind::texture3d, Usage::storage_write, Format::rgba32_float,
                                            scattering_size(), "per (r, mu, mu_s, nu) for a sun of unit E: single Mie without its phase (rgb)");
  SlotHandle irradiance = output("irradiance", ResourceKind::texture2d, Usage::storage_write, Format::rgba32_float,
                                 SizeSpec::rect_of(irradiance_width, irradiance_height),
                                 "the sky's irradiance on a horizontal surface per (r, mu_s), for a sun of unit E (rgb)");
  // Internal tables.
  SlotHandle delta_irradiance = irradiance_table("delta_irradiance", "the ground's irradiance of the last order (the sun's first)");
  std::array<SlotHandle, 2> irradiance_sum = {irradiance_table("irradiance_sum_even", "the irradiance summed to an even order"),
                                              irradiance_table("irradiance_sum_odd", "the irradiance summed to an odd order")};
  SlotHandle delta_rayleigh = scattering_table("delta_rayleigh", "single Rayleigh scattering, rgb");
  SlotHandle delta_mie = scattering_table("delta_mie", "single Mie scattering, rgb");
  SlotHandle delta_multiple = scattering_table("delta_multiple", "the last order's radiance (orders ≥ 2), rgb");
  SlotHandle density = scattering_table("density", "the radiance scattered per metre toward the ray, of the order being made");
  std::array<SlotHandle, 2> scattering_sum = {scattering_table("scattering_sum_even", "the scattering texel summed to an even order"),
                                              scattering_table("scattering_sum_odd", "the scattering texel summed to an odd order")};
  // Steps.
  StepHandle direct = step("direct_irradiance", PassKind::compute,
                           {{transmittance, Usage::sampled}, {delta_irradiance, Usage::storage_write}, {irradiance_sum[1], Usage::storage_write}});
  StepHandle single = step("single_scattering", PassKind::compute,
                           {{transmittance, Usage::sampled}, {delta_rayleigh, Usage::storage_write}, {delta_mie, Usage::storage_write},
                            {scattering_sum[1], Usage::storage_write}, {single_mie_scattering, Usage::storage_write}});
  struct OrderSteps {
    StepHandle density, indirect, multiple;
  };
  std::array<OrderSteps, kMaxOrders - 1> order_steps = make_order_steps();

  // The table slots an order's steps read and write.
  SlotHandle scattering_previous(int order) const { return scattering_sum[size_t((order - 1) % 2)]; }
  SlotHandle scattering_next(int order) const { return order == kMaxOrders ? scattering : scattering_sum[size_t(order % 2)]; }
  SlotHandle irradiance_previous(int order) const { return irradiance_sum[size_t((order - 1) % 2)]; }
  SlotHandle irradiance_next(int order) const { return order == kMaxOrders ? irradiance : irradiance_sum[size_t(order % 2)]; }

 private:
  // (nu · mu_s) × mu × r.
  SizeSpec scattering_size() const { return SizeSpec::volume_of(nu_mu_s, mu, r); }
  SlotHandle irradiance_table(std::string name, std::string doc) {
    return internal(std::move(name), ResourceKind::texture2d, Format::rgba32_float, SizeSpec::rect_of(irradiance_width, irradiance_height),
                    std::move(doc));
  }
  SlotHandle scattering_table(std::string name, std::string doc) {
    return internal(std::move(name), ResourceKind::texture3d, Format::rgba32_float, scattering_size(), std::move(doc));
  }
  std::array<OrderSteps, kMaxOrders - 1> make_order_steps() {
    std::array<OrderSteps, kMaxOrders - 1> steps{};
    for (int n = 2; n <= kMaxOrders; ++n) {
      OrderSteps& s = steps[size_t(n - 2)];
      const std::string order = std::to_string(n);
      // Order n's density reads order n − 1: single scattering for n = 2, delta_multiple above.
      std::vector<std::pair<SlotHandle, Usage>> previous_order =
          n == 2 ? std::vector<std::pair<SlotHandle, Usage>>{{delta_rayleigh, Usage::sampled}, {delta_mie, Usage::sampled}}
                 : std::vector<std::pair<SlotHandle, Usage>>{{delta_multiple, Usage::sampled}};
      std::vector<std::pair<SlotHandle, Usage>> density_uses = {{transmittance, Usage::sampled}, {delta_irradiance, Usage::sampled},
                                                                {density, Usage::storage_write}};
      density_uses.insert(density_uses.end(), previous_order.begin(), previous_order.end());
      s.density = step("density_" + order, PassKind::compute, density_uses);
      std::vector<std::pair<SlotHandle, Usage>> indirect_uses = {{irradiance_previous(n), Usage::sampled},
                                                                 {delta_irradiance, Usage::storage_write},
                                                                 {irradiance_next(n), Usage::storage_write}};
      indirect_uses.insert(indirect_uses.end(), previous_order.begin(), previous_order.end());
      s.indirect = step("indirect_irradiance_" + order, PassKind::compute, indirect_uses);
      s.multiple = step("multiple_scattering_" + order, PassKind::compute,
                        {{transmittance, Usage::sampled}, {density, Usage::sampled}, {scattering_previous(n), Usage::sampled},
                         {delta_multiple, Usage::storage_write}, {scattering_next(n), Usage::storage_write}});
    }
    return steps;
  }
};

// The tables' shape (Bruneton 2017's 4D-in-3D packing), read through the table's handles
// so a misspelt parameter does not compile.
std::vector<ParamProblem> check_table_shape(const PassDecl& decl, const Scene&, const std::vector<ParamValue>& values) {
  static const BrunetonTablesTable table;
  const int64_t nu = param_in(values, table.nu);
  const int64_t nu_mu_s = param_in(values, table.nu_mu_s);
  const int64_t mu = param_in(values, table.mu);
  std::vector<ParamProblem> problems;
  if (nu_mu_s % nu != 0 || nu_mu_s / nu < 2) {
    problems.push_back({param_name(decl, table.nu_mu_s), "must be a multiple of nu (" + std::to_string(nu) +
                                                             ") holding at least 2 mu_s texels per nu slice; got " + std::to_string(nu_mu_s)});
  }
  if (mu % 2 != 0) {
    problems.push_back({param_name(decl, table.mu), "must be even (half the texels below the horizon, half above); got " + std::to_string(mu)});
  }
  return problems;
}

class BrunetonTablesExecution final : public PassExecution {
 public:
  explicit BrunetonTablesExecution(const BrunetonTablesTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    direct_ = plumbing::create_compute_program(s.device, "atmosphere_bruneton_direct_irradiance.comp");
    single_ = plumbing::create_compute_program(s.device, "atmosphere_bruneton_single_scattering.comp");
    density_ = plumbing::create_compute_program(s.device, "atmosphere_bruneton_scattering_density.comp");
    indirect_ = plumbing::create_compute_program(s.device, "atmosphere_bruneton_indirect_irradiance.comp");
    multiple_ = plumbing::create_compute_program(s.device, "atmosphere_bruneton_multiple_scattering.comp");
    atmosphere_.setup(s, direct_);
    const std::string atmosphere_label = s.pass_name() + " atmosphere";
    plumbing::check_wrapped_uniform_mirror<physics::GpuAtmosphere>(single_, bruneton_single_scattering_shader::atmosphere, atmosphere_label);
    plumbing::check_wrapped_uniform_mirror<physics::GpuAtmosphere>(density_, bruneton_scattering_density_shader::atmosphere, atmosphere_label);
    plumbing::check_wrapped_uniform_mirror<physics::GpuAtmosphere>(indirect_, bruneton_indirect_irradiance_shader::atmosphere, atmosphere_label);
    plumbing::check_wrapped_uniform_mirror<physics::GpuAtmosphere>(multiple_, bruneton_multiple_scattering_shader::atmosphere, atmosphere_label);
    const int orders = int(s.param(t_.orders));
    for (int n = 1; n <= kMaxOrders; ++n) {
      gpu::BrunetonTableParams params{};
      params.size[0] = int32_t(s.param(t_.nu));
      params.size[1] = int32_t(s.param(t_.nu_mu_s) / s.param(t_.nu));
      params.size[2] = int32_t(s.param(t_.mu));
      params.size[3] = int32_t(s.param(t_.r));
      params.order[0] = n;
      params.order[1] = n <= orders ? 1 : 0;
      params.order[2] = int32_t(n == 1 ? s.param(t_.single_samples) : s.param(t_.samples));
      const std::string label = s.pass_name() + " params (order " + std::to_string(n) + ")";
      params_[size_t(n - 1)] = plumbing::create_shared_uniform_block(
          s.device, n == 1 ? single_ : multiple_,
          n == 1 ? bruneton_single_scattering_shader::params : bruneton_multiple_scattering_shader::params, label, params);
    }
  }

  void record(PassContext& c) override {
    const rhi::SamplerId nearest = c.sampler(rhi::StockSampler::nearest_clamp);
    if (c.step_is(t_.direct)) {
      atmosphere_buffer_ = atmosphere_.write(c);
      namespace shader = bruneton_direct_irradiance_shader;
      dispatch(c, direct_, irradiance_extent(c),
               {bind(shader::atmosphere, atmosphere_buffer_), bind(shader::params, params_[0]), bind(shader::transmittance, c.view(t_.transmittance)),
                bind(shader::nearest, nearest), bind(shader::delta_irradiance, c.view(t_.delta_irradiance)),
                bind(shader::irradiance_sum, c.view(t_.irradiance_sum[1]))});
      return;
    }
    if (c.step_is(t_.single)) {
      namespace shader = bruneton_single_scattering_shader;
      dispatch(c, single_, c.extent(t_.delta_rayleigh),
               {bind(shader::atmosphere, atmosphere_buffer_), bind(shader::params, params_[0]), bind(shader::transmittance, c.view(t_.transmittance)),
                bind(shader::nearest, nearest), bind(shader::delta_rayleigh, c.view(t_.delta_rayleigh)), bind(shader::delta_mie, c.view(t_.delta_mie)),
                bind(shader::scattering_sum, c.view(t_.scattering_sum[1])), bind(shader::single_mie_scattering, c.view(t_.single_mie_scattering))});
      return;
    }
    const int orders = int(c.param(t_.orders));
    for (int n = 2; n <= kMaxOrders; ++n) {
      const auto& s = t_.order_steps[size_t(n - 2)];
      const rhi::BufferId params = params_[size_t(n - 1)];
      // Order n − 1's radiance: single Rayleigh and Mie for n = 2, delta_multiple above.
      const rhi::TextureViewId rayleigh = c.view(n == 2 ? t_.delta_rayleigh : t_.delta_multiple);
      const rhi::TextureViewId mie = c.view(n == 2 ? t_.delta_mie : t_.delta_multiple);
      if (c.step_is(s.density)) {
        if (n > orders) return;  // nothing reads this order's density
        namespace shader = bruneton_scattering_density_shader;
        dispatch(c, density_, c.extent(t_.density),
                 {bind(shader::atmosphere, atmosphere_buffer_), bind(shader::params, params), bind(shader::transmittance, c.view(t_.transmittance)),
                  bind(shader::nearest, nearest), bind(shader::delta_rayleigh, rayleigh), bind(shader::delta_mie, mie), bind(shader::delta_multiple, mie),
                  bind(shader::delta_irradiance, c.view(t_.delta_irradiance)), bind(shader::density, c.view(t_.density))});
        return;
      }
      if (c.step_is(s.indirect)) {
        namespace shader = bruneton_indirect_irradiance_shader;
        dispatch(c, indirect_, irradiance_extent(c),
                 {bind(shader::atmosphere, atmosphere_buffer_), bind(shader::params, params), bind(shader::delta_rayleigh, rayleigh),
                  bind(shader::delta_mie, mie), bind(shader::delta_multiple, mie), bind(shader::nearest, nearest),
                  bind(shader::irradiance_previous, c.view(t_.irradiance_previous(n))), bind(shader::delta_irradiance, c.view(t_.delta_irradiance)),
                  bind(shader::irradiance_next, c.view(t_.irradiance_next(n)))});
        return;
      }
      if (c.step_is(s.multiple)) {
        namespace shader = bruneton_multiple_scattering_shader;
        dispatch(c, multiple_, c.extent(t_.delta_multiple),
                 {bind(shader::atmosphere, atmosphere_buffer_), bind(shader::params, params), bind(shader::transmittance, c.view(t_.transmittance)),
                  bind(shader::nearest, nearest), bind(shader::density, c.view(t_.density)),
                  bind(shader::scattering_previous, c.view(t_.scattering_previous(n))), bind(shader::delta_multiple, c.view(t_.delta_multiple)),
                  bind(shader::scattering_next, c.view(t_.scattering_next(n)))});
        return;
      }
    }
  }

 private:
  Extent irradiance_extent(const PassContext& c) const { return c.extent(t_.delta_irradiance); }

  // One step's dispatch; `resources` name the program's shader variables (checked against its layout).
  static void dispatch(PassContext& c, const plumbing::ComputeProgram& program, Extent size, const std::vector<rhi::BoundResource>& resources) {
    const rhi::BindGroupId group = c.bind_group(program, resources);
    plumbing::dispatch(c.encoder, c.name(), program, {group}, {size.width, size.height, size.depth});
  }

  const BrunetonTablesTable& t_;
  plumbing::ComputeProgram direct_, single_, density_, indirect_, multiple_;
  atmosphere::AtmosphereBlock atmosphere_;
  rhi::BufferId atmosphere_buffer_;
  std::array<rhi::BufferId, kMaxOrders> params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(BrunetonTablesTable, BrunetonTablesExecution);

}  // namespace volgraph
