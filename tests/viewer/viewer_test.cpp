// `volgraph view` as a user runs it (docs/viewer.md): the window's last presented image
// against the headless `render` of the same config and size, in the golden tests'
// metric; bad input said before any window opens; no display said clearly.
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include "tests/support/image_compare.h"
#include "tests/support/source_dir.h"

namespace volgraph {
namespace {

struct CommandRun {
  int exit_code = -1;
  std::string errors;  // stderr
};

std::filesystem::path scratch() {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / ("volgraph_viewer_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

// Runs `volgraph ARGS` (with `env` before it, e.g. "env -u DISPLAY"), stdout dropped.
CommandRun volgraph(const std::string& args, const std::string& env = "") {
  const std::filesystem::path errors = scratch() / "stderr.txt";
  const std::string command = env + " " + VOLGRAPH_BINARY + " " + args + " >/dev/null 2>" + errors.string();
  const int status = std::system(command.c_str());
  std::ifstream in(errors);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

// A PNG's texels as RGBA floats in [0, 1] (the 8-bit values, not decoded).
std::vector<float> png_texels(const std::filesystem::path& file, int& width, int& height) {
  int channels = 0;
  unsigned char* data = stbi_load(file.c_str(), &width, &height, &channels, 4);
  if (!data) return {};
  std::vector<float> out(size_t(width) * height * 4);
  for (size_t i = 0; i < out.size(); ++i) out[i] = data[i] / 255.0f;
  stbi_image_free(data);
  return out;
}

std::string config(const std::string& name) { return testing::source_dir() + "/configs/" + name; }

TEST(Viewer, ScreenshotMatchesTheHeadlessRender) {
  const std::filesystem::path rendered = scratch() / "render.png", shown = scratch() / "view.png";
  std::filesystem::remove(shown);
  const std::string common = config("demo_fog.json") + " --size 160x90 --frames 3 --validation";
  const CommandRun render = volgraph("render " + common + " -o " + rendered.string());
  ASSERT_EQ(render.exit_code, 0) << render.errors;
  const CommandRun view = volgraph("view " + common + " --screenshot " + shown.string());
  ASSERT_EQ(view.exit_code, 0) << view.errors;
  EXPECT_EQ(view.errors.find("validation"), std::string::npos) << view.errors;
  int w = 0, h = 0, rw = 0, rh = 0;
  const std::vector<float> a = png_texels(shown, w, h), b = png_texels(rendered, rw, rh);
  ASSERT_FALSE(a.empty()) << "no screenshot at " << shown;
  ASSERT_EQ(w, 160);
  ASSERT_EQ(h, 90);
  ASSERT_EQ(a.size(), b.size());
  // The golden tests' bounds (tests/gpu/configs_test.cpp).
  const testing::ImageDifference d = testing::compare_images(a, b);
  EXPECT_LE(d.relative_mean_error, 0.01) << d.describe();
  EXPECT_LE(d.outlier_fraction, 0.005) << d.describe();
}

// The config's errors come first: without a display, a window would have failed with
// "no display" instead of the message `render` gives.
TEST(Viewer, BadConfigExitsTwoBeforeAnyWindow) {
  const std::filesystem::path bad = scratch() / "bad.json";
  std::ofstream(bad) << "{ \"graph\": ";
  const CommandRun render = volgraph("render " + bad.string() + " -o " + (scratch() / "never.png").string());
  const CommandRun view = volgraph("view " + bad.string(), "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(view.exit_code, 2);
  EXPECT_EQ(render.exit_code, 2);
  EXPECT_EQ(view.errors, render.errors);
  const CommandRun missing = volgraph("view " + (scratch() / "missing.json").string(), "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.errors.find("missing.json"), std::string::npos) << missing.errors;
  EXPECT_EQ(missing.errors.find("display"), std::string::npos) << missing.errors;
}

TEST(Viewer, NoDisplayExitsTwoWithOneMessage) {
  const CommandRun view = volgraph("view " + config("demo_fog.json") + " --size 160x90 --frames 1", "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(view.exit_code, 2);
  EXPECT_NE(view.errors.find("no display"), std::string::npos) << view.errors;
  EXPECT_EQ(std::count(view.errors.begin(), view.errors.end(), '\n'), 1) << view.errors;
}

// --screenshot names a PNG: said before the config is read or a window opens.
TEST(Viewer, ScreenshotOtherThanPngExitsTwo) {
  const std::filesystem::path shot = scratch() / "shot.exr";
  const CommandRun view = volgraph("view " + config("demo_fog.json") + " --frames 1 --screenshot " + shot.string(),
                                   "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(view.exit_code, 2);
  EXPECT_NE(view.errors.find("expected a .png"), std::string::npos) << view.errors;
  EXPECT_FALSE(std::filesystem::exists(shot));
}

TEST(Viewer, WebGpuSurfaceIsNotWrittenYet) {
  const CommandRun view = volgraph("view " + config("demo_fog.json") + " --backend webgpu --frames 1");
  EXPECT_EQ(view.exit_code, 2);
  EXPECT_NE(view.errors.find("view: the WebGPU backend's window surface is not written yet"), std::string::npos) << view.errors;
  EXPECT_EQ(std::count(view.errors.begin(), view.errors.end(), '\n'), 1) << view.errors;
}

}  // namespace
}  // namespace volgraph
