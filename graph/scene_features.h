// What a scene contains that passes may need; a pass whose needs fail is culled.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace volgraph {

enum class SceneFeature : uint8_t {
  geometry,              // at least one object
  lights,                // at least one light
  shadow_casting_light,  // a directional or spot light that casts shadows
  medium,                // any participating medium (global, height fog or volume)
  local_volumes,         // media confined to local volumes
  atmosphere,
  clouds,
  translucent_objects,   // objects whose material transmits light
  count,
};

using SceneFeatures = uint32_t;  // bit (1 << feature)

constexpr SceneFeatures feature_bit(SceneFeature f) { return 1u << static_cast<uint32_t>(f); }
std::string_view feature_name(SceneFeature f);
std::optional<SceneFeature> feature_from_name(std::string_view name);
// "medium, clouds" for the bits set; `none` when there are none.
std::string features_text(SceneFeatures features, std::string_view none = "nothing");
// "medium or clouds": the alternatives of a pass's needs_any.
std::string features_or_text(SceneFeatures features);

// A pass runs when the scene has every feature of `needs` and, when `needs_any` is not
// empty, at least one of `needs_any` (fog_apply: a medium or clouds to composite).
constexpr bool needs_hold(SceneFeatures needs, SceneFeatures needs_any, SceneFeatures scene) {
  return (needs & ~scene) == 0 && (needs_any == 0 || (needs_any & scene) != 0);
}

// The parts of a scene a pass's result may depend on (its cache key, PassDecl::reads_scene).
// `atmosphere`: the planet's atmosphere and its sun light's direction and irradiance (not
// the other lights), so that its LUTs stay cached until the sky changes.
enum class ScenePart : uint8_t { camera, lights, media, geometry, background, atmosphere, clouds, volume_data };
using ScenePartMask = uint32_t;  // bit (1 << part)
constexpr ScenePartMask part_bit(ScenePart p) { return 1u << static_cast<uint32_t>(p); }

}  // namespace volgraph
