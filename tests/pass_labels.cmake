# A ctest label per pass type, derived from the tree: no table is kept by hand.
#
# Configure time (included by tests/CMakeLists.txt, before the test folders):
# - the pass types are the names the files under passes/ declare (`PassTable("name", …)`),
#   each with its source file;
# - a config's pass types are read from its JSON (string(JSON)), includes first, as the
#   loader merges them: a pass with "type" defines or replaces the pass of that name;
# - a file's facts are what it includes (#include, resolved in the tree) and the shaders it
#   names ("x.comp"), transitively: a pass's facts are its source's; a header that half the
#   pass types or more reach (graph plumbing, the camera) is infrastructure, not a fact;
# - a test source exercises a pass type when (1) it is named after it (`<pass>_test.cpp`),
#   (2) it names it as a string ("froxel_scatter", or `"type": "froxel_scatter"` in a
#   config it writes), it or a helper header of its own under tests/ (a pass's test file
#   that builds its config with the family's shared helper), (3) it names a config (".json" under configs/), whose pass types
#   it gets, or, where it names none of these, (4) its facts meet the pass's (it includes
#   physics/phase.h, or runs a twin shader that includes phase.glsl, as froxel_scatter's
#   shaders do): a test of shared physics is a test of every pass built on it.
# ctest time: volgraph_gtest_groups(TARGET LABEL) appends a script to the folder's
# TEST_INCLUDE_FILES that lists TARGET's cases with their source files (GoogleTest's JSON
# listing), gives each case its file's pass types — or, for a case parameterized by a
# shipped config (".../demo_fog_vulkan"), that config's — and adds one ctest test per group
# of cases with the same suite and labels (tests/gtest_groups_run.cmake).
include_guard(GLOBAL)

set(VOLGRAPH_CONFIGS_DIR ${PROJECT_SOURCE_DIR}/configs)

# The registered pass types, each with the file that declares it (`…Table("name", …)`,
# graph/pass_decl.h; `d.name = "…"` in older declarations). Adding a pass file re-runs the
# configure.
file(GLOB_RECURSE _vg_pass_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/passes/*.cpp)
set(VOLGRAPH_PASS_TYPES "")
foreach(_vg_source ${_vg_pass_sources})
  file(READ ${_vg_source} _vg_text)
  string(REGEX MATCHALL "d\\.name = \"[A-Za-z0-9_]+\"|Table\\([ \t\r\n]*\"[A-Za-z0-9_]+\"" _vg_matches "${_vg_text}")
  foreach(_vg_match ${_vg_matches})
    string(REGEX MATCH "\"([A-Za-z0-9_]+)\"" _vg_name "${_vg_match}")
    list(APPEND VOLGRAPH_PASS_TYPES ${CMAKE_MATCH_1})
    set_property(GLOBAL APPEND PROPERTY VOLGRAPH_PASS_SOURCE_${CMAKE_MATCH_1} ${_vg_source})
  endforeach()
endforeach()
list(REMOVE_DUPLICATES VOLGRAPH_PASS_TYPES)
list(SORT VOLGRAPH_PASS_TYPES)
if(NOT VOLGRAPH_PASS_TYPES)
  message(WARNING "tests/pass_labels.cmake: no pass declaration found under passes/: no pass-type labels")
endif()

# The shipped configs, as tests/gpu/shipped_configs.cpp and tests/cli list them: relative
# to configs/, sorted.
file(GLOB _vg_shipped CONFIGURE_DEPENDS RELATIVE ${VOLGRAPH_CONFIGS_DIR}
  ${VOLGRAPH_CONFIGS_DIR}/*.json ${VOLGRAPH_CONFIGS_DIR}/tests/*.json)
list(SORT _vg_shipped)
set(VOLGRAPH_SHIPPED_CONFIGS ${_vg_shipped})

# "name=type" for every pass `file` defines with a type, in the loader's order: its
# includes first (relative to the including file), then its own graph.passes. A file that
# does not exist or does not parse contributes nothing.
function(_vg_config_assignments file depth out)
  set(result "")
  if(depth GREATER 16 OR NOT EXISTS "${file}")
    set(${out} "" PARENT_SCOPE)
    return()
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${file}")
  file(READ "${file}" json)
  get_filename_component(dir "${file}" DIRECTORY)
  math(EXPR next "${depth} + 1")
  string(JSON include_type ERROR_VARIABLE error TYPE "${json}" include)
  set(includes "")
  if(NOT error AND include_type STREQUAL "STRING")
    string(JSON includes GET "${json}" include)
  elseif(NOT error AND include_type STREQUAL "ARRAY")
    string(JSON count LENGTH "${json}" include)
    if(count GREATER 0)
      math(EXPR last "${count} - 1")
      foreach(i RANGE ${last})
        string(JSON one GET "${json}" include ${i})
        list(APPEND includes "${one}")
      endforeach()
    endif()
  endif()
  foreach(relative ${includes})
    cmake_path(ABSOLUTE_PATH relative BASE_DIRECTORY "${dir}" NORMALIZE OUTPUT_VARIABLE included)
    _vg_config_assignments("${included}" ${next} sub)
    list(APPEND result ${sub})
  endforeach()
  string(JSON passes_type ERROR_VARIABLE error TYPE "${json}" graph passes)
  if(NOT error AND passes_type STREQUAL "ARRAY")
    string(JSON count LENGTH "${json}" graph passes)
    if(count GREATER 0)
      math(EXPR last "${count} - 1")
      foreach(i RANGE ${last})
        string(JSON name ERROR_VARIABLE name_error GET "${json}" graph passes ${i} name)
        string(JSON type ERROR_VARIABLE type_error GET "${json}" graph passes ${i} type)
        if(NOT name_error AND NOT type_error)
          list(APPEND result "${name}=${type}")
        endif()
      endforeach()
    endif()
  endif()
  set(${out} ${result} PARENT_SCOPE)
endfunction()

# The registered pass types one config uses (after its includes and replacements).
function(_vg_one_config_pass_types config out)
  _vg_config_assignments("${config}" 0 assignments)
  set(names "")
  foreach(assignment ${assignments})
    string(REGEX MATCH "^([^=]*)=(.*)$" _ "${assignment}")
    set(type_of_${CMAKE_MATCH_1} "${CMAKE_MATCH_2}")
    list(APPEND names "${CMAKE_MATCH_1}")
  endforeach()
  set(types "")
  if(names)
    list(REMOVE_DUPLICATES names)
  endif()
  foreach(name ${names})
    set(type "${type_of_${name}}")
    if(type IN_LIST VOLGRAPH_PASS_TYPES)
      list(APPEND types "${type}")
    elseif(NOT config MATCHES "/tests/cli/bad/")  # a broken config may misspell one
      message(WARNING "tests/pass_labels.cmake: ${config} uses pass type \"${type}\", "
                      "which is not among the declarations found under passes/ (${VOLGRAPH_PASS_TYPES})")
    endif()
  endforeach()
  set(${out} ${types} PARENT_SCOPE)
endfunction()

# volgraph_config_pass_types(OUT CONFIG...): the pass types the configs use, sorted. A
# config is a path, absolute or relative to configs/; SHIPPED stands for every shipped one.
function(volgraph_config_pass_types out)
  set(configs "")
  foreach(config ${ARGN})
    if(config STREQUAL "SHIPPED")
      list(APPEND configs ${VOLGRAPH_SHIPPED_CONFIGS})
    else()
      list(APPEND configs ${config})
    endif()
  endforeach()
  set(types "")
  foreach(config ${configs})
    if(NOT IS_ABSOLUTE "${config}")
      set(config "${VOLGRAPH_CONFIGS_DIR}/${config}")
    endif()
    if(NOT EXISTS "${config}")
      message(WARNING "tests/pass_labels.cmake: no config ${config}")
    endif()
    _vg_one_config_pass_types("${config}" one)
    list(APPEND types ${one})
  endforeach()
  if(types)
    list(REMOVE_DUPLICATES types)
    list(SORT types)
  endif()
  set(${out} ${types} PARENT_SCOPE)
endfunction()

# ---- Facts: what a file includes and the shaders it names ------------------------------
# _vg_direct(FILE OUT): the files of the tree FILE includes (#include "…", resolved from its
# folder, the root, shaders/ and shaders/include/) or names as a shader ("x.comp", from
# shaders/ and the tests' shader folders).
function(_vg_direct file out)
  set(direct "")
  if(EXISTS "${file}" AND NOT IS_DIRECTORY "${file}")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${file}")
    file(READ "${file}" text)
    get_filename_component(dir "${file}" DIRECTORY)
    set(root "${PROJECT_SOURCE_DIR}")
    string(REGEX MATCHALL "#[ \t]*include[ \t]+\"[^\"]+\"" includes "${text}")
    string(REGEX MATCHALL "\"[A-Za-z0-9_]+\\.(comp|vert|frag)\"" shaders "${text}")
    foreach(line ${includes} ${shaders})
      string(REGEX MATCH "\"([^\"]+)\"" _ "${line}")
      set(name "${CMAKE_MATCH_1}")
      foreach(base "${dir}" "${root}" "${root}/shaders" "${root}/shaders/include" "${root}/tests/gpu/shaders" "${root}/tests/unit/shaders")
        if(EXISTS "${base}/${name}" AND NOT IS_DIRECTORY "${base}/${name}")
          cmake_path(ABSOLUTE_PATH name BASE_DIRECTORY "${base}" NORMALIZE OUTPUT_VARIABLE found)
          list(APPEND direct "${found}")
          break()
        endif()
      endforeach()
    endforeach()
    list(REMOVE_DUPLICATES direct)
  endif()
  set(${out} "${direct}" PARENT_SCOPE)
endfunction()

# _vg_closure(FILE OUT): every file of the tree FILE reaches (not FILE itself), memoized.
function(_vg_closure file out)
  string(MAKE_C_IDENTIFIER "${file}" key)
  get_property(known GLOBAL PROPERTY _VG_CLOSURE_${key} SET)
  if(known)
    get_property(result GLOBAL PROPERTY _VG_CLOSURE_${key})
    set(${out} "${result}" PARENT_SCOPE)
    return()
  endif()
  set_property(GLOBAL PROPERTY _VG_CLOSURE_${key} "")  # a cycle ends here
  _vg_direct("${file}" direct)
  set(result "")
  foreach(next ${direct})
    list(APPEND result "${next}")
    _vg_closure("${next}" sub)
    list(APPEND result ${sub})
  endforeach()
  if(result)
    list(REMOVE_DUPLICATES result)
  endif()
  set_property(GLOBAL PROPERTY _VG_CLOSURE_${key} "${result}")
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

# A fact is a file under physics/, shaders/ or passes/ (graph/, tests/ and third parties are
# the frame around them). A pass's facts: everything its source reaches.
function(_vg_facts file out)
  _vg_closure("${file}" closure)
  set(facts "")
  foreach(reached ${closure})
    if(reached MATCHES "^${PROJECT_SOURCE_DIR}/(physics|shaders|passes)/")
      list(APPEND facts "${reached}")
    endif()
  endforeach()
  set(${out} "${facts}" PARENT_SCOPE)
endfunction()

# A test's facts are narrower: what it (or a helper of its own under tests/) includes
# directly, a CPU twin standing for its shader text (physics/media.h for
# shaders/include/media.glsl), and the shaders it runs with all they include — not what
# physics/atmosphere.h happens to include.
function(_vg_test_facts file out)
  _vg_direct("${file}" direct)
  set(facts "")
  foreach(reached ${direct})
    if(reached MATCHES "^${PROJECT_SOURCE_DIR}/tests/.*\\.h$")
      _vg_test_facts("${reached}" more)
      list(APPEND facts ${more})
    elseif(reached MATCHES "\\.(comp|vert|frag)$")
      _vg_closure("${reached}" more)
      list(APPEND facts "${reached}" ${more})
    elseif(reached MATCHES "^${PROJECT_SOURCE_DIR}/physics/([A-Za-z0-9_]+)\\.h$")
      set(twin "${PROJECT_SOURCE_DIR}/shaders/include/${CMAKE_MATCH_1}.glsl")
      list(APPEND facts "${reached}")
      if(EXISTS "${twin}")
        list(APPEND facts "${twin}")
      endif()
    elseif(reached MATCHES "^${PROJECT_SOURCE_DIR}/(shaders|passes)/")
      list(APPEND facts "${reached}")
    endif()
  endforeach()
  set(${out} "${facts}" PARENT_SCOPE)
endfunction()

# Each pass type's facts: its source and what it reaches; then the infrastructure, the facts
# half the pass types or more share, is taken out of every set.
list(LENGTH VOLGRAPH_PASS_TYPES _vg_type_count)
set(_vg_all_facts "")
foreach(_vg_type ${VOLGRAPH_PASS_TYPES})
  get_property(_vg_sources GLOBAL PROPERTY VOLGRAPH_PASS_SOURCE_${_vg_type})
  set(_vg_facts_of_type ${_vg_sources})
  foreach(_vg_source ${_vg_sources})
    _vg_facts("${_vg_source}" _vg_more)
    list(APPEND _vg_facts_of_type ${_vg_more})
  endforeach()
  list(REMOVE_DUPLICATES _vg_facts_of_type)
  set(_vg_facts_${_vg_type} ${_vg_facts_of_type})
  foreach(_vg_fact ${_vg_facts_of_type})
    string(MAKE_C_IDENTIFIER "${_vg_fact}" _vg_key)
    if(NOT DEFINED _vg_reach_${_vg_key})
      set(_vg_reach_${_vg_key} 0)
      list(APPEND _vg_all_facts "${_vg_fact}")
    endif()
    math(EXPR _vg_reach_${_vg_key} "${_vg_reach_${_vg_key}} + 1")
  endforeach()
endforeach()
math(EXPR _vg_infrastructure_reach "(${_vg_type_count} + 1) / 2")
set(VOLGRAPH_INFRASTRUCTURE_FACTS "")
foreach(_vg_fact ${_vg_all_facts})
  string(MAKE_C_IDENTIFIER "${_vg_fact}" _vg_key)
  if(_vg_reach_${_vg_key} GREATER_EQUAL _vg_infrastructure_reach)
    list(APPEND VOLGRAPH_INFRASTRUCTURE_FACTS "${_vg_fact}")
  endif()
endforeach()
foreach(_vg_type ${VOLGRAPH_PASS_TYPES})
  if(VOLGRAPH_INFRASTRUCTURE_FACTS)
    list(REMOVE_ITEM _vg_facts_${_vg_type} ${VOLGRAPH_INFRASTRUCTURE_FACTS})
  endif()
  set_property(GLOBAL PROPERTY VOLGRAPH_PASS_FACTS_${_vg_type} "${_vg_facts_${_vg_type}}")
endforeach()

# _vg_test_helper_headers(FILE OUT): the headers under tests/ FILE includes, and theirs:
# the helpers a split test file shares with its family (tests/gpu/closed_fog.h).
function(_vg_test_helper_headers file out)
  _vg_direct("${file}" direct)
  set(helpers "")
  foreach(reached ${direct})
    if(reached MATCHES "^${PROJECT_SOURCE_DIR}/tests/.*\\.h$" AND NOT reached STREQUAL file)
      _vg_test_helper_headers("${reached}" more)
      list(APPEND helpers "${reached}" ${more})
    endif()
  endforeach()
  if(helpers)
    list(REMOVE_DUPLICATES helpers)
  endif()
  set(${out} "${helpers}" PARENT_SCOPE)
endfunction()

# volgraph_test_file_pass_types(FILE OUT): the pass types a test source exercises (the four
# rules at the top of this file), sorted.
function(volgraph_test_file_pass_types file out)
  set(types "")
  get_filename_component(stem "${file}" NAME_WE)
  string(REGEX REPLACE "_test$" "" stem "${stem}")
  foreach(type ${VOLGRAPH_PASS_TYPES})                     # (1) named after the pass
    if(stem STREQUAL type OR stem MATCHES "^${type}_")     #     (light_volume_integral_test.cpp)
      list(APPEND types "${type}")
    endif()
  endforeach()
  file(READ "${file}" text)
  _vg_test_helper_headers("${file}" helpers)
  set(named_text "${text}")
  foreach(helper ${helpers})
    file(READ "${helper}" helper_text)
    string(APPEND named_text "\n${helper_text}")
  endforeach()
  # A string that is not a JSON key ("scene": {…} is the scene, not the pass).
  string(REGEX MATCHALL "\"[A-Za-z0-9_]+\"[ \t]*[^ \t:]" quoted "${named_text}")
  foreach(word ${quoted})                                  # (2) the pass named
    string(REGEX REPLACE "^\"([A-Za-z0-9_]+)\".*$" "\\1" word "${word}")
    if(word IN_LIST VOLGRAPH_PASS_TYPES)
      list(APPEND types "${word}")
    endif()
  endforeach()
  string(REGEX MATCHALL "\"[A-Za-z0-9_./]+\\.json\"" named_configs "${text}")
  foreach(config ${named_configs})                         # (3) a config named
    string(REGEX REPLACE "^\"(configs/)?|\"$" "" config "${config}")
    if(EXISTS "${VOLGRAPH_CONFIGS_DIR}/${config}")
      _vg_one_config_pass_types("${VOLGRAPH_CONFIGS_DIR}/${config}" more)
      list(APPEND types ${more})
    endif()
  endforeach()
  set(facts "")
  if(NOT types)                                            # (4) the facts shared, where
    _vg_test_facts("${file}" facts)                        #     no pass or config is named
  endif()
  if(facts AND VOLGRAPH_INFRASTRUCTURE_FACTS)
    list(REMOVE_ITEM facts ${VOLGRAPH_INFRASTRUCTURE_FACTS})
  endif()
  if(facts)
    foreach(type ${VOLGRAPH_PASS_TYPES})
      get_property(pass_facts GLOBAL PROPERTY VOLGRAPH_PASS_FACTS_${type})
      foreach(fact ${facts})
        if(fact IN_LIST pass_facts)
          list(APPEND types "${type}")
          break()
        endif()
      endforeach()
    endforeach()
  endif()
  if(types)
    list(REMOVE_DUPLICATES types)
    list(SORT types)
  endif()
  set(${out} "${types}" PARENT_SCOPE)
endfunction()

# quick: the inner loop before a commit (`tools/volgraph test -L quick`): every pass type
# once on each backend at 64×36, through the golden-image cases of the shipped configs that
# together use them all (unit tests, the loader's good and bad configs and the reference on
# demo_primitives carry the label from their own CMakeLists). A pass type no quick config
# uses is a configure warning.
set(VOLGRAPH_QUICK_CONFIGS demo_atmosphere_sunset_fog demo_atmosphere_noon_bruneton demo_raymarch_fog demo_attenuation_test
    tests_vignette demo_analytic_fog demo_atmosphere_haze demo_depth_fog demo_light_volume demo_primitives demo_clouds demo_clouds_weather tests_oracle_clouds_mie
    demo_clouds_temporal demo_rough_glass demo_volume_phantom demo_volume_file demo_voxels demo_glass_of_water)
set(_vg_quick_files "")
foreach(_vg_config ${VOLGRAPH_QUICK_CONFIGS})
  string(REGEX REPLACE "^tests_" "tests/" _vg_file "${_vg_config}")
  list(APPEND _vg_quick_files "${_vg_file}.json")
endforeach()
volgraph_config_pass_types(_vg_quick_types ${_vg_quick_files})
foreach(_vg_type ${VOLGRAPH_PASS_TYPES})
  if(NOT _vg_type IN_LIST _vg_quick_types)
    message(WARNING "tests/pass_labels.cmake: no quick config uses the pass type ${_vg_type}: add one to VOLGRAPH_QUICK_CONFIGS")
  endif()
endforeach()

# volgraph_gtest_groups(TARGET LABEL [CASE_SECONDS N] [GROUP_SIZE N] [LABELS L...]): TARGET's
# GoogleTest cases as ctest tests, a group of cases sharing a suite and labels per test
# (tests/gtest_groups_run.cmake, at ctest time), each labelled LABEL and the pass types of
# its cases' source file (or of the shipped config a case is parameterized by). CASE_SECONDS: each case's deadline (default 60); GROUP_SIZE: the
# most cases a group runs (default 16). TARGET links volgraph_gtest_main
# (tests/support/gtest_main.cpp), whose --case-seconds enforces the deadline.
# LABELS: more labels for every case (e.g. quick).
function(volgraph_gtest_groups target label)
  cmake_parse_arguments(arg "" "CASE_SECONDS;GROUP_SIZE" "LABELS" ${ARGN})
  if(NOT arg_CASE_SECONDS)
    set(arg_CASE_SECONDS 60)
  endif()
  if(NOT arg_GROUP_SIZE)
    set(arg_GROUP_SIZE 16)
  endif()
  target_link_libraries(${target} PRIVATE volgraph_gtest_main)
  set(script "# Generated by tests/pass_labels.cmake: ${target}'s cases in groups (tests/gtest_groups_run.cmake).\n")
  set(labels ${label} ${arg_LABELS})
  string(APPEND script "set(_vg_binary \"$<TARGET_FILE:${target}>\")\nset(_vg_target ${target})\nset(_vg_label \"${labels}\")\n")
  string(APPEND script "set(_vg_case_seconds ${arg_CASE_SECONDS})\nset(_vg_group_size ${arg_GROUP_SIZE})\n")
  # Each test source's pass types, by its path from the project's root (as GoogleTest
  # reports it: the build maps the root away, -fmacro-prefix-map).
  get_target_property(sources ${target} SOURCES)
  foreach(source ${sources})
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE OUTPUT_VARIABLE path)
    if(NOT path MATCHES "\\.cpp$" OR NOT EXISTS "${path}")
      continue()
    endif()
    volgraph_test_file_pass_types("${path}" types)
    file(RELATIVE_PATH relative "${PROJECT_SOURCE_DIR}" "${path}")
    string(MAKE_C_IDENTIFIER "${relative}" key)
    string(APPEND script "set(_vg_file_types_${key} \"${types}\")\n")
  endforeach()
  # Each shipped config's pass types, by config_test_name (tests/gpu/shipped_configs.h:
  # "tests/lambert_plane.json" → "tests_lambert_plane"), and the quick ones.
  foreach(config ${VOLGRAPH_SHIPPED_CONFIGS})
    string(REGEX REPLACE "\\.json$" "" stem "${config}")
    string(REGEX REPLACE "[^A-Za-z0-9]" "_" stem "${stem}")
    volgraph_config_pass_types(types ${config})
    string(APPEND script "set(_vg_config_types_${stem} \"${types}\")\n")
  endforeach()
  string(APPEND script "set(_vg_quick_configs \"${VOLGRAPH_QUICK_CONFIGS}\")\n")
  string(APPEND script "include([==[${CMAKE_CURRENT_FUNCTION_LIST_DIR}/gtest_groups_run.cmake]==])\n")
  set(file "${CMAKE_CURRENT_BINARY_DIR}/${target}_groups.cmake")
  file(GENERATE OUTPUT "${file}" CONTENT "${script}")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${file}")
endfunction()

# volgraph_label_config_tests(CONFIG TEST...): add the pass types CONFIG uses to the
# tests' LABELS (after their set_tests_properties(... LABELS ...)).
function(volgraph_label_config_tests config)
  volgraph_config_pass_types(types "${config}")
  if(types)
    set_property(TEST ${ARGN} APPEND PROPERTY LABELS ${types})
  endif()
endfunction()

# volgraph_label_bad_config_tests(CONFIG EXPECT_FILE TEST...): a broken config's test
# exercises the pass types its config uses that its expected message names (the rest of
# such a config is scaffolding around the one error).
function(volgraph_label_bad_config_tests config expect_file)
  volgraph_config_pass_types(types "${config}")
  set(named "")
  if(EXISTS "${expect_file}")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${expect_file}")
    file(READ "${expect_file}" expect)
    foreach(type ${types})
      if(expect MATCHES "(^|[^A-Za-z0-9_/])${type}([^A-Za-z0-9_/]|$)")  # not in a JSON pointer
        list(APPEND named ${type})
      endif()
    endforeach()
  endif()
  if(named)
    set_property(TEST ${ARGN} APPEND PROPERTY LABELS ${named})
  endif()
endfunction()
