#include "graph/compiler/steps.h"

namespace volgraph::compiler {

FlatGraph flatten(const Graph& graph) {
  FlatGraph f;
  f.graph = &graph;
  f.use_begin.reserve(graph.passes.size() + 1);
  f.use_begin.push_back(0);
  for (const GraphPass& p : graph.passes) {
    f.uses.insert(f.uses.end(), p.uses.begin(), p.uses.end());
    f.use_begin.push_back(uint32_t(f.uses.size()));
  }
  f.version_begin.reserve(graph.resources.size() + 1);
  f.version_begin.push_back(0);
  for (const GraphResource& r : graph.resources) {
    f.version_writer.insert(f.version_writer.end(), r.version_writers.begin(), r.version_writers.end());
    f.version_begin.push_back(uint32_t(f.version_writer.size()));
  }
  return f;
}

}  // namespace volgraph::compiler
