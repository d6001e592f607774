// The phase function as a fog pass's variant: froxel_scatter and raymarch_fog derive their
// tables from PhaseTable, so both declare the same five variants first (hg the default),
// each carrying its code for shaders/include/in_scattering.glsl (phase_codes.h), and
// dual_hg's two lobe parameters first among their parameters.
#pragma once

#include <string>

#include "graph/pass_decl.h"
#include "shaders/include/phase_codes.h"

namespace volgraph::fog {

struct PhaseTable : PassTable {
  using PassTable::PassTable;
  VariantHandle hg = variant("hg", "Henyey–Greenstein with the medium's g", PHASE_HG);
  VariantHandle isotropic = variant("isotropic", "p = 1/4π", PHASE_ISOTROPIC);
  VariantHandle rayleigh = variant("rayleigh", "3/(16π)·(1 + cos²θ)", PHASE_RAYLEIGH);
  VariantHandle schlick = variant("schlick", "Schlick's approximation of HG, k = 1.55g − 0.55g³ (clamped)", PHASE_SCHLICK);
  VariantHandle dual_hg = variant("dual_hg", "forward HG (the medium's g) and backward HG (g_back) mixed by w_forward", PHASE_DUAL_HG);
  ParamHandle<double> g_back = number("g_back", -0.3, -0.999, 0.999, "", "dual_hg: the backward lobe's g");
  ParamHandle<double> w_forward = number("w_forward", 0.7, 0, 1, "", "dual_hg: the forward lobe's weight");
};

}  // namespace volgraph::fog
