// The figures of the comparison tools as JSON, one writer each, shared by report.json
// (ab_report_json.cpp) and a sweep's point files (sweep_results.cpp). Internal to
// tools/compare: it pulls in nlohmann/json, so only .cpp files include it.
#pragma once

#include <nlohmann/json.hpp>

#include "tools/compare/ab_report.h"
#include "tools/compare/metrics.h"
#include "tools/compare/timing.h"

namespace volgraph::compare {

using Json = nlohmann::ordered_json;

// JSON has no infinities or NaN (RFC 8259 §6): those are written as the strings "inf",
// "-inf" and "nan".
Json number_json(double value);
Json spread_json(const Spread& spread);
Json timing_json(const TimingSummary& timing);
Json memory_json(const MemorySummary& memory);
Json metrics_json(const ErrorMetrics& metrics);

}  // namespace volgraph::compare
