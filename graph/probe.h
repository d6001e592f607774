// A pass's slot as the pass leaves it, kept to the end of the frame: the resource and
// version are added to the graph's outputs, so no aliasing reuses the memory first and a
// read-back after the frame sees what the pass wrote. What `render --dump PASS.SLOT=FILE`
// writes and `view`'s resource view shows.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "graph/diagnostics.h"
#include "graph/graph.h"

namespace volgraph {

// Parses "PASS.SLOT" (the part before any '='): the version the pass or its steps
// ("pass/step") leave in that slot. Throws ConfigError at `where`: no such pass, no bound
// slot, or the slot modified later by another pass (its message names the pass to probe
// instead). The graph is not changed.
ResourceVersion find_probe(const Graph& graph, const std::string& pass_dot_slot, const Where& where);

// find_probe's version kept as a graph output (once); returns its resource.
uint32_t probe_slot(Graph& graph, const std::string& pass_dot_slot, const Where& where);

// Every "PASS.SLOT" of the graph whose resource is a texture and that probe_slot accepts:
// each pass's written (out, inout) texture slots, in pass order.
std::vector<std::string> probe_names(const Graph& graph);

}  // namespace volgraph
