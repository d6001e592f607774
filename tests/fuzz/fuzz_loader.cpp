// libFuzzer target: arbitrary bytes as a config. Loading must end in a plan or a
// ConfigError — never a crash, hang, leak or sanitizer report. A config that loads
// is compiled under every debug switch and reported in all three formats.
#include <cstddef>
#include <cstdint>
#include <string>

#include "graph/config/config.h"
#include "graph/plan_report.h"
#include "passes/passes.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace volgraph;
  PassRegistry registry;
  register_builtin_passes(registry);
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const LoadedConfig loaded = load_config_text("fuzz/input.json", text, registry);
    for (const CompileOptions options : {CompileOptions{}, CompileOptions{false, false, true}}) {
      const Plan plan = compile_loaded(loaded, options);
      (void)plan_text(loaded.graph, plan);
      (void)plan_json(loaded.graph, plan);
      (void)plan_dot(loaded.graph, plan);
    }
  } catch (const ConfigError& e) {
    (void)e.what();
  }
  return 0;
}
