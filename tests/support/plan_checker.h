// An independent checker for compiled plans. It recomputes, from the graph alone, what
// the plan must satisfy (which passes live, dependency order, lifetimes, memory safety,
// aliasing hand-overs) and replays the plan's barriers as a synchronisation state
// machine per resource. It shares no code with the compiler beyond the contract headers
// (access_state for what each use needs, the requirements function for sizes).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "graph/graph.h"
#include "graph/plan.h"
#include "graph/pooling.h"

namespace volgraph::test {

// Violations, one readable line each naming the rule, the pass and the resource.
// Empty means the plan is correct. `requirements` must be the function the plan was
// compiled with (empty: estimate_requirements).
std::vector<std::string> check_plan(const Graph& graph, const Plan& plan, const CompileOptions& options);
std::vector<std::string> check_plan(const Graph& graph, const Plan& plan, const CompileOptions& options,
                                    const RequirementsFn& requirements);

// Violations of the pooling rules (graph/pooling.h) by `pool`, built for `plan` (whose
// lifetimes check_plan verifies): every live resource in exactly one object, unused ones
// in none; occupants of one object never alive together and of one description (kind,
// format, extent, buffer size, compared here field by field); persistent resources and
// every resource under --no-alias alone; the byte totals the objects' sums.
std::vector<std::string> check_pool(const Graph& graph, const Plan& plan, const ResourcePool& pool);

// What culling must give, computed independently (exposed for tests).
struct ExpectedCulling {
  std::vector<bool> live;                          // per pass
  std::vector<std::optional<CullReason>> reason;   // per pass; empty when live
};
ExpectedCulling expected_culling(const Graph& graph, bool cull);

// A readable dump of a plan, for failure messages.
std::string plan_text(const Graph& graph, const Plan& plan);

}  // namespace volgraph::test
