// The plot and report.html of a sweep, and the aggregate files written together.
#include "tools/compare/sweep_report.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "tools/output_files.h"

extern char** environ;

namespace volgraph::compare {
namespace {

std::string escape_xml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string figure(double value, int digits = 4) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

std::string coordinate(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", value);
  return text;
}

bool is_lavapipe(const std::string& device) { return device.find("llvmpipe") != std::string::npos; }

std::string device_title(const std::string& device) {
  const std::string name = device.empty() ? "(device unknown)" : device;
  return is_lavapipe(device) ? name + " — lavapipe (CPU)" : name;
}

std::string point_name(const PointResult& p) {
  if (!p.label.empty()) return p.series.empty() ? p.label : p.series + ": " + p.label;
  return p.series.empty() ? p.id : p.series;
}

double error_of(const PointResult& p, const std::string& metric) { return metric_value(p.metrics, metric); }

bool plottable(const PointResult& p, const std::string& metric) {
  return p.ok && std::isfinite(p.timing.frame_wall_ms.median) && std::isfinite(error_of(p, metric));
}

// The devices that rendered a point (a failed point may have none: it is listed apart).
std::vector<std::string> devices_that_rendered(const std::vector<PointResult>& results) {
  std::vector<std::string> devices;
  for (const PointResult& p : results) {
    if (p.ok && std::find(devices.begin(), devices.end(), p.device) == devices.end()) devices.push_back(p.device);
  }
  return devices;
}

std::vector<std::string> series_of(const std::vector<PointResult>& results) {
  std::vector<std::string> series;
  for (const PointResult& p : results) {
    if (std::find(series.begin(), series.end(), p.series) == series.end()) series.push_back(p.series);
  }
  return series;
}

// Tableau 10, a categorical palette readable by most colour-blind viewers.
std::string series_colour(size_t index) {
  static const char* const palette[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                                        "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};
  return palette[index % 10];
}

// One axis of a panel: the range shown and whether it is logarithmic.
struct Axis {
  double lo = 0, hi = 1;
  bool log = false;

  double at(double value) const {  // 0 at lo … 1 at hi
    if (log) return (std::log10(value) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
    return (value - lo) / (hi - lo);
  }
};

Axis axis_for(const std::vector<double>& values) {
  Axis axis;
  if (values.empty()) return axis;
  const auto [min_it, max_it] = std::minmax_element(values.begin(), values.end());
  const double lo = *min_it, hi = *max_it;
  axis.log = lo > 0 && hi / lo > 10;
  if (axis.log) {
    const double pad = 0.05 * (std::log10(hi) - std::log10(lo));
    axis.lo = std::pow(10, std::log10(lo) - pad);
    axis.hi = std::pow(10, std::log10(hi) + pad);
    return axis;
  }
  const double span = hi - lo;
  const double pad = span > 0 ? 0.05 * span : (lo != 0 ? 0.1 * std::abs(lo) : 1);
  axis.lo = lo - pad;
  axis.hi = hi + pad;
  if (lo >= 0 && axis.lo < 0) axis.lo = 0;
  return axis;
}

std::vector<double> ticks_of(const Axis& axis) {
  std::vector<double> ticks;
  if (axis.log) {
    const int first = int(std::floor(std::log10(axis.lo))), last = int(std::ceil(std::log10(axis.hi)));
    const bool few_decades = last - first <= 3;  // 1, 2, 5 a decade; 1 a decade over wider ranges
    for (int k = first; k <= last; ++k) {
      for (double m : {1.0, 2.0, 5.0}) {
        if (m != 1 && !few_decades) continue;
        const double v = m * std::pow(10, k);
        if (v >= axis.lo && v <= axis.hi) ticks.push_back(v);
      }
    }
    return ticks;
  }
  const double raw = (axis.hi - axis.lo) / 5;
  const double decade = std::pow(10, std::floor(std::log10(raw)));
  double step = decade * 10;
  for (double m : {1.0, 2.0, 5.0}) {
    if (decade * m >= raw) {
      step = decade * m;
      break;
    }
  }
  for (double v = std::ceil(axis.lo / step) * step; v <= axis.hi + step * 1e-9; v += step) {
    ticks.push_back(std::abs(v) < step * 1e-9 ? 0 : v);
  }
  return ticks;
}

// The layout of a panel, in SVG user units.
constexpr double panel_width = 780, plot_left = 80, plot_width = 480, plot_top = 40, plot_height = 300;
constexpr double panel_height = plot_top + plot_height + 60;

struct Panel {
  const SweepSpec& spec;
  const std::vector<PointResult>& ordered;
  const std::vector<std::string>& all_series;
  std::string device;
  double top = 0;

  double x_of(const Axis& a, double v) const { return plot_left + a.at(v) * plot_width; }
  double y_of(const Axis& a, double v) const { return top + plot_top + (1 - a.at(v)) * plot_height; }

  std::string draw() const {
    std::vector<const PointResult*> points;
    int left_out = 0;
    for (const PointResult& p : ordered) {
      if (p.device != device) continue;
      if (plottable(p, spec.metric))
        points.push_back(&p);
      else
        ++left_out;
    }
    std::ostringstream svg;
    svg << "<g class=\"panel\">\n";
    svg << "<text x=\"" << plot_left << "\" y=\"" << coordinate(top + 22) << "\" font-size=\"15\" font-weight=\"bold\">"
        << escape_xml(device_title(device)) << "</text>\n";
    std::vector<double> times, errors;
    for (const PointResult* p : points) {
      times.push_back(p->timing.frame_wall_ms.median);
      errors.push_back(error_of(*p, spec.metric));
    }
    const Axis x = axis_for(times), y = axis_for(errors);
    draw_axes(svg, x, y);
    if (points.empty()) {
      svg << "<text x=\"" << coordinate(plot_left + plot_width / 2) << "\" y=\""
          << coordinate(top + plot_top + plot_height / 2) << "\" text-anchor=\"middle\">no point to plot</text>\n";
    }
    draw_front(svg, points, x, y);
    draw_points(svg, points, x, y);
    draw_legend(svg, points);
    if (left_out > 0) {
      svg << "<text x=\"" << plot_left << "\" y=\"" << coordinate(top + panel_height - 6) << "\" font-size=\"11\">"
          << left_out << " point(s) not plotted: failed, or time or error not finite</text>\n";
    }
    svg << "</g>\n";
    return svg.str();
  }

  void draw_axes(std::ostringstream& svg, const Axis& x, const Axis& y) const {
    const double bottom = top + plot_top + plot_height;
    svg << "<rect x=\"" << plot_left << "\" y=\"" << coordinate(top + plot_top) << "\" width=\"" << plot_width
        << "\" height=\"" << plot_height << "\" fill=\"none\" stroke=\"#444\"/>\n";
    for (double t : ticks_of(x)) {
      const std::string px = coordinate(x_of(x, t));
      svg << "<line x1=\"" << px << "\" x2=\"" << px << "\" y1=\"" << coordinate(top + plot_top) << "\" y2=\""
          << coordinate(bottom) << "\" stroke=\"#e4e4e4\"/>\n";
      svg << "<text x=\"" << px << "\" y=\"" << coordinate(bottom + 16) << "\" font-size=\"11\" text-anchor=\"middle\">"
          << figure(t, 3) << "</text>\n";
    }
    for (double t : ticks_of(y)) {
      const std::string py = coordinate(y_of(y, t));
      svg << "<line x1=\"" << plot_left << "\" x2=\"" << plot_left + plot_width << "\" y1=\"" << py << "\" y2=\"" << py
          << "\" stroke=\"#e4e4e4\"/>\n";
      svg << "<text x=\"" << plot_left - 6 << "\" y=\"" << py << "\" font-size=\"11\" text-anchor=\"end\" dy=\"4\">"
          << figure(t, 3) << "</text>\n";
    }
    const std::string x_title = std::string("frame time, ms (median") + (x.log ? ", log scale)" : ")");
    svg << "<text x=\"" << coordinate(plot_left + plot_width / 2) << "\" y=\"" << coordinate(bottom + 36)
        << "\" font-size=\"12\" text-anchor=\"middle\">" << escape_xml(x_title) << "</text>\n";
    const std::string y_title = spec.metric + ", " + spec.mask + " (" +
                                (metric_lower_is_better(spec.metric) ? "lower" : "higher") + " is better" +
                                (y.log ? ", log scale)" : ")");
    const double y_mid = top + plot_top + plot_height / 2;
    svg << "<text x=\"18\" y=\"" << coordinate(y_mid)
        << "\" font-size=\"12\" text-anchor=\"middle\" transform=\"rotate(-90 18 " << coordinate(y_mid) << ")\">"
        << escape_xml(y_title) << "</text>\n";
  }

  void draw_front(std::ostringstream& svg, std::vector<const PointResult*> points, const Axis& x, const Axis& y) const {
    std::erase_if(points, [](const PointResult* p) { return !p->pareto; });
    std::stable_sort(points.begin(), points.end(), [](const PointResult* a, const PointResult* b) {
      return a->timing.frame_wall_ms.median < b->timing.frame_wall_ms.median;
    });
    if (points.size() < 2) return;
    svg << "<polyline class=\"front\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.5\" points=\"";
    for (const PointResult* p : points) {
      svg << coordinate(x_of(x, p->timing.frame_wall_ms.median)) << ","
          << coordinate(y_of(y, error_of(*p, spec.metric))) << " ";
    }
    svg << "\"/>\n";
  }

  void draw_points(std::ostringstream& svg, const std::vector<const PointResult*>& points, const Axis& x,
                   const Axis& y) const {
    for (const PointResult* p : points) {
      const size_t s = std::find(all_series.begin(), all_series.end(), p->series) - all_series.begin();
      const double t = p->timing.frame_wall_ms.median, e = error_of(*p, spec.metric);
      svg << "<circle cx=\"" << coordinate(x_of(x, t)) << "\" cy=\"" << coordinate(y_of(y, e)) << "\" r=\""
          << (p->pareto ? 6 : 4) << "\" fill=\"" << series_colour(s) << "\""
          << (p->pareto ? " stroke=\"#000\" stroke-width=\"1.5\"" : " fill-opacity=\"0.8\"") << "><title>"
          << escape_xml(point_name(*p) + " — " + figure(t) + " ms, " + spec.metric + " " + figure(e) +
                        (p->pareto ? " (Pareto front)" : ""))
          << "</title></circle>\n";
    }
  }

  void draw_legend(std::ostringstream& svg, const std::vector<const PointResult*>& points) const {
    const double left = plot_left + plot_width + 20;
    double row = top + plot_top + 8;
    for (size_t s = 0; s < all_series.size(); ++s) {
      const bool here =
          std::any_of(points.begin(), points.end(), [&](const PointResult* p) { return p->series == all_series[s]; });
      if (!here) continue;
      svg << "<circle cx=\"" << left + 6 << "\" cy=\"" << coordinate(row) << "\" r=\"5\" fill=\"" << series_colour(s)
          << "\"/><text x=\"" << left + 18 << "\" y=\"" << coordinate(row + 4) << "\" font-size=\"12\">"
          << escape_xml(all_series[s].empty() ? "(no series)" : all_series[s]) << "</text>\n";
      row += 20;
    }
    svg << "<line x1=\"" << left << "\" x2=\"" << left + 14 << "\" y1=\"" << coordinate(row) << "\" y2=\""
        << coordinate(row) << "\" stroke=\"#222\" stroke-width=\"1.5\"/><circle cx=\"" << left + 7 << "\" cy=\""
        << coordinate(row) << "\" r=\"4\" fill=\"#fff\" stroke=\"#000\" stroke-width=\"1.5\"/><text x=\"" << left + 18
        << "\" y=\"" << coordinate(row + 4) << "\" font-size=\"12\">Pareto front</text>\n";
  }
};

std::string html_metric_cell(double value) { return "<td class=\"num\">" + figure(value) + "</td>"; }

std::string device_table(const SweepSpec& spec, const std::vector<PointResult>& ordered, const std::string& device) {
  std::vector<const PointResult*> rows;
  std::string clock;
  for (const PointResult& p : ordered) {
    if (p.device != device || !p.ok) continue;
    rows.push_back(&p);
    if (clock.empty()) clock = p.timing.clock;
  }
  std::stable_sort(rows.begin(), rows.end(), [](const PointResult* a, const PointResult* b) {
    return a->timing.frame_wall_ms.median < b->timing.frame_wall_ms.median;
  });
  std::ostringstream html;
  html << "<h2>" << escape_xml(device_title(device)) << "</h2>\n";
  if (!clock.empty()) html << "<p class=\"clock\">Times: " << escape_xml(clock) << "</p>\n";
  html << "<table>\n<tr><th>front</th><th>series</th><th>setting</th><th>frame ms (median)</th><th>min – "
          "max</th><th>runs</th>"
       << "<th>error (" << escape_xml(spec.metric)
       << ")</th><th>rmse</th><th>rel_rmse</th><th>psnr dB</th><th>ssim</th><th>flip</th>"
       << "<th>max_abs</th><th>NaN / Inf</th><th>id</th></tr>\n";
  for (const PointResult* p : rows) {
    const Spread& t = p->timing.frame_wall_ms;
    html << "<tr" << (p->pareto ? " class=\"front\"" : "") << "><td>" << (p->pareto ? "★" : "") << "</td><td>"
         << escape_xml(p->series) << "</td><td>" << escape_xml(p->label) << "</td>" << html_metric_cell(t.median)
         << "<td class=\"num\">" << figure(t.min) << " – " << figure(t.max) << "</td><td class=\"num\">" << t.runs
         << "</td>" << html_metric_cell(metric_value(p->metrics, spec.metric)) << html_metric_cell(p->metrics.rmse)
         << html_metric_cell(p->metrics.relative_rmse) << html_metric_cell(p->metrics.psnr_db)
         << html_metric_cell(p->metrics.ssim) << html_metric_cell(p->metrics.flip)
         << html_metric_cell(p->metrics.max_abs_error) << "<td class=\"num\">" << p->metrics.nan_values << " / "
         << p->metrics.inf_values << "</td><td><code>" << escape_xml(p->id) << "</code></td></tr>\n";
  }
  html << "</table>\n";
  return html.str();
}

std::string failed_list(const std::vector<PointResult>& ordered) {
  std::ostringstream html;
  for (const PointResult& p : ordered) {
    if (p.ok) continue;
    if (html.tellp() == 0) html << "<h2>Failed points</h2>\n<ul class=\"failed\">\n";
    html << "<li><b>" << escape_xml(point_name(p)) << "</b> (<code>" << escape_xml(p.id) << "</code>"
         << (p.device.empty() ? "" : ", " + escape_xml(p.device)) << "): <pre>" << escape_xml(p.error)
         << "</pre></li>\n";
  }
  if (html.tellp() != 0) html << "</ul>\n";
  return html.str();
}

size_t spec_points_done(const SweepSpec& spec, const std::vector<PointResult>& ordered) {
  return size_t(std::count_if(spec.points.begin(), spec.points.end(), [&](const SweepPoint& point) {
    return std::any_of(ordered.begin(), ordered.end(), [&](const PointResult& p) { return p.id == point.id; });
  }));
}

// pareto.png from the SVG by rsvg-convert; empty when it fails (stderr says why).
std::vector<std::byte> render_png(const std::string& dir, const std::string& svg) {
  const std::string stem = (std::filesystem::path(dir) / (".pareto-render-" + std::to_string(::getpid()))).string();
  const std::string svg_file = stem + ".svg", png_file = stem + ".png";
  std::vector<std::byte> png;
  write_file_checked(svg_file, text_bytes(svg));
  const char* argv[] = {"rsvg-convert", "-o", png_file.c_str(), svg_file.c_str(), nullptr};
  pid_t child = 0;
  int status = 0;
  const bool spawned = posix_spawnp(&child, "rsvg-convert", nullptr, nullptr, const_cast<char**>(argv), environ) == 0;
  const bool converted =
      spawned && waitpid(child, &status, 0) == child && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (converted) {
    std::ifstream in(png_file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    png.resize(bytes.size());
    std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(png.data()));
  } else {
    std::cerr << "volgraph sweep: rsvg-convert failed on the plot: pareto.png not written (pareto.svg has the plot)\n";
  }
  std::error_code ec;
  std::filesystem::remove(svg_file, ec);
  std::filesystem::remove(png_file, ec);
  return png;
}

}  // namespace

std::string pareto_svg(const SweepSpec& spec, const std::vector<PointResult>& ordered) {
  const std::vector<std::string> devices = devices_that_rendered(ordered);
  const std::vector<std::string> all_series = series_of(ordered);
  const size_t panels = std::max<size_t>(devices.size(), 1);
  const double height = panels * panel_height + 10;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << panel_width << "\" height=\"" << coordinate(height)
      << "\" viewBox=\"0 0 " << panel_width << " " << coordinate(height)
      << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  if (devices.empty()) {
    svg << "<text x=\"" << panel_width / 2 << "\" y=\"" << panel_height / 2
        << "\" text-anchor=\"middle\">no point rendered yet</text>\n";
  }
  for (size_t d = 0; d < devices.size(); ++d) {
    svg << Panel{spec, ordered, all_series, devices[d], double(d) * panel_height}.draw();
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string sweep_report_html(const SweepSpec& spec, const std::vector<PointResult>& ordered, const std::string& svg) {
  const std::vector<std::string> devices = devices_that_rendered(ordered);
  const int failed = int(std::count_if(ordered.begin(), ordered.end(), [](const PointResult& p) { return !p.ok; }));
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>volgraph sweep: "
       << escape_xml(spec.file) << "</title>\n<style>\n"
       << "body{font-family:DejaVu Sans,Helvetica,Arial,sans-serif;margin:1.5em;color:#222}\n"
       << "table{border-collapse:collapse;font-size:13px}td,th{border:1px solid #ccc;padding:3px 6px}\n"
       << "th{background:#f2f2f2}td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}\n"
       << "tr.front{background:#fff4c2;font-weight:bold}pre{display:inline;white-space:pre-wrap}\n"
       << ".note{background:#eef4ff;border-left:4px solid #4e79a7;padding:.4em .8em}dt{font-weight:bold}\n"
       << "</style>\n</head>\n<body>\n<h1>Sweep: " << escape_xml(spec.file.empty() ? "(merged results)" : spec.file)
       << "</h1>\n";
  if (!spec.description.empty()) html << "<p>" << escape_xml(spec.description) << "</p>\n";
  html << "<dl>\n<dt>config</dt><dd>" << escape_xml(spec.config) << "</dd>\n<dt>size</dt><dd>" << spec.size.width << "×"
       << spec.size.height << ", " << spec.runs << " runs after " << spec.warmup << " warm-up, " << spec.frames
       << " frame(s), backend " << escape_xml(spec.backend) << "</dd>\n<dt>error</dt><dd>" << escape_xml(spec.metric)
       << " (" << (metric_lower_is_better(spec.metric) ? "lower" : "higher") << " is better) over "
       << escape_xml(spec.mask) << " pixels against the "
       << escape_xml(spec.reference == "cpu" ? "CPU reference" : spec.reference) << "</dd>\n"
       << "<dt>points</dt><dd>" << spec_points_done(spec, ordered) << " of the spec's " << spec.points.size()
       << " done; " << ordered.size() << " result(s), " << failed << " failed</dd>\n</dl>\n";
  if (std::any_of(ordered.begin(), ordered.end(), [](const PointResult& p) { return is_lavapipe(p.device); })) {
    html << "<p class=\"note\">Times on llvmpipe are lavapipe (CPU): Mesa's software Vulkan driver, so the “GPU” time "
            "is "
            "this machine's CPU time, not a GPU's.</p>\n";
  }
  html << "<p class=\"note\">The Pareto front (★, joined by a line) holds, per device, the points no other point of "
          "that "
          "device beats in both median frame time and "
       << escape_xml(spec.metric)
       << ". Times of different devices are not compared. Hover a point for its setting.</p>\n";
  html << svg;
  for (const std::string& device : devices) html << device_table(spec, ordered, device);
  html << failed_list(ordered);
  html << "</body>\n</html>\n";
  return html.str();
}

bool have_svg_converter() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream folders(path);
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    if (folder.empty()) folder = ".";
    if (::access((std::filesystem::path(folder) / "rsvg-convert").c_str(), X_OK) == 0) return true;
  }
  return false;
}

void write_aggregates(const std::string& dir, const SweepSpec& spec, std::vector<PointResult> results) {
  const bool png = have_svg_converter();
  if (!png)
    std::cerr << "volgraph sweep: rsvg-convert (Debian librsvg2-bin) not found: pareto.png not written (pareto.svg has "
                 "the plot)\n";
  write_aggregates(dir, spec, std::move(results), png);
}

void write_aggregates(const std::string& dir, const SweepSpec& spec, std::vector<PointResult> results, bool write_png) {
  for (PointResult& p : results) p.metric = spec.metric;  // the front and the plot take the same figure
  mark_pareto(results);
  const std::vector<PointResult> ordered = in_spec_order(spec, std::move(results));
  const std::filesystem::path folder(dir);
  std::filesystem::create_directories(folder);
  const std::string svg = pareto_svg(spec, ordered);
  std::vector<std::byte> png = write_png ? render_png(dir, svg) : std::vector<std::byte>{};
  OutputFiles files;
  files.stage((folder / "results.json").string(), "-o", text_bytes(results_json(spec, ordered)));
  files.stage((folder / "results.csv").string(), "-o", text_bytes(results_csv(ordered)));
  files.stage((folder / "results.md").string(), "-o", text_bytes(results_markdown(spec, ordered)));
  files.stage((folder / "report.html").string(), "-o", text_bytes(sweep_report_html(spec, ordered, svg)));
  files.stage((folder / "pareto.svg").string(), "-o", text_bytes(svg));
  if (!png.empty()) files.stage((folder / "pareto.png").string(), "-o", png);
  files.commit();
  std::error_code ec;
  if (png.empty()) std::filesystem::remove(folder / "pareto.png", ec);  // a stale plot would disagree with the rest
}

}  // namespace volgraph::compare
