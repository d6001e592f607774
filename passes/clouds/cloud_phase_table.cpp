// cloud_phase_table: the cloud droplets' phase function as a texture (physics/mie: Lorenz–Mie
// by BHMIE, Bohren & Huffman 1983, over Hansen & Travis 1974's modified gamma distribution of
// water droplets, r_eff `effective_radius`, v_eff `effective_variance`), per channel at the
// atmosphere's 680, 550 and 440 nm, in shaders/include/cloud_phase_table.h's parameterisation:
// texel i of `size` holds p(θ_i), θ_i = π((i + ½)/size)², dense near the forward peak.
// rgba32float: the forward peak (~600 /sr) and the back (~0.03 /sr) keep their exact values (the
// GPU reads what physics computed), and WebGPU cannot filter it, so cloud_march mixes the two
// texels itself, as the CPU twin does. Computed on the CPU (~0.15 s for 512 texels) and
// uploaded once; cached. cloud_march reads it through its optional `phase_table` input.
// Variant henyey_greenstein: one HG lobe of `g` tabulated alike (the analytic phase through
// the table, for comparing the two).
#include <span>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "passes/plumbing/staged_upload.h"
#include "passes/register_pass.h"
#include "physics/mie.h"

namespace volgraph {
namespace {

struct CloudPhaseTableTable : PassTable {
  CloudPhaseTableTable()
      : PassTable("cloud_phase_table", PassKind::transfer,
                  "The cloud droplets' Mie phase function per channel as a table over θ (Bohren & Huffman 1983; Hansen & Travis 1974).") {
    decl.needs = feature_bit(SceneFeature::clouds);
    decl.cached = true;
    decl.frame_invariant = true;
  }
  // Variants.
  VariantHandle mie = variant("mie", "Lorenz–Mie over Hansen & Travis's modified gamma distribution of water droplets (m = 1.333)");
  VariantHandle henyey_greenstein = variant("henyey_greenstein", "one Henyey–Greenstein lobe of g, tabulated alike (for comparisons)");
  // Parameters.
  ParamHandle<int64_t> size = integer("size", 512, 2, 8192, "texels", "the table's texels over θ (u = sqrt(θ/π) at (i + ½)/size)");
  ParamHandle<double> effective_radius =
      number("effective_radius", 10, 1, 30, "µm", "the droplets' effective radius r_eff (Hansen & Travis 1974's water cloud: 10 µm)");
  ParamHandle<double> effective_variance =
      number("effective_variance", 0.1, 0.02, 0.3, "", "the droplets' effective variance v_eff (Hansen & Travis 1974's water cloud: 0.1)");
  ParamHandle<double> g = number("g", 0.8, -0.998, 0.998, "", "henyey_greenstein: the lobe's mean cosine");
  // Slots.
  SlotHandle phase = output("phase", ResourceKind::texture2d, Usage::copy_dst, Format::rgba32_float, SizeSpec::row_of(size),
                            "rgb p(θ_i) per channel (1/sr) at θ_i = π((i + ½)/size)², a 1");
};

// The table's texels as the texture holds them: rgb p per channel, a 1.
std::vector<float> phase_texels(const physics::CloudPhaseTable& table) {
  std::vector<float> texels;
  texels.reserve(table.texels.size() * 4);
  for (const std::array<float, 3>& p : table.texels) texels.insert(texels.end(), {p[0], p[1], p[2], 1.0f});
  return texels;
}

class CloudPhaseTableExecution final : public PassExecution {
 public:
  explicit CloudPhaseTableExecution(const CloudPhaseTableTable& table) : t_(table) {}

  void setup(PassSetup& s) override { henyey_greenstein_ = s.variant_is(t_.henyey_greenstein); }

  // Runs when the cache key changed: the first frame, another size or distribution.
  void record(PassContext& c) override {
    const std::vector<float> texels = phase_texels(table(c));
    upload_.record(c, std::as_bytes(std::span(texels)), c.texture(t_.phase));
  }

 private:
  physics::CloudPhaseTable table(const PassContext& c) const {
    const uint32_t n = uint32_t(c.param(t_.size));
    if (henyey_greenstein_) return physics::henyey_greenstein_phase_table(c.param(t_.g), n);
    return physics::cloud_droplet_phase_table({c.param(t_.effective_radius), c.param(t_.effective_variance)}, n);
  }

  const CloudPhaseTableTable& t_;
  bool henyey_greenstein_ = false;
  plumbing::StagedUpload upload_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(CloudPhaseTableTable, CloudPhaseTableExecution);

}  // namespace volgraph
