// The checks behind the uniform blocks, against the SPIR-V of the shaders, no GPU needed.
// No hand-written C++ mirror of a GLSL block or struct is left: every one is written once
// for GLSL and C++ (GPU_STRUCT under shaders/include/, gpu_struct.h), its members asserted
// at compile time against each shader. What is checked here:
// - the blocks that hold one shared struct (`uniform SceneFrameBlock { SceneFrame frame; };`):
//   plumbing::check_wrapped_uniform_mirror, as the passes check them at setup — reflection
//   sees one member, so the size;
// - the SPIR-V struct reader against reflection;
// - structs with a member moved, and a block of another size, which must fail naming it
//   (rhi::check_uniform_block, which every check uses).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "graph/rhi/spirv_reflect.h"
#include "passes/atmosphere/bruneton_uniforms.h"
#include "passes/fog/fog_frame.h"
#include "passes/fog/temporal.h"
#include "passes/plumbing/light_list.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/scene_geometry.h"
#include "passes/plumbing/shadow_view.h"
#include "passes/uniform_mirrors.h"
#include "shaders/include/cloud_shadow_view.h"
#include "shaders/include/scene_frame.h"
#include "shaders/include/translucency_params.h"
#include "physics/atmosphere.h"
#include "physics/media_field.h"
#include "shaders/shader_library.h"

namespace volgraph {
namespace {

std::span<const uint32_t> spirv(std::string_view shader) {
  const std::span<const uint32_t> words = shader_spirv(shader);
  if (words.empty()) throw std::logic_error("no shader " + std::string(shader));
  return words;
}

uint32_t stage_of(std::string_view shader) {
  if (shader.ends_with(".comp")) return rhi::shader_stage::compute;
  if (shader.ends_with(".vert")) return rhi::shader_stage::vertex;
  return rhi::shader_stage::fragment;
}

// What the passes check against: the shader's reflected blocks, in a program.
plumbing::ComputeProgram reflected(std::string_view shader) {
  const rhi::ShaderStageCode stage{spirv(shader), stage_of(shader)};
  plumbing::ComputeProgram program;
  program.uniform_blocks = rhi::reflect_uniform_blocks({&stage, 1}, shader);
  return program;
}

// The message a check throws, or "" when it passes.
template <typename Check>
std::string error_of(Check check) {
  try {
    check();
  } catch (const std::exception& error) {
    return error.what();
  }
  return "";
}

// The block at (set, binding) in `shader` holds one Block.
template <typename Block>
std::string wrapped_error(std::string_view shader, uint32_t set, uint32_t binding, std::string_view name) {
  return error_of([&] { plumbing::check_wrapped_uniform_mirror<Block>(reflected(shader), set, binding, name); });
}

// The structs a SPIR-V module declares, as a uniform block lays them out: glslang emits a
// struct used in a block with Offset decorations (and an undecorated copy for the
// functions that take it by value); only the decorated ones are kept.
class SpirvStructs {
 public:
  explicit SpirvStructs(std::span<const uint32_t> words) {
    for (size_t i = 5; i < words.size();) {
      const uint32_t count = words[i] >> 16, op = words[i] & 0xffff;
      if (count == 0 || i + count > words.size()) throw std::runtime_error("malformed SPIR-V");
      read(op, words.subspan(i + 1, count - 1));
      i += count;
    }
  }

  // The decorated struct named `name` (GLSL's struct name) as a block: its members' names,
  // offsets and declared sizes, its size the end of its last member; none when the module
  // has no such struct in a block.
  std::optional<rhi::UniformBlockLayout> laid_out(std::string_view name) const {
    for (const auto& [id, members] : structs_) {
      if (names_.contains(id) && names_.at(id) == name && offsets_.contains(id)) return layout(id);
    }
    return std::nullopt;
  }

 private:
  static std::string literal(std::span<const uint32_t> words) {
    std::string text;
    for (const uint32_t word : words) {
      for (int byte = 0; byte < 4; ++byte) {
        const char c = char((word >> (8 * byte)) & 0xff);
        if (c == '\0') return text;
        text += c;
      }
    }
    return text;
  }

  void read(uint32_t op, std::span<const uint32_t> w) {
    switch (op) {
      case 5: names_[w[0]] = literal(w.subspan(1)); break;                                  // OpName
      case 6: member_names_[w[0]][w[1]] = literal(w.subspan(2)); break;                     // OpMemberName
      case 71: if (w[1] == 6) array_strides_[w[0]] = w[2]; break;                           // OpDecorate ArrayStride
      case 72:                                                                              // OpMemberDecorate
        if (w[2] == 35) offsets_[w[0]][w[1]] = w[3];                                        // Offset
        if (w[2] == 7) matrix_strides_[w[0]][w[1]] = w[3];                                  // MatrixStride
        break;
      case 21: case 22: scalar_bytes_[w[0]] = w[1] / 8; break;                              // OpTypeInt, OpTypeFloat
      case 23: vectors_[w[0]] = {w[1], w[2]}; break;                                        // OpTypeVector
      case 24: matrices_[w[0]] = {w[1], w[2]}; break;                                       // OpTypeMatrix
      case 28: arrays_[w[0]] = {w[1], w[2]}; break;                                         // OpTypeArray
      case 30: structs_[w[0]] = {w.begin() + 1, w.end()}; break;                            // OpTypeStruct
      case 43: constants_[w[1]] = w[2]; break;                                              // OpConstant
      default: break;
    }
  }

  // Bytes of a value of type `type`, member `member` of struct `parent` (matrices take
  // their stride from it).
  uint64_t size_of(uint32_t type, uint32_t parent, uint32_t member) const {
    if (scalar_bytes_.contains(type)) return scalar_bytes_.at(type);
    if (vectors_.contains(type)) return vectors_.at(type).count * size_of(vectors_.at(type).element, parent, member);
    if (matrices_.contains(type)) return matrices_.at(type).count * matrix_strides_.at(parent).at(member);
    if (arrays_.contains(type)) return constants_.at(arrays_.at(type).count) * array_strides_.at(type);
    if (structs_.contains(type)) return layout(type).size;
    throw std::runtime_error("a member of a type this test does not size");
  }

  rhi::UniformBlockLayout layout(uint32_t id) const {
    rhi::UniformBlockLayout block;
    block.name = names_.at(id);
    const std::vector<uint32_t>& types = structs_.at(id);
    for (uint32_t m = 0; m < types.size(); ++m) {
      const uint64_t offset = offsets_.at(id).at(m), size = size_of(types[m], id, m);
      const auto names = member_names_.find(id);
      const bool named = names != member_names_.end() && names->second.contains(m);
      block.members.push_back({named ? names->second.at(m) : "member " + std::to_string(m), offset, size});
      block.size = offset + size;
    }
    return block;
  }

  struct Composite {
    uint32_t element, count;
  };
  std::map<uint32_t, std::string> names_;
  std::map<uint32_t, std::map<uint32_t, std::string>> member_names_;
  std::map<uint32_t, std::map<uint32_t, uint64_t>> offsets_, matrix_strides_;
  std::map<uint32_t, uint64_t> array_strides_, scalar_bytes_, constants_;
  std::map<uint32_t, Composite> vectors_, matrices_, arrays_;
  std::map<uint32_t, std::vector<uint32_t>> structs_;
};

// Mirror's members against the GLSL struct `glsl` in every shader that declares it in a
// block (at least one must): the messages of those that differ, and how many matched.
template <typename Mirror>
std::vector<std::string> nested_errors(std::string_view glsl, std::string_view name, int& matched) {
  std::vector<std::string> errors;
  matched = 0;
  for (const std::string_view shader : shader_spirv_names()) {  // every shader in shaders/
    const std::optional<rhi::UniformBlockLayout> layout = SpirvStructs(spirv(shader)).laid_out(glsl);
    if (!layout) continue;
    static constexpr auto offsets = Mirror::offsets();
    const std::string error = error_of([&] { rhi::check_uniform_block(*layout, sizeof(Mirror), offsets, name); });
    if (error.empty()) {
      ++matched;
    } else {
      errors.push_back(std::string(shader) + ": " + error);
    }
  }
  return errors;
}

#define EXPECT_NESTED_MATCH(Mirror, glsl)                                     \
  do {                                                                        \
    int matched = 0;                                                          \
    EXPECT_EQ(nested_errors<Mirror>(glsl, #Mirror, matched), std::vector<std::string>{}); \
    EXPECT_GT(matched, 0) << "no shader declares " << glsl << " in a block";  \
  } while (false)

// ---- Blocks holding one shared struct ---------------------------------------------------

// The scene pass's frame, and the translucency pass's surfaces that bind the same buffer.
TEST(UniformMirrors, SceneFrameBlocksMatch) {
  for (const char* shader : {"scene.vert", "scene.frag", "scene_shadowed.frag", "scene_media_shadowed.frag",
                             "scene_translucent_shadowed.frag", "scene_media_translucent_shadowed.frag", "scene_cloud_shadowed.frag",
                             "scene_shadowed_cloud_shadowed.frag", "scene_media_shadowed_cloud_shadowed.frag",
                             "scene_translucent_shadowed_cloud_shadowed.frag", "scene_media_translucent_shadowed_cloud_shadowed.frag",
                             "translucency_refract.frag"}) {
    EXPECT_EQ(wrapped_error<gpu::SceneFrame>(shader, 0, 0, "gpu::SceneFrame"), "") << shader;
  }
}

TEST(UniformMirrors, TranslucencyBlocksMatch) {
  for (const char* shader : {"translucency_refract.frag", "translucency_transmittance.frag", "translucency_radiance.frag",
                             "translucency_accumulate.frag"}) {
    EXPECT_EQ(wrapped_error<gpu::TranslucencyParams>(shader, 0, 1, "gpu::TranslucencyParams"), "") << shader;
  }
}

TEST(UniformMirrors, FogFrameBlocksMatch) {
  struct At {
    const char* shader;
    uint32_t binding;
  };
  for (const At at : std::initializer_list<At>{
           {"froxel_voxelize.comp", 0}, {"froxel_scatter.comp", 0}, {"froxel_scatter_shadowed.comp", 0},
           {"froxel_scatter_media_shadowed.comp", 0}, {"froxel_scatter_translucent_shadowed.comp", 0},
           {"froxel_scatter_media_translucent_shadowed.comp", 0}, {"froxel_scatter_cloud_shadowed.comp", 0},
           {"froxel_scatter_shadowed_cloud_shadowed.comp", 0}, {"froxel_scatter_media_shadowed_cloud_shadowed.comp", 0},
           {"froxel_scatter_translucent_shadowed_cloud_shadowed.comp", 0}, {"froxel_scatter_media_translucent_shadowed_cloud_shadowed.comp", 0}, {"scatter_integrate.comp", 0}, {"froxel_temporal.comp", 0},
           {"pixel_temporal.comp", 0}, {"cloud_temporal.comp", 0}, {"opacity_shadow_map.comp", 0}, {"depth_fog.comp", 0}, {"height_fog.comp", 0},
           {"analytic_fog.comp", 0}, {"raymarch_fog.comp", 0}, {"raymarch_fog_shadowed.comp", 0},
           {"raymarch_fog_translucent_shadowed.comp", 0}, {"raymarch_fog_cloud_shadowed.comp", 0},
           {"raymarch_fog_shadowed_cloud_shadowed.comp", 0}, {"raymarch_fog_translucent_shadowed_cloud_shadowed.comp", 0},
           {"froxel_apply_transmittance.frag", 0}, {"froxel_apply_scattering.frag", 0}, {"light_volume_ends.frag", 0},
           {"light_volume_faces.frag", 4}, {"light_volume_resolve.frag", 3}}) {
    EXPECT_EQ(wrapped_error<gpu::FogFrame>(at.shader, 0, at.binding, "gpu::FogFrame"), "") << at.shader;
  }
}

TEST(UniformMirrors, AtmosphereBlocksMatch) {
  for (const char* shader : {"atmosphere_transmittance_lut.comp", "atmosphere_multiscattering_lut.comp", "atmosphere_skyview_lut.comp",
                             "atmosphere_sky.frag", "atmosphere_sky_raymarch.frag", "atmosphere_aerial_perspective.comp"}) {
    EXPECT_EQ(wrapped_error<physics::GpuAtmosphere>(shader, 0, 0, "GpuAtmosphere"), "") << shader;
  }
  // Bruneton 2017's tables and their readers.
  for (const char* shader : {"atmosphere_bruneton_direct_irradiance.comp", "atmosphere_bruneton_single_scattering.comp",
                             "atmosphere_bruneton_scattering_density.comp", "atmosphere_bruneton_indirect_irradiance.comp",
                             "atmosphere_bruneton_multiple_scattering.comp", "atmosphere_aerial_perspective_bruneton.comp",
                             "atmosphere_sky_bruneton.frag"}) {
    EXPECT_EQ(wrapped_error<physics::GpuAtmosphere>(shader, 0, 0, "GpuAtmosphere"), "") << shader;
  }
}

TEST(UniformMirrors, ShadowViewBlocksMatch) {
  struct At {
    const char* shader;
    uint32_t set, binding;
  };
  for (const At at : std::initializer_list<At>{
           {"shadow.vert", 0, 0}, {"scene_shadowed.frag", 2, 2}, {"scene_media_shadowed.frag", 2, 2},
           {"froxel_scatter_shadowed.comp", 1, 2}, {"froxel_scatter_media_shadowed.comp", 1, 2},
           {"froxel_scatter_translucent_shadowed.comp", 1, 2}, {"froxel_scatter_media_translucent_shadowed.comp", 1, 2},
           {"froxel_scatter_shadowed_cloud_shadowed.comp", 1, 2}, {"froxel_scatter_media_translucent_shadowed_cloud_shadowed.comp", 1, 2},
           {"raymarch_fog_shadowed.comp", 1, 2}, {"opacity_shadow_map.comp", 0, 1}, {"light_volume_unproject.frag", 0, 0},
           {"light_volume_cells.frag", 0, 2}, {"light_volume_ends.frag", 0, 3}, {"translucent_shadow.vert", 0, 0},
           {"translucent_shadow.frag", 0, 0}, {"translucent_shadow_depth.frag", 0, 0}, {"scene_translucent_shadowed.frag", 2, 2},
           {"scene_media_translucent_shadowed.frag", 2, 2}, {"scene_shadowed_cloud_shadowed.frag", 2, 2},
           {"scene_media_shadowed_cloud_shadowed.frag", 2, 2}, {"scene_translucent_shadowed_cloud_shadowed.frag", 2, 2},
           {"scene_media_translucent_shadowed_cloud_shadowed.frag", 2, 2}}) {
    EXPECT_EQ(wrapped_error<plumbing::ShadowViewBlock>(at.shader, at.set, at.binding, "ShadowViewBlock"), "") << at.shader;
  }
}

// cloud_shadow_map's view as the scene's cloud-shadowed shaders (set 2, binding 9) and
// froxel_scatter's (set 1) hold it.
TEST(UniformMirrors, CloudShadowViewBlocksMatch) {
  for (const char* shader : {"froxel_scatter_cloud_shadowed.comp", "froxel_scatter_shadowed_cloud_shadowed.comp",
                             "froxel_scatter_media_shadowed_cloud_shadowed.comp", "froxel_scatter_translucent_shadowed_cloud_shadowed.comp",
                             "froxel_scatter_media_translucent_shadowed_cloud_shadowed.comp", "raymarch_fog_cloud_shadowed.comp",
                             "raymarch_fog_shadowed_cloud_shadowed.comp", "raymarch_fog_translucent_shadowed_cloud_shadowed.comp"}) {
    EXPECT_EQ(wrapped_error<gpu::CloudShadowView>(shader, 1, 9, "gpu::CloudShadowView"), "") << shader;
  }
  for (const char* shader : {"scene_cloud_shadowed.frag", "scene_shadowed_cloud_shadowed.frag", "scene_media_shadowed_cloud_shadowed.frag",
                             "scene_translucent_shadowed_cloud_shadowed.frag", "scene_media_translucent_shadowed_cloud_shadowed.frag"}) {
    EXPECT_EQ(wrapped_error<gpu::CloudShadowView>(shader, 2, 9, "gpu::CloudShadowView"), "") << shader;
  }
  // cloud_march's transmittance_map variant: the map's placement (sun_optical_depth_view).
  for (const char* shader : {"cloud_march_transmittance_map.comp", "cloud_march_weather_transmittance_map.comp"}) {
    EXPECT_EQ(wrapped_error<gpu::CloudShadowView>(shader, 0, 12, "gpu::CloudShadowView"), "") << shader;
  }
}

// The reader agrees with reflection where both see a struct: FogFrame is Frame's only
// member, SceneFrame SceneFrameBlock's; and LightList is as the scene frame holds it.
TEST(UniformMirrors, NestedLayoutsAgreeWithReflection) {
  const rhi::UniformBlockLayout frame = plumbing::uniform_block_at(reflected("froxel_voxelize.comp").uniform_blocks, 0, 0);
  EXPECT_EQ(SpirvStructs(spirv("froxel_voxelize.comp")).laid_out("FogFrame")->size, frame.members.at(0).size);
  const rhi::UniformBlockLayout scene = plumbing::uniform_block_at(reflected("scene.frag").uniform_blocks, 0, 0);
  const SpirvStructs scene_structs(spirv("scene.frag"));
  EXPECT_EQ(scene_structs.laid_out("SceneFrame")->size, scene.members.at(0).size);
  EXPECT_EQ(scene_structs.laid_out("LightList")->size, scene_structs.laid_out("SceneFrame")->members.at(2).size);
  EXPECT_FALSE(SpirvStructs(spirv("composite.comp")).laid_out("FogFrame"));
}

// ---- Deliberate mismatches --------------------------------------------------------------

// gpu::SceneFrame with its ambient irradiance moved after the lights.
struct MovedAmbientSceneFrame {
  float view_projection[16];
  gpu::LightList light_list;
  float ambient_irradiance[4];
  gpu::MediaField media;
  static constexpr std::array<uint64_t, 4> offsets() {
    return {offsetof(MovedAmbientSceneFrame, view_projection), offsetof(MovedAmbientSceneFrame, ambient_irradiance),
            offsetof(MovedAmbientSceneFrame, light_list), offsetof(MovedAmbientSceneFrame, media)};
  }
};
static_assert(sizeof(MovedAmbientSceneFrame) == sizeof(gpu::SceneFrame));

// GpuMediumVolume with its fade and noise swapped.
struct SwappedMediumVolume {
  float world_to_local[16];
  float size_shape[4];
  float noise[4];
  float fade[4];
  gpu::MediumCoefficients medium;
  static constexpr std::array<uint64_t, 5> offsets() {
    return {offsetof(SwappedMediumVolume, world_to_local), offsetof(SwappedMediumVolume, size_shape),
            offsetof(SwappedMediumVolume, fade), offsetof(SwappedMediumVolume, noise), offsetof(SwappedMediumVolume, medium)};
  }
};

TEST(UniformMirrors, MovedMemberFailsNamingIt) {
  // Against the SceneFrame struct as scene.frag lays it out (its block holds one SceneFrame).
  int matched = 0;
  const std::vector<std::string> scene_errors = nested_errors<MovedAmbientSceneFrame>("SceneFrame", "MovedAmbientSceneFrame", matched);
  EXPECT_EQ(matched, 0);
  const std::string scene = "scene.frag: host struct MovedAmbientSceneFrame does not match uniform block SceneFrame (set 0, binding 0): "
                            "member 1 (ambient_irradiance, 16 bytes) is at offset 64 in the block, 848 in the host struct";
  EXPECT_NE(std::find(scene_errors.begin(), scene_errors.end(), scene), scene_errors.end()) << scene_errors.at(0);
  const std::vector<std::string> errors = nested_errors<SwappedMediumVolume>("MediumVolume", "SwappedMediumVolume", matched);
  EXPECT_EQ(matched, 0);
  ASSERT_FALSE(errors.empty());
  // One error per shader that declares the struct (the scene pass's too: its frame holds the fogs' MediaField).
  const std::string voxelize = "froxel_voxelize.comp: host struct SwappedMediumVolume does not match uniform block MediumVolume "
                               "(set 0, binding 0): member 2 (fade, 16 bytes) is at offset 80 in the block, 96 in the host struct";
  EXPECT_NE(std::find(errors.begin(), errors.end(), voxelize), errors.end()) << errors[0];
}

// A wrapped block is checked by size: a frame block one vec4 short fails.
TEST(UniformMirrors, WrappedBlockOfAnotherSizeFails) {
  struct ShortFrame {
    gpu::ViewRays view;
    gpu::FroxelGrid grid;
    float jitter[4];
    gpu::LightList light_list;
    gpu::MediaField media;
  };
  EXPECT_EQ(wrapped_error<ShortFrame>("froxel_voxelize.comp", 0, 0, "ShortFrame"),
            "host struct ShortFrame does not match uniform block Frame (set 0, binding 0): the block is " +
                std::to_string(sizeof(gpu::FogFrame)) + " bytes, the host struct " + std::to_string(sizeof(ShortFrame)) +
                " (the sizes must be equal)");
}

}  // namespace
}  // namespace volgraph
