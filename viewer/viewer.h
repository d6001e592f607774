// volgraph view: a config's graph in a resizable GLFW window on Vulkan (docs/viewer.md).
#pragma once

#include <stdexcept>
#include <string>

#include "graph/config/config.h"

namespace volgraph::viewer {

struct ViewOptions {
  int frames = 0;            // --frames N: render N frames, then exit; 0: until ESC or the window closes
  std::string screenshot;    // --screenshot FILE.png: the last presented image ("" for none)
  bool validation = false;   // the Khronos validation layer, as `render --validation`
  int device = -1;           // --device N (vulkan::ContextOptions::device_index)
  CompileOptions compile;
  std::string title;         // the window's title
};

// No window can be opened here (no display): the user's setup, exit 2.
struct NoDisplay : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Opens the window and runs frames of `loaded` (compiled already, so that its errors came
// first) until ESC, the window's close or options.frames. Returns the exit code: 0, or 1
// when validation reported messages (printed on stderr). Throws NoDisplay, DeviceError,
// IoError (the screenshot).
int run(LoadedConfig& loaded, const ViewOptions& options);

}  // namespace volgraph::viewer
