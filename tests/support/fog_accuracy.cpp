// A fog technique against the CPU reference: see fog_accuracy.h for what is compared
// and what is excluded.
#include "tests/support/fog_accuracy.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>


namespace volgraph::accuracy {
namespace {

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

LoadedConfig load_linear_text(const std::string& name, const std::string& text, const PassRegistry& registry,
                              const Overrides& overrides) {
  return load_config_text(name, text, registry, linear_output(load_config_text(name, text, registry, overrides).config, overrides));
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
