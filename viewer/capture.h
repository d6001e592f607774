// The viewer's capture (F12, or the script's `capture PREFIX`): PREFIX.png (the graph's
// image as `render` writes it), PREFIX.exr (its linear float texels) and PREFIX.json, a
// config that includes the viewed one and amends it with what the viewer changed, so
// `volgraph render PREFIX.json --frames N` gives the same image (docs/viewer.md "Capture").
#pragma once

#include <optional>
#include <string>

#include "graph/config/config.h"
#include "graph/scene/scene.h"

namespace volgraph::viewer {

struct CaptureState {
  std::string config;          // the viewed config file
  Overrides overrides;         // the command line's and the viewer's variants and parameters
  Camera camera;               // the scene's camera as viewed (fly camera included)
  std::optional<Light> sun;    // the sun as viewed, when it has a name (a config replaces a light by name)
  Extent size;                 // the window's
  int frames = 0;              // frames since the graph was last (re)built
};

// The capture config's text, for a file at `json_path` (its include is relative to it).
std::string capture_config(const CaptureState& state, const std::string& json_path);

// The command that renders the capture again (with --graph FILE where the view had one:
// a config cannot replace an included graph whole).
std::string capture_render_command(const std::string& json_path, const CaptureState& state);

}  // namespace volgraph::viewer
