// The base of GPU test fixtures that load a config's text on each backend: the built-in
// passes registered, the config loaded, one frame run and its first `count` graph outputs
// read; `scene_` keeps the last config's scene (for references and twins). `Param` is the
// fixture's parameter (a Backend, or a tuple whose first element is one).
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/scene/scene.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {

template <typename Param = Backend>
class ConfigOnEachBackend : public OnEachBackend<Param> {
 protected:
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend<Param>::SetUp();
  }
  // `name` names the text in messages (its includes resolve against its folder).
  std::vector<Texels> render_outputs(const std::string& name, const std::string& text, size_t count) {
    const LoadedConfig loaded = load_config_text(name, text, registry_);
    scene_ = loaded.config.scene;
    Executor executor(this->device(), loaded.graph, &scene_, {});
    executor.run_frame();
    std::vector<Texels> out;
    for (size_t i = 0; i < count; ++i) out.push_back(executor.read_output(i));
    return out;
  }

  PassRegistry registry_;
  Scene scene_;
};

}  // namespace volgraph::testing
