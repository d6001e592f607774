// Resources a render graph passes between its nodes: kinds, formats, sizes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "graph/rhi/types.h"

namespace volgraph {

// How a slot's size is decided: fixed, a fraction of the frame's output size,
// or a square whose side is an integer parameter of the pass (shadow map resolution).
struct SizeSpec {
  enum class Mode : uint8_t { absolute, relative, square_param };
  Mode mode = Mode::relative;
  Extent absolute{};             // absolute: all three; relative/square_param: depth only
  float scale_x = 1.0f;          // relative
  float scale_y = 1.0f;          // relative
  std::string param;             // square_param: the side; relative: the depth, when set
  std::string divisor_param;     // relative: x and y are also divided by this parameter, when set
  std::string depth_param;       // square_param: the depth (layers), when set
  std::string height_param;      // square_param: the height, when set (a rectangle `param` wide)
  // divisor_param a choice parameter: each value's divisor (full resolution 1, half 2)
  std::vector<std::pair<std::string, int64_t>> divisor_choices;
  uint64_t buffer_bytes = 0;     // buffers: absolute size in bytes

  static SizeSpec fixed(uint32_t w, uint32_t h = 1, uint32_t d = 1);
  static SizeSpec of_output(float sx = 1.0f, float sy = 1.0f, uint32_t depth = 1);
  // The output divided by integer parameter `divisor` in x and y, as many slices as
  // integer parameter `slices` (froxel grids: pixels per froxel, slices).
  static SizeSpec of_output_divided(std::string divisor, std::string slices);
  // The output divided in x and y by the divisor `choices` gives choice parameter `param`'s value.
  static SizeSpec of_output_divided_by_choice(std::string param, std::vector<std::pair<std::string, int64_t>> choices);
  static SizeSpec square_of(std::string param_name);
  // A volume: square slices of side `side_param`, `depth_param` of them (light-space layers).
  static SizeSpec square_layers_of(std::string side_param, std::string depth_param);
  // A rectangle: `width_param` wide, `height_param` high (lookup tables: 256 × 64).
  static SizeSpec rect_of(std::string width_param, std::string height_param);
  static SizeSpec bytes(uint64_t n);
};

// A concrete resource once sizes are resolved against the frame.
struct ResourceDesc {
  std::string name;  // "pass.slot" of the pass that creates it
  ResourceKind kind = ResourceKind::texture2d;
  Format format = Format::undefined;
  Extent extent{};
  uint64_t buffer_bytes = 0;
  bool persistent = false;  // lives across frames (history, LUT cache): never aliased
};

// Bytes the resource's contents take, before any alignment a backend adds.
uint64_t content_bytes(const ResourceDesc& desc);

}  // namespace volgraph
