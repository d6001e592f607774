// Resources a render graph passes between its nodes: kinds, formats, sizes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "graph/param_handle.h"
#include "graph/rhi/types.h"

namespace volgraph {

// How a slot's size is decided: fixed, a fraction of the frame's output size,
// or a square whose side is an integer parameter of the pass (shadow map resolution).
// Parameters are named by their handles (graph/param_handle.h), so a size names only
// parameters its pass's table declares, of the right type: a misspelt one does not compile.
struct SizeSpec {
  enum class Mode : uint8_t { absolute, relative, square_param };
  using ParamIndex = std::optional<uint16_t>;  // an index into the pass's params (PassDecl::params)
  Mode mode = Mode::relative;
  Extent absolute{};             // absolute: all three; relative/square_param: depth only
  uint32_t fixed_height = 0;     // square_param: a height of its own when not 0 (row_of: 1)
  ParamIndex mip_param;          // textures: a mip chain of this parameter's levels (clamped to the extent's full chain), when set
  float scale_x = 1.0f;          // relative
  float scale_y = 1.0f;          // relative
  ParamIndex param;              // square_param: the side; relative: the depth, when set
  ParamIndex divisor_param;      // relative: x and y are also divided by this parameter, when set
  ParamIndex depth_param;        // square_param: the depth (layers), when set
  ParamIndex height_param;       // square_param: the height, when set (a rectangle `param` wide)
  // divisor_param a choice parameter: each choice's name and divisor (full resolution 1, half 2)
  std::vector<std::pair<std::string, int64_t>> divisor_choices;
  uint64_t buffer_bytes = 0;     // buffers: absolute size in bytes

  static SizeSpec fixed(uint32_t w, uint32_t h = 1, uint32_t d = 1);
  static SizeSpec of_output(float sx = 1.0f, float sy = 1.0f, uint32_t depth = 1);
  // The output divided by integer parameter `divisor` in x and y, as many slices as
  // integer parameter `slices` (froxel grids: pixels per froxel, slices).
  static SizeSpec of_output_divided(ParamHandle<int64_t> divisor, ParamHandle<int64_t> slices);
  // The output divided in x and y by `divisor_of` the value of choice parameter `choice`
  // (full resolution 1, half 2): each choice's divisor taken from the handle's own choices.
  template <typename Enum, typename DivisorOf>
    requires std::is_invocable_r_v<int64_t, DivisorOf, Enum>
  static SizeSpec of_output_divided_by_choice(const ChoiceHandle<Enum>& choice, DivisorOf divisor_of) {
    SizeSpec s = of_output(1.0f, 1.0f, 1);
    s.divisor_param = choice.text.index;
    for (const auto& [value, name] : choice.choices) s.divisor_choices.emplace_back(name, int64_t{divisor_of(value)});
    return s;
  }
  static SizeSpec square_of(ParamHandle<int64_t> side);
  // A volume: square slices of side `side`, `depth` of them (light-space layers).
  static SizeSpec square_layers_of(ParamHandle<int64_t> side, ParamHandle<int64_t> depth);
  // One row `width` wide (1D tables: a phase function over angle).
  static SizeSpec row_of(ParamHandle<int64_t> width);
  // A rectangle: `width` wide, `height` high (lookup tables: 256 × 64).
  static SizeSpec rect_of(ParamHandle<int64_t> width, ParamHandle<int64_t> height);
  // A volume: `width` × `height` slices, `depth` of them (Bruneton's 4D tables packed in 3D).
  static SizeSpec volume_of(ParamHandle<int64_t> width, ParamHandle<int64_t> height, ParamHandle<int64_t> depth);
  static SizeSpec bytes(uint64_t n);
  // This size with a mip chain of `levels` levels (level i max(1, extent >> i); no more
  // than the extent's full chain): a texture a pass filters down (generate_mips).
  SizeSpec with_mips(ParamHandle<int64_t> levels) const;
  // The parameters the size is made of (for checks: each must be one its pass declares).
  std::vector<uint16_t> params() const;
};

// A concrete resource once sizes are resolved against the frame.
struct ResourceDesc {
  std::string name;  // "pass.slot" of the pass that creates it
  ResourceKind kind = ResourceKind::texture2d;
  Format format = Format::undefined;
  Extent extent{};
  uint64_t buffer_bytes = 0;
  bool persistent = false;  // lives across frames (history, LUT cache): never aliased
  uint32_t mip_levels = 1;  // textures: level i is max(1, extent >> i)
};

// The levels of a full mip chain of `extent` (down to 1 × 1 × 1).
uint32_t full_mip_chain(Extent extent);

// Bytes the resource's contents take, before any alignment a backend adds.
uint64_t content_bytes(const ResourceDesc& desc);

}  // namespace volgraph
