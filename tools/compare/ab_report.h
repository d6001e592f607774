// What `volgraph ab` found, and its files: report.json (every figure, the exact command
// lines, each plan's memory, versions, device) and a self-contained report.html (the
// images side by side with a slider and zoom, the error heatmaps with their colour bar,
// the metrics table, the per-pass timings, the two plans' memory; nothing fetched from
// the network), the images as PNG (tone-mapped for display) and PFM (linear) and the
// heatmaps as PNG beside them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tools/compare/metrics.h"
#include "tools/compare/rgb_image.h"
#include "tools/compare/timing.h"

namespace volgraph::compare {

struct MemorySummary {
  uint64_t aliased_bytes = 0, unaliased_bytes = 0, lower_bound_bytes = 0, persistent_bytes = 0;
  uint32_t passes_run = 0, passes_culled = 0;
};

// One image of the comparison: A, B or the reference.
struct Rendered {
  std::string label;    // "A", "B", "reference"
  std::string setting;  // what it is, e.g. "scatter_integrate=hillaire, fog_media.slices=64" or "graph configs/graphs/raymarch_fog.json"
  std::string command;  // a command line that renders this image alone (render or reference)
  RgbImage image;       // linear
  std::optional<TimingSummary> timing;  // A and B
  std::optional<MemorySummary> memory;  // A and B
  double seconds = 0;   // the reference's render time (CPU)
};

// The figures of one image against another over one mask.
struct MaskedMetrics {
  std::string mask;  // "all pixels", "fog-only pixels" …
  size_t mask_pixels = 0;
  ErrorMetrics metrics;
};

struct Comparison {
  std::string test, against;  // labels of renders, e.g. "A", "reference"
  std::vector<MaskedMetrics> by_mask;  // the first is every pixel
  std::vector<float> abs_error_map, flip_map;  // per pixel (metrics.h, flip.h)
};

struct AbReport {
  std::string volgraph_version;  // git describe at build time
  std::string command_line;      // the ab command exactly as run
  std::string config;
  std::string pass;              // the pass compared, "" for whole graphs
  std::string backend, device, driver;
  bool device_is_cpu = false;    // lavapipe: the "GPU" is this CPU; the report says so
  uint32_t width = 0, height = 0;
  int frames = 1;                // the compared image is the last of this many frames (1: the first frame)
  std::vector<Rendered> renders;          // A, B, and the reference when there is one
  std::vector<Comparison> comparisons;    // A and B against the reference, or B against A
  std::vector<std::string> notes;         // what the reader must know (timing clock, exclusions)
};

// report.json: every figure of `report`, keys in the order written here. A number that
// is not finite (PSNR of identical images is +inf) is written as the string "inf",
// "-inf" or "nan", so the file stays valid JSON; every other number is a JSON number.
std::string ab_report_json(const AbReport& report);

// report.html: one self-contained page (images as data: URIs, CSS and script inline).
// The viewer follows the page's address fragment through the same handlers a click
// uses: #show=<layer> clicks that toggle button (layers: a, b, reference,
// error-<test>-vs-<against>, flip-<test>-vs-<against>), #split=<0…1> moves the slider,
// #left=<layer>&right=<layer> picks the two images of the split, #zoom=<factor>.
// Once loaded the page logs "report ready viewer=x,y,w,h metrics=x,y,w,h" (CSS pixels
// in the page) on the console and puts the same boxes in its title.
std::string ab_report_html(const AbReport& report);

// The exposure every image of the report is shown at (display_image.h): found from the
// reference when there is one, else from the first render.
double report_display_exposure(const AbReport& report);

// Whether a comparison's map (abs_error_map, flip_map) is drawn: one value a pixel of the
// report's images (the first render's size, else width × height). The JSON, the page
// and the files leave out a map that is not.
bool heatmap_fits(const std::vector<float>& map, const AbReport& report);

// A label as a file name stem ("A" → "a", "reference" → "reference"): lower case,
// characters other than letters and digits → '_'.
std::string report_file_stem(const std::string& label);

// Every file of the report directory: (file name, bytes), report.json and report.html
// first, then a.png, a.pfm, b.png, b.pfm, reference.png/.pfm and the heatmaps
// (error_<test>_vs_<against>.png, flip_<test>_vs_<against>.png).
std::vector<std::pair<std::string, std::vector<std::byte>>> ab_report_files(const AbReport& report);

}  // namespace volgraph::compare
