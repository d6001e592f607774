// volume_phantom: a procedural scalar volume for volume_visualize (RTR4 14.3.1), made once by
// the graph and cached: `density` (size³, r the density in [0, 1]) of a phantom in the unit
// box. Variants: `sphere` (a signed-distance-like ramp: 0.5 on the sphere of `radius`, rising
// inward and falling outward linearly over `shell`, so the isosurface of any density ρ inside
// the ramp is exactly the sphere of radius radius + (0.5 − ρ)·shell) and `shells` (nested
// shells of densities 0.25, 0.5 and a core of 1, with the same ramps). Each texel is
// shaders/include/volume_phantom.h at its centre, the text the CPU twin
// (physics/volume_phantom.h) compiles too. Shader: shaders/volume_phantom.comp.
#include <cstdint>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/plumbing/programs.h"
#include "passes/register_pass.h"
#include "shaders/bindings/volume_phantom.comp.h"
#include "physics/volume_phantom.h"

namespace volgraph {
namespace {

namespace volume_phantom_shader = shaders::volume_phantom_comp;

struct VolumePhantomTable : PassTable {
  VolumePhantomTable()
      : PassTable("volume_phantom", PassKind::compute,
                  "A procedural scalar volume (a sphere or nested shells) for volume_visualize.") {
    decl.cached = true;
    decl.frame_invariant = true;
  }
  // Variants.
  VariantHandle sphere = variant("sphere",
                                 "a sphere: density ramp(radius − r), 0.5 on the sphere, linear over `shell` (its isosurfaces are exact spheres)",
                                 VOLUME_PHANTOM_SPHERE);
  VariantHandle shells = variant("shells", "nested shells of densities 0.25 (0.8–1 of radius), 0.5 (0.45–0.65) and a core of 1 (below 0.25)",
                                 VOLUME_PHANTOM_SHELLS);
  // Parameters.
  ParamHandle<int64_t> size = integer("size", 64, 4, 512, "texels", "the volume's side (a cube)");
  ParamHandle<double> radius = number("radius", 0.35, 0.01, 0.5, "box", "the sphere's (the outer shell's) radius, a fraction of the box's side");
  ParamHandle<double> shell = number("shell", 0.1, 0.001, 0.5, "box",
                                     "the width of the ramp across each boundary (density 0 to 1), a fraction of the box's side");
  // Slots.
  SlotHandle density = output("density", ResourceKind::texture3d, Usage::storage_write, Format::rgba16_float,
                              SizeSpec::square_layers_of(size, size), "r the density in [0, 1] (g b a zero); the unit box's texel centres");
};

class VolumePhantomExecution final : public PassExecution {
 public:
  explicit VolumePhantomExecution(const VolumePhantomTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "volume_phantom.comp");
    const gpu::VolumePhantomParams params{{float(s.param(t_.radius)), float(s.param(t_.shell)), 0, 0},
                                          {s.variant().shader_code, 0, 0, 0}};
    params_ = plumbing::create_shared_uniform_block(s.device, program_, volume_phantom_shader::params, s.name() + " params", params);
  }

  // Runs when the cache key changed: the first frame, or another variant or parameter.
  void record(PassContext& c) override {
    const rhi::BindGroupId group =
        c.bind_group(program_, {bind(volume_phantom_shader::params, params_), bind(volume_phantom_shader::density, c.view(t_.density))});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.density));
  }

 private:
  const VolumePhantomTable& t_;
  plumbing::ComputeProgram program_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(VolumePhantomTable, VolumePhantomExecution);

}  // namespace volgraph
