// Strict reading of JSON values with diagnostics. Internal to graph/config: it pulls
// in nlohmann/json, which must stay out of widely included headers.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "graph/diagnostics.h"
#include "graph/config/json_lines.h"

namespace volgraph::config {

using Json = nlohmann::ordered_json;

struct Source {
  std::string file;  // as named by the user (or the including file)
  std::string dir;   // folder that relative paths inside the file start from
  JsonLines lines;
};

// A JSON value, where it is, and the sink for what is wrong with it.
class Node {
 public:
  Node(const Source& source, const Json& json, std::string pointer, Diagnostics& diags)
      : source_(&source), json_(&json), pointer_(std::move(pointer)), diags_(&diags) {}

  const Json& json() const { return *json_; }
  const std::string& pointer() const { return pointer_; }
  const Source& source() const { return *source_; }
  Where where() const;
  void error(std::string message) const;

  // Whether this is an object; reports keys not in `allowed`, with a suggestion.
  bool object(std::initializer_list<const char*> allowed) const;
  bool object_any_keys() const;
  bool array() const;
  std::optional<Node> member(const char* key) const;
  Node child(const std::string& key) const;
  Node element(size_t index) const;
  size_t size() const { return json_->size(); }

  std::optional<double> number(double min, double max) const;
  std::optional<int64_t> integer(int64_t min, int64_t max) const;
  std::optional<bool> boolean() const;
  std::optional<std::string> string() const;
  std::optional<std::array<double, 3>> vec3(double min, double max) const;
  // A path relative to the file's folder; checks the file exists.
  std::optional<std::string> existing_path() const;

 private:
  const Source* source_;
  const Json* json_;
  std::string pointer_;
  Diagnostics* diags_;
};

// Why `path` cannot be read as a file ("" when it can): "no such file", "is a directory",
// "not a regular file" (a FIFO, a device: never opened, it could block), "permission denied".
std::string file_problem(const std::string& path);

// Nesting of arrays and objects in one file: far deeper than any config needs, shallow
// enough that no reader of the document recurses near the stack's end.
constexpr int kMaxJsonDepth = 256;

// Reads the file at `path` into `out`: "" when it could, else why not (file_problem's
// words, "cannot open it", "read error").
std::string read_text_file(const std::string& path, std::string& out);

// `text` (the file `path`) as one JSON document, refused as every volgraph file is: a NUL
// byte (nlohmann/json would end the input there), nesting deeper than kMaxJsonDepth
// (checked before parsing), invalid JSON (at its line) and each repeated key (nlohmann
// keeps the last silently) — one diagnostic each, and nullopt.
std::optional<Json> parse_json_document(const std::string& path, const std::string& text, Diagnostics& diags);

// A pass or parameter name: a letter or '_', then letters, digits and '_'.
bool valid_name(const std::string& name);

std::string describe(const Json& j);  // "a string \"x\"", "an object", ... for messages
std::string range_text(double min, double max);

// Reads member `key` into `out` when present (leaves it unchanged when absent or bad).
void read(const Node& obj, const char* key, double& out, double min, double max);
void read(const Node& obj, const char* key, std::array<double, 3>& out, double min, double max);
void read(const Node& obj, const char* key, bool& out);
void read(const Node& obj, const char* key, std::string& out);

}  // namespace volgraph::config
