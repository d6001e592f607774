# Which tests exercise which pass type: `ctest -L froxel_scatter` (or `tools/volgraph test
# -L froxel_scatter`) runs every test that runs or unit-tests that pass type, its shader or
# its CPU twin. The labels are added to the test's own (unit, gpu, cli, …).
#
# - CLI tests (tests/cli): derived, no table — a config's tests get the pass types the
#   config uses, read from its JSON and its includes; a broken config's (cli.bad.*) those
#   of them its .expect message names.
# - GoogleTest tests: this table. Each regex (CMake syntax) is matched against the ctest
#   name: "Suite.Test", or for a parameterized test "Prefix/Suite.Test/param" (e.g.
#   "Backends/FroxelFog.StressLimitsLeaveNoNanOrInfInAnyVolume/vulkan"; CMake 3.25 may add
#   "  # GetParam() = …"). A test whose name matches nothing gets no pass label.
#     pass_tests(PASS_TYPE REGEX...)    the matching tests exercise PASS_TYPE
#     config_tests(REGEX CONFIG...)     the matching tests run these configs (relative to
#                                       configs/; SHIPPED: all): every pass type in them
#     each_shipped_config(PREFIX)       instances PREFIX<config_test_name>[_vulkan|_webgpu]:
#                                       each its own config's pass types
# The pass types are the registered ones (passes/passes.cpp, and the declarations under
# passes/); a name that is not one is a configure warning. The variables below are local
# to this file. Machinery: tests/pass_labels_impl.cmake.

# ---- Tests that share a graph (tests/gpu, tests/unit): one name each ----------------------
# tests/gpu/froxel_fog_test.cpp: scene → froxel_voxelize → froxel_scatter → scatter_integrate
# → froxel_apply → composite (every test but the last, which renders surfaces only).
set(froxel_chain "(^|/)FroxelFog\\.(NothingAppears|APureAbsorber|HillaireIsExact|StressLimits|WithoutAMedium|ADenseBoxShadows|SkippingEmpty)")
# ... with shadow_map → opacity_shadow_map (volumetric shadows by the opacity map).
set(froxel_opacity_shadow "(^|/)FroxelFog\\.(StressLimits|ADenseBoxShadowsTheFogUnderItThroughAnOpacityShadowMap|TheOpacityShadowMapDims)")
# tests/gpu/temporal_fog_test.cpp: froxel_voxelize → froxel_scatter → froxel_temporal.
set(temporal_froxels "(^|/)TemporalFog\\.(TheHistoryPair|AStillCameraWithoutJitter|AStillCameraConvergesToTheAverage|TheDefaultBlend|AfterTheCameraRises|AfterTheCameraMovesTheReprojectedFroxel|StressScenes|PassesAfterATemporalPass)")
# ... scene → raymarch_fog → pixel_temporal.
set(temporal_pixels "(^|/)(TemporalFog\\.(AfterTheCameraMovesTheReprojectedPixel|AStillCameraConvergesForThePerPixelMarch|StressScenes|PassesAfterATemporalPass|APassReadingAHistoryPair)|PixelTemporalFirstFrame\\.)")
# tests/gpu/raymarch_fog_test.cpp: scene → raymarch_fog → fog_apply → composite.
set(raymarch "(^|/)RaymarchFog\\.")
# tests/gpu/closed_fog_test.cpp: scene → depth_fog | height_fog | analytic_fog → fog_apply → composite.
set(closed_fog "(^|/)ClosedFog\\.")
# tests/gpu/light_volume_test.cpp: shadow_map → scene → light_volume, and raymarch_fog beside it.
set(light_volume "(^|/)LightVolume\\.")
# tests/gpu/physics_twins_test.cpp, the shared GLSL includes against their CPU twins:
# phase, media (Hillaire's step, height-fog depth), airlight, light_volume's I(t).
set(twins_physics "(^|/)PhysicsTwins\\.ShadersMatchTheirCpuTwins")
# noise.glsl and media_field.glsl (sample_media: voxelize, the march, light_transmittance).
set(twins_media_field "(^|/)PhysicsTwins\\.NoiseAndMediaField")
# view_rays.glsl, froxel.glsl, temporal_blend.glsl.
set(twins_temporal "(^|/)PhysicsTwins\\.TemporalReprojection")
# tests/unit/phase_test.cpp: phase.h (froxel_scatter's variants, the march, height_fog,
# the airlight of analytic_fog and light_volume).
set(phase "^Phase\\.")
# in_scattering.glsl ↔ physics/in_scattering.h: shared by froxel_scatter and raymarch_fog.
set(in_scattering "^InScattering\\." "(^|/)PhysicsTwins\\.InScattering")
# raymarch_fog_test.cpp's phase-variant test also runs the froxel chain.
set(phase_variants "(^|/)RaymarchFog\\.EveryPhaseVariant")

# ---- The table: pass type → tests ------------------------------------------------------
pass_tests(froxel_voxelize
  "${froxel_chain}" "${phase_variants}" "${temporal_froxels}" "${twins_media_field}")
pass_tests(froxel_scatter
  "${froxel_chain}" ${in_scattering} "${phase_variants}" "${temporal_froxels}" "${twins_physics}" "${twins_media_field}" "${phase}"
  "^SpirvReflect\\.FroxelScatterBlock")          # froxel_scatter.comp's uniform blocks
pass_tests(scatter_integrate
  "${froxel_chain}" "${phase_variants}" "${twins_physics}"
  "(^|/)TemporalFog\\.PassesAfterATemporalPass"
  "^Media\\.(OneMinusExpOverX|HillaireIsExact|WronskiConverges|IntegrationSteps)")  # media.h's steps
pass_tests(froxel_apply
  "${froxel_chain}" "${phase_variants}")
pass_tests(froxel_temporal
  "${temporal_froxels}" "${twins_temporal}"
  "^FroxelReprojection\\." "^TemporalBlend\\.")  # temporal.h, froxel.h
pass_tests(pixel_temporal
  "${temporal_pixels}" "${twins_temporal}" "^TemporalBlend\\.")
pass_tests(raymarch_fog
  "${raymarch}" ${in_scattering} "${light_volume}" "${temporal_pixels}" "${twins_physics}" "${twins_media_field}" "${phase}"
  "^Media\\.(OneMinusExpOverX|HillaireIsExact|WronskiConverges|IntegrationSteps)")
pass_tests(fog_apply
  "${raymarch}" "${closed_fog}" "(^|/)TemporalFog\\.PassesAfterATemporalPass")
pass_tests(analytic_fog
  "(^|/)ClosedFog\\.(AnalyticFog|StressLimits)" "${twins_physics}" "${phase}"
  "^Airlight\\.")                                # airlight.h
pass_tests(height_fog
  "(^|/)ClosedFog\\.(HeightFog|StressLimits)" "${twins_physics}" "${phase}"
  "^Media\\.HeightFog")
pass_tests(depth_fog
  "(^|/)ClosedFog\\.(DepthFog|StressLimits)"
  "^Media\\.DepthFog")
pass_tests(light_volume
  "${light_volume}" "${twins_physics}" "${phase}"
  "^LightVolumeIntegral\\." "^Airlight\\.")     # light_volume_integral.h, airlight.h
pass_tests(opacity_shadow_map
  "${froxel_opacity_shadow}" "${twins_media_field}"
  "^ShadowFit\\.(MediaVolumeBounds|ShadowedBounds)")  # the light's view holds the media
pass_tests(shadow_map
  "${froxel_opacity_shadow}" "${light_volume}"
  "^ShadowFit\\."                                # shadow_fit.h
  "^SpirvReflect\\.ShadowVertex"                 # shadow.vert
  "^Loader\\.ShadowMapLight")                    # its light parameter's checks
pass_tests(scene
  "(^|/)FroxelFog\\." "${raymarch}" "${closed_fog}" "${light_volume}" "${temporal_pixels}"
  "^(Meshes|Gltf|Textures)\\."                   # what the scene pass draws
  "^SpirvReflect\\.(SceneStages|SceneBlocks|SamplingThroughFunctionParameters|UnshadowedScene)")  # scene.vert/.frag
pass_tests(composite
  "(^|/)FroxelFog\\." "${raymarch}" "${closed_fog}"
  "(^|/)TemporalFog\\.APassReadingAHistoryPair"
  "(^|/)CompositeShader\\."                      # composite.comp against its CPU twin
  "^SpirvReflect\\.(CompositeDeclares|CompositeParams|MatchingHostStruct|WorkgroupSize$)"  # composite.comp's interface
  "^WebGpuCpp\\.CompositePipeline" "^WebGpuDevice\\.(CompositePipeline|MismatchedLayout)")  # composite.comp on Dawn
pass_tests(clear
  "(^|/)ExecutorTest\\.APassTypeWithoutAnImplementation"
  "^WebGpuResources\\.(AnUndeclaredUsage|TheSameCopyDeclared)")
# copy: only through configs (tests/clear_composite.json, refraction_copy.json) below.

# ---- Tests that load shipped configs: every pass type in them ----------------------------
each_shipped_config("(^|/)(ConfigRender|CrossBackend|TemporalFirstFrame)\\.[A-Za-z]+/")   # golden images, cross-backend, first frames
config_tests("^WebGpuResources\\.CreatedObjects" SHIPPED)                  # every shipped config
config_tests("(^|/)GraphResourcesTest\\.PlanMemory" demo_primitives.json demo_point_lights.json refraction_copy.json)
config_tests("^ShippedConfigs\\.PointLights" demo_point_lights.json)
config_tests("^ShippedConfigs\\.UnusedUtilityPasses" refraction_copy.json)
config_tests("^ShippedConfigs\\.JsonReport" demo_primitives.json)
config_tests("(^|/)ExecutorTest\\.(ClearedRadiance|DebugSwitches|ToneMaps)" tests/clear_composite.json)
config_tests("(^|/)ExecutorTest\\.LambertPlane" tests/lambert_plane_lit.json)
config_tests("(^|/)ExecutorTest\\.PointLightRadiance" demo_point_lights.json)
config_tests("(^|/)ExecutorTest\\.AlbedoTexture" tests/textured_plane.json)
config_tests("(^|/)ExecutorTest\\.ShadowMappedPlane" tests/lambert_plane.json)
config_tests("(^|/)ExecutorTest\\.FullShadow" tests/full_shadow.json)
config_tests("(^|/)Vignette\\." tests/vignette.json)                              # tests/gpu/vignette_test.cpp
config_tests("(^|/)PassCache\\." demo_fog.json)                                   # tests/gpu/pass_cache_test.cpp
config_tests("(^|/)TemporalFog\\.TheFroxelChainOverFrames" tests/oracle_fog_sphere.json)
config_tests("(^|/)TemporalFog\\.TheFogDemos" demo_fog.json demo_godrays.json demo_raymarch_fog.json)
# tests/accuracy: each technique's graph after the oracle scenes (which include the froxel chain).
config_tests("^FogAccuracy\\.EveryTechnique"
  tests/oracle_global_fog.json tests/oracle_height_fog.json tests/oracle_fog_sphere.json tests/oracle_dense_fog.json
  tests/oracle_point_fog.json tests/oracle_shadowed_fog.json
  graphs/raymarch_fog.json graphs/analytic_fog.json graphs/light_volume_fog.json graphs/height_fog.json)
config_tests("^FogAccuracy\\.FroxelChainConverges" tests/oracle_fog_sphere.json)
config_tests("^FogAccuracy\\.HillaireErrsLess" tests/oracle_dense_fog.json)
config_tests("^FogAccuracy\\.ASunFivePercentDimmer" tests/oracle_global_fog.json)
config_tests("^FogAccuracy\\.NoisyVolume" tests/oracle_noise_volume.json graphs/raymarch_fog.json)
# tests/accuracy/light_attenuation_test.cpp: the shipped graphs, and raymarch_fog at its defaults.
config_tests("^LightAttenuation\\." graphs/froxel_fog.json graphs/analytic_fog.json graphs/light_volume_fog.json graphs/height_fog.json)
pass_tests(raymarch_fog "^LightAttenuation\\.(Point|Sun)")
# tests/reference: the CPU reference against the GPU's golden image of demo_primitives.
config_tests("^ReferenceVersusGpu\\.DemoPrimitivesMatchesTheGoldenImage" demo_primitives.json)

# ---- froxel_voxelize's average (tests/gpu/froxel_voxelize_test.cpp, tests/unit/media_average_test.cpp)
# The slab: scene → froxel_voxelize → froxel_scatter → scatter_integrate → froxel_apply →
# composite; the noise volume: froxel_voxelize alone; the average's CPU twin, and
# media_average.glsl against it.
set(voxelize_slab "(^|/)FroxelVoxelize\\.AnAbsorbingSlab")
set(voxelize_noise "(^|/)FroxelVoxelize\\.JitteredFrames")
pass_tests(froxel_voxelize "${voxelize_slab}" "${voxelize_noise}" "^(MediaAverage|ShapeInterval)\\." "(^|/)PhysicsTwins\\.MediaAverage")
pass_tests(froxel_scatter "${voxelize_slab}")
pass_tests(scatter_integrate "${voxelize_slab}")
pass_tests(froxel_apply "${voxelize_slab}")
pass_tests(scene "${voxelize_slab}")
pass_tests(composite "${voxelize_slab}")

# tests/gpu/atmosphere_sky_test.cpp, atmosphere_sky_view_test.cpp: the LUT passes → scene →
# sky (both variants); tests/reference/sky_view_twin_test.cpp: the sky's CPU twin.
pass_tests(sky "(^|/)(Sky|SkyView)\\." "^SkyViewTwin\\.")
pass_tests(atmosphere_skyview_lut "(^|/)(Sky|SkyView)\\.")

# tests/gpu/atmosphere_bruneton_test.cpp: atmosphere_transmittance_lut → atmosphere_bruneton_tables
# (→ atmosphere_aerial_perspective bruneton, → scene → sky bruneton); tests/unit/atmosphere_bruneton_test.cpp:
# the tables' CPU twin and the pass's shape check.
pass_tests(atmosphere_bruneton_tables "(^|/)AtmosphereBruneton\\." "^AtmosphereBrunetonTables\\.")
# tests/gpu/cloud_noise_test.cpp and tests/unit/cloud_noise_test.cpp (its text, compiled as C++).
pass_tests(cloud_noise "(^|/)CloudNoise\\.")
# tests/unit/cloud_density_test.cpp: the density of the layer cloud_noise's texels make
# (shaders/include/cloud_density.h, compiled as C++).
pass_tests(cloud_noise "(^|/)CloudDensity\\.")
pass_tests(atmosphere_transmittance_lut "(^|/)AtmosphereBruneton\\.")
pass_tests(atmosphere_aerial_perspective "(^|/)AtmosphereBruneton\\.AerialPerspective")
pass_tests(sky "(^|/)AtmosphereBruneton\\.SkyPass")
pass_tests(scene "(^|/)AtmosphereBruneton\\.SkyPass")

# tests/gpu/atmosphere_apply_test.cpp: scene (lit through the air), and scene → the LUTs →
# atmosphere_aerial_perspective (both variants) → aerial_perspective_apply.
pass_tests(scene "(^|/)AtmosphereApply\\.")
pass_tests(aerial_perspective_apply "(^|/)AtmosphereApply\\.ReadsTheAir")
pass_tests(atmosphere_aerial_perspective "(^|/)AtmosphereApply\\.ReadsTheAir")
pass_tests(atmosphere_transmittance_lut "(^|/)AtmosphereApply\\.ReadsTheAir")
pass_tests(atmosphere_multiscattering_lut "(^|/)AtmosphereApply\\.ReadsTheAir")
pass_tests(atmosphere_bruneton_tables "(^|/)AtmosphereApply\\.ReadsTheAir")

# tests/gpu/translucency_test.cpp: scene → translucency (every variant; froxel_apply and
# aerial_perspective_apply beside it for the fogged and air-seen sheets);
# tests/gpu/shadow_casters_test.cpp: shadow_map's masked casters; tests/unit: the shared
# optics (physics/translucency.h), the material keys, glTF's extensions; the reference's
# translucent rays; the accuracy test against them.
pass_tests(translucency "(^|/)Translucency\\." "^TranslucencyConfig\\." "^GltfTranslucency\\." "^TranslucencyReference\\."
  "^TranslucencyAccuracy\\.")
pass_tests(scene "(^|/)Translucency\\.")
pass_tests(shadow_map "(^|/)ShadowCasters\\.")

# ---- quick: the inner loop before a commit (`tools/volgraph test -L quick`) ----------------
# Every pass type once on each backend at 64×36, through the shipped configs that together
# use them all (the golden-image case of each; unit tests, the loader's good and bad configs
# and the reference on demo_primitives carry the label from their own CMakeLists).
set(quick_configs demo_atmosphere_sunset_fog demo_atmosphere_noon_bruneton demo_raymarch_fog demo_attenuation_test tests_vignette
                  demo_analytic_fog demo_atmosphere_haze demo_depth_fog demo_light_volume demo_primitives)
string(REPLACE ";" "|" quick_alternatives "${quick_configs}")
quick_tests("(^|/)ConfigRender\\.MatchesItsGoldenImage/(${quick_alternatives})_(vulkan|webgpu)$")
set(quick_files "")
foreach(config ${quick_configs})
  string(REGEX REPLACE "^tests_" "tests/" file "${config}")
  list(APPEND quick_files "${file}.json")
endforeach()
volgraph_config_pass_types(quick_types ${quick_files})
foreach(type ${VOLGRAPH_PASS_TYPES})
  if(NOT type IN_LIST quick_types)
    message(WARNING "tests/pass_labels.cmake: no quick config uses the pass type ${type}: add one to quick_configs")
  endif()
endforeach()
