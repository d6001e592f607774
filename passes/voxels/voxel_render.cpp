// voxel_render: voxelize's grid drawn over the scene (RTR4 13.10), two ways that give the same
// image:
//   dda:   direct ray casting of the grid — per pixel, the camera ray against the grid's box
//          (slab method), then Amanatides & Woo 1987's DDA, voxel to voxel, to the first set
//          voxel, shaded by the face the ray entered it through. A compute step.
//   faces: the grid as a mesh of cube faces (RTR4 13.10): the faces between two solid voxels
//          culled and, with `meshing` greedy, the rest merged into rectangles
//          (passes/voxels/voxel_faces.h), rasterized as two triangles a quad with a depth
//          buffer of the pass's own. The quads are meshed at setup on the CPU twin's voxels
//          (voxel_mesh.h voxelize_on_cpu: the same object at the same resolution as the wired
//          voxelize, equal to the GPU's bit for bit) and kept per object content +
//          resolution; their vertex and index buffers are uploaded then, as scene_geometry
//          uploads the scene's meshes. The compute step lays the scene's colour (and hit 0),
//          the graphics step draws the quads over it. `plan --setup` notes the quad counts.
// Both shade flat Lambert by the face's normal (shaders/include/voxel_shading.h), lit by the
// scene's first directional light (else a headlight of irradiance π), albedo `albedo`, and
// keep a face only where it is nearer than the scene's depth along the pixel's ray; elsewhere
// the scene's colour shows. Outputs `color` and `hit` (r the distance in metres along the ray
// to the face, 0 where none). Shaders: shaders/voxel_render.comp, voxel_faces.vert/.frag.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/sun_for_shader.h"
#include "passes/register_pass.h"
#include "passes/voxels/voxel_faces.h"
#include "passes/voxels/voxel_mesh.h"
#include "physics/camera.h"
#include "shaders/bindings/voxel_faces.frag.h"
#include "shaders/bindings/voxel_render.comp.h"
#include "shaders/include/voxel_grid.h"
#include "shaders/include/voxel_render_params.h"

namespace volgraph {
namespace {

namespace voxel_render_shader = shaders::voxel_render_comp;

// Which quads the faces variant draws (both cover the same faces).
enum class FaceMeshing : uint8_t { greedy, culled };

struct VoxelRenderTable : PassTable {
  VoxelRenderTable()
      : PassTable("voxel_render", PassKind::compute,
                  "voxelize's grid drawn over the scene: ray cast by a 3D DDA (Amanatides & Woo 1987) or rasterized as cube faces (RTR4 13.10).") {}
  // Variants.
  VariantHandle dda = variant("dda", "per pixel, Amanatides & Woo's DDA through the grid to the first set voxel, shaded by its entered face",
                              VOXEL_RENDER_DDA);
  VariantHandle faces = variant("faces", "the grid's exposed cube faces (culled, or greedily merged) rasterized with a depth buffer, shaded as dda",
                                VOXEL_RENDER_FACES);
  // Parameters.
  ParamHandle<std::array<double, 3>> albedo = vec3("albedo", {0.8, 0.8, 0.8}, 0, 1, "", "the voxels' Lambertian albedo");
  ChoiceHandle<FaceMeshing> meshing = choice("meshing", FaceMeshing::greedy, {{FaceMeshing::greedy, "greedy"}, {FaceMeshing::culled, "culled"}},
                                             "faces: the quads drawn — greedy (merged rectangles) or culled (one per exposed voxel face)");
  // Slots.
  SlotHandle voxels = input("voxels", ResourceKind::texture3d, Usage::sampled, "voxelize.voxels: r 1 where set");
  SlotHandle grid = input("grid", ResourceKind::buffer, Usage::uniform_read, "voxelize.grid: the grid's placement");
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth: the voxels are tested against it",
                           {.format = Format::d32_float});
  SlotHandle scene_color = input("scene_color", ResourceKind::texture2d, Usage::sampled, "the scene's linear radiance, where the rays miss");
  SlotHandle color = output("color", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float, SizeSpec::of_output(),
                            "the voxels over the scene (the frame's size, as its scene_color; rgba16f, the shader's storage format)");
  SlotHandle hit = output("hit", ResourceKind::texture2d, Usage::storage_write, Format::r32_float, SizeSpec::of_output(),
                          "r the distance (m) along the pixel's ray to the voxel face it enters, 0 where it meets none");
  SlotHandle face_depth = internal("face_depth", ResourceKind::texture2d, Format::d32_float, SizeSpec::of_output(),
                                   "faces: the quads' depth buffer (the nearest quad wins)");
  // Steps: the compute step (dda draws there; faces lays the scene behind), then faces' quads over it.
  StepHandle cast = step("cast", PassKind::compute,
                         {{voxels, Usage::sampled}, {grid, Usage::uniform_read}, {depth, Usage::sampled}, {scene_color, Usage::sampled},
                          {color, Usage::storage_write}, {hit, Usage::storage_write}});
  StepHandle draw_faces = step("faces", PassKind::graphics,
                               {{depth, Usage::sampled}, {color, Usage::color_attachment_load}, {hit, Usage::color_attachment_load},
                                {face_depth, Usage::depth_attachment}},
                               only_in({faces}));
};

// The faces variant's quads for one object at one resolution: the CPU twin's voxels meshed.
struct VoxelFaceMeshes {
  gpu::VoxelGrid grid{};
  int64_t solid = 0;
  std::vector<voxels::FaceQuad> culled, greedy;
};

// FNV-1a over bytes: the key of an object's triangles (in the grid's coordinates) and grid.
uint64_t voxel_content_hash(std::span<const std::byte> bytes, uint64_t hash = 14695981039346656037ull) {
  for (const std::byte b : bytes) hash = (hash ^ uint64_t(b)) * 1099511628211ull;
  return hash;
}

// Meshed once per object content + resolution (the voxelization on the CPU is the cost), shared
// by every faces pass and executor of the process.
std::shared_ptr<const VoxelFaceMeshes> voxel_face_meshes(const Scene& scene, size_t object, int resolution) {
  static std::mutex mutex;
  static std::map<std::pair<uint64_t, int>, std::shared_ptr<const VoxelFaceMeshes>> cache;
  const std::vector<voxels::Triangle> triangles = voxels::world_triangles(scene, object);
  const gpu::VoxelGrid grid = voxels::grid_around(triangles, resolution);
  const std::vector<float> corners = voxels::grid_corners(triangles, grid);
  const std::pair key{voxel_content_hash(std::as_bytes(std::span(&grid, 1)), voxel_content_hash(std::as_bytes(std::span(corners)))), resolution};
  const std::lock_guard lock(mutex);
  if (const auto found = cache.find(key); found != cache.end()) return found->second;
  auto meshes = std::make_shared<VoxelFaceMeshes>();
  const std::vector<uint8_t> solid = voxels::voxelize_on_cpu(corners, resolution);
  meshes->grid = grid;
  for (const uint8_t s : solid) meshes->solid += s != 0;
  meshes->culled = voxels::culled_faces(solid, resolution);
  meshes->greedy = voxels::greedy_faces(solid, resolution);
  cache.emplace(key, meshes);
  return meshes;
}

class VoxelRenderExecution final : public PassExecution {
 public:
  explicit VoxelRenderExecution(const VoxelRenderTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "voxel_render.comp");
    plumbing::check_wrapped_uniform_mirror<gpu::VoxelRenderParams>(program_, voxel_render_shader::params, s.name() + " params");
    plumbing::check_wrapped_uniform_mirror<gpu::VoxelGrid>(program_, voxel_render_shader::grid, s.name() + " grid");
    params_ = s.device.create_buffer({s.name() + " params", sizeof(gpu::VoxelRenderParams), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
    if (s.variant_is(t_.faces)) setup_faces(s);
  }

  void record(PassContext& c) override {
    if (c.step_is(t_.draw_faces)) return record_faces(c);
    namespace shader = voxel_render_shader;
    const gpu::VoxelRenderParams params = render_params(c);
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    const rhi::BindGroupId group = c.bind_group(
        program_, {bind(shader::params, params_), bind(shader::grid, c.buffer(t_.grid)), bind(shader::voxels, c.view(t_.voxels)),
                   bind(shader::scene_depth, c.view(t_.depth)), bind(shader::scene_color, c.view(t_.scene_color)),
                   bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)), bind(shader::color, c.view(t_.color)),
                   bind(shader::hit, c.view(t_.hit))});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.color));
  }

 private:
  // The wired voxelize's object and resolution meshed on the CPU twin; the chosen quads uploaded.
  void setup_faces(PassSetup& s) {
    using namespace rhi;
    RenderPipelineDesc pipeline;
    pipeline.label = s.name() + " faces";
    pipeline.vertex_buffers = {{voxels::kFaceVertexFloats * 4, {{0, VertexFormat::float32x3, 0}, {1, VertexFormat::float32x3, 12}}}};
    pipeline.colors = {{s.desc(t_.color).format, BlendMode::replace}, {Format::r32_float, BlendMode::replace}};
    pipeline.depth = {Format::d32_float, true, CompareFunction::less};
    pipeline.cull = CullMode::back;  // the exposed faces bound closed solids: a back face is always behind a front one
    faces_ = plumbing::create_render_program(s.device, pipeline, "voxel_faces.vert", "voxel_faces.frag");
    const int64_t object = s.producer_param(t_.voxels, "object"), resolution = s.producer_param(t_.voxels, "resolution");
    const std::shared_ptr<const VoxelFaceMeshes> meshes = voxel_face_meshes(*s.scene, size_t(object), int(resolution));
    const bool greedy = s.param(t_.meshing) == FaceMeshing::greedy;
    const std::vector<voxels::FaceQuad>& quads = greedy ? meshes->greedy : meshes->culled;
    const glm::vec3 origin(meshes->grid.origin[0], meshes->grid.origin[1], meshes->grid.origin[2]);
    voxels::FaceTriangles triangles = voxels::face_triangles(quads, origin, meshes->grid.origin[3]);
    if (triangles.indices.empty()) triangles = {std::vector<float>(voxels::kFaceVertexFloats, 0.0f), {0, 0, 0}};  // a buffer may not be empty
    face_index_count_ = quads.empty() ? 0 : uint32_t(triangles.indices.size());
    face_vertices_ = s.device.create_buffer({s.name() + " face vertices", triangles.vertices.size() * 4, buffer_usage::vertex});
    s.device.write_buffer(face_vertices_, 0, std::as_bytes(std::span(triangles.vertices)));
    face_indices_ = s.device.create_buffer({s.name() + " face indices", triangles.indices.size() * 4, buffer_usage::index});
    s.device.write_buffer(face_indices_, 0, std::as_bytes(std::span(triangles.indices)));
    s.note("faces: object " + std::to_string(object) + " at " + std::to_string(resolution) + "³ meshed on the CPU twin's voxels at setup (" +
           std::to_string(meshes->solid) + " set; cached by the object's content and the resolution): naive " +
           std::to_string(6 * meshes->solid) + " faces, culled " + std::to_string(meshes->culled.size()) + ", greedy " +
           std::to_string(meshes->greedy.size()) + " quads; drawing " + (greedy ? "greedy" : "culled") + ": " +
           std::to_string(quads.size()) + " quads, " + std::to_string(2 * quads.size()) + " triangles");
  }

  // The quads over the compute step's scene colour, nearest first by the pass's depth buffer.
  void record_faces(PassContext& c) {
    namespace shader = shaders::voxel_faces_frag;
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.color), rhi::LoadOp::load}, {c.view(t_.hit), rhi::LoadOp::load}};
    pass.depth = {c.view(t_.face_depth), rhi::LoadOp::clear, 1.0f, false};
    c.encoder.begin_render_pass(pass);
    if (face_index_count_ > 0) {
      c.encoder.set_pipeline(faces_.pipeline);
      c.encoder.set_bind_group(0, c.bind_group(faces_, {bind(shader::params, params_), bind(shader::scene_depth, c.view(t_.depth)),
                                                        bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp))}));
      c.encoder.set_vertex_buffer(0, face_vertices_);
      c.encoder.set_index_buffer(face_indices_, rhi::IndexFormat::uint32);
      c.encoder.draw_indexed(face_index_count_);
    }
    c.encoder.end_render_pass();
  }

  gpu::VoxelRenderParams render_params(const PassContext& c) const {
    const Scene& scene = *c.scene;
    const Extent size = c.extent(t_.color);
    gpu::VoxelRenderParams p{};
    p.view = fog::pack_view_rays(scene.camera, size);
    physics::to_floats(physics::view_projection(scene.camera, double(size.width) / size.height), p.view_projection);
    const std::array<double, 3> albedo = c.param(t_.albedo);
    for (int i = 0; i < 3; ++i) p.albedo[i] = float(albedo[size_t(i)]);
    plumbing::write_sun_for_shader(scene, p.light_direction, p.light_irradiance);
    p.variant = {c.variant().shader_code, 0, 0, 0};
    return p;
  }

  const VoxelRenderTable& t_;
  plumbing::ComputeProgram program_;
  plumbing::RenderProgram faces_;  // the variant faces' quads
  rhi::BufferId params_, face_vertices_, face_indices_;
  uint32_t face_index_count_ = 0;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(VoxelRenderTable, VoxelRenderExecution);

}  // namespace volgraph
