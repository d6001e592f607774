#!/usr/bin/env bash
# render --backend webgpu of a frame whose textures lavapipe cannot hold (16384x12000
# rgba32_float is 3 GiB, over its 2 GiB maxMemoryAllocationSize): exit 1, one line that
# says out of device memory and names the texture being created, no image written.
#   out_of_memory_cli_test.sh VOLGRAPH CONFIG
volgraph=$1
config=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$volgraph" render "$config" --backend webgpu --size 16384x12000 -o "$tmp/out.pfm" >"$tmp/stdout" 2>"$tmp/err"
code=$?
[ "$code" -eq 1 ] || fail "exit $code (expected 1); stderr: $(cat "$tmp/err")"
grep -q '^volgraph: out of device memory: Dawn: creating texture ".*" (16384x12000x1, 1 mip levels): .*VK_ERROR_OUT_OF_DEVICE_MEMORY$' "$tmp/err" ||
  fail "expected one out-of-memory line naming the texture, got: $(cat "$tmp/err")"
[ "$(grep -c '^volgraph:' "$tmp/err")" -eq 1 ] || fail "more than one volgraph line: $(cat "$tmp/err")"
! grep -q "device lost" "$tmp/err" || fail "reported as a lost device: $(cat "$tmp/err")"
[ ! -e "$tmp/out.pfm" ] || fail "an image was written"
echo "ok"
