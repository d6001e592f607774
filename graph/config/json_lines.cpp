#include "graph/config/json_lines.h"

#include <map>
#include <string>

namespace volgraph {
namespace {

// Escapes a key as a JSON pointer reference token (RFC 6901).
std::string pointer_token(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  JsonLines run() {
    skip_space();
    value("");
    return std::move(lines_);
  }

  std::vector<DuplicateKey> duplicates() {
    run();
    return std::move(duplicates_);
  }

 private:
  void skip_space() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') ++line_;
      if (c != ' ' && c != '\n' && c != '\r' && c != '\t') return;
      ++pos_;
    }
  }

  // Reads a string literal; returns its raw contents (escapes other than \" and \\ kept).
  std::string string_literal() {
    std::string out;
    ++pos_;  // opening quote
    while (pos_ < text_.size() && text_[pos_] != '"') {
      if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) {
        ++pos_;
        const char e = text_[pos_];
        out += (e == '"' || e == '\\' || e == '/') ? e : '\\';
        if (e != '"' && e != '\\' && e != '/') out += e;
      } else {
        out += text_[pos_];
      }
      ++pos_;
    }
    ++pos_;  // closing quote
    return out;
  }

  void value(const std::string& pointer) {
    lines_.emplace(pointer, line_);
    if (pos_ >= text_.size()) return;
    const char c = text_[pos_];
    if (c == '{') return object(pointer);
    if (c == '[') return array(pointer);
    if (c == '"') {
      string_literal();
      return;
    }
    while (pos_ < text_.size() && text_[pos_] != ',' && text_[pos_] != '}' && text_[pos_] != ']' &&
           text_[pos_] != ' ' && text_[pos_] != '\n' && text_[pos_] != '\r' && text_[pos_] != '\t') {
      ++pos_;
    }
  }

  void object(const std::string& pointer) {
    ++pos_;
    skip_space();
    std::map<std::string, int> seen;  // key → its line
    while (pos_ < text_.size() && text_[pos_] != '}') {
      const int key_line = line_;
      const std::string name = string_literal();
      const std::string key = pointer + "/" + pointer_token(name);
      if (const auto [it, fresh] = seen.emplace(name, key_line); !fresh) {
        duplicates_.push_back({key, name, key_line, it->second});
      }
      skip_space();
      ++pos_;  // colon
      skip_space();
      value(key);
      lines_[key] = key_line;
      skip_space();
      if (pos_ < text_.size() && text_[pos_] == ',') ++pos_;
      skip_space();
    }
    ++pos_;
  }

  void array(const std::string& pointer) {
    ++pos_;
    skip_space();
    for (size_t i = 0; pos_ < text_.size() && text_[pos_] != ']'; ++i) {
      value(pointer + "/" + std::to_string(i));
      skip_space();
      if (pos_ < text_.size() && text_[pos_] == ',') ++pos_;
      skip_space();
    }
    ++pos_;
  }

  std::string_view text_;
  size_t pos_ = 0;
  int line_ = 1;
  JsonLines lines_;
  std::vector<DuplicateKey> duplicates_;
};

}  // namespace

JsonLines index_json_lines(std::string_view text) { return Scanner(text).run(); }

int line_of_offset(std::string_view text, size_t offset) {
  int line = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

std::vector<DuplicateKey> duplicate_keys(std::string_view text) { return Scanner(text).duplicates(); }

std::optional<size_t> too_deep_at(std::string_view text, int max_depth) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    else if (c == '[' || c == '{') {
      if (++depth > max_depth) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return std::nullopt;
}

}  // namespace volgraph
