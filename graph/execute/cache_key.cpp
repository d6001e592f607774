#include "graph/execute/cache_key.h"

#include <string>

namespace volgraph {
namespace {

uint64_t mix(uint64_t h, uint64_t v) {  // FNV-1a, a 64-bit word at a time
  for (int i = 0; i < 8; ++i) h = (h ^ ((v >> (8 * i)) & 0xff)) * 0x100000001b3ull;
  return h;
}

uint64_t mix(uint64_t h, const std::string& s) {
  for (const char c : s) h = (h ^ uint8_t(c)) * 0x100000001b3ull;
  return mix(h, s.size());
}

}  // namespace

uint64_t pass_cache_key(const CacheKeyInputs& in) {
  const GraphPass& pass = *in.pass;
  uint64_t h = mix(0xcbf29ce484222325ull, pass.decl->name);
  h = mix(h, pass.variant);
  for (const ParamValue& v : pass.params) h = mix(h, param_value_text(v));
  h = mix(h, in.scene_hash);
  for (const uint64_t k : in.input_keys) h = mix(h, k);
  if (!pass.decl->frame_invariant) h = mix(h, in.frame + 1);
  return h;
}

}  // namespace volgraph
