// The atmosphere's passes (a planet's sky and aerial perspective: graph/scene/scene.h
// Atmosphere): the lookup tables first, each cached until the atmosphere or its sun changes.
#pragma once

#include "graph/pass_decl.h"

namespace volgraph {

PassDecl atmosphere_transmittance_lut_pass();
PassDecl atmosphere_multiscattering_lut_pass();
PassDecl atmosphere_skyview_lut_pass();
PassDecl atmosphere_aerial_perspective_pass();
PassDecl atmosphere_bruneton_tables_pass();
PassDecl sky_pass();
PassDecl aerial_perspective_apply_pass();

}  // namespace volgraph
