// Line numbers for JSON pointers: nlohmann/json keeps no positions, so the loader
// scans the (already parsed, hence valid) text once and remembers where each value starts.
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>

namespace volgraph {

using JsonLines = std::unordered_map<std::string, int>;

// Maps the JSON pointer of every value (and "" for the root) to its 1-based line;
// an object member maps to the line of its key.
JsonLines index_json_lines(std::string_view text);

// 1-based line of byte `offset` in `text`.
int line_of_offset(std::string_view text, size_t offset);

}  // namespace volgraph
