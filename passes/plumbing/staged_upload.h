// A transfer pass's texels copied into its output texture through a staging buffer of its
// own, remade only when the size changes (cloud_phase_table, cloud_weather_map, volume_file,
// transfer_table: cached passes that record when their source changes).
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "graph/execute/pass_execution.h"

namespace volgraph::plumbing {

class StagedUpload {
 public:
  // Writes `bytes` to the staging buffer and records their copy into `texture` (the whole of
  // it: the bytes are its texels, rows tightly packed).
  void record(PassContext& c, std::span<const std::byte> bytes, rhi::TextureId texture) {
    if (staging_bytes_ != bytes.size()) {
      staging_ = c.device.create_buffer({c.name() + " texels", bytes.size(), rhi::buffer_usage::copy_src | rhi::buffer_usage::copy_dst});
      staging_bytes_ = bytes.size();
    }
    c.device.write_buffer(staging_, 0, bytes);
    c.encoder.copy_buffer_to_texture(staging_, 0, texture);
  }

 private:
  rhi::BufferId staging_;
  size_t staging_bytes_ = 0;
};

}  // namespace volgraph::plumbing
