// The sweep loop: every point not yet in DIR/points rendered, saved as it finishes and
// the aggregates rewritten after it, with the progress shown as it goes.
#include <algorithm>
#include <chrono>
#include <mutex>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <ostream>
#include <set>

#include "tools/compare/sweep_results.h"

namespace volgraph::compare {
namespace {

// "1:23", "1:02:03".
std::string clock_text(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  } else {
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
  }
  return text;
}

std::string milliseconds_text(double ms) {
  char text[32];
  std::snprintf(text, sizeof text, ms >= 100 ? "%.0f" : ms >= 10 ? "%.1f" : "%.2f", ms);
  return text;
}

// The label, after its series' name when the spec has several.
std::string point_name(const SweepPoint& point, bool several_series) {
  if (point.label.empty()) return point.series.empty() ? point.id : point.series;
  return several_series && !point.series.empty() ? point.series + ": " + point.label : point.label;
}

bool has_several_series(const SweepSpec& spec) {
  return std::any_of(spec.points.begin(), spec.points.end(),
                     [&](const SweepPoint& p) { return p.series != spec.points.front().series; });
}

// "label: 12.3 ms, rel_rmse 0.0123 (4.1 s)" or "label: FAILED: message".
std::string outcome_text(const std::string& name, const PointResult& result, const std::string& metric) {
  if (!result.ok) return name + ": FAILED: " + result.error;
  char error[32], seconds[32];
  std::snprintf(error, sizeof error, "%.3g", metric_value(result.metrics, metric));
  std::snprintf(seconds, sizeof seconds, "%.1f", result.seconds);
  return name + ": " + milliseconds_text(result.timing.frame_wall_ms.median) + " ms, " + metric + " " + error + " (" +
         seconds + " s)";
}

class Progress {
 public:
  Progress(std::ostream& out, bool terminal, int total, int done)
      : out_(out), terminal_(terminal), total_(total), done_(done) {}

  // Before the first point: what is already done.
  void start(const std::string& dir) {
    if (done_ > 0) out_ << "resuming: " << done_ << " of " << total_ << " points already in " << dir << "/points\n";
    if (terminal_ && done_ < total_) draw("");
    out_.flush();
  }

  void finished(const std::string& name, const PointResult& result, const std::string& metric, double seconds_so_far,
                int ran) {
    ++done_;
    const std::string counter = "[" + std::to_string(done_) + "/" + std::to_string(total_) + "] ";
    if (!terminal_) {
      out_ << counter << outcome_text(name, result, metric) << "\n";
      out_.flush();
      return;
    }
    if (!result.ok) out_ << "\r\x1b[K" << counter << outcome_text(name, result, metric) << "\n";
    const double per_point = seconds_so_far / std::max(ran, 1);
    draw(name, seconds_so_far, per_point * (total_ - done_));
    out_.flush();
  }

  void end() {
    if (drawn_) out_ << "\n";
    out_.flush();
  }

 private:
  // "\r[#####-----] 12/40 points  1:23 elapsed, ~2:05 left  label"
  void draw(const std::string& last, double elapsed = 0, double left = -1) {
    constexpr int width = 24;
    drawn_ = true;
    const int filled = total_ > 0 ? done_ * width / total_ : width;
    out_ << "\r[" << std::string(filled, '#') << std::string(width - filled, '-') << "] " << done_ << "/" << total_
         << " points  " << clock_text(elapsed) << " elapsed";
    if (left >= 0) out_ << ", ~" << clock_text(left) << " left";
    if (!last.empty()) out_ << "  " << last;
    out_ << "\x1b[K";
  }

  std::ostream& out_;
  bool terminal_;
  int total_, done_;
  bool drawn_ = false;
};

PointResult failed_result(const std::string& message) {
  PointResult failed;
  failed.ok = false;
  failed.error = message.empty() ? "failed (no message)" : message;
  return failed;
}

// The point's identity is the spec's, whatever the runner filled in.
void stamp(PointResult& result, const SweepPoint& point, const SweepSpec& spec, double seconds) {
  result.id = point.id;
  result.series = point.series;
  result.label = point.label;
  result.graph = point.graph;
  result.settings = point.settings;
  if (result.metric.empty()) result.metric = spec.metric;
  if (result.seconds == 0) result.seconds = seconds;
  result.pareto = false;
}

}  // namespace

SweepSummary run_sweep(const SweepSpec& spec, const std::string& dir, const PointRunner& runner, std::ostream& progress,
                       bool terminal, std::mutex* writes) {
  std::vector<PointResult> results = read_results(dir);
  std::set<std::string> done;
  for (const PointResult& r : results) done.insert(r.id);
  std::vector<const SweepPoint*> to_run;
  for (const SweepPoint& point : spec.points) {
    if (!done.count(point.id)) to_run.push_back(&point);
  }
  SweepSummary summary;
  summary.skipped = int(spec.points.size() - to_run.size());
  const bool png = have_svg_converter();
  if (!png)
    std::cerr << "volgraph sweep: rsvg-convert (Debian librsvg2-bin) not found: pareto.png not written (pareto.svg has "
                 "the plot)\n";

  const bool several_series = has_several_series(spec);
  Progress shown(progress, terminal, int(spec.points.size()), summary.skipped);
  shown.start(dir);
  using Clock = std::chrono::steady_clock;
  const auto sweep_start = Clock::now();
  for (const SweepPoint* point : to_run) {
    const auto start = Clock::now();
    PointResult result;
    try {
      result = runner(*point);
    } catch (const std::exception& e) {
      result = failed_result(e.what());
    }
    const auto end = Clock::now();
    stamp(result, *point, spec, std::chrono::duration<double>(end - start).count());
    results.push_back(result);
    {
      const std::unique_lock<std::mutex> lock = writes ? std::unique_lock<std::mutex>(*writes) : std::unique_lock<std::mutex>();
      save_point(dir, result);
      write_aggregates(dir, spec, results, png);
    }
    ++summary.ran;
    summary.failed += !result.ok;
    shown.finished(point_name(*point, several_series), result, spec.metric,
                   std::chrono::duration<double>(Clock::now() - sweep_start).count(), summary.ran);
  }
  if (to_run.empty()) write_aggregates(dir, spec, results, png);  // a finished sweep's aggregates, up to date
  shown.end();
  return summary;
}

}  // namespace volgraph::compare
