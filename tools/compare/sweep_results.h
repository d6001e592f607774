// The results of a sweep, one file a point: DIR/points/<id>.json, written whole (to a
// temporary name, then renamed) as soon as the point is done, so that Ctrl-C leaves
// every finished point saved and a second run resumes without redoing them. The
// aggregate files are rewritten after every point: results.json, results.csv, the
// Pareto front (time against error, per device), report.html with the plot as SVG, and
// pareto.png beside it.
#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "tools/compare/ab_report.h"
#include "tools/compare/metrics.h"
#include "tools/compare/sweep_spec.h"
#include "tools/compare/timing.h"

namespace volgraph::compare {

struct PointResult {
  std::string id, series, label, graph;
  std::vector<std::pair<std::string, std::string>> settings;
  bool ok = false;
  std::string error;    // why the point failed (ok false)
  std::string backend, device, driver;
  bool device_is_cpu = false;
  std::string command;  // a self-contained command that renders this point alone
  TimingSummary timing;
  MemorySummary memory;
  ErrorMetrics metrics;  // against the reference over the spec's mask
  std::string metric;    // the spec's metric: which figure the front is taken on
  double seconds = 0;    // wall time to render and measure the point
  bool pareto = false;   // on the front of its device (set by mark_pareto)
};

std::string point_result_json(const PointResult& result);
// Throws ConfigError naming `file` (and the JSON pointer) when the text is not a point result.
PointResult parse_point_result(const std::string& text, const std::string& file);
// The point result in the file at `path` (parse_point_result of its text); throws
// ConfigError naming it when it cannot be read.
PointResult read_point_file(const std::filesystem::path& path);

// Marks, within each device, the points no other point of that device beats in both
// frame time (median) and the metric; failed points are never on the front.
void mark_pareto(std::vector<PointResult>& results);

// Throws ConfigError when DIR/points exists and is not a folder (a damaged sweep folder).
void check_points_folder(const std::string& dir);
// The finished points in DIR/points (every *.json there), sorted by id. A damaged point
// file or points folder is bad input: ConfigError naming the file (and JSON pointer).
std::vector<PointResult> read_results(const std::string& dir);
// Writes DIR/points/<id>.json (temporary name, then rename).
void save_point(const std::string& dir, const PointResult& result);
// The same as DIR/points/<stem>.json (merge_results' <id>@<device hash>). The file's
// pareto is always false: the front depends on the other points (results.json has it).
void save_point_as(const std::string& dir, const std::string& stem, const PointResult& result);
// Rewrites results.json, results.csv, results.md, report.html, pareto.svg and pareto.png from
// `results` (in the spec's point order where the spec is given), all staged and renamed
// together. pareto.png needs rsvg-convert (librsvg2-bin): without it no PNG is written
// (a stale one is removed) and stderr says so.
void write_aggregates(const std::string& dir, const SweepSpec& spec, std::vector<PointResult> results);
// The same, the PNG written only when `write_png` (run_sweep checks for rsvg-convert once).
void write_aggregates(const std::string& dir, const SweepSpec& spec, std::vector<PointResult> results, bool write_png);
// Whether rsvg-convert is on PATH.
bool have_svg_converter();

// The aggregates' parts, for write_aggregates and its tests. The points in the spec's
// order (every copy of a point, by device), then the points the spec does not have.
std::vector<PointResult> in_spec_order(const SweepSpec& spec, std::vector<PointResult> results);
// results.json: the spec's figures, every point with its pareto flag, a summary per device.
std::string results_json(const SweepSpec& spec, const std::vector<PointResult>& ordered);
// results.csv (RFC 4180, CRLF): id, series, label, device, ok, error, frame_ms_median,
// frame_ms_min, frame_ms_max, runs, the metrics (rmse … rel_mean, nan, inf), pareto, then
// one column a setting key over all points (its value: a JSON string's text, other JSON as
// written; empty where a point lacks the key). A failed point's figures are empty.
std::string results_csv(const std::vector<PointResult>& ordered);
// results.md: a Markdown table per device (series, setting, frame ms median and range, the
// ratio to the fastest, the spec's metric, FLIP, the front), three significant digits.
std::string results_markdown(const SweepSpec& spec, const std::vector<PointResult>& ordered);
// 8 hex digits of the FNV-1a hash of a device name: merge_results names a point done on
// several devices DIR/points/<id>@<hash>.json.
std::string device_hash(const std::string& device);

// Runs every point of the spec that DIR/points does not hold yet, saving each when done
// and the aggregates after each; a point whose runner throws is saved as failed with the
// message and the sweep goes on. Progress on `progress`: a bar with points done, elapsed
// and an estimate when `terminal`, else one plain line per point.
using PointRunner = std::function<PointResult(const SweepPoint&)>;
struct SweepSummary {
  int ran = 0, skipped = 0, failed = 0;  // ran counts the failed too; skipped: already in DIR/points
};
// `writes`, when given, is held while a point's file and the aggregates are written
// (interrupt_guard.h: a Ctrl-C then waits for them).
SweepSummary run_sweep(const SweepSpec& spec, const std::string& dir, const PointRunner& runner, std::ostream& progress,
                       bool terminal, std::mutex* writes = nullptr);

// --emit-jobs: DIR/jobs.txt (one self-contained shell command a line, `command_for(point)`)
// and DIR/manifest.json (the spec, each point's id, label and command), for GNU parallel
// (`parallel < DIR/jobs.txt`) or a Slurm array (tools/sweep_slurm.sh).
void write_jobs(const std::string& dir, const SweepSpec& spec, const std::function<std::string(const SweepPoint&)>& command_for);

// --merge: the point results of every DIR gathered into `out` (a point done in several
// keeps one copy per device; identical copies are one), aggregates rewritten. Merging
// twice gives the same files.
// The rule: `out`'s own points count as one more dir, after the others. A point id done
// on one device is out/points/<id>.json; done on several, each copy is
// out/points/<id>@<device_hash(device)>.json (the id inside stays the spec's). Two copies
// of one id and device that differ: the first dir listed wins, stderr says which. Point
// files of `out` the merge replaced (an <id>.json now split by device) are removed.
// Without a spec the aggregates take the metric of the first point.
void merge_results(const std::vector<std::string>& dirs, const std::string& out, const SweepSpec* spec);

}  // namespace volgraph::compare
