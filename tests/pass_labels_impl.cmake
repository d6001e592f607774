# The machinery behind tests/pass_labels.cmake (the table): a ctest label per pass type.
#
# Configure time (included by tests/CMakeLists.txt, before the test folders):
# - the pass types are the names the code registers (passes/passes.cpp, passes/**.cpp);
# - a config's pass types are read from its JSON (string(JSON)), includes first, as the
#   loader merges them: a pass with "type" defines or replaces the pass of that name;
# - the table's rules are resolved into (regex → pass types).
# ctest time: volgraph_gtest_groups(TARGET LABEL) appends a script to the folder's
# TEST_INCLUDE_FILES that lists TARGET's cases, matches each case's name against the rules
# and adds one ctest test per group of cases with the same suite and pass types
# (tests/gtest_groups_run.cmake).
include_guard(GLOBAL)

set(VOLGRAPH_CONFIGS_DIR ${PROJECT_SOURCE_DIR}/configs)

# The registered pass types: what passes/passes.cpp registers (`registry.add(NAME_pass())`),
# and the names passes/ declares (`d.name = "…"`, `…Table("…", …)`, graph/pass_decl.h).
# Editing passes.cpp or adding a pass file re-runs the configure.
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/passes/passes.cpp)
file(GLOB_RECURSE _vg_pass_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/passes/*.cpp)
set(VOLGRAPH_PASS_TYPES "")
foreach(_vg_source ${_vg_pass_sources})
  file(READ ${_vg_source} _vg_text)
  string(REGEX MATCHALL "registry\\.add\\([A-Za-z0-9_]+_pass\\(\\)\\)" _vg_matches "${_vg_text}")
  foreach(_vg_match ${_vg_matches})
    string(REGEX MATCH "add\\(([A-Za-z0-9_]+)_pass" _vg_name "${_vg_match}")
    list(APPEND VOLGRAPH_PASS_TYPES ${CMAKE_MATCH_1})
  endforeach()
  string(REGEX MATCHALL "d\\.name = \"[A-Za-z0-9_]+\"|Table\\([ \t\r\n]*\"[A-Za-z0-9_]+\"" _vg_matches "${_vg_text}")
  foreach(_vg_match ${_vg_matches})
    string(REGEX MATCH "\"([A-Za-z0-9_]+)\"" _vg_name "${_vg_match}")
    list(APPEND VOLGRAPH_PASS_TYPES ${CMAKE_MATCH_1})
  endforeach()
endforeach()
list(REMOVE_DUPLICATES VOLGRAPH_PASS_TYPES)
list(SORT VOLGRAPH_PASS_TYPES)
if(NOT VOLGRAPH_PASS_TYPES)
  message(WARNING "tests/pass_labels_impl.cmake: no pass declaration found under passes/: no pass-type labels")
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
      message(WARNING "tests/pass_labels_impl.cmake: ${config} uses pass type \"${type}\", "
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

# The rules: parallel global lists of regexes and of their pass types ("a,b,c").
function(_vg_add_rule regex types)
  if("" MATCHES "${regex}")  # an empty name never matches; this also checks the regex compiles
    message(FATAL_ERROR "tests/pass_labels.cmake: the regex \"${regex}\" matches every test name")
  endif()
  if(regex MATCHES ";")
    message(FATAL_ERROR "tests/pass_labels.cmake: no ';' in a regex, please: \"${regex}\"")
  endif()
  get_property(regexes GLOBAL PROPERTY VOLGRAPH_LABEL_REGEXES)
  get_property(all_types GLOBAL PROPERTY VOLGRAPH_LABEL_TYPES)
  list(FIND regexes "${regex}" at)
  if(at EQUAL -1)  # a new regex
    string(REPLACE ";" "," joined "${types}")
    set_property(GLOBAL APPEND PROPERTY VOLGRAPH_LABEL_REGEXES "${regex}")
    set_property(GLOBAL APPEND PROPERTY VOLGRAPH_LABEL_TYPES "${joined}")
  else()  # one the table gave already: one test of it at ctest time
    list(GET all_types ${at} joined)
    string(REPLACE "," ";" merged "${joined}")
    list(APPEND merged ${types})
    list(REMOVE_DUPLICATES merged)
    string(REPLACE ";" "," joined "${merged}")
    list(REMOVE_AT all_types ${at})
    list(INSERT all_types ${at} "${joined}")
    set_property(GLOBAL PROPERTY VOLGRAPH_LABEL_TYPES "${all_types}")
  endif()
endfunction()

# The table's three forms.
# pass_tests(PASS_TYPE REGEX...): the tests whose names match any REGEX exercise PASS_TYPE.
function(pass_tests type)
  if(NOT type IN_LIST VOLGRAPH_PASS_TYPES)
    message(WARNING "tests/pass_labels.cmake: \"${type}\" is not a registered pass type (${VOLGRAPH_PASS_TYPES})")
  endif()
  foreach(regex ${ARGN})
    _vg_add_rule("${regex}" "${type}")
  endforeach()
  set_property(GLOBAL APPEND PROPERTY VOLGRAPH_TABLE_TYPES ${type})
endfunction()

# config_tests(REGEX CONFIG...): the tests matching REGEX run these configs (relative to
# configs/, or SHIPPED): they exercise every pass type the configs use.
function(config_tests regex)
  volgraph_config_pass_types(types ${ARGN})
  if(types)
    _vg_add_rule("${regex}" "${types}")
  endif()
  set_property(GLOBAL APPEND PROPERTY VOLGRAPH_TABLE_TYPES ${types})
endfunction()

# each_shipped_config(PREFIX): tests parameterized over the shipped configs, their
# instances named PREFIX then config_test_name(config) (tests/gpu/shipped_configs.h:
# "tests/lambert_plane.json" → "tests_lambert_plane") and maybe _vulkan / _webgpu: each
# instance exercises the pass types of its own config.
function(each_shipped_config prefix)
  foreach(config ${VOLGRAPH_SHIPPED_CONFIGS})
    string(REGEX REPLACE "\\.json$" "" stem "${config}")
    string(REGEX REPLACE "[^A-Za-z0-9]" "_" stem "${stem}")
    volgraph_config_pass_types(types ${config})
    if(types)
      _vg_add_rule("${prefix}${stem}(_vulkan|_webgpu)?( |$)" "${types}")
    endif()
    set_property(GLOBAL APPEND PROPERTY VOLGRAPH_TABLE_TYPES ${types})
  endforeach()
endfunction()

# quick_tests(REGEX...): the matching tests are in the `quick` label too (the inner loop
# before a commit: every pass type once on each backend at a tiny size; tests/pass_labels.cmake).
function(quick_tests)
  foreach(regex ${ARGN})
    _vg_add_rule("${regex}" quick)
  endforeach()
endfunction()

# The table, read in a function's scope: its variables stay there.
function(_vg_read_table)
  include(${CMAKE_CURRENT_FUNCTION_LIST_DIR}/pass_labels.cmake)
endfunction()
_vg_read_table()

get_property(_vg_covered GLOBAL PROPERTY VOLGRAPH_TABLE_TYPES)
set(_vg_uncovered "")
foreach(_vg_type ${VOLGRAPH_PASS_TYPES})
  if(NOT _vg_type IN_LIST _vg_covered)
    list(APPEND _vg_uncovered ${_vg_type})
  endif()
endforeach()
if(_vg_uncovered)
  message(STATUS "tests/pass_labels.cmake: no GoogleTest rule gives these pass types a label: ${_vg_uncovered}")
endif()

# volgraph_gtest_groups(TARGET LABEL [CASE_SECONDS N] [GROUP_SIZE N] [LABELS L...]): TARGET's
# GoogleTest cases as ctest tests, a group of cases sharing a suite and labels per test
# (tests/gtest_groups_run.cmake, at ctest time), each labelled LABEL and the pass types the
# table gives its cases. CASE_SECONDS: each case's deadline (default 60); GROUP_SIZE: the
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
  get_property(regexes GLOBAL PROPERTY VOLGRAPH_LABEL_REGEXES)
  get_property(types GLOBAL PROPERTY VOLGRAPH_LABEL_TYPES)
  set(script "# Generated by tests/pass_labels_impl.cmake: ${target}'s cases in groups (tests/gtest_groups_run.cmake).\n")
  set(labels ${label} ${arg_LABELS})
  string(APPEND script "set(_vg_binary \"$<TARGET_FILE:${target}>\")\nset(_vg_target ${target})\nset(_vg_label \"${labels}\")\n")
  string(APPEND script "set(_vg_case_seconds ${arg_CASE_SECONDS})\nset(_vg_group_size ${arg_GROUP_SIZE})\n")
  string(APPEND script "set(_vg_regexes \"\")\nset(_vg_types \"\")\n")
  list(LENGTH regexes count)
  if(count GREATER 0)
    math(EXPR last "${count} - 1")
    foreach(i RANGE ${last})
      list(GET regexes ${i} regex)
      list(GET types ${i} joined)
      string(APPEND script "list(APPEND _vg_regexes [==[${regex}]==])\nlist(APPEND _vg_types ${joined})\n")
    endforeach()
  endif()
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
