// Line numbers for JSON pointers: nlohmann/json keeps no positions, so the loader
// scans the (already parsed, hence valid) text once and remembers where each value starts.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace volgraph {

using JsonLines = std::unordered_map<std::string, int>;

// Maps the JSON pointer of every value (and "" for the root) to its 1-based line;
// an object member maps to the line of its key.
JsonLines index_json_lines(std::string_view text);

// 1-based line of byte `offset` in `text`.
int line_of_offset(std::string_view text, size_t offset);

// A key an object of the (already parsed, hence valid) text repeats: nlohmann/json keeps
// the last silently, so the loader refuses it.
struct DuplicateKey {
  std::string pointer;  // of the repeated member
  std::string key;      // as written, escapes kept
  int line = 0, first_line = 0;
};
std::vector<DuplicateKey> duplicate_keys(std::string_view text);

// The byte offset of the first '[' or '{' (outside strings) that opens a level deeper
// than `max_depth`, checked before parsing so that no reader recurses that deep.
std::optional<size_t> too_deep_at(std::string_view text, int max_depth);

}  // namespace volgraph
