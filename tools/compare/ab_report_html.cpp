// report.html: one page that needs nothing but itself. The images are PNG data: URIs,
// the style and the script are inline, and the page's Content-Security-Policy forbids
// every fetch, so nothing can reach the network even by mistake.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "tools/compare/ab_report.h"
#include "tools/compare/display_image.h"
#include "tools/compare/heatmap.h"
#include "tools/image_io.h"

namespace volgraph::compare {
namespace {

constexpr double kViewerMaxWidth = 960, kViewerMaxHeight = 720;
constexpr int kThumbnailWidth = 320;

std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += ch;
    }
  }
  return out;
}

// RFC 4648, section 4.
std::string base64(const std::vector<std::byte>& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    uint32_t group = 0;
    for (size_t k = 0; k < 3; ++k) group = group << 8 | (k < n ? uint32_t(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) out += k <= n ? kAlphabet[(group >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

std::string png_data_uri(const Rgba8Image& image) {
  return "data:image/png;base64," + base64(encode_png_rgba8(image.width, image.height, image.rgba));
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string number(double value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "∞" : "−∞";
  return format("%.4g", value);
}

// Binary units (IEC 80000-13), the exact count in the tooltip.
std::string bytes_text(uint64_t bytes) {
  static constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB"};
  std::string shown = std::to_string(bytes) + " B";
  double value = double(bytes);
  for (const char* unit : kUnits) {
    if (value < 1024.0) break;
    value /= 1024.0;
    shown = format("%.2f", value) + " " + unit;
  }
  return "<span title=\"" + std::to_string(bytes) + " bytes\">" + shown + "</span>";
}

std::string spread_text(const Spread& spread) {
  if (spread.runs == 0) return "—";
  return format("%.3f", spread.median) + " <small>[" + format("%.3f", spread.min) + "–" + format("%.3f", spread.max) + "]</small>";
}

// The key of a layer of the viewer: the file stem with '-' for '_' ("error-a-vs-reference").
std::string layer_key(const std::string& stem) {
  std::string out = stem;
  std::replace(out.begin(), out.end(), '_', '-');
  return out;
}

struct Layer {
  std::string key, name, data_uri;
};

struct Heatmap {
  Layer layer;
  ColourMap map;
  HeatmapRange range;
  std::string what;
};

struct Page {
  std::vector<Layer> renders;
  std::vector<std::pair<const Comparison*, std::vector<Heatmap>>> heatmaps;
  uint32_t width = 0, height = 0;
  double viewer_width = 0, viewer_height = 0;
};

// The viewer shows an image small enough for the page at a whole number of screen
// pixels a pixel when it fits (pixels stay square and crisp), scaled down otherwise.
void size_viewer(Page& page) {
  if (page.width == 0 || page.height == 0) return;
  double scale = std::min(kViewerMaxWidth / page.width, kViewerMaxHeight / page.height);
  if (scale >= 1) scale = std::floor(scale);
  page.viewer_width = std::round(page.width * scale);
  page.viewer_height = std::round(page.height * scale);
}

Page page_of(const AbReport& report) {
  Page page;
  const double exposure = report_display_exposure(report);
  for (const Rendered& render : report.renders) {
    page.renders.push_back({layer_key(report_file_stem(render.label)), render.label,
                            png_data_uri(display_image(render.image, exposure))});
  }
  page.width = report.renders.empty() ? report.width : report.renders.front().image.width;  // heatmap_fits' size
  page.height = report.renders.empty() ? report.height : report.renders.front().image.height;
  for (const Comparison& comparison : report.comparisons) {
    const std::string pair = report_file_stem(comparison.test) + "_vs_" + report_file_stem(comparison.against);
    const std::string names = comparison.test + " vs " + comparison.against;
    std::vector<Heatmap> maps;
    if (heatmap_fits(comparison.abs_error_map, report)) {
      const HeatmapRange range = abs_error_range(comparison.abs_error_map);
      maps.push_back({{layer_key("error_" + pair), "|" + names + "|",
                       png_data_uri(heatmap_image(comparison.abs_error_map, page.width, page.height, ColourMap::viridis, range))},
                      ColourMap::viridis, range, "largest absolute channel error (linear radiance), viridis"});
    }
    if (heatmap_fits(comparison.flip_map, report)) {
      maps.push_back({{layer_key("flip_" + pair), "FLIP " + names,
                       png_data_uri(heatmap_image(comparison.flip_map, page.width, page.height, ColourMap::magma, kFlipRange))},
                      ColourMap::magma, kFlipRange, "HDR-FLIP error (Andersson et al. 2021), magma"});
    }
    page.heatmaps.emplace_back(&comparison, std::move(maps));
  }
  size_viewer(page);
  return page;
}

const char* kStyle = R"css(
:root { color-scheme: dark; }
* { box-sizing: border-box; }
body { margin: 0; padding: 16px 24px 48px; background: #202124; color: #e8eaed;
       font: 14px/1.45 system-ui, sans-serif; }
h1 { font-size: 20px; margin: 0 0 8px; }
h2 { font-size: 16px; margin: 24px 0 8px; border-bottom: 1px solid #3c4043; padding-bottom: 4px; }
h3 { font-size: 14px; margin: 12px 0 6px; }
code { font: 12px/1.4 ui-monospace, monospace; background: #2d2e31; padding: 1px 4px; border-radius: 3px;
       word-break: break-all; }
dl.facts { display: grid; grid-template-columns: max-content 1fr; gap: 2px 16px; margin: 0; }
dl.facts dt { color: #9aa0a6; }
dl.facts dd { margin: 0; }
.cpu-note { margin: 8px 0; padding: 6px 10px; background: #5c3b00; border-left: 4px solid #fbbc04; font-weight: 600; }
.controls { display: flex; flex-wrap: wrap; gap: 8px 16px; align-items: center; margin: 8px 0; }
.controls button, .controls select { font: inherit; color: inherit; background: #303134; border: 1px solid #5f6368;
       border-radius: 4px; padding: 2px 10px; cursor: pointer; }
.controls button[aria-pressed="true"] { background: #1a73e8; border-color: #1a73e8; }
#viewer { position: relative; overflow: hidden; background: #000; outline: 1px solid #5f6368; cursor: ew-resize;
          touch-action: none; user-select: none; }
#viewer.single { cursor: grab; }
#viewer .layer { position: absolute; left: 0; top: 0; width: 100%; height: 100%; overflow: hidden; }
#viewer img { position: absolute; left: 0; top: 0; width: 100%; height: 100%; transform-origin: 0 0; }
#split-line { position: absolute; top: 0; width: 0; height: 100%; border-left: 2px solid #fff;
              margin-left: -1px; pointer-events: none; mix-blend-mode: difference; }
img.pixels { image-rendering: pixelated; }
#viewer-caption { color: #9aa0a6; margin: 4px 0 0; }
.row { display: flex; flex-wrap: wrap; gap: 16px; align-items: flex-start; }
figure { margin: 0; }
figcaption { max-width: 320px; font-size: 12px; color: #bdc1c6; }
.heatmap { display: flex; gap: 6px; align-items: stretch; }
.bar { width: 14px; border: 1px solid #5f6368; }
.bar-labels { display: flex; flex-direction: column; justify-content: space-between; font-size: 12px; }
table { border-collapse: collapse; font-variant-numeric: tabular-nums; }
th, td { border: 1px solid #3c4043; padding: 3px 8px; text-align: right; }
th { background: #2d2e31; }
td.name, th.name { text-align: left; }
td.bad { background: #5c1f1f; }
[hidden] { display: none !important; }
)css";

// The viewer: toggle buttons, two <select>s and a slider, zoom. Every change goes
// through the handlers a click, a drag or a key uses; the address fragment calls them.
const char* kScript = R"js(
(function () {
  'use strict';
  const viewer = document.getElementById('viewer');
  const views = [document.getElementById('view-left'), document.getElementById('view-right')];
  const rightLayer = document.getElementById('layer-right');
  const line = document.getElementById('split-line');
  const slider = document.getElementById('split');
  const pick = { left: document.getElementById('left'), right: document.getElementById('right') };
  const caption = document.getElementById('viewer-caption');
  const zoomLabel = document.getElementById('zoom-level');
  const toggles = Array.from(document.querySelectorAll('button[data-show]'));
  const sources = {};
  document.querySelectorAll('img[data-layer]').forEach(function (img) { sources[img.dataset.layer] = img; });
  const state = { mode: 'split', shown: toggles.length ? toggles[0].dataset.show : '', zoom: 1, x: 0, y: 0 };

  function nameOf(key) { return sources[key] ? sources[key].dataset.name : key; }
  function show(view, key) {
    const uri = sources[key] ? sources[key].getAttribute('src') : '';
    if (view.getAttribute('src') !== uri) view.setAttribute('src', uri);
    view.alt = nameOf(key);
  }
  function render() {
    const split = Number(slider.value);
    const single = state.mode === 'single';
    viewer.classList.toggle('single', single);
    show(views[0], single ? state.shown : pick.left.value);
    show(views[1], pick.right.value);
    rightLayer.hidden = single;
    line.hidden = single;
    rightLayer.style.clipPath = 'inset(0 0 0 ' + (100 * split) + '%)';
    line.style.left = (100 * split) + '%';
    caption.textContent = single ? 'showing ' + nameOf(state.shown)
        : 'left of the line: ' + nameOf(pick.left.value) + '; right: ' + nameOf(pick.right.value);
    toggles.forEach(function (b) {
      b.setAttribute('aria-pressed', String(single && b.dataset.show === state.shown));
    });
    const transform = 'translate(' + state.x + 'px,' + state.y + 'px) scale(' + state.zoom + ')';
    views.forEach(function (v) { v.style.transform = transform; });
    zoomLabel.textContent = (Math.round(state.zoom * 100) / 100) + '×';
  }
  function clampView() {
    const w = viewer.clientWidth, h = viewer.clientHeight;
    state.zoom = Math.min(64, Math.max(1, state.zoom));
    state.x = Math.min(0, Math.max(w - w * state.zoom, state.x));
    state.y = Math.min(0, Math.max(h - h * state.zoom, state.y));
  }
  function zoomAt(factor, cx, cy) {
    const zoom = Math.min(64, Math.max(1, state.zoom * factor));
    const f = zoom / state.zoom;
    state.x = cx - (cx - state.x) * f;
    state.y = cy - (cy - state.y) * f;
    state.zoom = zoom;
    clampView();
    render();
  }
  function zoomCentre(factor) { zoomAt(factor, viewer.clientWidth / 2, viewer.clientHeight / 2); }

  toggles.forEach(function (b) {
    b.addEventListener('click', function () { state.mode = 'single'; state.shown = b.dataset.show; render(); });
  });
  slider.addEventListener('input', function () { state.mode = 'split'; render(); });
  pick.left.addEventListener('change', function () { state.mode = 'split'; render(); });
  pick.right.addEventListener('change', function () { state.mode = 'split'; render(); });
  document.getElementById('zoom-in').addEventListener('click', function () { zoomCentre(2); });
  document.getElementById('zoom-out').addEventListener('click', function () { zoomCentre(0.5); });
  document.getElementById('zoom-fit').addEventListener('click', function () {
    state.zoom = 1; state.x = 0; state.y = 0; render();
  });
  viewer.addEventListener('wheel', function (e) {
    e.preventDefault();
    const r = viewer.getBoundingClientRect();
    zoomAt(e.deltaY < 0 ? 1.25 : 0.8, e.clientX - r.left, e.clientY - r.top);
  }, { passive: false });

  // Dragging moves the split line (the slider's own input event), or pans a zoomed
  // view when one image is shown or Shift is held.
  let drag = null;
  function moveSplit(e) {
    const r = viewer.getBoundingClientRect();
    slider.value = String(Math.min(1, Math.max(0, (e.clientX - r.left) / r.width)));
    slider.dispatchEvent(new Event('input'));
  }
  viewer.addEventListener('pointerdown', function (e) {
    viewer.setPointerCapture(e.pointerId);
    drag = (state.mode === 'single' || e.shiftKey) ? { pan: true, x: e.clientX - state.x, y: e.clientY - state.y } : { pan: false };
    if (!drag.pan) moveSplit(e);
  });
  viewer.addEventListener('pointermove', function (e) {
    if (!drag) return;
    if (!drag.pan) { moveSplit(e); return; }
    state.x = e.clientX - drag.x; state.y = e.clientY - drag.y;
    clampView();
    render();
  });
  viewer.addEventListener('pointerup', function () { drag = null; });
  document.addEventListener('keydown', function (e) {
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
    if (e.key === '+' || e.key === '=') zoomCentre(2);
    if (e.key === '-') zoomCentre(0.5);
  });

  // #show=b, #split=0.25, #left=a&right=reference, #zoom=4: the same handlers as a click.
  function choose(select, key) {
    if (!Array.from(select.options).some(function (o) { return o.value === key; })) {
      console.warn('report: no image "' + key + '" to pick');
      return;
    }
    select.value = key;
    select.dispatchEvent(new Event('change'));
  }
  function applyFragment() {
    const params = new URLSearchParams(location.hash.slice(1));
    if (params.has('left')) choose(pick.left, params.get('left'));
    if (params.has('right')) choose(pick.right, params.get('right'));
    if (params.has('split')) {
      slider.value = params.get('split');
      slider.dispatchEvent(new Event('input'));
    }
    if (params.has('show')) {
      const button = document.getElementById('show-' + params.get('show'));
      if (button) button.click(); else console.warn('report: no toggle "' + params.get('show') + '"');
    }
    if (params.has('zoom')) {
      document.getElementById('zoom-fit').click();
      zoomCentre(Number(params.get('zoom')) || 1);
    }
  }
  window.addEventListener('hashchange', applyFragment);
  render();
  applyFragment();

  function box(id) {
    const r = document.getElementById(id).getBoundingClientRect();
    return [r.left + window.scrollX, r.top + window.scrollY, r.width, r.height].map(Math.round).join(',');
  }
  window.addEventListener('load', function () {
    const layout = 'viewer=' + box('viewer') + ' metrics=' + box('metrics-table');
    document.title = document.title + ' [' + layout + ']';
    console.log('report ready ' + layout);
  });
})();
)js";

std::string fact(const std::string& name, const std::string& value_html) {
  return "<dt>" + escape(name) + "</dt><dd>" + value_html + "</dd>\n";
}

std::string header_html(const AbReport& report) {
  std::ostringstream out;
  out << "<header>\n<h1>volgraph ab: " << escape(report.config) << "</h1>\n";
  if (report.device_is_cpu) {
    out << "<div class=\"cpu-note\" id=\"cpu-note\">lavapipe (CPU): the GPU is this CPU; times are CPU times</div>\n";
  }
  out << "<dl class=\"facts\">\n";
  out << fact("config", "<code>" + escape(report.config) + "</code>");
  out << fact("pass", report.pass.empty() ? "the whole graph" : "<code>" + escape(report.pass) + "</code>");
  for (const Rendered& render : report.renders) out << fact(render.label, escape(render.setting));
  out << fact("device", escape(report.device) + (report.device_is_cpu ? " (CPU)" : ""));
  out << fact("backend", escape(report.backend));
  out << fact("driver", escape(report.driver));
  out << fact("image", std::to_string(report.width) + " × " + std::to_string(report.height));
  out << fact("frames", report.frames == 1 ? std::string("the compared image is the first frame") : "the compared image is frame " + std::to_string(report.frames));
  out << fact("volgraph", escape(report.volgraph_version));
  out << fact("command", "<code>" + escape(report.command_line) + "</code>");
  out << "</dl>\n</header>\n";
  return out.str();
}

std::string toggle_button(const Layer& layer) {
  return "<button type=\"button\" id=\"show-" + escape(layer.key) + "\" data-show=\"" + escape(layer.key) +
         "\" aria-pressed=\"false\">" + escape(layer.name) + "</button>";
}

std::string option(const Layer& layer, const std::string& selected) {
  return "<option value=\"" + escape(layer.key) + "\"" + (layer.key == selected ? " selected" : "") + ">" +
         escape(layer.name) + "</option>";
}

std::string viewer_html(const Page& page) {
  std::vector<const Layer*> layers;
  for (const Layer& layer : page.renders) layers.push_back(&layer);
  for (const auto& [comparison, maps] : page.heatmaps) {
    for (const Heatmap& map : maps) layers.push_back(&map.layer);
  }
  const std::string left = layers.empty() ? "" : layers[0]->key;
  const std::string right = layers.size() > 1 ? layers[1]->key : left;
  std::ostringstream out;
  out << "<section id=\"viewer-section\">\n<h2>Compare</h2>\n<div class=\"controls\">\n<span>show:</span>";
  for (const Layer* layer : layers) out << toggle_button(*layer);
  out << "\n<label>split <select id=\"left\">";
  for (const Layer* layer : layers) out << option(*layer, left);
  out << "</select> | <select id=\"right\">";
  for (const Layer* layer : layers) out << option(*layer, right);
  out << "</select></label>\n<input type=\"range\" id=\"split\" min=\"0\" max=\"1\" step=\"0.001\" value=\"0.5\" "
         "aria-label=\"split position\">\n";
  out << "<span>zoom: <button type=\"button\" id=\"zoom-out\">−</button> <span id=\"zoom-level\">1×</span> "
         "<button type=\"button\" id=\"zoom-in\">+</button> <button type=\"button\" id=\"zoom-fit\">fit</button></span>\n";
  out << "</div>\n";
  out << "<div id=\"viewer\" style=\"width:" << page.viewer_width << "px;height:" << page.viewer_height << "px\">"
      << "<div class=\"layer\" id=\"layer-left\"><img class=\"pixels\" id=\"view-left\" alt=\"\"></div>"
      << "<div class=\"layer\" id=\"layer-right\"><img class=\"pixels\" id=\"view-right\" alt=\"\"></div>"
      << "<div id=\"split-line\"></div></div>\n";
  out << "<p id=\"viewer-caption\"></p>\n<p><small>Drag across the image to move the split line; mouse wheel or "
         "+/− zoom; Shift-drag (or drag when one image is shown) pans.</small></p>\n</section>\n";
  return out.str();
}

std::string source_image(const Layer& layer, double width, double height) {
  return "<img class=\"pixels\" data-layer=\"" + escape(layer.key) + "\" data-name=\"" + escape(layer.name) +
         "\" alt=\"" + escape(layer.name) + "\" width=\"" + format("%.0f", width) + "\" height=\"" +
         format("%.0f", height) + "\" src=\"" + layer.data_uri + "\">";
}

double thumbnail_height(const Page& page) {
  return page.width ? std::round(double(kThumbnailWidth) * page.height / page.width) : 0;
}

std::string images_html(const AbReport& report, const Page& page) {
  std::ostringstream out;
  out << "<section id=\"images\">\n<h2>Images</h2>\n<p><small>Shown at exposure " << number(report_display_exposure(report))
      << " for all (the reference's 99th percentile luminance at 0.9), sRGB; magenta: a NaN or Inf pixel.</small></p>\n"
         "<div class=\"row\">\n";
  for (size_t i = 0; i < page.renders.size(); ++i) {
    const Rendered& render = report.renders[i];
    out << "<figure>" << source_image(page.renders[i], kThumbnailWidth, thumbnail_height(page)) << "<figcaption><b>"
        << escape(render.label) << "</b>: " << escape(render.setting) << "<br><code>" << escape(render.command)
        << "</code>";
    if (!render.timing && render.seconds > 0) out << "<br>rendered in " << format("%.2f", render.seconds) << " s";
    out << "</figcaption></figure>\n";
  }
  out << "</div>\n</section>\n";
  return out.str();
}

std::string heatmap_figure(const Heatmap& map, const Page& page) {
  const double height = thumbnail_height(page);
  std::ostringstream out;
  out << "<figure><div class=\"heatmap\">" << source_image(map.layer, kThumbnailWidth, height)
      << "<div class=\"bar\" style=\"height:" << height << "px;background:" << css_gradient(map.map) << "\"></div>"
      << "<div class=\"bar-labels\"><span>" << number(map.range.max) << "</span><span>" << number(map.range.min)
      << "</span></div></div><figcaption>" << escape(map.layer.name) << ": " << escape(map.what)
      << "; cyan: not finite</figcaption></figure>\n";
  return out.str();
}

std::string heatmaps_html(const Page& page) {
  std::ostringstream out;
  out << "<section id=\"heatmaps\">\n<h2>Error maps</h2>\n";
  for (const auto& [comparison, maps] : page.heatmaps) {
    out << "<h3>" << escape(comparison->test) << " against " << escape(comparison->against) << "</h3>\n<div class=\"row\">\n";
    for (const Heatmap& map : maps) out << heatmap_figure(map, page);
    out << "</div>\n";
  }
  out << "</section>\n";
  return out.str();
}

std::string count_cell(size_t count) {
  return std::string(count ? "<td class=\"bad\">" : "<td>") + std::to_string(count) + "</td>";
}

std::string metrics_html(const AbReport& report) {
  std::ostringstream out;
  out << "<section id=\"metrics\">\n<h2>Error</h2>\n<table id=\"metrics-table\">\n<tr><th class=\"name\">test vs "
         "against</th><th class=\"name\">mask</th><th>RMSE</th><th>rel RMSE</th><th>PSNR (dB)</th><th>SSIM</th>"
         "<th>FLIP</th><th>max abs</th><th>NaN</th><th>Inf</th><th>pixels</th></tr>\n";
  for (const Comparison& comparison : report.comparisons) {
    for (const MaskedMetrics& masked : comparison.by_mask) {
      const ErrorMetrics& m = masked.metrics;
      out << "<tr><td class=\"name\">" << escape(comparison.test) << " vs " << escape(comparison.against)
          << "</td><td class=\"name\">" << escape(masked.mask) << "</td><td>" << number(m.rmse) << "</td><td>"
          << number(m.relative_rmse) << "</td><td>" << number(m.psnr_db) << "</td><td>" << number(m.ssim) << "</td><td>"
          << number(m.flip) << "</td><td>" << number(m.max_abs_error) << "</td>" << count_cell(m.nan_values)
          << count_cell(m.inf_values) << "<td>" << m.compared_pixels << " / " << masked.mask_pixels << "</td></tr>\n";
    }
  }
  out << "</table>\n<p><small>Linear radiance. PSNR's peak is the reference's largest value; SSIM of the luminance "
         "(Wang et al. 2004); FLIP: mean HDR-FLIP (Andersson et al. 2021). Pixels: compared (both finite) / in the mask."
         "</small></p>\n</section>\n";
  return out.str();
}

std::vector<const Rendered*> timed_renders(const AbReport& report) {
  std::vector<const Rendered*> out;
  for (const Rendered& render : report.renders) {
    if (render.timing) out.push_back(&render);
  }
  return out;
}

// Every pass of every timed render, in the order they first appear.
std::vector<std::pair<std::string, std::string>> pass_rows(const std::vector<const Rendered*>& timed) {
  std::vector<std::pair<std::string, std::string>> rows;
  for (const Rendered* render : timed) {
    for (const PassTimes& pass : render->timing->passes) {
      const std::pair<std::string, std::string> row{pass.pass, pass.type};
      if (std::find(rows.begin(), rows.end(), row) == rows.end()) rows.push_back(row);
    }
  }
  return rows;
}

const PassTimes* times_of(const Rendered& render, const std::pair<std::string, std::string>& row) {
  for (const PassTimes& pass : render.timing->passes) {
    if (pass.pass == row.first && pass.type == row.second) return &pass;
  }
  return nullptr;
}

std::string timing_html(const AbReport& report) {
  const std::vector<const Rendered*> timed = timed_renders(report);
  std::ostringstream out;
  out << "<section id=\"timing\">\n<h2>Time (ms, median [min–max])</h2>\n";
  if (timed.empty()) return out.str() + "<p>No timings.</p>\n</section>\n";
  out << "<table id=\"timing-table\">\n<tr><th class=\"name\">pass</th><th class=\"name\">type</th>";
  for (const Rendered* render : timed) out << "<th>" << escape(render->label) << " GPU</th>";
  for (const Rendered* render : timed) out << "<th>" << escape(render->label) << " CPU recording</th>";
  out << "</tr>\n";
  for (const auto& row : pass_rows(timed)) {
    out << "<tr><td class=\"name\">" << escape(row.first) << "</td><td class=\"name\">" << escape(row.second) << "</td>";
    for (const Rendered* render : timed) {
      const PassTimes* pass = times_of(*render, row);
      out << "<td>" << (pass && render->timing->gpu_timestamps ? spread_text(pass->gpu_ms) : "—") << "</td>";
    }
    for (const Rendered* render : timed) {
      const PassTimes* pass = times_of(*render, row);
      out << "<td>" << (pass ? spread_text(pass->cpu_ms) : "—") << "</td>";
    }
    out << "</tr>\n";
  }
  out << "<tr><th class=\"name\" colspan=\"2\">frame (wall, submit to completion)</th>";
  for (const Rendered* render : timed) out << "<td>" << spread_text(render->timing->frame_wall_ms) << "</td>";
  for (size_t i = 0; i < timed.size(); ++i) out << "<td></td>";
  out << "</tr>\n</table>\n<ul>\n";
  for (const Rendered* render : timed) {
    const TimingSummary& t = *render->timing;
    out << "<li>" << escape(render->label) << ": " << t.runs << " runs after " << t.warmup << " warm-up frames; "
        << (t.gpu_timestamps ? "GPU time stamps" : "no GPU time stamps") << ". " << escape(t.clock) << "</li>\n";
  }
  out << "</ul>\n</section>\n";
  return out.str();
}

std::string memory_html(const AbReport& report) {
  std::vector<const Rendered*> planned;
  for (const Rendered& render : report.renders) {
    if (render.memory) planned.push_back(&render);
  }
  std::ostringstream out;
  out << "<section id=\"memory\">\n<h2>Memory (the plans)</h2>\n";
  if (planned.empty()) return out.str() + "<p>No plans.</p>\n</section>\n";
  out << "<table id=\"memory-table\">\n<tr><th class=\"name\"></th>";
  for (const Rendered* render : planned) out << "<th>" << escape(render->label) << "</th>";
  out << "</tr>\n";
  auto row = [&](const char* name, auto value_of) {
    out << "<tr><td class=\"name\">" << name << "</td>";
    for (const Rendered* render : planned) out << "<td>" << value_of(*render->memory) << "</td>";
    out << "</tr>\n";
  };
  row("transient, aliased", [](const MemorySummary& m) { return bytes_text(m.aliased_bytes); });
  row("transient, unaliased", [](const MemorySummary& m) { return bytes_text(m.unaliased_bytes); });
  row("lower bound", [](const MemorySummary& m) { return bytes_text(m.lower_bound_bytes); });
  row("persistent", [](const MemorySummary& m) { return bytes_text(m.persistent_bytes); });
  row("passes run", [](const MemorySummary& m) { return std::to_string(m.passes_run); });
  row("passes culled", [](const MemorySummary& m) { return std::to_string(m.passes_culled); });
  out << "</table>\n</section>\n";
  return out.str();
}

std::string notes_html(const AbReport& report) {
  if (report.notes.empty()) return "";
  std::ostringstream out;
  out << "<section id=\"notes\">\n<h2>Notes</h2>\n<ul>\n";
  for (const std::string& note : report.notes) out << "<li>" << escape(note) << "</li>\n";
  out << "</ul>\n</section>\n";
  return out.str();
}

}  // namespace

std::string ab_report_html(const AbReport& report) {
  const Page page = page_of(report);
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; "
         "style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n"
         "<title>volgraph ab: "
      << escape(report.config) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n";
  out << header_html(report) << viewer_html(page) << metrics_html(report) << images_html(report, page)
      << heatmaps_html(page) << timing_html(report) << memory_html(report) << notes_html(report);
  out << "<script>" << kScript << "</script>\n</body>\n</html>\n";
  return out.str();
}

}  // namespace volgraph::compare
