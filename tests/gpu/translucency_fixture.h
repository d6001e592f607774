// The translucency pass's GPU tests' fixture: each backend × a variant of the pass (its
// name the parameter's second part), the built-in passes registered, a config rendered on
// the backend and its first output read; the case names "<backend>_<variant>". Shared by
// translucency_test.cpp, translucency_dispersion_test.cpp, translucency_dual_source_test.cpp
// and translucency_rough_test.cpp (its members are the fixture's, so the files a unity build
// batches together share no namespace-scope names).
#pragma once

#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/scene/scene.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {

class TranslucencyVariantFixture : public OnEachBackend<std::tuple<Backend, std::string>> {
 public:
  static std::string case_name(const ::testing::TestParamInfo<std::tuple<Backend, std::string>>& info) {
    return std::string(backend_name(std::get<0>(info.param))) + "_" + std::get<1>(info.param);
  }

 protected:
  Backend backend() const override { return std::get<0>(GetParam()); }
  const std::string& variant() const { return std::get<1>(GetParam()); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  // `path` names the config (its includes resolve against its folder); scene_ keeps its scene.
  Texels render(const std::string& text, const std::string& path = "translucency.json") {
    const LoadedConfig loaded = load_config_text(path, text, registry_);
    scene_ = loaded.config.scene;
    Executor executor(device(), loaded.graph, &scene_, {});
    executor.run_frame();
    return executor.read_output(0);
  }

  PassRegistry registry_;
  Scene scene_;
};

}  // namespace volgraph::testing
