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
//
// Variant six_view_depth: Karabassi et al. 1999's six-view depth method (RTR4 13.10.3) — the
// triangles drawn by orthographic projection along ±x, ±y, ±z over the grid's box into six
// depth maps of resolution² (internal slots; texel (i, j) on the line through voxel centres),
// then a compute step sets a voxel where its centre lies between the nearest surfaces seen
// from both sides along all three axes. It fills the solid (the compute variant marks the
// surface) and has the method's failure cases: a cavity no view sees is filled, a part
// thinner than a voxel between two centres is missed. Shaders: shaders/voxelize_view.vert,
// shaders/voxelize_six_view.comp, shaders/include/six_view_depth.glsl.
#include <array>
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
#include "shaders/bindings/voxelize_six_view.comp.h"
#include "shaders/bindings/voxelize_view.vert.h"
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
  // Variants.
  VariantHandle conservative = variant("conservative", "every voxel a triangle touches, by the triangle–box overlap test (RTR4 22.12): the surface");
  VariantHandle six_view_depth = variant("six_view_depth", "Karabassi et al. 1999: voxels whose centres lie between the nearest surfaces six orthographic depth views see: the solid");
  // Parameters.
  ParamHandle<int64_t> object = integer("object", 0, 0, 1 << 20, "", "the object voxelized: its index in scene.objects");
  ParamHandle<int64_t> resolution = integer("resolution", 64, 2, 256, "voxels", "the grid's voxels along each axis (a cube)");
  // Slots.
  SlotHandle voxels = output("voxels", ResourceKind::texture3d, Usage::storage_write, Format::rgba8_unorm,
                             SizeSpec::square_layers_of(resolution, resolution),
                             "r 1 where a triangle of the object overlaps the voxel, else 0 (g b a 0); x, y, z as the world's");
  SlotHandle grid = output("grid", ResourceKind::buffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(sizeof(gpu::VoxelGrid)),
                           "the grid's placement (shaders/include/voxel_grid.h): origin and voxel side (m), resolution");
  SlotHandle view_x_plus = view_depth("view_x_plus", "along +x (from the grid's low x)");
  SlotHandle view_x_minus = view_depth("view_x_minus", "along −x (from the grid's high x)");
  SlotHandle view_y_plus = view_depth("view_y_plus", "along +y");
  SlotHandle view_y_minus = view_depth("view_y_minus", "along −y");
  SlotHandle view_z_plus = view_depth("view_z_plus", "along +z");
  SlotHandle view_z_minus = view_depth("view_z_minus", "along −z");
  std::array<SlotHandle, 6> views() const { return {view_x_plus, view_x_minus, view_y_plus, view_y_minus, view_z_plus, view_z_minus}; }
  // Steps: the grid's placement for both variants, then the overlap test, or the six views and the fill.
  StepHandle place = step("grid", PassKind::transfer, {{grid, Usage::copy_dst}});
  StepHandle draw_views = step("views", PassKind::graphics,
                               {{view_x_plus, Usage::depth_attachment}, {view_x_minus, Usage::depth_attachment},
                                {view_y_plus, Usage::depth_attachment}, {view_y_minus, Usage::depth_attachment},
                                {view_z_plus, Usage::depth_attachment}, {view_z_minus, Usage::depth_attachment}},
                               only_in({six_view_depth}));
  StepHandle overlap = step("overlap", PassKind::compute, {{voxels, Usage::storage_write}}, only_in({conservative}));
  StepHandle fill = step("fill", PassKind::compute,
                         {{view_x_plus, Usage::sampled}, {view_x_minus, Usage::sampled}, {view_y_plus, Usage::sampled},
                          {view_y_minus, Usage::sampled}, {view_z_plus, Usage::sampled}, {view_z_minus, Usage::sampled},
                          {voxels, Usage::storage_write}},
                         only_in({six_view_depth}));

 private:
  SlotHandle view_depth(std::string name, const std::string& along) {
    return internal(std::move(name), ResourceKind::texture2d, Format::d32_float, SizeSpec::square_of(resolution),
                    "six_view_depth: the depth (0 at the side it looks from) of the nearest surface seen " + along + ", resolution²");
  }
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
    params_ = s.device.create_buffer({s.name() + " params", sizeof(gpu::VoxelizeParams), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
    if (s.variant_is(t_.conservative)) {
      program_ = plumbing::create_compute_program(s.device, "voxelize.comp");
      plumbing::check_wrapped_uniform_mirror<gpu::VoxelizeParams>(program_, voxelize_shader::params, s.name() + " params");
      return;
    }
    fill_ = plumbing::create_compute_program(s.device, "voxelize_six_view.comp");
    plumbing::check_wrapped_uniform_mirror<gpu::VoxelizeParams>(fill_, shaders::voxelize_six_view_comp::params, s.name() + " params");
    rhi::RenderPipelineDesc pipeline;
    pipeline.label = s.name() + " views";
    pipeline.vertex_buffers = {{4 * sizeof(float), {{0, rhi::VertexFormat::float32x3, 0}}}};  // the corners, xyzw each
    pipeline.depth = {Format::d32_float, true, rhi::CompareFunction::less};  // the nearest surface; both windings (cull none)
    views_ = plumbing::create_render_program(s.device, pipeline, "voxelize_view.vert", "");
    for (size_t v = 0; v < view_params_.size(); ++v) {
      view_params_[v] = s.device.create_buffer({s.name() + " view " + std::to_string(v), sizeof(gpu::VoxelizeParams),
                                                rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
    }
  }

  // Runs when the cache key changed: the first frame, another object or resolution, new geometry.
  void record(PassContext& c) override {
    if (c.step_is(t_.place)) return place_grid(c);
    if (c.step_is(t_.draw_views)) return draw_views(c);
    if (c.step_is(t_.fill)) return fill_solid(c);
    namespace shader = voxelize_shader;
    upload_geometry(c);
    const rhi::BindGroupId group = c.bind_group(
        program_, {bind(shader::params, params_), bind(shader::Corners, corners_), bind(shader::voxels, c.view(t_.voxels))});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.voxels));
  }

 private:
  // The grid's placement for the readers (a step of its own: culled where none reads it).
  void place_grid(PassContext& c) {
    const std::vector<voxels::Triangle> triangles = voxels::world_triangles(*c.scene, size_t(c.param(t_.object)));
    const gpu::VoxelGrid grid = voxels::grid_around(triangles, int(c.param(t_.resolution)));
    c.encoder.update_buffer(c.buffer(t_.grid), 0, std::as_bytes(std::span(&grid, 1)));
  }

  // The object's triangles in the grid's coordinates uploaded and the parameters written, by
  // the first step that reads them (overlap, or views).
  void upload_geometry(PassContext& c) {
    const int resolution = int(c.param(t_.resolution));
    const std::vector<voxels::Triangle> triangles = voxels::world_triangles(*c.scene, size_t(c.param(t_.object)));
    upload_corners(c, voxels::grid_corners(triangles, voxels::grid_around(triangles, resolution)));
    triangle_count_ = uint32_t(triangles.size());
    gpu::VoxelizeParams params{{int32_t(triangles.size()), resolution, 0, 0}};
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    if (!c.variant_is(t_.six_view_depth)) return;
    for (size_t v = 0; v < view_params_.size(); ++v) {
      params.counts.z = int32_t(v);
      c.device.write_buffer(view_params_[v], 0, std::as_bytes(std::span(&params, 1)));
    }
  }

  // six_view_depth: the triangles into each view's depth map, the nearest surface kept.
  void draw_views(PassContext& c) {
    upload_geometry(c);
    const std::array<SlotHandle, 6> views = t_.views();
    for (size_t v = 0; v < views.size(); ++v) {
      rhi::RenderPassDesc pass;
      pass.label = c.name() + " " + std::to_string(v);
      pass.depth = {c.view(views[v]), rhi::LoadOp::clear, 1.0f, false};
      c.encoder.begin_render_pass(pass);
      if (triangle_count_ > 0) {
        c.encoder.set_pipeline(views_.pipeline);
        c.encoder.set_bind_group(0, c.bind_group(views_, {bind(shaders::voxelize_view_vert::params, view_params_[v])}));
        c.encoder.set_vertex_buffer(0, corners_);
        c.encoder.draw(3 * triangle_count_);
      }
      c.encoder.end_render_pass();
    }
  }

  // six_view_depth: a voxel is solid where its centre is inside along all three axes.
  void fill_solid(PassContext& c) {
    namespace shader = shaders::voxelize_six_view_comp;
    const rhi::BindGroupId group = c.bind_group(
        fill_, {bind(shader::params, params_), bind(shader::view_x_plus, c.view(t_.view_x_plus)),
                bind(shader::view_x_minus, c.view(t_.view_x_minus)), bind(shader::view_y_plus, c.view(t_.view_y_plus)),
                bind(shader::view_y_minus, c.view(t_.view_y_minus)), bind(shader::view_z_plus, c.view(t_.view_z_plus)),
                bind(shader::view_z_minus, c.view(t_.view_z_minus)), bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)),
                bind(shader::voxels, c.view(t_.voxels))});
    plumbing::dispatch(c.encoder, c.name(), fill_, {group}, c.extent(t_.voxels));
  }

  // The triangles' corners into the pass's storage buffer (made again when the count changes;
  // one vec4 at least, as a binding may not be empty).
  void upload_corners(PassContext& c, std::vector<float> corners) {
    if (corners.empty()) corners.assign(4, 0.0f);
    const size_t bytes = corners.size() * sizeof(float);
    if (bytes != corners_bytes_) {
      if (corners_bytes_) c.device.destroy(corners_);
      corners_ = c.device.create_buffer(
          {c.name() + " corners", bytes, rhi::buffer_usage::storage | rhi::buffer_usage::vertex | rhi::buffer_usage::copy_dst});
      corners_bytes_ = bytes;
    }
    c.device.write_buffer(corners_, 0, std::as_bytes(std::span(corners)));
  }

  const VoxelizeTable& t_;
  plumbing::ComputeProgram program_;  // conservative's overlap test
  plumbing::ComputeProgram fill_;     // six_view_depth's fill
  plumbing::RenderProgram views_;     // six_view_depth's depth views
  rhi::BufferId params_, corners_;
  std::array<rhi::BufferId, 6> view_params_{};  // each view's parameters (counts.z the view)
  size_t corners_bytes_ = 0;
  uint32_t triangle_count_ = 0;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(VoxelizeTable, VoxelizeExecution);

}  // namespace volgraph
