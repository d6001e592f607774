// Errors in user input: which file, where in it (JSON pointer, line), what was expected.
#pragma once

#include <exception>
#include <string>
#include <string_view>
#include <vector>

namespace volgraph {

struct Where {
  std::string file;     // as the user named it; "<command line>" for flags
  std::string pointer;  // JSON pointer, "" for the whole document
  int line = 0;         // 1-based; 0 when unknown
};

struct Diagnostic {
  Where where;
  std::string message;
};

// "file:line: error at /pointer: message".
std::string format_diagnostic(const Diagnostic& d);
// The same with "warning" for what is accepted but not done as asked.
std::string format_warning(const Diagnostic& d);

// Thrown when input is invalid; carries every diagnostic found before giving up.
class ConfigError : public std::exception {
 public:
  explicit ConfigError(std::vector<Diagnostic> diagnostics);
  const char* what() const noexcept override { return text_.c_str(); }
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
  std::string text_;
};

// Collects diagnostics while loading; throws the errors together at a checkpoint and
// keeps the warnings (input accepted, but not drawn as it asks) for the caller to show.
class Diagnostics {
 public:
  void error(Where where, std::string message);
  void warning(Where where, std::string message);
  bool empty() const { return list_.empty(); }
  void throw_if_any() const;
  const std::vector<Diagnostic>& warnings() const { return warnings_; }

 private:
  std::vector<Diagnostic> list_;
  std::vector<Diagnostic> warnings_;
};

// " (did you mean \"x\"?)" when a candidate is close to `word`, else "".
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);
// "one of a, b, c" for messages that list what is allowed.
std::string one_of(const std::vector<std::string>& candidates);

}  // namespace volgraph
