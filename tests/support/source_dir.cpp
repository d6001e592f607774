#include "tests/support/source_dir.h"

namespace volgraph::testing {

const std::string& source_dir() {
  static const std::string dir = VOLGRAPH_SOURCE_DIR;
  return dir;
}

}  // namespace volgraph::testing
