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

TEST(JsonLines, FindsEveryRepeatedKeyWithItsPointerAndBothLines) {
  const std::string text =
      "{\n"
      "  \"a\": 1,\n"
      "  \"b\": [{\"x\": 1, \"y\": 2,\n"
      "          \"x\": 3}],\n"
      "  \"a\": 2\n"
      "}\n";
  const std::vector<DuplicateKey> duplicates = duplicate_keys(text);
  ASSERT_EQ(duplicates.size(), 2u);
  EXPECT_EQ(duplicates[0].pointer, "/b/0/x");
  EXPECT_EQ(duplicates[0].line, 4);
  EXPECT_EQ(duplicates[0].first_line, 3);
  EXPECT_EQ(duplicates[1].pointer, "/a");
  EXPECT_EQ(duplicates[1].key, "a");
  EXPECT_EQ(duplicates[1].line, 5);
  EXPECT_EQ(duplicates[1].first_line, 2);
  EXPECT_TRUE(duplicate_keys(R"({"a": {"k": 1}, "b": {"k": 2}})").empty());  // one key in two objects
}

TEST(JsonLines, TooDeepIsTheOffsetOfTheFirstBracketPastTheLimit) {
  EXPECT_EQ(too_deep_at("[[[]]]", 3), std::nullopt);
  EXPECT_EQ(too_deep_at("[[[[]]]]", 3), std::optional<size_t>(3));
  EXPECT_EQ(too_deep_at(R"({"a": "[[[[[[", "b": [[]]})", 2), std::optional<size_t>(22));  // brackets in strings do not count
  EXPECT_EQ(too_deep_at(R"(["\"[[[", [[[]]]])", 3), std::optional<size_t>(12));  // nor after an escaped quote
  EXPECT_EQ(too_deep_at(std::string(50000, '[') + std::string(50000, ']'), 256), std::optional<size_t>(256));
}

}  // namespace
}  // namespace volgraph
