// A sweep spread over machines: the job list (one shell command a point, for GNU
// parallel or a Slurm array) and the merge of the point files the jobs wrote.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

#include "tools/compare/sweep_results.h"
#include "tools/output_files.h"

namespace volgraph::compare {
namespace {

using Json = nlohmann::ordered_json;

// One point file found by the merge.
struct Copy {
  PointResult result;
  std::string text;  // as save_point writes it: what "identical" compares
  std::string dir;
};

std::vector<std::filesystem::path> point_files(const std::string& dir) {
  check_points_folder(dir);
  const std::filesystem::path folder = std::filesystem::path(dir) / "points";
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && entry.path().extension() == ".json" && name.find(".tmp-") == std::string::npos &&
        name.front() != '.') {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string same_folder_key(const std::string& dir) {
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(dir, ec);
  return ec ? dir : canonical.string();
}

// The dirs to read, each once, `out` last.
std::vector<std::string> merge_inputs(const std::vector<std::string>& dirs, const std::string& out) {
  std::vector<std::string> inputs;
  std::set<std::string> seen;
  for (const std::string& dir : dirs) {
    if (!std::filesystem::is_directory(dir)) throw std::runtime_error(dir + ": not a sweep folder (no such folder)");
    if (seen.insert(same_folder_key(dir)).second) inputs.push_back(dir);
  }
  if (seen.insert(same_folder_key(out)).second) inputs.push_back(out);
  return inputs;
}

// Every copy worth keeping: one per id and device, the first dir's when copies differ.
std::vector<Copy> gather(const std::vector<std::string>& inputs) {
  std::vector<Copy> kept;
  std::map<std::pair<std::string, std::string>, size_t> by_id_device;
  for (const std::string& dir : inputs) {
    for (const auto& file : point_files(dir)) {
      PointResult result = read_point_file(file);
      result.pareto = false;
      Copy copy{result, point_result_json(result), dir};
      const auto key = std::make_pair(result.id, result.device);
      const auto found = by_id_device.find(key);
      if (found == by_id_device.end()) {
        by_id_device.emplace(key, kept.size());
        kept.push_back(std::move(copy));
        continue;
      }
      const Copy& first = kept[found->second];
      if (first.text != copy.text) {
        std::cerr << "volgraph sweep --merge: point " << result.id << " on '" << result.device << "' differs between "
                  << first.dir << " and " << dir << "; kept " << first.dir << "'s\n";
      }
    }
  }
  return kept;
}

// The file name of each kept copy: the id, or id@device-hash when the id has several devices.
std::vector<std::string> stems_of(const std::vector<Copy>& kept) {
  std::map<std::string, int> devices_per_id;
  for (const Copy& c : kept) ++devices_per_id[c.result.id];
  std::vector<std::string> stems;
  std::set<std::string> taken;
  for (const Copy& c : kept) {
    const bool shared = devices_per_id[c.result.id] > 1;
    const std::string stem = shared ? c.result.id + "@" + device_hash(c.result.device) : c.result.id;
    if (!taken.insert(stem).second) {
      throw std::runtime_error("point " + c.result.id + ": two devices with one hash (" + stem + "); merge them apart");
    }
    stems.push_back(stem);
  }
  return stems;
}

SweepSpec spec_of_results(const std::vector<PointResult>& results) {
  SweepSpec spec;
  for (const PointResult& r : results) {
    if (is_metric_name(r.metric)) {
      spec.metric = r.metric;
      break;
    }
  }
  return spec;
}

}  // namespace

void write_jobs(const std::string& dir, const SweepSpec& spec,
                const std::function<std::string(const SweepPoint&)>& command_for) {
  std::string jobs;
  Json points = Json::array();
  for (const SweepPoint& point : spec.points) {
    const std::string command = command_for(point);
    if (command.find_first_of("\r\n") != std::string::npos) {
      throw std::invalid_argument("point " + point.id +
                                  ": its command has a line break; jobs.txt takes one command a line");
    }
    jobs += command + "\n";
    points.push_back(Json{{"id", point.id}, {"label", point.label}, {"series", point.series}, {"command", command}});
  }
  const Json manifest{{"spec", spec.file},           {"config", spec.config}, {"metric", spec.metric},
                      {"count", spec.points.size()}, {"jobs", "jobs.txt"},    {"points", points}};
  std::filesystem::create_directories(dir);
  const std::filesystem::path folder(dir);
  OutputFiles files;
  files.stage((folder / "jobs.txt").string(), "-o", text_bytes(jobs));
  files.stage((folder / "manifest.json").string(), "-o", text_bytes(manifest.dump(2) + "\n"));
  files.commit();
}

void merge_results(const std::vector<std::string>& dirs, const std::string& out, const SweepSpec* spec) {
  std::filesystem::create_directories(out);
  const std::vector<Copy> kept = gather(merge_inputs(dirs, out));
  const std::vector<std::string> stems = stems_of(kept);
  const std::vector<std::filesystem::path> before = point_files(out);
  for (size_t i = 0; i < kept.size(); ++i) save_point_as(out, stems[i], kept[i].result);
  const std::set<std::string> now(stems.begin(), stems.end());
  for (const auto& file : before) {
    std::error_code ec;
    if (!now.count(file.stem().string())) std::filesystem::remove(file, ec);  // its copy is now under <id>@<hash>
  }
  std::vector<PointResult> results = read_results(out);
  write_aggregates(out, spec ? *spec : spec_of_results(results), std::move(results));
}

}  // namespace volgraph::compare
