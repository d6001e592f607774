// VOLGRAPH_SIMULATE_FAULT=out_of_memory|device_lost makes the driver fail (to test how
// every command reports failures on a driver that never fails).
#pragma once

#include <cstdlib>
#include <optional>
#include <string_view>

#include "graph/rhi/device_error.h"

namespace volgraph {

// The fault the environment asks for: none when unset, nullopt for another value.
inline std::optional<SimulatedFault> simulated_fault() {
  const char* value = std::getenv("VOLGRAPH_SIMULATE_FAULT");
  if (!value || !*value) return SimulatedFault::none;
  if (std::string_view(value) == "out_of_memory") return SimulatedFault::out_of_memory;
  if (std::string_view(value) == "device_lost") return SimulatedFault::device_lost;
  return std::nullopt;
}

}  // namespace volgraph
