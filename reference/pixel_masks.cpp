// Pixel masks from the reference's exact visibility: see pixel_masks.h.
#include "reference/pixel_masks.h"

#include <algorithm>

#include "physics/camera.h"
#include "reference/renderer.h"

namespace volgraph::reference {
namespace {

bool sees_surface(const Renderer& renderer, uint32_t width, uint32_t height, uint32_t i, uint32_t j) {
  return renderer.surface_hit(physics::pixel_ray(renderer.scene().camera, width, height, i, j)).has_value();
}

// Whether any pixel of the 3×3 neighbourhood of (i, j), clipped to the frame, sees a surface.
bool near_surface(const std::vector<bool>& surface, uint32_t width, uint32_t height, uint32_t i, uint32_t j) {
  for (uint32_t y = j == 0 ? 0 : j - 1; y <= std::min(j + 1, height - 1); ++y) {
    for (uint32_t x = i == 0 ? 0 : i - 1; x <= std::min(i + 1, width - 1); ++x) {
      if (surface[size_t(y) * width + x]) return true;
    }
  }
  return false;
}

// Per pixel (row-major): whether the pixel's centre sees a surface.
std::vector<bool> surface_pixels(const Scene& scene, uint32_t width, uint32_t height) {
  const Renderer renderer(scene);
  std::vector<bool> surface(size_t(width) * height);
  for (uint32_t j = 0; j < height; ++j) {
    for (uint32_t i = 0; i < width; ++i) surface[size_t(j) * width + i] = sees_surface(renderer, width, height, i, j);
  }
  return surface;
}

// Whether every pixel of the 3×3 neighbourhood of (i, j) sees a surface (the frame's edge
// pixels, whose neighbourhood is cut, never).
bool inside_surface(const std::vector<bool>& surface, uint32_t width, uint32_t height, uint32_t i, uint32_t j) {
  if (i == 0 || j == 0 || i + 1 >= width || j + 1 >= height) return false;
  for (uint32_t y = j - 1; y <= j + 1; ++y) {
    for (uint32_t x = i - 1; x <= i + 1; ++x) {
      if (!surface[size_t(y) * width + x]) return false;
    }
  }
  return true;
}

}  // namespace

std::vector<bool> fog_only_pixels(const Scene& scene, uint32_t width, uint32_t height) {
  const std::vector<bool> surface = surface_pixels(scene, width, height);
  std::vector<bool> fog_only(surface.size());
  for (uint32_t j = 0; j < height; ++j) {
    for (uint32_t i = 0; i < width; ++i) fog_only[size_t(j) * width + i] = !near_surface(surface, width, height, i, j);
  }
  return fog_only;
}

std::vector<bool> surface_only_pixels(const Scene& scene, uint32_t width, uint32_t height) {
  const std::vector<bool> surface = surface_pixels(scene, width, height);
  std::vector<bool> inside(surface.size());
  for (uint32_t j = 0; j < height; ++j) {
    for (uint32_t i = 0; i < width; ++i) inside[size_t(j) * width + i] = inside_surface(surface, width, height, i, j);
  }
  return inside;
}

}  // namespace volgraph::reference
