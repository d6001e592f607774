// The loader's diagnostics: one test per kind of bad input. Each checks the file,
// the JSON pointer (and line where the text fixes it) and the expectation named.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "passes/passes.h"
#include "tests/support/source_dir.h"

namespace volgraph {
namespace {

// A valid config; tests break one thing in it at a time.
const char* kValid = R"({
  "output": { "size": [64, 32] },
  "scene": {
    "camera": { "position": [0, 1, 5], "target": [0, 0, 0] },
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "objects": [ { "shape": "plane", "size": [10, 1, 10], "material": "grey" } ],
    "lights": [ { "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1] } ]
  },
  "graph": {
    "passes": [
      { "name": "sun_shadow", "type": "shadow_map", "params": { "resolution": 256 } },
      { "name": "lit", "type": "scene", "inputs": { "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view" } },
      { "name": "final", "type": "composite", "inputs": { "color": "lit.color" } }
    ],
    "outputs": ["final.output"]
  }
})";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "fixture text lacks: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

class Loader : public ::testing::Test {
 protected:
  Loader() { register_builtin_passes(registry_); }

  LoadedConfig load(const std::string& text, const Overrides& o = {}) {
    return load_config_text("test.json", text, registry_, o);
  }

  // The diagnostics a bad config gets (fails the test when it loads).
  std::vector<Diagnostic> errors(const std::string& text, const Overrides& o = {}) {
    try {
      const LoadedConfig loaded = load(text, o);
      compile_loaded(loaded);
    } catch (const ConfigError& e) {
      EXPECT_FALSE(e.diagnostics().empty());
      return e.diagnostics();
    }
    ADD_FAILURE() << "expected a ConfigError";
    return {};
  }

  // Exactly one diagnostic, at `pointer`, whose message contains `expect`.
  Diagnostic one_error(const std::string& text, const std::string& pointer, const std::string& expect,
                       const Overrides& o = {}) {
    const auto list = errors(text, o);
    if (list.size() != 1) {
      ADD_FAILURE() << "expected one diagnostic, got " << list.size() << ":\n" << ConfigError(list).what();
      return list.empty() ? Diagnostic{} : list[0];
    }
    EXPECT_EQ(list[0].where.pointer, pointer) << format_diagnostic(list[0]);
    EXPECT_NE(list[0].message.find(expect), std::string::npos) << format_diagnostic(list[0]);
    return list[0];
  }

  PassRegistry registry_;
};

TEST_F(Loader, ValidConfigLoadsAndWires) {
  const LoadedConfig c = load(kValid);
  EXPECT_EQ(c.graph.passes.size(), 3u);
  EXPECT_EQ(c.graph.output_size, (Extent{64, 32, 1}));
  EXPECT_EQ(c.graph.resources[0].desc.extent, (Extent{256, 256, 1}));  // shadow map side from its parameter
  EXPECT_EQ(std::get<int64_t>(c.params[0][size_t(c.graph.passes[0].decl->param_index("resolution"))]), 256);
}

TEST_F(Loader, InvalidJsonNamesTheLine) {
  const Diagnostic d = one_error("{\n  \"output\": {\n    \"size\": [1, 2,]\n  }\n}\n", "", "invalid JSON");
  EXPECT_EQ(d.where.file, "test.json");
  EXPECT_EQ(d.where.line, 3);
}

TEST_F(Loader, NumberTooLargeForADoubleIsInvalidJson) {  // found by fuzz_loader
  one_error(replace(kValid, "[64, 32]", "[1e400, 32]"), "", "invalid JSON: number overflow");
}

TEST_F(Loader, NestingPast256LevelsIsRefusedBeforeParsing) {
  const std::string deep = std::string(50000, '[') + std::string(50000, ']');
  const Diagnostic d = one_error(replace(kValid, "\"output\": { \"size\": [64, 32] },", "\"description\": " + deep + ","), "",
                                 "arrays and objects nest deeper than 256 levels");
  EXPECT_EQ(d.where.line, 2);
}

TEST_F(Loader, NulByteIsAnErrorAtItsLine) {
  const Diagnostic d = one_error(kValid + std::string("\n\0{}", 4), "", "a NUL byte at offset");
  EXPECT_EQ(d.where.line, 18);
}

TEST_F(Loader, RepeatedKeyIsAnErrorAtTheRepeat) {
  const Diagnostic d = one_error(replace(kValid, "\"output\": { \"size\": [64, 32] },", "\"output\": {},\n  \"output\": {},"),
                                 "/output", "duplicate key \"output\" (first at line 2)");
  EXPECT_EQ(d.where.line, 3);
}

TEST_F(Loader, TinyLightDirectionIsRefusedAtItsPointer) {
  one_error(replace(kValid, "\"direction\": [0, -1, 0]", "\"direction\": [1e-200, -1e-200, 0]"), "/scene/lights/0/direction",
            "light direction has length 1.41e-200; expected a direction of length at least 1e-6");
}

TEST_F(Loader, CameraUpAlongTheViewIsRefused) {
  one_error(replace(kValid, "\"position\": [0, 1, 5]", "\"position\": [0, 5, 0]"), "/scene/camera",
            "camera up is parallel to the view direction");
}

TEST_F(Loader, IntegerFormatForAFloatColourIsRefused) {
  one_error(replace(kValid, "\"name\": \"lit\", \"type\": \"scene\",", "\"name\": \"lit\", \"type\": \"scene\", \"outputs\": { \"color\": { \"format\": \"r32_uint\" } },"),
            "/graph/passes/1/outputs/color", "r32_uint does not; expected a format like rgba16_float");
}

TEST_F(Loader, RenderTargetsOfOnePassMustHaveOneSize) {
  const std::string text = replace(kValid, "\"name\": \"lit\", \"type\": \"scene\",",
                                   "\"name\": \"lit\", \"type\": \"scene\", \"outputs\": { \"color\": { \"size\": [32, 16] } },");
  one_error(text, "/graph/passes/1/outputs/color", "\"color\" is 32x16, \"depth\" 64x32");
}

TEST_F(Loader, AVariantNeedsAName) {
  Overrides o;
  o.variants = {"final="};
  one_error(kValid, "--variant final=", "expected --variant PASS=VARIANT with a variant's name", o);
}

TEST_F(Loader, UnknownKeySuggestsTheKnownOne) {
  const Diagnostic d = one_error(replace(kValid, "\"graph\"", "\"grpah\""), "/grpah", "did you mean \"graph\"");
  EXPECT_EQ(d.where.line, 9);
  EXPECT_EQ(format_diagnostic(d).rfind("test.json:9: error at /grpah: unknown key \"grpah\"", 0), 0u) << format_diagnostic(d);
}

TEST_F(Loader, WrongTypeSaysWhatWasExpected) {
  const Diagnostic d = one_error(replace(kValid, "[64, 32]", "\"big\""), "/output/size", "expected [width, height]");
  EXPECT_EQ(d.where.line, 2);
}

TEST_F(Loader, AbsurdResolutionIsOutOfRange) {
  one_error(replace(kValid, "[64, 32]", "[100000, 100000]"), "/output/size/0", "expected an integer in [1, 16384]");
}

TEST_F(Loader, NonNumberInVectorIsRejected) {
  one_error(replace(kValid, "\"albedo\": [0.5, 0.5, 0.5]", "\"albedo\": [0.5, \"x\", 0.5]"),
            "/scene/materials/grey/albedo", "expected an array of 3 numbers in [0, 1]");
}

TEST_F(Loader, UnknownPassTypeSuggests) {
  one_error(replace(kValid, "\"type\": \"shadow_map\"", "\"type\": \"shadowmap\""), "/graph/passes/0/type",
            "unknown pass type \"shadowmap\" (did you mean \"shadow_map\"?)");
}

TEST_F(Loader, UnknownVariantSuggests) {
  one_error(replace(kValid, "\"type\": \"shadow_map\",", "\"type\": \"shadow_map\", \"variant\": \"pfc\","),
            "/graph/passes/0/variant", "no variant \"pfc\" (did you mean \"pcf\"?)");
}

TEST_F(Loader, UnknownParameterSuggests) {
  one_error(replace(kValid, "\"resolution\": 256", "\"resolutoin\": 256"), "/graph/passes/0/params/resolutoin",
            "no parameter \"resolutoin\" (did you mean \"resolution\"?)");
}

TEST_F(Loader, ParameterOfWrongType) {
  one_error(replace(kValid, "\"resolution\": 256", "\"resolution\": \"high\""), "/graph/passes/0/params/resolution",
            "expects an integer in [64, 16384], got \"high\"");
}

TEST_F(Loader, ParameterOutOfRange) {
  one_error(replace(kValid, "\"resolution\": 256", "\"resolution\": 100000"), "/graph/passes/0/params/resolution",
            "expects an integer in [64, 16384], got 100000");
}

TEST_F(Loader, UnknownInputSlotSuggests) {
  one_error(replace(kValid, "{ \"shadow_map\": \"sun_shadow.depth\"", "{ \"shadowmap\": \"sun_shadow.depth\""),
            "/graph/passes/1/inputs/shadowmap", "no input slot \"shadowmap\" (did you mean \"shadow_map\"?)");
}

TEST_F(Loader, WiringToMissingPassSuggests) {
  one_error(replace(kValid, "\"sun_shadow.depth\"", "\"sun_shadw.depth\""), "/graph/passes/1/inputs/shadow_map",
            "no pass named \"sun_shadw\" (did you mean \"sun_shadow\"?)");
}

TEST_F(Loader, WiringToMissingSlotSuggests) {
  one_error(replace(kValid, "\"sun_shadow.depth\"", "\"sun_shadow.dept\""), "/graph/passes/1/inputs/shadow_map",
            "has no output \"dept\" (did you mean \"depth\"?)");
}

TEST_F(Loader, WiringNeedsPassDotSlot) {
  one_error(replace(kValid, "\"sun_shadow.depth\"", "\"sun_shadow\""), "/graph/passes/1/inputs/shadow_map",
            "expected \"pass.slot\"");
}

TEST_F(Loader, RequiredInputNotWired) {
  one_error(replace(kValid, "\"inputs\": { \"color\": \"lit.color\" }", "\"inputs\": {}"), "/graph/passes/2",
            "input \"color\" (texture2d) is not wired");
}

TEST_F(Loader, WiringOfWrongKind) {
  one_error(replace(kValid, "{ \"color\": \"lit.color\" }", "{ \"color\": \"sun_shadow.light_view\" }"),
            "/graph/passes/2/inputs/color", "takes a texture2d, but 'sun_shadow.light_view' is a buffer");
}

TEST_F(Loader, WiringOfWrongFormat) {
  std::string text = replace(kValid, "{ \"name\": \"final\"", "{ \"name\": \"blank\", \"type\": \"clear\" },\n      { \"name\": \"final\"");
  one_error(replace(text, "\"shadow_map\": \"sun_shadow.depth\"", "\"shadow_map\": \"blank.target\""),
            "/graph/passes/1/inputs/shadow_map", "takes format d32_float, but 'blank.target' is rgba16_float");
}

TEST_F(Loader, CycleNamesItsPassesInOrder) {
  const std::string text = replace(kValid, "{ \"name\": \"final\"",
                                   "{ \"name\": \"a\", \"type\": \"copy\", \"inputs\": { \"source\": \"b.copy\" } },\n"
                                   "      { \"name\": \"b\", \"type\": \"copy\", \"inputs\": { \"source\": \"a.copy\" } },\n"
                                   "      { \"name\": \"final\"");
  const Diagnostic d = one_error(text, "/graph/passes/2", "the graph has a cycle: a → b → a");
  EXPECT_EQ(d.where.line, 13);
}

TEST_F(Loader, DuplicatePassName) {
  one_error(replace(kValid, "\"name\": \"final\"", "\"name\": \"lit\""), "/graph/passes/2/name", "defined twice");
}

TEST_F(Loader, PassWithoutType) {
  one_error(replace(kValid, "\"name\": \"final\", \"type\": \"composite\",", "\"name\": \"final\","), "/graph/passes/2",
            "has no \"type\"");
}

TEST_F(Loader, NoGraphOutputs) {
  one_error(replace(kValid, "\"outputs\": [\"final.output\"]", "\"outputs\": []"), "/graph/outputs", "no outputs");
}

TEST_F(Loader, OutputOfAnInputSlot) {
  one_error(replace(kValid, "[\"final.output\"]", "[\"final.color\"]"), "/graph/outputs/0", "has no output \"color\"");
}

TEST_F(Loader, UnknownMaterialSuggests) {
  one_error(replace(kValid, "\"material\": \"grey\"", "\"material\": \"gray\""), "/scene/objects/0/material",
            "unknown material \"gray\" (did you mean \"grey\"?)");
}

TEST_F(Loader, UnknownEnumValueSuggests) {
  one_error(replace(kValid, "\"type\": \"directional\"", "\"type\": \"directonal\""), "/scene/lights/0/type",
            "unknown value \"directonal\" (did you mean \"directional\"?)");
}

TEST_F(Loader, MissingGltfFile) {
  one_error(replace(kValid, "{ \"shape\": \"plane\", \"size\": [10, 1, 10], \"material\": \"grey\" }",
                    "{ \"shape\": \"gltf\", \"file\": \"no/such/model.glb\" }"),
            "/scene/objects/0/file", "file not found: \"no/such/model.glb\"");
}

TEST_F(Loader, UnknownFormatSuggests) {
  one_error(replace(kValid, "\"inputs\": { \"color\": \"lit.color\" }",
                    "\"inputs\": { \"color\": \"lit.color\" }, \"outputs\": { \"output\": { \"format\": \"rgba16f\" } }"),
            "/graph/passes/2/outputs/output/format", "unknown format \"rgba16f\"");
}

TEST_F(Loader, FormatNotStorageCapable) {
  // A pass type whose storage output's format may be chosen.
  PassDecl writer;
  writer.name = "storage_writer";
  writer.variants = {{"default", ""}};
  SlotDecl out = slot_out("out", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float, SizeSpec::of_output(), "");
  out.format_overridable = true;
  writer.slots = {out};
  registry_.add(writer);
  one_error(replace(kValid, "{ \"name\": \"final\"",
                    "{ \"name\": \"w\", \"type\": \"storage_writer\", \"outputs\": { \"out\": { \"format\": \"rgba8_srgb\" } } },\n"
                    "      { \"name\": \"final\""),
            "/graph/passes/2/outputs/out", "not a storage format");
}

TEST_F(Loader, FixedFormatCannotBeOverridden) {
  one_error(replace(kValid, "\"params\": { \"resolution\": 256 }",
                    "\"params\": { \"resolution\": 256 }, \"outputs\": { \"depth\": { \"format\": \"d16_unorm\" } }"),
            "/graph/passes/0/outputs/depth", "is fixed (d32_float)");
}

TEST_F(Loader, SizeOverrideOutOfRange) {
  one_error(replace(kValid, "\"name\": \"lit\", \"type\": \"scene\",",
                    "\"name\": \"lit\", \"type\": \"scene\", \"outputs\": { \"color\": { \"size\": [70000, 10] } },"),
            "/graph/passes/1/outputs/color/size/0", "expected an integer in [1, 16384]");
}

TEST_F(Loader, ShadowMapLightMustExist) {
  one_error(replace(kValid, "\"resolution\": 256", "\"resolution\": 256, \"light\": 3"),
            "/graph/passes/0/params/light", "light 3 does not exist: scene.lights has 1");
}

TEST_F(Loader, ShadowMapLightMustBeDirectionalOrSpot) {
  std::string text = replace(kValid, "\"irradiance\": [1, 1, 1] }",
                             "\"irradiance\": [1, 1, 1] }, { \"type\": \"point\", \"intensity\": [1, 1, 1] }");
  one_error(replace(text, "\"resolution\": 256", "\"resolution\": 256, \"light\": 1"), "/graph/passes/0/params/light",
            "light 1 is a point light; shadow_map takes a directional or spot light");
}

TEST_F(Loader, ManyErrorsReportedTogether) {
  std::string text = replace(kValid, "\"graph\"", "\"grpah\"");
  text = replace(text, "\"camera\"", "\"camrea\"");
  EXPECT_EQ(errors(text).size(), 2u);
}

TEST_F(Loader, CommandLineSetAndVariantApply) {
  Overrides o;
  o.sets = {"sun_shadow.resolution=512", "final.exposure=-1.5"};
  o.variants = {"final=reinhard"};
  o.size = Extent{100, 50, 1};
  const LoadedConfig c = load(kValid, o);
  EXPECT_EQ(c.graph.resources[0].desc.extent.width, 512u);
  EXPECT_EQ(c.graph.passes[2].decl->variants[c.graph.passes[2].variant].name, "reinhard");
  EXPECT_DOUBLE_EQ(std::get<double>(c.params[2][0]), -1.5);
  EXPECT_EQ(c.graph.output_size, (Extent{100, 50, 1}));
}

TEST_F(Loader, CommandLineErrorsNameTheFlag) {
  Overrides o;
  o.sets = {"sun_shadw.resolution=512"};
  const Diagnostic d = one_error(kValid, "--set sun_shadw.resolution=512", "no pass named \"sun_shadw\"", o);
  EXPECT_EQ(d.where.file, "<command line>");
  Overrides v;
  v.variants = {"final=acse"};
  one_error(kValid, "--variant final=acse", "no variant \"acse\" (did you mean \"aces\"?)", v);
  Overrides bad;
  bad.sets = {"sun_shadow.resolution=huge"};
  one_error(kValid, "--set sun_shadow.resolution=huge", "expects an integer", bad);
}

// Files on disk: includes, their diagnostics and cycles.
class LoaderFiles : public Loader {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("volgraph_loader_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const auto path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }
  std::filesystem::path dir_;
};

TEST_F(LoaderFiles, IncludedFileDiagnosticsNameThatFile) {
  const std::string scene = write("scene.json", "{\n  \"scene\": {\n    \"camera\": { \"fov\": 40 }\n  }\n}\n");
  const std::string main = write("main.json", replace(kValid, "\"output\"", "\"include\": \"scene.json\", \"output\""));
  try {
    load_config(main, registry_);
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    ASSERT_EQ(e.diagnostics().size(), 1u) << e.what();
    EXPECT_EQ(e.diagnostics()[0].where.file, scene);
    EXPECT_EQ(e.diagnostics()[0].where.pointer, "/scene/camera/fov");
    EXPECT_EQ(e.diagnostics()[0].where.line, 3);
  }
}

TEST_F(LoaderFiles, MissingIncludePointsAtTheInclude) {
  const std::string main = write("main.json", replace(kValid, "\"output\"", "\"include\": [\"nope.json\"], \"output\""));
  try {
    load_config(main, registry_);
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.diagnostics()[0].where.file, main);
    EXPECT_EQ(e.diagnostics()[0].where.pointer, "/include/0");
    EXPECT_NE(std::string(e.what()).find("cannot read"), std::string::npos) << e.what();
  }
}

TEST_F(LoaderFiles, IncludeCycleIsReported) {
  write("a.json", "{ \"include\": \"b.json\" }");
  write("b.json", "{ \"include\": \"a.json\" }");
  try {
    load_config((dir_ / "a.json").string(), registry_);
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("include cycle"), std::string::npos) << e.what();
  }
}

TEST_F(LoaderFiles, IncludedPassIsAmendedByName) {
  const std::string graph = write("graph.json", replace(kValid, "\"output\": { \"size\": [64, 32] },", ""));
  const std::string main = write("main.json", R"({
    "include": "graph.json",
    "graph": { "passes": [ { "name": "final", "variant": "aces", "params": { "exposure": 2 } } ] }
  })");
  const LoadedConfig c = load_config(main, registry_);
  EXPECT_EQ(c.graph.passes[2].decl->variants[c.graph.passes[2].variant].name, "aces");
  EXPECT_DOUBLE_EQ(std::get<double>(c.params[2][0]), 2.0);
  EXPECT_EQ(std::get<int64_t>(c.params[0][1]), 256);  // the included setting stays
}

// A named light replaces the included light of that name where it stood; unnamed and new
// names are appended (the viewer's captures move the sun this way).
TEST_F(LoaderFiles, NamedLightReplacesTheIncludedOneInPlace) {
  const std::string base = write("base.json", replace(kValid, R"("lights": [ { "type": "directional",)",
                                                      R"("lights": [ { "name": "sun", "type": "directional",)"));
  const std::string main = write("main.json", R"({
    "include": "base.json",
    "scene": { "lights": [ { "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1] },
                           { "name": "sun", "type": "directional", "direction": [0, -1, -1], "irradiance": [2, 2, 2] } ] }
  })");
  const LoadedConfig c = load_config(main, registry_);
  ASSERT_EQ(c.config.scene.lights.size(), 2u);
  EXPECT_EQ(c.config.scene.lights[0].name, "sun");
  EXPECT_EQ(c.config.scene.lights[0].irradiance[0], 2.0);
  EXPECT_EQ(c.config.scene.lights[0].direction[2], -1.0);
  EXPECT_EQ(c.config.scene.lights[1].type, LightType::point);
}

TEST(MissingFile, ConfigThatDoesNotExist) {
  PassRegistry registry;
  register_builtin_passes(registry);
  try {
    load_config("/no/such/config.json", registry);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.diagnostics()[0].where.file, "/no/such/config.json");
    EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos);
  }
}

// A glTF model loads with what it uses and volgraph does not draw reported as a warning at
// the object's file (format_warning), not refused: the glass vase's alpha-masked flowers are
// not cut in the shadow maps. Its thickness texture is sampled: not named.
TEST_F(Loader, AModelsIgnoredFeaturesAreWarningsAtItsFile) {
  const std::string text = R"({ "output": { "size": [16, 16] },
    "scene": { "camera": { "position": [0, 0.3, 1], "target": [0, 0.1, 0] },
      "objects": [ { "shape": "gltf", "file": ")" + std::string(::volgraph::testing::source_dir()) + R"(/../shared/assets/gltf/GlassVaseFlowers/GlassVaseFlowers.glb" } ],
      "lights": [ { "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1] } ] },
    "graph": { "passes": [ { "name": "lit", "type": "scene" },
      { "name": "out", "type": "composite", "inputs": { "color": "lit.color" } } ], "outputs": ["out.output"] } })";
  const LoadedConfig loaded = load(text);
  ASSERT_FALSE(loaded.warnings.empty());
  bool mask = false;
  for (const Diagnostic& w : loaded.warnings) {
    EXPECT_EQ(w.where.pointer, "/scene/objects/0/file") << format_warning(w);
    mask |= w.message.find("alphaMode MASK") != std::string::npos;
    EXPECT_EQ(w.message.find("thicknessTexture"), std::string::npos) << format_warning(w);
    EXPECT_NE(format_warning(w).find(": warning at /scene/objects/0/file: "), std::string::npos) << format_warning(w);
  }
  EXPECT_TRUE(mask);
  EXPECT_TRUE(load(replace(text, "GlassVaseFlowers/GlassVaseFlowers.glb", "Suzanne/Suzanne.gltf")).warnings.empty());
}

}  // namespace
}  // namespace volgraph
