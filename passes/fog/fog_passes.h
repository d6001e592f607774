// The participating-media passes (one file per technique in passes/fog/).
#pragma once

#include "graph/pass_decl.h"

namespace volgraph {

PassDecl froxel_voxelize_pass();
PassDecl froxel_scatter_pass();
PassDecl froxel_temporal_pass();
PassDecl scatter_integrate_pass();
PassDecl froxel_apply_pass();
PassDecl pixel_temporal_pass();
PassDecl fog_apply_pass();
PassDecl raymarch_fog_pass();
PassDecl depth_fog_pass();
PassDecl height_fog_pass();
PassDecl analytic_fog_pass();
PassDecl opacity_shadow_map_pass();
PassDecl light_volume_pass();

}  // namespace volgraph
