// froxel_scatter's volumetric self-shadowing on both backends, through the froxel chain: a
// dense box between a light and a fog layer dims the layer under it by the box's
// transmittance — only with shadow_steps, and at the defaults by each volume's chord — and
// skipping empty froxels changes nothing. Fixture: froxel_fog.h.
#include <gtest/gtest.h>

#include "tests/gpu/froxel_fog.h"

namespace volgraph::testing {
namespace {

class FroxelScatter : public FroxelFogFixture {};

// The layer under the box (froxel_fog.h's layer_under_box): with shadow_steps the layer's
// in-scattering under the box drops by the box's transmittance e^(−1) — its exact chord,
// plus fp16: 2 % allowed — and beside it stays; with shadow_steps 0, the box changes nothing.
TEST_P(FroxelScatter, ADenseBoxShadowsTheFogUnderItOnlyWithShadowSteps) {
  expect_box_shadow(render(load(layer_under_box(false, 256))), render(load(layer_under_box(true, 256))));
  const Texels open_unshadowed = render(load(layer_under_box(false, 0)));
  const Texels unshadowed = render(load(layer_under_box(true, 0)));
  for (size_t k = 0; k < open_unshadowed.rgba.size(); ++k) ASSERT_EQ(unshadowed.rgba[k], open_unshadowed.rgba[k]) << k;
}

// At froxel_scatter's defaults the box shadows the layer too, exactly: a volume without edge
// fade or noise dims the light by e^(−σt·chord) (each volume's chord toward the light,
// light_transmittance.glsl), so under the box the in-scattering is e^(−1) of the open
// layer's (1 with the volumes ignored) and beside it 1, within 2 % (fp16).
TEST_P(FroxelScatter, ADenseBoxShadowsTheFogUnderItAtTheDefaults) {
  FogCase open = layer_under_box(false, 0), shadowed = layer_under_box(true, 0);
  open.scatter_params = shadowed.scatter_params = "{}";
  expect_box_shadow(render(load(open)), render(load(shadowed)));
}

// Skipping the light loop in froxels without scattering (the default) is exact: the image
// is bit-identical with skip_empty off, on media confined to local volumes.
TEST_P(FroxelScatter, SkippingEmptyFroxelsChangesNothing) {
  FogCase skipping = layer_under_box(true, 16);
  FogCase lighting_all = skipping;
  lighting_all.scatter_params = R"({ "shadow_steps": 16, "shadow_distance": 20, "skip_empty": false })";
  const Texels a = render(load(skipping)), b = render(load(lighting_all));
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  for (size_t k = 0; k < a.rgba.size(); ++k) ASSERT_EQ(a.rgba[k], b.rgba[k]) << k;
}

INSTANTIATE_TEST_SUITE_P(Backends, FroxelScatter, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
