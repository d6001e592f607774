// A scene object's triangles for voxelize, and the CPU twin of its voxelization.
//
// The triangles are read as scene_geometry reads them (passes/plumbing/meshes.h for the
// primitive shapes, passes/plumbing/gltf.h for glTF files), carried into the world by the
// object's model matrix, then into the grid's coordinates (one voxel a unit cube) on the CPU,
// so the GPU and the twin test the same floats.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "graph/scene/scene.h"
#include "shaders/include/voxel_grid.h"

namespace volgraph::voxels {

using Triangle = std::array<Vec3, 3>;

// Object `index` of the scene as world-space triangles (throws std::runtime_error for a broken glTF file).
std::vector<Triangle> world_triangles(const Scene& scene, size_t index);

// The grid over the triangles' world bounding box, padded to a cube about its centre (the
// largest side), `resolution` voxels along each axis; no margin, so a mesh's extreme faces lie on the grid's faces.
gpu::VoxelGrid grid_around(const std::vector<Triangle>& triangles, int resolution);

// The triangles in the grid's coordinates, three xyzw corners (w 0) each: what the shader reads.
std::vector<float> grid_corners(const std::vector<Triangle>& triangles, const gpu::VoxelGrid& grid);

// The CPU twin: 1 where a triangle overlaps the voxel (shaders/include/voxel_overlap.h), x fastest, then y, then z.
std::vector<uint8_t> voxelize_on_cpu(const std::vector<float>& corners, int resolution);

}  // namespace volgraph::voxels
