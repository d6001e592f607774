// A compiled plan as people and tools read it: text, JSON, Graphviz dot.
#pragma once

#include <string>

#include "graph/plan.h"

namespace volgraph {

struct PlanReportContext {
  std::string config_file;  // shown in the header; may be empty
};

std::string plan_text(const Graph& graph, const Plan& plan, const PlanReportContext& context = {});
std::string plan_json(const Graph& graph, const Plan& plan, const PlanReportContext& context = {});
std::string plan_dot(const Graph& graph, const Plan& plan, const PlanReportContext& context = {});

std::string bytes_text(uint64_t bytes);  // "12.5 MiB"

}  // namespace volgraph
