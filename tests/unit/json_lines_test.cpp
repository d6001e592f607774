#include "graph/config/json_lines.h"

#include <gtest/gtest.h>

namespace volgraph {
namespace {

TEST(JsonLines, MapsPointersToLinesOfKeysAndElements) {
  const std::string text =
      "{\n"
      "  \"a\": 1,\n"
      "  \"b\": {\n"
      "    \"c/d\": [10,\n"
      "      20, {\"e~\": \"x\\\"y\"}]\n"
      "  }\n"
      "}\n";
  const JsonLines lines = index_json_lines(text);
  EXPECT_EQ(lines.at(""), 1);
  EXPECT_EQ(lines.at("/a"), 2);
  EXPECT_EQ(lines.at("/b"), 3);
  EXPECT_EQ(lines.at("/b/c~1d"), 4);
  EXPECT_EQ(lines.at("/b/c~1d/0"), 4);
  EXPECT_EQ(lines.at("/b/c~1d/1"), 5);
  EXPECT_EQ(lines.at("/b/c~1d/2/e~0"), 5);
}

TEST(JsonLines, LineOfOffsetCountsNewlines) {
  EXPECT_EQ(line_of_offset("a\nb\nc", 0), 1);
  EXPECT_EQ(line_of_offset("a\nb\nc", 2), 2);
  EXPECT_EQ(line_of_offset("a\nb\nc", 4), 3);
}

}  // namespace
}  // namespace volgraph
