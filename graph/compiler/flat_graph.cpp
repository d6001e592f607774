#include "graph/compiler/steps.h"

namespace volgraph::compiler {

FlatGraph flatten(const Graph& graph) {
  FlatGraph f;
  f.graph = &graph;
  f.use_begin.reserve(graph.passes.size() + 1);
  f.pass_kind.reserve(graph.passes.size());
  f.pass_needs.reserve(graph.passes.size());
  f.pass_needs_any.reserve(graph.passes.size());
  f.use_begin.push_back(0);
  size_t uses = 0;
  for (const GraphPass& p : graph.passes) uses += p.uses.size();
  f.uses.reserve(uses);
  for (const GraphPass& p : graph.passes) {
    f.uses.insert(f.uses.end(), p.uses.begin(), p.uses.end());
    f.use_begin.push_back(uint32_t(f.uses.size()));
    f.pass_kind.push_back(p.kind);
    f.pass_needs.push_back(p.needs);
    f.pass_needs_any.push_back(p.needs_any);
  }
  f.version_begin.reserve(graph.resources.size() + 1);
  f.resource_kind.reserve(graph.resources.size());
  f.version_writer.reserve(graph.resources.size() + uses);  // versions: at most one per resource and per use
  f.version_begin.push_back(0);
  for (const GraphResource& r : graph.resources) {
    f.version_writer.insert(f.version_writer.end(), r.version_writers.begin(), r.version_writers.end());
    f.version_begin.push_back(uint32_t(f.version_writer.size()));
    f.resource_kind.push_back(r.desc.kind);
  }
  return f;
}

}  // namespace volgraph::compiler
