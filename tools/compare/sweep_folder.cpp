// A sweep folder's identity (sweep_folder.h): recorded by the first run, checked by every
// later run, job, tune and merge, so that one folder never mixes two sweeps' points.
#include "tools/compare/sweep_folder.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "graph/diagnostics.h"
#include "tools/output_files.h"

namespace volgraph::compare {
namespace {

namespace fs = std::filesystem;

const char* const kIdentityFile = "sweep_settings.txt";

[[noreturn]] void refuse(const std::string& dir, const std::string& message) {
  throw ConfigError({{{"<command line>", dir, 0}, message}});
}

// "key value" lines as a map, in file order lost (the keys are few and fixed).
std::map<std::string, std::string> identity_fields(const std::string& text) {
  std::map<std::string, std::string> fields;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const size_t space = line.find(' ');
    fields[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
  }
  return fields;
}

bool holds_points(const std::string& dir) {
  std::error_code ec;
  const fs::path points = fs::path(dir) / "points";
  if (!fs::is_directory(points, ec)) return false;
  for (const auto& entry : fs::directory_iterator(points, ec)) {
    if (entry.path().extension() == ".json") return true;
  }
  return false;
}

std::string identity_file(const std::string& dir) { return (fs::path(dir) / kIdentityFile).string(); }

}  // namespace

std::string sweep_identity_text(const SweepSpec& spec) {
  std::ostringstream o;
  o << "spec " << canonical_path_text(spec.file) << "\nconfig " << canonical_path_text(spec.config) << "\nsize " << spec.size.width << "x"
    << spec.size.height << "\nruns " << spec.runs << "\nwarmup " << spec.warmup << "\nframes " << spec.frames << "\nbackend "
    << spec.backend << "\nreference " << (spec.reference == "cpu" ? spec.reference : canonical_path_text(spec.reference))
    << (spec.reference_mode == "straight" ? "" : " " + spec.reference_mode) << "\nmetric "
    << spec.metric << "\nmask " << spec.mask << "\n";
  return o.str();
}

std::optional<std::string> read_sweep_identity(const std::string& dir) {
  const std::string file = identity_file(dir);
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (!fs::exists(status)) {
    if (holds_points(dir)) refuse(dir, "holds sweep points but no " + file + "; expected a folder that volgraph sweep wrote");
    return std::nullopt;
  }
  if (!fs::is_regular_file(status)) refuse(dir, file + " is not a file; expected the sweep's settings");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  if (!(in && text << in.rdbuf()) && fs::file_size(file, ec) != 0) refuse(dir, file + ": cannot be read");
  if (text.str().empty()) {  // a write that failed half-way: no identity, unless points depend on it
    if (holds_points(dir)) refuse(dir, file + " is empty; expected the settings of the sweep whose points the folder holds");
    return std::nullopt;
  }
  if (!identity_fields(text.str()).count("spec")) {
    refuse(dir, file + " names no spec (a folder of an older volgraph); expected a folder of one sweep: start an empty one");
  }
  return text.str();
}

std::string identity_difference(const std::string& held, const std::string& now) {
  const auto a = identity_fields(held), b = identity_fields(now);
  std::string out;
  for (const char* key : {"spec", "config", "size", "runs", "warmup", "frames", "backend", "reference", "metric", "mask"}) {
    const auto x = a.find(key), y = b.find(key);
    const std::string first = x == a.end() ? "(none)" : x->second, second = y == b.end() ? "(none)" : y->second;
    if (first != second) out += (out.empty() ? "" : ", ") + std::string(key) + " " + first + " against " + second;
  }
  return out;
}

void claim_sweep_folder(const SweepSpec& spec, const std::string& dir) {
  const std::string now = sweep_identity_text(spec);
  const std::optional<std::string> held = read_sweep_identity(dir);
  if (!held) {
    OutputFiles out;  // whole or not at all: a full disk leaves no empty file to block the rerun
    out.stage(identity_file(dir), "-o", text_bytes(now));
    out.commit();
    return;
  }
  if (*held == now) return;
  refuse(dir, "holds the points of a sweep measured with other settings (" + identity_file(dir) + ": the folder's " +
                  identity_difference(*held, now) + " this command's); expected an empty folder or the same spec, size, runs, backend and reference");
}

std::string common_sweep_identity(const std::vector<std::string>& dirs, const std::string& out, const SweepSpec* spec) {
  std::string identity, whose;
  if (spec) identity = sweep_identity_text(*spec), whose = "SPEC " + spec->file;
  auto take = [&](const std::string& dir, bool must_be_sweep) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
      if (must_be_sweep) refuse(dir, "not a sweep folder (no such folder)");
      return;
    }
    const std::optional<std::string> held = read_sweep_identity(dir);
    if (!held) {
      if (must_be_sweep) refuse(dir, "not a sweep folder (no " + identity_file(dir) + "); expected a folder that volgraph sweep wrote");
      return;
    }
    if (identity.empty()) {
      identity = *held, whose = dir;
      return;
    }
    if (*held != identity) {
      refuse(dir, "holds another sweep than " + whose + " (" + whose + "'s " + identity_difference(identity, *held) + " " + dir +
                      "'s); a merge takes the folders of one spec and settings");
    }
  };
  for (const std::string& dir : dirs) take(dir, true);
  take(out, false);
  return identity;
}

SweepSpec spec_of_identity(const std::string& identity) {
  const auto fields = identity_fields(identity);
  auto field = [&](const char* key) {
    const auto found = fields.find(key);
    return found == fields.end() ? std::string() : found->second;
  };
  SweepSpec spec;
  spec.file = field("spec");
  spec.config = field("config");
  unsigned width = 0, height = 0;
  if (std::sscanf(field("size").c_str(), "%ux%u", &width, &height) == 2) spec.size = {width, height, 1};
  auto number = [&](const char* key, int fallback) {
    try {
      return std::stoi(field(key));
    } catch (const std::exception&) {
      return fallback;
    }
  };
  spec.runs = number("runs", spec.runs);
  spec.warmup = number("warmup", spec.warmup);
  spec.frames = number("frames", spec.frames);
  if (!field("backend").empty()) spec.backend = field("backend");
  if (!field("reference").empty()) spec.reference = field("reference");
  if (!field("metric").empty()) spec.metric = field("metric");
  if (!field("mask").empty()) spec.mask = field("mask");
  return spec;
}

}  // namespace volgraph::compare
