// Typed handles to a pass type's parameters: an index into its declaration's params
// (PassDecl::params), typed by the parameter's value. Apart from graph/pass_decl.h so
// that SizeSpec (graph/resource.h) can name the parameters a size is made of.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace volgraph {

template <typename T>  // bool, int64_t, double, std::array<double, 3>, std::string (a choice)
struct ParamHandle {
  uint16_t index = 0;
};

// A choice parameter read as the pass's own enum: each choice's value and name, stated
// once in the table, so an execution compares values, never names.
template <typename Enum>
struct ChoiceHandle {
  ParamHandle<std::string> text;
  std::vector<std::pair<Enum, std::string>> choices;
  Enum value_of(const std::string& name) const {
    for (const auto& [value, choice_name] : choices) {
      if (choice_name == name) return value;
    }
    throw std::logic_error("no choice named " + name);  // the loader accepts only declared choices
  }
};

}  // namespace volgraph
