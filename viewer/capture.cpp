#include "viewer/capture.h"

#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>
#include <vector>

namespace volgraph::viewer {
namespace {

// A JSON string: quotes, backslashes and control characters escaped.
std::string quoted(const std::string& text) {
  std::ostringstream out;
  out << '"';
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out << '\\' << c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec;
    } else {
      out << c;
    }
  }
  out << '"';
  return out.str();
}

// A double as the loader reads it back to the bit (17 significant digits).
std::string number(double v) {
  std::ostringstream out;
  out << std::setprecision(17) << v;
  return out.str();
}

std::string vec3(const Vec3& v) { return "[" + number(v[0]) + ", " + number(v[1]) + ", " + number(v[2]) + "]"; }

std::string camera_json(const Camera& c) {
  return "{ \"position\": " + vec3(c.position) + ", \"target\": " + vec3(c.target) + ", \"up\": " + vec3(c.up) +
         ", \"fov_y_deg\": " + number(c.fov_y_deg) + ", \"near\": " + number(c.near) + ", \"far\": " + number(c.far) + " }";
}

std::string sun_json(const Light& l) {
  return "{ \"name\": " + quoted(l.name) + ", \"type\": \"directional\", \"direction\": " + vec3(l.direction) +
         ", \"irradiance\": " + vec3(l.irradiance) + ", \"cast_shadows\": " + (l.cast_shadows ? "true" : "false") + " }";
}

// Each pass the overrides touch: its variant and its parameters (JSON text as given).
struct PassAmendment {
  std::string variant;
  std::vector<std::pair<std::string, std::string>> params;
};

std::map<std::string, PassAmendment> amendments(const Overrides& o) {
  std::map<std::string, PassAmendment> out;
  for (const std::string& v : o.variants) {  // PASS=VARIANT
    const size_t eq = v.find('=');
    out[v.substr(0, eq)].variant = v.substr(eq + 1);
  }
  for (const std::string& s : o.sets) {  // PASS.PARAM=VALUE
    const size_t dot = s.find('.'), eq = s.find('=');
    out[s.substr(0, dot)].params.push_back({s.substr(dot + 1, eq - dot - 1), s.substr(eq + 1)});
  }
  return out;
}

std::string passes_json(const std::map<std::string, PassAmendment>& passes) {
  std::ostringstream out;
  bool first_pass = true;
  for (const auto& [name, a] : passes) {
    out << (first_pass ? "\n      " : ",\n      ") << "{ \"name\": " << quoted(name);
    first_pass = false;
    if (!a.variant.empty()) out << ", \"variant\": " << quoted(a.variant);
    if (!a.params.empty()) {
      out << ", \"params\": {";
      for (size_t i = 0; i < a.params.size(); ++i) out << (i ? ", " : " ") << quoted(a.params[i].first) << ": " << a.params[i].second;
      out << " }";
    }
    out << " }";
  }
  return out.str();
}

std::string include_path(const std::string& config, const std::string& json_path) {
  const std::filesystem::path target = std::filesystem::absolute(config);
  const std::filesystem::path from = std::filesystem::absolute(json_path).parent_path();
  const std::filesystem::path relative = target.lexically_relative(from);
  return relative.empty() ? target.string() : relative.string();
}

}  // namespace

std::string capture_render_command(const std::string& json_path, const CaptureState& state) {
  const std::string graph = state.overrides.graph.empty() ? "" : " --graph " + state.overrides.graph;
  return "volgraph render " + json_path + graph + " --frames " + std::to_string(state.frames) + " -o " +
         std::filesystem::path(json_path).replace_extension(".render.png").string();
}

std::string capture_config(const CaptureState& state, const std::string& json_path) {
  std::ostringstream out;
  out << "{\n  \"description\": "
      << quoted("volgraph view's capture of " + state.config + " after " + std::to_string(state.frames) +
                " frames: the same image again with `" + capture_render_command(json_path, state) + "`")
      << ",\n  \"include\": " << quoted(include_path(state.config, json_path)) << ",\n  \"output\": { \"size\": ["
      << state.size.width << ", " << state.size.height << "] },\n  \"scene\": {\n    \"camera\": " << camera_json(state.camera);
  if (state.sun) out << ",\n    \"lights\": [ " << sun_json(*state.sun) << " ]";
  out << "\n  }";
  const std::map<std::string, PassAmendment> passes = amendments(state.overrides);
  if (!passes.empty()) out << ",\n  \"graph\": {\n    \"passes\": [" << passes_json(passes) << "\n    ]\n  }";
  out << "\n}\n";
  return out.str();
}

}  // namespace volgraph::viewer
