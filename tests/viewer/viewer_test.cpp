// `volgraph view` as a user runs it (docs/viewer.md): the window's last presented image
// against the headless `render` of the same config and size, in the golden tests'
// metric; bad input said before any window opens; no display said clearly.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <chrono>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
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

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Written whole, then renamed over `file`: the viewer's poll never sees half a file.
void replace_file(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path temporary = file.string() + ".new";
  std::ofstream(temporary) << text;
  std::filesystem::rename(temporary, file);
}

size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

testing::ImageDifference difference(const std::filesystem::path& a, const std::filesystem::path& b) {
  int w = 0, h = 0, bw = 0, bh = 0;
  const std::vector<float> x = png_texels(a, w, h), y = png_texels(b, bw, bh);
  EXPECT_FALSE(x.empty()) << "no image at " << a;
  EXPECT_FALSE(y.empty()) << "no image at " << b;
  EXPECT_EQ(x.size(), y.size());
  if (x.empty() || x.size() != y.size()) return {1.0, 1.0};
  return testing::compare_images(x, y);
}

// The golden tests' bounds (tests/gpu/configs_test.cpp).
void expect_golden_match(const std::filesystem::path& a, const std::filesystem::path& b) {
  const testing::ImageDifference d = difference(a, b);
  EXPECT_LE(d.relative_mean_error, 0.01) << a << " against " << b << ": " << d.describe();
  EXPECT_LE(d.outlier_fraction, 0.005) << a << " against " << b << ": " << d.describe();
}

void expect_different(const std::filesystem::path& a, const std::filesystem::path& b) {
  EXPECT_GT(difference(a, b).relative_mean_error, 0.01) << a << " and " << b << " should differ";
}

// demo_analytic_fog and its graph (an include) copied to a folder of their own, to edit.
std::filesystem::path copy_analytic_fog(const std::string& folder) {
  const std::filesystem::path dir = scratch() / folder;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "graphs");
  std::filesystem::copy_file(config("demo_analytic_fog.json"), dir / "demo_analytic_fog.json");
  std::filesystem::copy_file(config("graphs/analytic_fog.json"), dir / "graphs" / "analytic_fog.json");
  return dir;
}

// Runs `volgraph view CONFIG --script` in a thread; once the script's first screenshot
// (`first`) is written, `edit` runs, then the viewer's wait-change sees it.
CommandRun view_with_edit(const std::string& args, const std::filesystem::path& first, const std::function<void()>& edit) {
  CommandRun run;
  std::thread viewer([&] { run = volgraph(args); });
  for (int i = 0; i < 1200 && !std::filesystem::exists(first); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  edit();
  viewer.join();
  return run;
}

// The viewer's cases run on each backend: Vulkan under the validation layer, WebGPU
// (Dawn on the window's X11 surface) with Dawn's errors printed as "dawn: " lines.
class ViewerOn : public ::testing::TestWithParam<std::string> {
 protected:
  // The backend's options for `render` and `view` alike.
  std::string backend() const { return GetParam() == "webgpu" ? " --backend webgpu" : " --validation"; }
  // Neither a validation message nor a Dawn error was printed.
  static void expect_clean(const CommandRun& view) {
    EXPECT_EQ(view.errors.find("validation"), std::string::npos) << view.errors;
    EXPECT_EQ(view.errors.find("dawn:"), std::string::npos) << view.errors;
  }
};

INSTANTIATE_TEST_SUITE_P(Backends, ViewerOn, ::testing::Values("vulkan", "webgpu"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST_P(ViewerOn, ScreenshotMatchesTheHeadlessRender) {
  const std::filesystem::path rendered = scratch() / "render.png", shown = scratch() / "view.png";
  std::filesystem::remove(shown);
  const std::string common = config("demo_fog.json") + " --size 160x90 --frames 3" + backend();
  const CommandRun render = volgraph("render " + common + " -o " + rendered.string());
  ASSERT_EQ(render.exit_code, 0) << render.errors;
  const CommandRun view = volgraph("view " + common + " --no-overlay --screenshot " + shown.string());
  ASSERT_EQ(view.exit_code, 0) << view.errors;
  expect_clean(view);
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

// A variant changed between frames (the control API through --script) gives what
// `render --variant` gives; a refused parameter keeps that graph, with the loader's message.
TEST_P(ViewerOn, ScriptVariantMatchesRenderVariant) {
  const std::filesystem::path dir = scratch() / ("variant_" + GetParam()), script = dir / "script.txt";
  std::filesystem::create_directories(dir);
  const std::filesystem::path before = dir / "before.png", shown = dir / "view.png", rendered = dir / "render.png",
                              plain = dir / "plain.png";
  std::filesystem::remove(shown);
  std::ofstream(script) << "frames 3\nscreenshot " << before.string() << "\nvariant final reinhard\n"
                        << "param final exposure 99\nframes 3\nscreenshot " << shown.string() << "\n";
  const std::string common = config("demo_fog.json") + " --size 160x90" + backend();
  const CommandRun view = volgraph("view " + common + " --no-overlay --script " + script.string());
  ASSERT_EQ(view.exit_code, 0) << view.errors;
  expect_clean(view);
  EXPECT_EQ(count_of(view.errors, "parameter \"exposure\" expects a number in [-20, 20], got 99"), 1u) << view.errors;
  ASSERT_EQ(volgraph("render " + common + " --frames 3 --variant final=reinhard -o " + rendered.string()).exit_code, 0);
  ASSERT_EQ(volgraph("render " + common + " --frames 3 -o " + plain.string()).exit_code, 0);
  expect_golden_match(shown, rendered);
  expect_golden_match(before, plain);
  expect_different(shown, plain);  // the variant did change the image
}

// Hot reload: an include edited while the viewer runs is reloaded; the image is the
// edited config's.
TEST_P(ViewerOn, EditedIncludeIsReloaded) {
  const std::filesystem::path dir = copy_analytic_fog("reload_" + GetParam()), script = dir / "script.txt";
  const std::filesystem::path before = dir / "before.png", after = dir / "after.png", rendered = dir / "render.png";
  std::ofstream(script) << "frames 2\nscreenshot " << before.string() << "\nwait-change\nframes 2\nscreenshot " << after.string() << "\n";
  const std::filesystem::path include = dir / "graphs" / "analytic_fog.json";
  const std::string args = (dir / "demo_analytic_fog.json").string() + " --size 160x90" + backend();
  const CommandRun view = view_with_edit("view " + args + " --no-overlay --script " + script.string(), before, [&] {
    std::string text = read_text(include);
    text.replace(text.find("\"aces\""), 6, "\"reinhard\"");
    replace_file(include, text);
  });
  ASSERT_EQ(view.exit_code, 0) << view.errors;
  expect_clean(view);
  ASSERT_EQ(volgraph("render " + args + " --frames 2 -o " + rendered.string()).exit_code, 0);
  expect_golden_match(after, rendered);
  expect_different(after, before);
}

// A bad edit keeps the last good graph: the frames after it equal the ones before, and
// the loader's message (file, JSON pointer) is printed once.
TEST_P(ViewerOn, BadEditKeepsTheLastGoodFrame) {
  const std::filesystem::path dir = copy_analytic_fog("bad_edit_" + GetParam()), script = dir / "script.txt";
  const std::filesystem::path before = dir / "before.png", after = dir / "after.png";
  std::ofstream(script) << "frames 2\nscreenshot " << before.string() << "\nwait-change\nframes 2\nscreenshot " << after.string() << "\n";
  const std::filesystem::path include = dir / "graphs" / "analytic_fog.json";
  const CommandRun view = view_with_edit("view " + (dir / "demo_analytic_fog.json").string() + " --size 160x90" + backend() + " --no-overlay --script " + script.string(),
                                         before, [&] {
                                           std::string text = read_text(include);
                                           text.replace(text.find("\"aces\""), 6, "\"nope\"");
                                           replace_file(include, text);
                                         });
  ASSERT_EQ(view.exit_code, 0) << view.errors;
  expect_clean(view);
  EXPECT_EQ(count_of(view.errors, "analytic_fog.json"), 1u) << view.errors;
  EXPECT_EQ(count_of(view.errors, "/graph/passes/3/variant"), 1u) << view.errors;
  EXPECT_EQ(read_text(after), read_text(before));
}

// A script is checked before any window opens: one message with the file and line, exit 2.
TEST(Viewer, BadScriptExitsTwoBeforeAnyWindow) {
  const std::filesystem::path script = scratch() / "bad_script.txt";
  std::ofstream(script) << "frames 2\nzoom 3\n";
  const CommandRun view = volgraph("view " + config("demo_fog.json") + " --script " + script.string(), "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(view.exit_code, 2);
  EXPECT_NE(view.errors.find("bad_script.txt"), std::string::npos) << view.errors;
  EXPECT_NE(view.errors.find("unknown command \"zoom\""), std::string::npos) << view.errors;
  EXPECT_EQ(view.errors.find("display"), std::string::npos) << view.errors;
}

// A region of two same-sized PNGs (columns [x0, x1)) as RGBA floats, for the golden metric.
std::vector<float> columns(const std::filesystem::path& file, int x0, int x1) {
  int w = 0, h = 0;
  const std::vector<float> all = png_texels(file, w, h);
  std::vector<float> out;
  for (int y = 0; y < h && !all.empty(); ++y) {
    for (int x = std::max(x0, 0); x < std::min(x1, w); ++x) out.insert(out.end(), &all[(size_t(y) * w + x) * 4], &all[(size_t(y) * w + x) * 4 + 4]);
  }
  return out;
}

// The overlay (on by default) is drawn over the frame's left part (its panel is at most
// half the window wide): there the screenshot differs from --no-overlay's, to its right
// it is the same frame.
TEST_P(ViewerOn, OverlayDrawsOverTheLeftOfTheFrame) {
  const std::filesystem::path dir = scratch() / ("overlay_" + GetParam()), with = dir / "with.png", without = dir / "without.png";
  std::filesystem::create_directories(dir);
  const std::string common = "view " + config("demo_fog.json") + " --size 320x180 --frames 3" + backend() + " --screenshot ";
  const CommandRun shown = volgraph(common + with.string());
  ASSERT_EQ(shown.exit_code, 0) << shown.errors;
  expect_clean(shown);
  const CommandRun plain = volgraph(common + without.string() + " --no-overlay");
  ASSERT_EQ(plain.exit_code, 0) << plain.errors;
  const std::vector<float> left_with = columns(with, 0, 160), left_without = columns(without, 0, 160);
  const std::vector<float> right_with = columns(with, 170, 320), right_without = columns(without, 170, 320);
  ASSERT_FALSE(left_with.empty());
  ASSERT_EQ(left_with.size(), left_without.size());
  ASSERT_EQ(right_with.size(), right_without.size());
  EXPECT_GT(testing::compare_images(left_with, left_without).relative_mean_error, 0.05);
  const testing::ImageDifference right = testing::compare_images(right_with, right_without);
  EXPECT_LE(right.relative_mean_error, 0.01) << right.describe();
  EXPECT_LE(right.outlier_fraction, 0.005) << right.describe();
}

// demo_fog and its graph copied to a folder of their own, `edit` applied to the config's text.
std::filesystem::path edited_demo_fog(const std::string& folder, const std::function<void(std::string&)>& edit) {
  const std::filesystem::path dir = scratch() / folder;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "graphs");
  std::filesystem::copy_file(config("graphs/froxel_fog.json"), dir / "graphs" / "froxel_fog.json");
  std::string text = read_text(config("demo_fog.json"));
  edit(text);
  std::ofstream(dir / "demo_fog.json") << text;
  return dir / "demo_fog.json";
}

void replace_once(std::string& text, const std::string& what, const std::string& with) {
  const size_t at = text.find(what);
  ASSERT_NE(at, std::string::npos) << what;
  text.replace(at, what.size(), with);
}

// The script's `camera` (set_camera, as WASD and the mouse move it) gives `render` of the
// config with that camera; `sun AZ EL` gives the config with the sun light's direction
// pointing away from azimuth AZ (from +z toward +x), elevation EL.
TEST(Viewer, ScriptCameraAndSunMatchRenderOfThatScene) {
  const std::filesystem::path dir = scratch() / "camera", script = dir / "script.txt";
  std::filesystem::create_directories(dir);
  const std::filesystem::path shown = dir / "view.png", rendered = dir / "render.png", plain = dir / "plain.png";
  std::ofstream(script) << "camera 2 2.5 6 0.5 0.8 0\nsun 30 20\nframes 3\nscreenshot " << shown.string() << "\n";
  const std::string common = " --size 160x90 --validation";
  const CommandRun view = volgraph("view " + config("demo_fog.json") + common + " --no-overlay --script " + script.string());
  ASSERT_EQ(view.exit_code, 0) << view.errors;
  EXPECT_EQ(view.errors.find("validation"), std::string::npos) << view.errors;
  // sun 30 20: travelling along -(cos 20 sin 30, sin 20, cos 20 cos 30).
  const std::filesystem::path moved = edited_demo_fog("camera_config", [](std::string& text) {
    replace_once(text, "\"position\": [0, 1.6, 7], \"target\": [0, 1.0, 0]", "\"position\": [2, 2.5, 6], \"target\": [0.5, 0.8, 0]");
    replace_once(text, "\"direction\": [0.15, -0.3, 0.94]", "\"direction\": [-0.4698463104, -0.3420201433, -0.8137976617]");
  });
  ASSERT_EQ(volgraph("render " + moved.string() + common + " --frames 3 -o " + rendered.string()).exit_code, 0);
  ASSERT_EQ(volgraph("render " + config("demo_fog.json") + common + " --frames 3 -o " + plain.string()).exit_code, 0);
  expect_golden_match(shown, rendered);
  expect_different(shown, plain);
}

// camera and sun take numbers, six and two: checked before any window, file and line named.
TEST(Viewer, BadCameraOrSunLineExitsTwoBeforeAnyWindow) {
  const std::filesystem::path short_camera = scratch() / "short_camera.txt", word_sun = scratch() / "word_sun.txt";
  std::ofstream(short_camera) << "camera 1 2 3\n";
  std::ofstream(word_sun) << "frames 1\nsun 30 high\n";
  const std::string no_display = "env -u DISPLAY -u WAYLAND_DISPLAY";
  const CommandRun a = volgraph("view " + config("demo_fog.json") + " --script " + short_camera.string(), no_display);
  EXPECT_EQ(a.exit_code, 2);
  EXPECT_NE(a.errors.find("short_camera.txt"), std::string::npos) << a.errors;
  EXPECT_NE(a.errors.find("camera takes 6 word(s)"), std::string::npos) << a.errors;
  const CommandRun b = volgraph("view " + config("demo_fog.json") + " --script " + word_sun.string(), no_display);
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.errors.find("word_sun.txt"), std::string::npos) << b.errors;
  EXPECT_NE(b.errors.find("sun high: expected a number"), std::string::npos) << b.errors;
  EXPECT_EQ(b.errors.find("display"), std::string::npos) << b.errors;
}

// A capture (F12; the script's `capture PREFIX`) after a variant, a parameter, a camera
// and a sun change writes PNG, EXR and a config; `render` of that config with the frames
// it names gives the same PNG, byte for byte, and it differs from the unchanged config's.
TEST_P(ViewerOn, CaptureRendersTheSameImageHeadless) {
  const std::filesystem::path dir = scratch() / ("capture_" + GetParam()), script = dir / "script.txt";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path prefix = dir / "shot", again = dir / "again.png", plain = dir / "plain.png";
  std::ofstream(script) << "frames 2\nvariant final reinhard\nparam final exposure 1.5\ncamera 2 2.5 6 0.5 0.8 0\nsun 30 20\n"
                        << "frames 2\ncapture " << prefix.string() << "\n";
  const std::string size = " --size 160x90" + backend();
  const CommandRun view = volgraph("view " + config("demo_fog.json") + size + " --no-overlay --script " + script.string());
  ASSERT_EQ(view.exit_code, 0) << view.errors;
  expect_clean(view);
  ASSERT_TRUE(std::filesystem::exists(prefix.string() + ".exr"));
  const std::string json = prefix.string() + ".json";
  EXPECT_NE(read_text(json).find("--frames 2"), std::string::npos) << read_text(json);
  const CommandRun render = volgraph("render " + json + backend() + " --frames 2 -o " + again.string());
  ASSERT_EQ(render.exit_code, 0) << render.errors;
  EXPECT_EQ(read_text(again), read_text(prefix.string() + ".png"));
  ASSERT_EQ(volgraph("render " + config("demo_fog.json") + size + " --frames 2 -o " + plain.string()).exit_code, 0);
  expect_different(again, plain);
}

// The resource view (`show PASS.SLOT`, the overlay's "Resources"): a texture a pass writes,
// shown in place of the output, is what `render --dump PASS.SLOT=FILE.png` writes.
TEST_P(ViewerOn, ShownResourceEqualsItsDump) {
  const std::filesystem::path dir = scratch() / ("show_" + GetParam()), script = dir / "script.txt";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path shown = dir / "shown.png", dumped = dir / "dumped.png";
  std::ofstream(script) << "frames 1\nshow fog_apply.color\nframes 2\nscreenshot " << shown.string() << "\n";
  const std::string common = config("demo_fog.json") + " --size 160x90" + backend();
  const CommandRun view = volgraph("view " + common + " --no-overlay --script " + script.string());
  ASSERT_EQ(view.exit_code, 0) << view.errors;
  expect_clean(view);
  ASSERT_EQ(volgraph("render " + common + " --frames 2 --dump fog_apply.color=" + dumped.string() + " -o " + (dir / "out.png").string()).exit_code, 0);
  EXPECT_EQ(difference(shown, dumped).relative_mean_error, 0.0);
  expect_different(shown, dir / "out.png");  // the view showed the slot, not the output
}

// A 3D resource is shown a slice at a time, scaled by 2^exposure; a name the graph does not
// have is one message and the view stays as it was.
TEST(Viewer, ResourceViewSlicesAndExposesA3DTexture) {
  const std::filesystem::path dir = scratch() / "show_3d", script = dir / "script.txt";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  auto shot = [&](const std::string& name) { return (dir / (name + ".png")).string(); };
  std::ofstream(script) << "show fog_integral.integrated_scattering\nslice 4\nexposure 2\nframes 1\nscreenshot " << shot("near") << "\n"
                        << "slice 40\nframes 1\nscreenshot " << shot("far") << "\n"
                        << "exposure 4\nframes 1\nscreenshot " << shot("brighter") << "\n"
                        << "show nope.slot\nframes 1\nscreenshot " << shot("kept") << "\n";
  const CommandRun view = volgraph("view " + config("demo_fog.json") + " --size 160x90 --validation --no-overlay --script " + script.string());
  ASSERT_EQ(view.exit_code, 0) << view.errors;
  EXPECT_EQ(view.errors.find("validation"), std::string::npos) << view.errors;
  EXPECT_EQ(count_of(view.errors, "no pass named \"nope\""), 1u) << view.errors;
  expect_different(shot("near"), shot("far"));
  int w = 0, h = 0;
  double far_sum = 0, brighter_sum = 0;
  for (const float v : png_texels(shot("far"), w, h)) far_sum += v;
  for (const float v : png_texels(shot("brighter"), w, h)) brighter_sum += v;
  EXPECT_GT(brighter_sum, far_sum * 1.1);
  expect_golden_match(shot("kept"), shot("brighter"));  // the same slot a frame later (the fog's history moves on)
}

// The shader sources copied to a folder of their own, to edit (view --shaders DIR).
std::filesystem::path copy_shaders(const std::string& folder) {
  const std::filesystem::path dir = scratch() / folder;
  std::filesystem::remove_all(dir);
  std::filesystem::copy(testing::source_dir() + "/shaders", dir, std::filesystem::copy_options::recursive);
  return dir;
}

// Shader hot reload: composite.comp edited while the viewer runs is compiled again and the
// graph rebuilt with it; every pixel is then the edited shader's constant (sRGB 8-bit of
// 0.25, 0.5, 0.75: 137, 188, 225).
TEST_P(ViewerOn, EditedShaderIsReloaded) {
  const std::filesystem::path shaders = copy_shaders("shaders_" + GetParam()), dir = scratch() / ("shader_edit_" + GetParam());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path script = dir / "script.txt", before = dir / "before.png", after = dir / "after.png";
  std::ofstream(script) << "frames 2\nscreenshot " << before.string() << "\nwait-change\nframes 1\nscreenshot " << after.string() << "\n";
  const std::filesystem::path composite = shaders / "composite.comp";
  const CommandRun view = view_with_edit("view " + config("demo_fog.json") + " --size 160x90" + backend() + " --no-overlay --shaders " +
                                             shaders.string() + " --script " + script.string(),
                                         before, [&] {
                                           std::string text = read_text(composite);
                                           const std::string store = "vec4(tone_map(radiance.rgb, params.exposure_ev, params.tone_map_op), 1.0)";
                                           text.replace(text.find(store), store.size(), "vec4(0.25, 0.5, 0.75, 1.0)");
                                           replace_file(composite, text);
                                         });
  ASSERT_EQ(view.exit_code, 0) << view.errors;
  expect_clean(view);
  EXPECT_EQ(count_of(view.errors, "view: shaders reloaded: composite.comp"), 1u) << view.errors;
  int w = 0, h = 0;
  const std::vector<float> texels = png_texels(after, w, h);
  ASSERT_EQ(texels.size(), size_t(160 * 90 * 4));
  for (size_t i = 0; i < texels.size(); i += 4) {
    ASSERT_EQ(int(std::lround(texels[i] * 255)), 137) << "pixel " << i / 4;
    ASSERT_EQ(int(std::lround(texels[i + 1] * 255)), 188) << "pixel " << i / 4;
    ASSERT_EQ(int(std::lround(texels[i + 2] * 255)), 225) << "pixel " << i / 4;
  }
}

// A shader edit that does not compile (here in an include) is one message naming the
// shader, and the last good shaders keep running: the frames are unchanged.
TEST(Viewer, ShaderThatDoesNotCompileKeepsTheLastGoodOne) {
  const std::filesystem::path shaders = copy_shaders("shaders_bad"), dir = scratch() / "shader_bad_edit";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path script = dir / "script.txt", before = dir / "before.png", after = dir / "after.png";
  std::ofstream(script) << "frames 2\nscreenshot " << before.string() << "\nwait-change\nframes 1\nscreenshot " << after.string() << "\n";
  const std::filesystem::path include = shaders / "include" / "tonemap.glsl";
  const CommandRun view = view_with_edit("view " + config("demo_analytic_fog.json") + " --size 160x90 --validation --no-overlay --shaders " +
                                             shaders.string() + " --script " + script.string(),
                                         before, [&] { replace_file(include, read_text(include) + "\nthis is not GLSL\n"); });
  ASSERT_EQ(view.exit_code, 0) << view.errors;
  EXPECT_EQ(view.errors.find("validation"), std::string::npos) << view.errors;
  EXPECT_EQ(count_of(view.errors, "does not compile; the last good one runs on"), 1u) << view.errors;
  EXPECT_NE(view.errors.find("ERROR"), std::string::npos) << view.errors;
  EXPECT_EQ(read_text(after), read_text(before));  // a frame later (no temporal pass here), the same shaders
}

}  // namespace
}  // namespace volgraph
