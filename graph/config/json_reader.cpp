#include "graph/config/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <unistd.h>

namespace volgraph::config {
namespace {

std::string number_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

std::string file_problem(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) return "no such file";
  if (std::filesystem::is_directory(status)) return "is a directory";
  if (!std::filesystem::is_regular_file(status)) return "not a regular file";
  if (::access(path.c_str(), R_OK) != 0) return "permission denied";
  return "";
}

std::string describe(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return j.get<bool>() ? "true" : "false";
    case Json::value_t::string: return "the string " + j.dump();
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "the number " + j.dump();
    case Json::value_t::array: return "an array of " + std::to_string(j.size());
    case Json::value_t::object: return "an object";
    default: return "an unsupported value";
  }
}

std::string range_text(double min, double max) { return "[" + number_text(min) + ", " + number_text(max) + "]"; }

Where Node::where() const {
  const auto it = source_->lines.find(pointer_);
  return {source_->file, pointer_.empty() ? "/" : pointer_, it == source_->lines.end() ? 0 : it->second};
}

void Node::error(std::string message) const { diags_->error(where(), std::move(message)); }

bool Node::object_any_keys() const {
  if (json_->is_object()) return true;
  error("expected an object, got " + describe(*json_));
  return false;
}

bool Node::object(std::initializer_list<const char*> allowed) const {
  if (!object_any_keys()) return false;
  std::vector<std::string> names(allowed.begin(), allowed.end());
  for (const auto& item : json_->items()) {
    const std::string& key = item.key();
    if (std::find(names.begin(), names.end(), key) != names.end()) continue;
    child(key).error("unknown key \"" + key + "\"" + did_you_mean(key, names) + "; expected " + one_of(names));
  }
  return true;  // the known keys are still read, so one run reports every mistake
}

bool Node::array() const {
  if (json_->is_array()) return true;
  error("expected an array, got " + describe(*json_));
  return false;
}

std::optional<Node> Node::member(const char* key) const {
  if (!json_->is_object()) return std::nullopt;
  const auto it = json_->find(key);
  if (it == json_->end()) return std::nullopt;
  return child(key);
}

Node Node::child(const std::string& key) const {
  std::string token;
  for (char c : key) token += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
  return Node(*source_, json_->at(key), pointer_ + "/" + token, *diags_);
}

Node Node::element(size_t index) const {
  return Node(*source_, json_->at(index), pointer_ + "/" + std::to_string(index), *diags_);
}

std::optional<double> Node::number(double min, double max) const {
  if (!json_->is_number()) {
    error("expected a number in " + range_text(min, max) + ", got " + describe(*json_));
    return std::nullopt;
  }
  const double v = json_->get<double>();
  if (!std::isfinite(v) || v < min || v > max) {
    error("expected a number in " + range_text(min, max) + ", got " + json_->dump());
    return std::nullopt;
  }
  return v;
}

std::optional<int64_t> Node::integer(int64_t min, int64_t max) const {
  const bool integral = json_->is_number_integer() ||
                        (json_->is_number_float() && std::floor(json_->get<double>()) == json_->get<double>());
  if (!integral) {
    error("expected an integer in " + range_text(double(min), double(max)) + ", got " + describe(*json_));
    return std::nullopt;
  }
  const double v = json_->get<double>();
  if (!(v >= double(min) && v <= double(max))) {
    error("expected an integer in " + range_text(double(min), double(max)) + ", got " + json_->dump());
    return std::nullopt;
  }
  return static_cast<int64_t>(v);
}

std::optional<bool> Node::boolean() const {
  if (json_->is_boolean()) return json_->get<bool>();
  error("expected true or false, got " + describe(*json_));
  return std::nullopt;
}

std::optional<std::string> Node::string() const {
  if (json_->is_string()) return json_->get<std::string>();
  error("expected a string, got " + describe(*json_));
  return std::nullopt;
}

std::optional<std::array<double, 3>> Node::vec3(double min, double max) const {
  const bool shape = json_->is_array() && json_->size() == 3 && (*json_)[0].is_number() &&
                     (*json_)[1].is_number() && (*json_)[2].is_number();
  if (!shape) {
    error("expected an array of 3 numbers in " + range_text(min, max) + ", got " + describe(*json_));
    return std::nullopt;
  }
  std::array<double, 3> v{};
  for (size_t i = 0; i < 3; ++i) {
    const auto x = element(i).number(min, max);
    if (!x) return std::nullopt;
    v[i] = *x;
  }
  return v;
}

std::optional<std::string> Node::existing_path() const {
  const auto text = string();
  if (!text) return std::nullopt;
  if (text->empty()) {
    error("expected a file path, got an empty string");
    return std::nullopt;
  }
  const std::filesystem::path p = std::filesystem::path(source_->dir) / *text;
  if (const std::string problem = file_problem(p.string()); !problem.empty()) {
    const std::string what = problem == "no such file" ? "file not found" : problem;
    error(what + ": \"" + *text + "\" (looked for " + p.lexically_normal().string() + ")");
    return std::nullopt;
  }
  return p.lexically_normal().string();
}

void read(const Node& obj, const char* key, double& out, double min, double max) {
  if (auto n = obj.member(key)) {
    if (auto v = n->number(min, max)) out = *v;
  }
}

void read(const Node& obj, const char* key, std::array<double, 3>& out, double min, double max) {
  if (auto n = obj.member(key)) {
    if (auto v = n->vec3(min, max)) out = *v;
  }
}

void read(const Node& obj, const char* key, bool& out) {
  if (auto n = obj.member(key)) {
    if (auto v = n->boolean()) out = *v;
  }
}

void read(const Node& obj, const char* key, std::string& out) {
  if (auto n = obj.member(key)) {
    if (auto v = n->string()) out = *v;
  }
}

std::string read_text_file(const std::string& path, std::string& out) {
  if (std::string problem = file_problem(path); !problem.empty()) return problem;
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot open it";
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) return "read error";
  out = s.str();
  return "";
}

namespace {

// nlohmann's message without its "[json.exception.parse_error.101] " prefix.
std::string json_message(const std::exception& e) {
  const std::string msg = e.what();
  const size_t close = msg.find("] ");
  return close == std::string::npos ? msg : msg.substr(close + 2);
}

}  // namespace

std::optional<Json> parse_json_document(const std::string& path, const std::string& text, Diagnostics& diags) {
  if (const size_t nul = text.find('\0'); nul != std::string::npos) {
    diags.error({path, "", line_of_offset(text, nul)}, "a NUL byte at offset " + std::to_string(nul) + "; expected JSON text");
    return std::nullopt;
  }
  if (const std::optional<size_t> deep = too_deep_at(text, kMaxJsonDepth)) {
    diags.error({path, "", line_of_offset(text, *deep)}, "arrays and objects nest deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return std::nullopt;
  }
  Json json;
  try {
    json = Json::parse(text);
  } catch (const Json::parse_error& e) {
    diags.error({path, "", line_of_offset(text, e.byte > 0 ? e.byte - 1 : 0)}, "invalid JSON: " + json_message(e));
    return std::nullopt;
  } catch (const Json::exception& e) {  // e.g. a number too large for a double
    diags.error({path, "", 0}, "invalid JSON: " + json_message(e));
    return std::nullopt;
  }
  const std::vector<DuplicateKey> duplicates = duplicate_keys(text);
  for (const DuplicateKey& d : duplicates) {
    diags.error({path, d.pointer, d.line},
                "duplicate key \"" + d.key + "\" (first at line " + std::to_string(d.first_line) + "); keys must be unique");
  }
  if (!duplicates.empty()) return std::nullopt;
  return json;
}

bool valid_name(const std::string& name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  return std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

}  // namespace volgraph::config
