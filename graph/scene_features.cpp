#include "graph/scene_features.h"

#include <array>

namespace volgraph {
namespace {
constexpr std::array<std::string_view, static_cast<size_t>(SceneFeature::count)> kNames = {
    "geometry", "lights", "shadow_casting_light", "medium", "local_volumes",
    "atmosphere", "clouds", "translucent_objects",
};
}  // namespace

std::string_view feature_name(SceneFeature f) { return kNames[static_cast<size_t>(f)]; }

std::optional<SceneFeature> feature_from_name(std::string_view name) {
  for (size_t i = 0; i < kNames.size(); ++i) {
    if (kNames[i] == name) return static_cast<SceneFeature>(i);
  }
  return std::nullopt;
}

std::string features_text(SceneFeatures features, std::string_view none) {
  std::string out;
  for (size_t i = 0; i < kNames.size(); ++i) {
    if (!(features & (1u << i))) continue;
    if (!out.empty()) out += ", ";
    out += kNames[i];
  }
  return out.empty() ? std::string(none) : out;
}

std::string features_or_text(SceneFeatures features) {
  std::string out;
  for (size_t i = 0; i < kNames.size(); ++i) {
    if (!(features & (1u << i))) continue;
    if (!out.empty()) out += " or ";
    out += kNames[i];
  }
  return out;
}

}  // namespace volgraph
