// The CPU reference that `ab` and `sweep` measure against (tools/compare/render_setting.h)
// takes the config's cloud passes as `volgraph reference` does: the cloud_noise sizes and
// cloud_march parameters of its graph, not each pass's defaults.
#include <gtest/gtest.h>

#include <string>

#include "graph/config/config.h"
#include "passes/passes.h"
#include "reference/clouds.h"
#include "reference/image_render.h"
#include "reference/renderer.h"
#include "tools/compare/render_setting.h"

namespace volgraph::compare {
namespace {

// A 6 × 4 view up into a cumulus layer, noise at 16³/16³/16² (the defaults are 128³/32³/128²).
const char* const kCloudConfig = R"({ "output": { "size": [6, 4] },
  "scene": { "camera": { "position": [0, 2, 0], "target": [0, 2.58, -1], "fov_y_deg": 60, "far": 20000 },
    "background": { "radiance": [0.12, 0.2, 0.42] },
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "objects": [ { "name": "box", "shape": "box", "material": "grey", "size": [1, 1, 1], "transform": { "translate": [0, 0, 6000] } } ],
    "lights": [ { "name": "sun", "type": "directional", "direction": [-0.3, -0.5, 0.81], "irradiance": [3, 3, 3] } ],
    "clouds": { "coverage": 0.6, "extinction": 0.06 } },
  "graph": { "passes": [
      { "name": "lit", "type": "scene" },
      { "name": "noise", "type": "cloud_noise", "params": { "shape_size": 16, "detail_size": 16, "curl_size": 16 } },
      { "name": "march", "type": "cloud_march", "params": { "ambient": [0.2, 0.2, 0.3] },
        "inputs": { "depth": "lit.depth", "shape": "noise.shape", "detail": "noise.detail", "curl": "noise.curl" } },
      { "name": "apply", "type": "fog_apply", "inputs": { "color": "lit.color", "fog_scattering": "march.clouds", "fog_transmittance": "march.transmittance" } } ],
    "outputs": ["apply.color"] } })";

std::vector<double> reference_rgb(const LoadedConfig& loaded, const reference::CloudReferenceSettings& clouds) {
  reference::IntegrationSettings integration;
  integration.relative_tolerance = ReferenceSettings{}.tolerance;
  integration.clouds = clouds;
  const reference::Renderer renderer(loaded.config.scene, integration);
  return reference::render_image(renderer, {.width = 6, .height = 4}).rgb;
}

TEST(RenderReference, TakesTheConfigsCloudPasses) {
  PassRegistry registry;
  register_builtin_passes(registry);
  const LoadedConfig loaded = load_config_text("clouds.json", kCloudConfig, registry);
  const RgbImage image = render_reference(loaded, {});
  const std::vector<double> with_graph = reference_rgb(loaded, reference::cloud_reference_settings(loaded.graph, loaded.params));
  const std::vector<double> with_defaults = reference_rgb(loaded, {});
  ASSERT_EQ(image.rgb.size(), with_graph.size());
  ASSERT_NE(with_graph, with_defaults) << "the case cannot tell the graph's cloud settings from the defaults";
  for (size_t i = 0; i < image.rgb.size(); ++i) EXPECT_EQ(image.rgb[i], float(with_graph[i])) << "value " << i;
}

}  // namespace
}  // namespace volgraph::compare
