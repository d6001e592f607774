#include "graph/diagnostics.h"

#include <algorithm>
#include <numeric>

namespace volgraph {
namespace {

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

namespace {

std::string format_as(const Diagnostic& d, const char* severity) {
  std::string out = d.where.file;
  if (d.where.line > 0) out += ":" + std::to_string(d.where.line);
  out += std::string(": ") + severity;
  if (!d.where.pointer.empty()) out += " at " + d.where.pointer;
  return out + ": " + d.message;
}

}  // namespace

std::string format_diagnostic(const Diagnostic& d) { return format_as(d, "error"); }

std::string format_warning(const Diagnostic& d) { return format_as(d, "warning"); }

ConfigError::ConfigError(std::vector<Diagnostic> diagnostics) : diagnostics_(std::move(diagnostics)) {
  for (const Diagnostic& d : diagnostics_) {
    if (!text_.empty()) text_ += '\n';
    text_ += format_diagnostic(d);
  }
}

void Diagnostics::error(Where where, std::string message) { list_.push_back({std::move(where), std::move(message)}); }

void Diagnostics::warning(Where where, std::string message) { warnings_.push_back({std::move(where), std::move(message)}); }

void Diagnostics::throw_if_any() const {
  if (!list_.empty()) throw ConfigError(list_);
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string* best = nullptr;
  size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    const size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = &c;
    }
  }
  return best ? " (did you mean \"" + *best + "\"?)" : "";
}

std::string one_of(const std::vector<std::string>& candidates) {
  std::string out = "one of ";
  for (size_t i = 0; i < candidates.size(); ++i) out += (i ? ", " : "") + candidates[i];
  return out;
}

}  // namespace volgraph
