// A GPU test fixture on each backend that loads a config's text, runs one frame and reads its
// first output: what tests of one pass's output under a small hand-written graph share.
#pragma once

#include <string>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {

class ConfigOutputOnEachBackend : public OnEachBackend<Backend> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  // The config's first graph output after one frame (`name` names the text in messages).
  Texels first_output(const std::string& name, const std::string& text) {
    const LoadedConfig loaded = load_config_text(name, text, registry_);
    scene_ = loaded.config.scene;
    Executor executor(device(), loaded.graph, &scene_, {});
    executor.run_frame();
    return executor.read_output(0);
  }
  PassRegistry registry_;
  Scene scene_;
};

}  // namespace volgraph::testing
