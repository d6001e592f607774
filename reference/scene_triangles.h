// The scene's objects as world-space triangles with a material per triangle: the same
// meshes the GPU passes rasterise (passes/plumbing/meshes.h primitives, passes/plumbing/gltf.h models),
// placed by the same model matrices, with vertex normals carried by the normal matrix and
// texture coordinates kept for the material's textures.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "graph/scene/scene.h"
#include "passes/plumbing/textures.h"
#include "reference/bvh.h"
#include "reference/texture_sampling.h"

namespace volgraph::reference {

// A surface's material: factors times textures (absent textures are white).
struct SurfaceMaterial {
  Vec3 albedo{0.8, 0.8, 0.8};
  Vec3 emissive{0, 0, 0};
  int base_color_image = -1;  // index into SceneTriangles::images, −1 for none
  int emissive_image = -1;
  int transmission_image = -1;  // stored linear: red × the transmission factor
  int thickness_image = -1;     // stored linear: green × the thickness factor
  plumbing::SamplerWrap wrap;
  // How it passes light, its lengths in world metres: thickness times the object's
  // length scale (physics::length_scale), σt per channel from attenuation_color at
  // attenuation_distance times that scale (RTR4 eq. 14.23), as the GPU's object block.
  Translucency translucency;
  Vec3 sigma_t{0, 0, 0};
};

// What a triangle carries beyond its corners: per-corner world normals (not unit, as the
// vertex shader outputs them) and texture coordinates, its material, its object.
struct TriangleAttributes {
  std::array<Vec3, 3> normals;
  std::array<std::array<double, 2>, 3> uvs;
  uint32_t material = 0;
  uint32_t object = 0;  // index into Scene::objects
};

struct SceneTriangles {
  std::vector<Triangle> triangles;  // world space
  std::vector<TriangleAttributes> attributes;
  std::vector<SurfaceMaterial> materials;
  std::vector<LinearImage> images;
  std::vector<bool> casts_shadows;  // per triangle: its object's cast_shadows
};

// Throws std::runtime_error for a glTF file or texture that cannot be read.
SceneTriangles scene_triangles(const Scene& scene);

// A material's albedo and emission at texture coordinate (u, v).
Vec3 albedo_at(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v);
Vec3 emission_at(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v);
// Its transmission factor and thickness (world m) at (u, v): the factors times their textures'
// red and green channels (KHR_materials_transmission, KHR_materials_volume).
double transmission_at(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v);
double thickness_at(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v);

// Whether a surface of this material is drawn as a layer (blends or transmits); its
// coverage at (u, v), α times the base colour texture's alpha; a layer's coverage, that
// where it blends and 1 otherwise (the GPU's translucent pass); whether (u, v) is a hole
// (alpha mode mask, coverage below the cutoff).
bool is_translucent(const SurfaceMaterial& m);
double coverage_at(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v);
double layer_coverage(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v);
bool is_hole(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v);

}  // namespace volgraph::reference
