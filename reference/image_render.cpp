#include "reference/image_render.h"

#include <atomic>
#include <mutex>
#include <system_error>
#include <thread>

namespace volgraph::reference {
namespace {

// Prints the percentage of rows done when it changes; safe to call from any thread.
class Progress {
 public:
  Progress(std::ostream* out, uint32_t rows) : out_(out), rows_(rows) {}
  void row_done() {
    const uint32_t done = ++done_;
    if (!out_) return;
    const int percent = int(uint64_t(done) * 100 / rows_);
    std::lock_guard lock(mutex_);
    if (percent == shown_) return;
    shown_ = percent;
    *out_ << "\rreference: " << percent << " %" << (done == rows_ ? "\n" : "") << std::flush;
  }

 private:
  std::ostream* out_;
  uint32_t rows_;
  std::atomic<uint32_t> done_{0};
  std::mutex mutex_;
  int shown_ = -1;
};

void render_rows(const std::function<Vec3(uint32_t, uint32_t)>& pixel, const RenderSettings& s,
                 std::atomic<uint32_t>& next_row, Progress& progress, ReferenceImage& image) {
  for (uint32_t j = next_row++; j < s.height; j = next_row++) {
    for (uint32_t i = 0; i < s.width; ++i) {
      const Vec3 l = pixel(i, j);
      std::copy(l.begin(), l.end(), image.rgb.begin() + ptrdiff_t((size_t(j) * s.width + i) * 3));
    }
    progress.row_done();
  }
}

}  // namespace

ReferenceImage render_image(const Renderer& renderer, const RenderSettings& settings) {
  return render_pixels(
      [&](uint32_t i, uint32_t j) {
        return renderer.pixel_radiance(i, j, settings.width, settings.height, settings.samples_per_axis);
      },
      settings);
}

ReferenceImage render_pixels(const std::function<Vec3(uint32_t, uint32_t)>& pixel, const RenderSettings& settings) {
  ReferenceImage image{settings.width, settings.height, std::vector<double>(size_t(settings.width) * settings.height * 3)};
  const unsigned threads = std::max(1u, settings.threads ? settings.threads : std::thread::hardware_concurrency());
  std::atomic<uint32_t> next_row{0};
  Progress progress(settings.progress, settings.height);
  std::vector<std::thread> workers;
  for (unsigned t = 1; t < threads; ++t) {
    try {
      workers.emplace_back([&] { render_rows(pixel, settings, next_row, progress, image); });
    } catch (const std::system_error&) {  // the system gives no more threads: render with those it gave
      break;
    }
  }
  render_rows(pixel, settings, next_row, progress, image);
  for (std::thread& w : workers) w.join();
  return image;
}

}  // namespace volgraph::reference
