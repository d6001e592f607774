// A fog technique against the CPU reference: see fog_accuracy.h for what is compared
// and what is excluded.
#include "tests/support/fog_accuracy.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "physics/camera.h"
#include "reference/renderer.h"

namespace volgraph::accuracy {
namespace {

bool sees_surface(const reference::Renderer& renderer, uint32_t width, uint32_t height, uint32_t i, uint32_t j) {
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
  const reference::Renderer renderer(scene);
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

// The reference's RGB as the RGBA floats compare_images takes.
std::vector<float> rgba_of(const reference::ReferenceImage& image) {
  std::vector<float> out(size_t(image.width) * image.height * 4, 1.0f);
  for (size_t p = 0; p < size_t(image.width) * image.height; ++p) {
    for (size_t c = 0; c < 3; ++c) out[4 * p + c] = float(image.rgb[3 * p + c]);
  }
  return out;
}

// Only the pixels marked in `kept`, in order.
std::vector<float> kept_pixels(const std::vector<float>& rgba, const std::vector<bool>& kept) {
  std::vector<float> out;
  for (size_t p = 0; p < kept.size(); ++p) {
    if (kept[p]) out.insert(out.end(), rgba.begin() + std::ptrdiff_t(4 * p), rgba.begin() + std::ptrdiff_t(4 * p + 4));
  }
  return out;
}

}  // namespace

std::string FogComparison::describe() const {
  std::ostringstream out;
  out << difference.describe() << " over " << compared_pixels << " of " << pixels << " pixels";
  return out.str();
}

Overrides linear_output(const LoadedConfig& loaded, Overrides overrides) {
  for (const PassNode& pass : loaded.config.passes) {
    if (pass.type != "composite") continue;
    overrides.variants.push_back(pass.name + "=none");
    overrides.sets.push_back(pass.name + ".exposure=0");
  }
  return overrides;
}

LoadedConfig load_linear(const std::string& path, const PassRegistry& registry, const Overrides& overrides) {
  return load_config(path, registry, linear_output(load_config(path, registry, overrides), overrides));
}

LoadedConfig load_linear_text(const std::string& name, const std::string& text, const PassRegistry& registry,
                              const Overrides& overrides) {
  return load_config_text(name, text, registry, linear_output(load_config_text(name, text, registry, overrides), overrides));
}

reference::ReferenceImage render_reference(const LoadedConfig& loaded, unsigned threads) {
  const reference::Renderer renderer(loaded.config.scene);
  const Extent size = loaded.config.output_size;
  return reference::render_image(renderer, {.width = size.width, .height = size.height, .threads = threads});
}

Texels render_gpu(rhi::Device& device, const LoadedConfig& loaded) {
  Executor executor(device, loaded.graph, &loaded.config.scene, {});
  executor.run_frame();
  return executor.read_output(0);
}

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

FogComparison compare_fog(const Texels& gpu, const reference::ReferenceImage& ref, const std::vector<bool>& compared) {
  if (gpu.width != ref.width || gpu.height != ref.height || compared.size() != size_t(ref.width) * ref.height) {
    throw std::invalid_argument("compare_fog: the GPU image, the reference and the pixel mask differ in size");
  }
  FogComparison out;
  out.pixels = compared.size();
  out.compared_pixels = size_t(std::count(compared.begin(), compared.end(), true));
  out.difference = testing::compare_images(kept_pixels(gpu.rgba, compared), kept_pixels(rgba_of(ref), compared));
  return out;
}

}  // namespace volgraph::accuracy
