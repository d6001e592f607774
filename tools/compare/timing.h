// Times of repeated runs, reported with their spread: the median, the fastest and the
// slowest of the runs after the warm-up.
#pragma once

#include <string>
#include <vector>

namespace volgraph::compare {

struct Spread {
  double median = 0, min = 0, max = 0;
  int runs = 0;
};

Spread spread_of(std::vector<double> samples);

struct PassTimes {
  std::string pass, type;
  Spread gpu_ms, cpu_ms;  // gpu_ms from time stamps (0 when the device has none); cpu_ms recording
};

// A setting's frame times over `runs` frames after `warmup` frames.
struct TimingSummary {
  int runs = 0, warmup = 0;
  Spread frame_wall_ms;  // submit to completion, GPU time stamps off
  std::vector<PassTimes> passes;  // from frames with time stamps on (when the device has them)
  bool gpu_timestamps = false;
  std::string clock;  // what the times measure on this device, e.g. "lavapipe (CPU): …"
};

}  // namespace volgraph::compare
