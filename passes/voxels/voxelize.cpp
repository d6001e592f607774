// voxelize: a scene object's surface as voxels (RTR4 13.10), the conservative compute variant:
// every voxel a triangle touches is set, by Akenine-Möller's triangle–box overlap test with
// the separating axis theorem (RTR4 22.12; shaders/include/voxel_overlap.h, the text the CPU
// twin passes/voxels/voxel_mesh.h compiles too), so thin walls and triangles smaller than a
// voxel are never missed. Object `object` (an index into scene.objects: a box, sphere, plane
// or glTF model) is read on the CPU as scene_geometry reads the scene's meshes and uploaded
// here, in the grid's coordinates, as a storage buffer the pass owns (the scene's own
// geometry, as scene_geometry's vertex buffers are). The grid is the object's world bounding
// box padded to a cube about its centre; its placement goes to `grid` for the readers.
// One invocation per voxel loops over every triangle: each voxel is written exactly once
// (no clear, no atomics, the same result on every run and backend); the cost, voxels ×
// triangles, suits models of a few thousand triangles at 64³ — a per-triangle splat over its
// bounding box's voxels (after a clear) is the way to larger models. Cached: it runs again
// only when the object, its resolution or the scene's geometry change. Shader: shaders/voxelize.comp.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/plumbing/programs.h"
#include "passes/register_pass.h"
#include "passes/voxels/voxel_mesh.h"
#include "shaders/bindings/voxelize.comp.h"
#include "shaders/include/voxelize_params.h"

namespace volgraph {
namespace {

namespace voxelize_shader = shaders::voxelize_comp;

std::vector<ParamProblem> voxelized_object_problems(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params);

struct VoxelizeTable : PassTable {
  VoxelizeTable()
      : PassTable("voxelize", PassKind::compute,
                  "A scene object's surface voxelized into a 3D texture by the conservative triangle–box overlap test (RTR4 13.10, 22.12).") {
    decl.needs = feature_bit(SceneFeature::geometry);
    decl.check_scene = voxelized_object_problems;
    decl.reads_scene = part_bit(ScenePart::geometry);
    decl.cached = true;
    decl.frame_invariant = true;
  }
  // Parameters.
  ParamHandle<int64_t> object = integer("object", 0, 0, 1 << 20, "", "the object voxelized: its index in scene.objects");
  ParamHandle<int64_t> resolution = integer("resolution", 64, 2, 256, "voxels", "the grid's voxels along each axis (a cube)");
  // Slots.
  SlotHandle voxels = output("voxels", ResourceKind::texture3d, Usage::storage_write, Format::rgba8_unorm,
                             SizeSpec::square_layers_of(resolution, resolution),
                             "r 1 where a triangle of the object overlaps the voxel, else 0 (g b a 0); x, y, z as the world's");
  SlotHandle grid = output("grid", ResourceKind::buffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(sizeof(gpu::VoxelGrid)),
                           "the grid's placement (shaders/include/voxel_grid.h): origin and voxel side (m), resolution");
};

std::vector<ParamProblem> voxelized_object_problems(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params) {
  static const VoxelizeTable table;
  const int64_t index = param_in(params, table.object);
  if (index < int64_t(scene.objects.size())) return {};
  return {{param_name(decl, table.object),
           "object " + std::to_string(index) + " does not exist: scene.objects has " + std::to_string(scene.objects.size())}};
}

class VoxelizeExecution final : public PassExecution {
 public:
  explicit VoxelizeExecution(const VoxelizeTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "voxelize.comp");
    plumbing::check_wrapped_uniform_mirror<gpu::VoxelizeParams>(program_, voxelize_shader::params, s.name() + " params");
    params_ = s.device.create_buffer({s.name() + " params", sizeof(gpu::VoxelizeParams), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  // Runs when the cache key changed: the first frame, another object or resolution, new geometry.
  void record(PassContext& c) override {
    namespace shader = voxelize_shader;
    const int resolution = int(c.param(t_.resolution));
    const std::vector<voxels::Triangle> triangles = voxels::world_triangles(*c.scene, size_t(c.param(t_.object)));
    const gpu::VoxelGrid grid = voxels::grid_around(triangles, resolution);
    upload_corners(c, voxels::grid_corners(triangles, grid));
    const gpu::VoxelizeParams params{{int32_t(triangles.size()), resolution, 0, 0}};
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    c.encoder.update_buffer(c.buffer(t_.grid), 0, std::as_bytes(std::span(&grid, 1)));  // for the readers
    const rhi::BindGroupId group = c.bind_group(
        program_, {bind(shader::params, params_), bind(shader::Corners, corners_), bind(shader::voxels, c.view(t_.voxels))});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.voxels));
  }

 private:
  // The triangles' corners into the pass's storage buffer (made again when the count changes;
  // one vec4 at least, as a binding may not be empty).
  void upload_corners(PassContext& c, std::vector<float> corners) {
    if (corners.empty()) corners.assign(4, 0.0f);
    const size_t bytes = corners.size() * sizeof(float);
    if (bytes != corners_bytes_) {
      if (corners_bytes_) c.device.destroy(corners_);
      corners_ = c.device.create_buffer({c.name() + " corners", bytes, rhi::buffer_usage::storage | rhi::buffer_usage::copy_dst});
      corners_bytes_ = bytes;
    }
    c.device.write_buffer(corners_, 0, std::as_bytes(std::span(corners)));
  }

  const VoxelizeTable& t_;
  plumbing::ComputeProgram program_;
  rhi::BufferId params_, corners_;
  size_t corners_bytes_ = 0;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(VoxelizeTable, VoxelizeExecution);

}  // namespace volgraph
