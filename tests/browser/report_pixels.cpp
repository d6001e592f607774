// Pixel checks on screenshots of report.html (check_report.sh): that a box of the page
// shows given images split at a given place (and magnified about its centre), that a box is not blank, and that two
// screenshots differ in a box. Boxes are "x,y,w,h" in screenshot pixels, as the page
// logs them. Exit 0 when the check holds, 1 with a message when it does not, 2 on bad
// arguments or unreadable files.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <vector>

#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace {

struct Picture {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // 3 bytes a pixel, row 0 at the top

  const unsigned char* at(int x, int y) const { return &rgb[3 * (size_t(y) * width + x)]; }
};

struct Box {
  int x = 0, y = 0, w = 0, h = 0;
};

std::optional<Picture> load(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!data) {
    std::fprintf(stderr, "report_pixels: cannot read %s: %s\n", path.c_str(), stbi_failure_reason());
    return std::nullopt;
  }
  Picture picture{w, h, std::vector<unsigned char>(data, data + size_t(w) * h * 3)};
  stbi_image_free(data);
  return picture;
}

std::optional<Box> parse_box(const std::string& text, const Picture& shot) {
  Box box;
  if (std::sscanf(text.c_str(), "%d,%d,%d,%d", &box.x, &box.y, &box.w, &box.h) != 4 || box.w <= 0 || box.h <= 0) {
    std::fprintf(stderr, "report_pixels: \"%s\" is not a box x,y,w,h\n", text.c_str());
    return std::nullopt;
  }
  if (box.x < 0 || box.y < 0 || box.x + box.w > shot.width || box.y + box.h > shot.height) {
    std::fprintf(stderr, "report_pixels: box %s lies outside the %dx%d screenshot (make the window larger)\n", text.c_str(),
                 shot.width, shot.height);
    return std::nullopt;
  }
  return box;
}

std::optional<double> parse_number(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') {
    std::fprintf(stderr, "report_pixels: \"%s\" is not a number\n", text.c_str());
    return std::nullopt;
  }
  return value;
}

bool close(const unsigned char* a, const unsigned char* b, int tolerance) {
  for (int c = 0; c < 3; ++c) {
    if (std::abs(int(a[c]) - int(b[c])) > tolerance) return false;
  }
  return true;
}

// Whether the screenshot pixel shows source pixel (x, y), or, where the page shrinks the
// image (nearest-neighbour sampling may round either way), one of its neighbours.
bool shows(const unsigned char* got, const Picture& source, int x, int y, bool shrunk) {
  constexpr int kTolerance = 8;
  const int reach = shrunk ? 1 : 0;
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      const int sx = std::clamp(x + dx, 0, source.width - 1), sy = std::clamp(y + dy, 0, source.height - 1);
      if (close(got, source.at(sx, sy), kTolerance)) return true;
    }
  }
  return false;
}

// Samples a grid of screenshot pixels in the box: each should show the pixel of the
// left image (left of the split) or the right one that it covers when the image is
// stretched over the box and magnified `zoom` times about the box's centre. Pixels
// next to an image pixel's edge (closer than 1.5 screen pixels or a quarter of an image
// pixel) or the split line are skipped (rounding of the scaling); 95 % of the rest
// must match within 8/255.
int check_match(const Picture& shot, const Box& box, const Picture& left, const Picture& right, double split, double zoom) {
  constexpr int kGrid = 48;
  constexpr double kMatchedShare = 0.95;
  int sampled = 0, matched = 0;
  std::string first_miss;
  for (int gy = 0; gy < kGrid; ++gy) {
    for (int gx = 0; gx < kGrid; ++gx) {
      const int sx = box.x + int((gx + 0.5) * box.w / kGrid), sy = box.y + int((gy + 0.5) * box.h / kGrid);
      const double u = (sx + 0.5 - box.x) / box.w, v = (sy + 0.5 - box.y) / box.h;
      if (std::abs(u - split) * box.w < 3) continue;
      const Picture& source = u < split ? left : right;
      const double fx = (0.5 + (u - 0.5) / zoom) * source.width, fy = (0.5 + (v - 0.5) / zoom) * source.height;
      const double pixel_w = zoom * box.w / source.width, pixel_h = zoom * box.h / source.height;  // screen pixels an image pixel
      const bool shrunk = pixel_w < 1 || pixel_h < 1;
      const double margin_x = std::min(1.5, 0.25 * pixel_w), margin_y = std::min(1.5, 0.25 * pixel_h);
      if (!shrunk && (std::abs(fx - std::round(fx)) * pixel_w < margin_x || std::abs(fy - std::round(fy)) * pixel_h < margin_y)) {
        continue;
      }
      const int ix = std::min(source.width - 1, int(fx)), iy = std::min(source.height - 1, int(fy));
      ++sampled;
      const unsigned char* got = shot.at(sx, sy);
      if (shows(got, source, ix, iy, shrunk)) {
        ++matched;
      } else if (first_miss.empty()) {
        const unsigned char* expected = source.at(ix, iy);
        char text[160];
        std::snprintf(text, sizeof text, "at (%d,%d) the page shows %d,%d,%d, the %s image %d,%d,%d", sx, sy, got[0], got[1],
                      got[2], u < split ? "left" : "right", expected[0], expected[1], expected[2]);
        first_miss = text;
      }
    }
  }
  if (sampled > 0 && matched >= kMatchedShare * sampled) return 0;
  std::fprintf(stderr, "report_pixels: the viewer does not show the images: %d of %d samples match; first miss %s\n", matched,
               sampled, first_miss.c_str());
  return 1;
}

// Not blank: besides the box's most common colour, at least 2 % of its pixels.
int check_not_blank(const Picture& shot, const Box& box) {
  std::map<unsigned, int> counts;
  for (int y = box.y; y < box.y + box.h; ++y) {
    for (int x = box.x; x < box.x + box.w; ++x) {
      const unsigned char* p = shot.at(x, y);
      ++counts[unsigned(p[0]) << 16 | unsigned(p[1]) << 8 | p[2]];
    }
  }
  int most = 0;
  for (const auto& [colour, count] : counts) most = std::max(most, count);
  const int total = box.w * box.h, others = total - most;
  if (others >= 0.02 * total) return 0;
  std::fprintf(stderr, "report_pixels: the box is blank: %d of %d pixels differ from its most common colour\n", others, total);
  return 1;
}

// Differ: at least 10 % of the box's pixels differ by more than 8/255 in a channel.
int check_differ(const Picture& a, const Picture& b, const Box& box) {
  if (b.width < box.x + box.w || b.height < box.y + box.h) {
    std::fprintf(stderr, "report_pixels: the second screenshot is smaller than the box\n");
    return 2;
  }
  int differing = 0;
  for (int y = box.y; y < box.y + box.h; ++y) {
    for (int x = box.x; x < box.x + box.w; ++x) differing += close(a.at(x, y), b.at(x, y), 8) ? 0 : 1;
  }
  if (differing >= 0.1 * box.w * box.h) return 0;
  std::fprintf(stderr, "report_pixels: the screenshots do not differ in the box: %d of %d pixels\n", differing, box.w * box.h);
  return 1;
}

int usage() {
  std::fprintf(stderr,
               "usage: report_pixels match SHOT.png BOX LEFT.png RIGHT.png SPLIT [ZOOM]\n"
               "       report_pixels not-blank SHOT.png BOX\n"
               "       report_pixels differ SHOT.png OTHER.png BOX\n");
  return 2;
}

int run(const std::vector<std::string>& args) {
  if (args.size() < 3) return usage();
  const auto shot = load(args[1]);
  if (!shot) return 2;
  if (args[0] == "match" && (args.size() == 6 || args.size() == 7)) {
    const auto box = parse_box(args[2], *shot);
    const auto left = load(args[3]), right = load(args[4]);
    const auto split = parse_number(args[5]), zoom = parse_number(args.size() == 7 ? args[6] : "1");
    if (!box || !left || !right || !split || !(*split >= 0 && *split <= 1) || !zoom || !(*zoom >= 1)) return 2;
    return check_match(*shot, *box, *left, *right, *split, *zoom);
  }
  if (args[0] == "not-blank" && args.size() == 3) {
    const auto box = parse_box(args[2], *shot);
    return box ? check_not_blank(*shot, *box) : 2;
  }
  if (args[0] == "differ" && args.size() == 4) {
    const auto other = load(args[2]);
    const auto box = parse_box(args[3], *shot);
    return other && box ? check_differ(*shot, *other, *box) : 2;
  }
  return usage();
}

}  // namespace

int main(int argc, char** argv) { return run(std::vector<std::string>(argv + 1, argv + argc)); }
