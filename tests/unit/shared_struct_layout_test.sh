#!/usr/bin/env bash
# A struct written once for GLSL and C++ (shaders/include/gpu_struct.h) whose C++ layout
# differs from the shader's does not compile: the bindings header the build writes
# (shaders/binding_names.cpp) asserts its size and offsets. A scalar array (std140 strides
# it by 16, C++ by 4) must fail, naming the struct; the same struct with a vec4 array must
# compile (the control).
#   shared_struct_layout_test.sh <volgraph_binding_names> <source root> <c++ compiler>
set -euo pipefail
generator="$1" root="$2" cxx="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/shaders/include"
cp "$root/shaders/include/gpu_struct.h" "$work/shaders/include/"

attempt() {  # attempt MEMBER: writes the struct with MEMBER, returns the compiler's status
  cat >"$work/shaders/include/probe_params.h" <<HEADER
#ifndef PROBE_PARAMS_H
#define PROBE_PARAMS_H
#include "gpu_struct.h"
GPU_BEGIN
GPU_STRUCT(ProbeParams) {
  vec4 first;
  $1
};
GPU_END
#endif
HEADER
  cat >"$work/shaders/probe.comp" <<'SHADER'
#version 450
#extension GL_GOOGLE_include_directive : require
#include "include/probe_params.h"
layout(local_size_x = 1) in;
layout(set = 0, binding = 0) uniform ProbeBlock { ProbeParams params; };
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D probe_out;
void main() { imageStore(probe_out, ivec2(0), params.first * params.weights[1].x); }
SHADER
  sed -i 's/params.weights\[1\].x/params.weights[1]/' "$work/shaders/probe.comp"
  [ "$2" = vec4 ] && sed -i 's/params.weights\[1\])/params.weights[1].x)/' "$work/shaders/probe.comp"
  glslangValidator --quiet --target-env vulkan1.1 -o "$work/probe.spv" "$work/shaders/probe.comp"
  "$generator" "$work/probe.spv" probe_comp "$work/probe.comp.h" "ProbeParams=shaders/include/probe_params.h"
  printf '#include "probe.comp.h"\n' >"$work/use.cpp"
  "$cxx" -std=c++20 -fsyntax-only -I"$root" -I"$work" "$work/use.cpp" >"$work/log" 2>&1
}

if attempt "float weights[2];" float; then
  echo "FAIL: a scalar array in a shared struct compiled; std140 strides it by 16" >&2
  exit 1
fi
grep -q "ProbeParams" "$work/log" || { echo "FAIL: the error does not name the struct:" >&2; cat "$work/log" >&2; exit 1; }
echo "refused as expected: $(grep -m1 -o 'ProbeParams[^"]*' "$work/log")"
if ! attempt "vec4 weights[2];" vec4; then
  echo "FAIL: the control (a vec4 array) did not compile:" >&2
  cat "$work/log" >&2
  exit 1
fi
echo "the control compiles"
