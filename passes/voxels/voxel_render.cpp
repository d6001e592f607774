// voxel_render: voxelize's grid drawn over the scene (RTR4 13.10), two ways that give the same
// image, and a third that draws the smooth surface the voxels approximate:
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
//   marching_cubes: the object's signed distance on the grid's (n + 1)³ points
//          (signed_distance.h) meshed by marching cubes at iso 0 (Lorensen & Cline 1987,
//          marching_cubes.h) at setup, kept per object content + resolution as faces' quads
//          are; drawn by the graphics step `surface` (shaders/voxel_surface.vert/.frag) with
//          Lambert by the interpolated gradient normal. `plan --setup` notes the counts.
// All shade Lambert by the face's normal (shaders/include/voxel_shading.h), lit by the
// scene's first directional light (else a headlight of irradiance π), albedo `albedo`, and
// keep a surface only where it is nearer than the scene's depth along the pixel's ray; elsewhere
// the scene's colour shows. Outputs `color` and `hit` (r the distance in metres along the ray
// to the face, 0 where none). Shaders: shaders/voxel_render.comp, voxel_faces.vert/.frag.
#include <array>
#include <chrono>
#include <cstdio>
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
#include "passes/voxels/marching_cubes.h"
#include "passes/voxels/signed_distance.h"
#include "passes/voxels/voxel_faces.h"
#include "passes/voxels/voxel_mesh.h"
#include "physics/camera.h"
#include "shaders/bindings/voxel_faces.frag.h"
#include "shaders/bindings/voxel_render.comp.h"
#include "shaders/bindings/voxel_surface.frag.h"
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
  VariantHandle marching_cubes = variant("marching_cubes",
                                         "the object's signed distance on the grid's points meshed by marching cubes (Lorensen & Cline 1987), smooth Lambert by the gradient normal",
                                         VOXEL_RENDER_MARCHING_CUBES);
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
  SlotHandle surface_depth = internal("surface_depth", ResourceKind::texture2d, Format::d32_float, SizeSpec::of_output(),
                                      "marching_cubes: the surface's depth buffer (the nearest triangle wins)");
  // Steps: the compute step (dda draws there; faces and marching_cubes lay the scene behind), then their meshes over it.
  StepHandle cast = step("cast", PassKind::compute,
                         {{voxels, Usage::sampled}, {grid, Usage::uniform_read}, {depth, Usage::sampled}, {scene_color, Usage::sampled},
                          {color, Usage::storage_write}, {hit, Usage::storage_write}});
  StepHandle draw_faces = step("faces", PassKind::graphics,
                               {{depth, Usage::sampled}, {color, Usage::color_attachment_load}, {hit, Usage::color_attachment_load},
                                {face_depth, Usage::depth_attachment}},
                               only_in({faces}));
  StepHandle draw_surface = step("surface", PassKind::graphics,
                                 {{depth, Usage::sampled}, {color, Usage::color_attachment_load}, {hit, Usage::color_attachment_load},
                                  {surface_depth, Usage::depth_attachment}},
                                 only_in({marching_cubes}));
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

// An object on voxelize's grid: its triangles in the grid's coordinates, the grid, and the
// key of both + the resolution (what the CPU meshes below are kept by).
struct ObjectOnGrid {
  gpu::VoxelGrid grid{};
  std::vector<float> corners;
  std::pair<uint64_t, int> key;
};

ObjectOnGrid object_on_grid(const Scene& scene, size_t object, int resolution) {
  const std::vector<voxels::Triangle> triangles = voxels::world_triangles(scene, object);
  ObjectOnGrid o;
  o.grid = voxels::grid_around(triangles, resolution);
  o.corners = voxels::grid_corners(triangles, o.grid);
  o.key = {voxel_content_hash(std::as_bytes(std::span(&o.grid, 1)), voxel_content_hash(std::as_bytes(std::span(o.corners)))), resolution};
  return o;
}

// Meshed once per object content + resolution (the voxelization on the CPU is the cost), shared
// by every faces pass and executor of the process.
std::shared_ptr<const VoxelFaceMeshes> voxel_face_meshes(const Scene& scene, size_t object, int resolution) {
  static std::mutex mutex;
  static std::map<std::pair<uint64_t, int>, std::shared_ptr<const VoxelFaceMeshes>> cache;
  const ObjectOnGrid on_grid = object_on_grid(scene, object, resolution);
  const std::lock_guard lock(mutex);
  if (const auto found = cache.find(on_grid.key); found != cache.end()) return found->second;
  auto meshes = std::make_shared<VoxelFaceMeshes>();
  const std::vector<uint8_t> solid = voxels::voxelize_on_cpu(on_grid.corners, resolution);
  meshes->grid = on_grid.grid;
  for (const uint8_t s : solid) meshes->solid += s != 0;
  meshes->culled = voxels::culled_faces(solid, resolution);
  meshes->greedy = voxels::greedy_faces(solid, resolution);
  cache.emplace(on_grid.key, meshes);
  return meshes;
}

// The marching_cubes variant's surface for one object at one resolution, and what it cost.
struct VoxelSurfaceMesh {
  gpu::VoxelGrid grid{};
  voxels::SurfaceMesh mesh;
  int64_t winding_number_lines = 0, lines = 0;  // grid lines signed by the generalized winding number, of all
  double field_seconds = 0, mesh_seconds = 0;
};

// Extracted once per object content + resolution (the signed distance is the cost), shared by
// every marching_cubes pass and executor of the process.
std::shared_ptr<const VoxelSurfaceMesh> voxel_surface_mesh(const Scene& scene, size_t object, int resolution) {
  static std::mutex mutex;
  static std::map<std::pair<uint64_t, int>, std::shared_ptr<const VoxelSurfaceMesh>> cache;
  const ObjectOnGrid on_grid = object_on_grid(scene, object, resolution);
  const std::lock_guard lock(mutex);
  if (const auto found = cache.find(on_grid.key); found != cache.end()) return found->second;
  using clock = std::chrono::steady_clock;
  auto surface = std::make_shared<VoxelSurfaceMesh>();
  surface->grid = on_grid.grid;
  const clock::time_point start = clock::now();
  const voxels::SignedDistanceField field = voxels::signed_distance_on_grid(on_grid.corners, resolution);
  const clock::time_point meshing = clock::now();
  surface->mesh = voxels::marching_cubes(field.distance, resolution);
  surface->winding_number_lines = field.fallback_lines;
  surface->lines = field.lines;
  surface->field_seconds = std::chrono::duration<double>(meshing - start).count();
  surface->mesh_seconds = std::chrono::duration<double>(clock::now() - meshing).count();
  cache.emplace(on_grid.key, surface);
  return surface;
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
    if (s.variant_is(t_.marching_cubes)) setup_surface(s);
  }

  void record(PassContext& c) override {
    if (c.step_is(t_.draw_faces)) return record_faces(c);
    if (c.step_is(t_.draw_surface)) return record_surface(c);
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
  // A pipeline drawing a mesh of position + normal vertices (6 floats) over `color` and `hit`.
  plumbing::RenderProgram create_mesh_program(PassSetup& s, const std::string& what, const char* vertex, const char* fragment) const {
    using namespace rhi;
    static_assert(voxels::kFaceVertexFloats == voxels::kSurfaceVertexFloats);
    RenderPipelineDesc pipeline;
    pipeline.label = s.name() + " " + what;
    pipeline.vertex_buffers = {{voxels::kFaceVertexFloats * 4, {{0, VertexFormat::float32x3, 0}, {1, VertexFormat::float32x3, 12}}}};
    pipeline.colors = {{s.desc(t_.color).format, BlendMode::replace}, {Format::r32_float, BlendMode::replace}};
    pipeline.depth = {Format::d32_float, true, CompareFunction::less};
    pipeline.cull = CullMode::back;  // the meshes bound closed solids: a back face is always behind a front one
    return plumbing::create_render_program(s.device, pipeline, vertex, fragment);
  }

  // The mesh's vertex and index buffers (a buffer may not be empty: one degenerate triangle stands in).
  void upload_mesh(PassSetup& s, std::vector<float> vertices, std::vector<uint32_t> indices) {
    using namespace rhi;
    mesh_index_count_ = uint32_t(indices.size());
    if (indices.empty()) vertices.assign(voxels::kFaceVertexFloats, 0.0f), indices = {0, 0, 0};
    mesh_vertices_ = s.device.create_buffer({s.name() + " mesh vertices", vertices.size() * 4, buffer_usage::vertex});
    s.device.write_buffer(mesh_vertices_, 0, std::as_bytes(std::span(vertices)));
    mesh_indices_ = s.device.create_buffer({s.name() + " mesh indices", indices.size() * 4, buffer_usage::index});
    s.device.write_buffer(mesh_indices_, 0, std::as_bytes(std::span(indices)));
  }

  void setup_faces(PassSetup& s) {
    mesh_program_ = create_mesh_program(s, "faces", "voxel_faces.vert", "voxel_faces.frag");
    const int64_t object = s.producer_param(t_.voxels, "object"), resolution = s.producer_param(t_.voxels, "resolution");
    const std::shared_ptr<const VoxelFaceMeshes> meshes = voxel_face_meshes(*s.scene, size_t(object), int(resolution));
    const bool greedy = s.param(t_.meshing) == FaceMeshing::greedy;
    const std::vector<voxels::FaceQuad>& quads = greedy ? meshes->greedy : meshes->culled;
    const glm::vec3 origin(meshes->grid.origin[0], meshes->grid.origin[1], meshes->grid.origin[2]);
    voxels::FaceTriangles triangles = voxels::face_triangles(quads, origin, meshes->grid.origin[3]);
    upload_mesh(s, std::move(triangles.vertices), std::move(triangles.indices));
    s.note("faces: object " + std::to_string(object) + " at " + std::to_string(resolution) + "³ meshed on the CPU twin's voxels at setup (" +
           std::to_string(meshes->solid) + " set; cached by the object's content and the resolution): naive " +
           std::to_string(6 * meshes->solid) + " faces, culled " + std::to_string(meshes->culled.size()) + ", greedy " +
           std::to_string(meshes->greedy.size()) + " quads; drawing " + (greedy ? "greedy" : "culled") + ": " +
           std::to_string(quads.size()) + " quads, " + std::to_string(2 * quads.size()) + " triangles");
  }

  // The wired voxelize's object and resolution: its signed distance meshed by marching cubes.
  void setup_surface(PassSetup& s) {
    mesh_program_ = create_mesh_program(s, "surface", "voxel_surface.vert", "voxel_surface.frag");
    const int64_t object = s.producer_param(t_.voxels, "object"), resolution = s.producer_param(t_.voxels, "resolution");
    const std::shared_ptr<const VoxelSurfaceMesh> surface = voxel_surface_mesh(*s.scene, size_t(object), int(resolution));
    const glm::vec3 origin(surface->grid.origin[0], surface->grid.origin[1], surface->grid.origin[2]);
    upload_mesh(s, voxels::surface_vertices(surface->mesh, origin, surface->grid.origin[3]), surface->mesh.indices);
    char seconds[96];
    std::snprintf(seconds, sizeof seconds, "signed distance %.2f s, marching cubes %.3f s", surface->field_seconds, surface->mesh_seconds);
    s.note("marching_cubes: object " + std::to_string(object) + " at " + std::to_string(resolution) + "³: signed distance on " +
           std::to_string(resolution + 1) + "³ grid points (" + std::to_string(surface->winding_number_lines) + " of " +
           std::to_string(surface->lines) + " lines signed by the winding number), meshed at setup (cached by the object's content and the resolution; " +
           seconds + "): " + std::to_string(surface->mesh.indices.size() / 3) + " triangles, " +
           std::to_string(surface->mesh.positions.size()) + " vertices");
  }

  void record_faces(PassContext& c) {
    namespace shader = shaders::voxel_faces_frag;
    record_mesh(c, c.view(t_.face_depth), {bind(shader::params, params_), bind(shader::scene_depth, c.view(t_.depth)),
                                           bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp))});
  }

  void record_surface(PassContext& c) {
    namespace shader = shaders::voxel_surface_frag;
    record_mesh(c, c.view(t_.surface_depth), {bind(shader::params, params_), bind(shader::scene_depth, c.view(t_.depth)),
                                              bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp))});
  }

  // The mesh over the compute step's scene colour, nearest first by the pass's depth buffer.
  void record_mesh(PassContext& c, rhi::TextureViewId depth_buffer, const std::vector<rhi::BoundResource>& bindings) {
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.color), rhi::LoadOp::load}, {c.view(t_.hit), rhi::LoadOp::load}};
    pass.depth = {depth_buffer, rhi::LoadOp::clear, 1.0f, false};
    c.encoder.begin_render_pass(pass);
    if (mesh_index_count_ > 0) {
      c.encoder.set_pipeline(mesh_program_.pipeline);
      c.encoder.set_bind_group(0, c.bind_group(mesh_program_, bindings));
      c.encoder.set_vertex_buffer(0, mesh_vertices_);
      c.encoder.set_index_buffer(mesh_indices_, rhi::IndexFormat::uint32);
      c.encoder.draw_indexed(mesh_index_count_);
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
  plumbing::RenderProgram mesh_program_;  // faces' quads or marching_cubes' surface
  rhi::BufferId params_, mesh_vertices_, mesh_indices_;
  uint32_t mesh_index_count_ = 0;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(VoxelRenderTable, VoxelRenderExecution);

}  // namespace volgraph
