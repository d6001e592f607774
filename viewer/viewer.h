// volgraph view: a config's graph in a resizable GLFW window on Vulkan or WebGPU (docs/viewer.md).
#pragma once

#include <stdexcept>
#include <string>

#include "graph/config/config.h"
#include "viewer/control.h"

namespace volgraph::viewer {

struct ViewOptions {
  int frames = 0;            // --frames N: render N frames, then exit; 0: until ESC or the window closes
  std::string screenshot;    // --screenshot FILE.png: the last presented image ("" for none)
  bool overlay = true;       // the Dear ImGui overlay (F1 toggles; --no-overlay: off and never drawn)
  bool validation = false;   // the Khronos validation layer, as `render --validation` (Vulkan)
  std::string backend = "vulkan";
  std::string shaders;       // --shaders DIR: the shader sources watched for hot reload ("": the build's shaders/, when present)  // --backend: vulkan or webgpu (Dawn on the window's X11 surface)
  int device = -1;           // --device N (vulkan::ContextOptions::device_index)
  CompileOptions compile;
  std::string title;         // the window's title
  std::string config;        // the config file: reloaded (R, hot reload, the script's reload)
  const PassRegistry* registry = nullptr;
  Overrides overrides;       // the command line's --set/--variant/--graph, kept under every reload
  bool scripted = false;     // --script given: its commands run between frames, then the viewer exits
  std::vector<ScriptCommand> script;  // read_script's commands (an empty script: exit after none)
};

// No window can be opened here (no display): the user's setup, exit 2.
struct NoDisplay : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Opens the window and runs frames of `loaded` (compiled already, so that its errors came
// first) until ESC, the window's close, options.frames or the script's end. Returns the
// exit code: 0, or 1 when validation or Dawn reported messages (printed on stderr) or a script's
// wait-change timed out. Throws NoDisplay, DeviceError, IoError (the screenshot).
int run(LoadedConfig loaded, const ViewOptions& options);

}  // namespace volgraph::viewer
