#!/usr/bin/env bash
# render --backend webgpu with no Vulkan driver (VK_ICD_FILENAMES names a missing file):
# Dawn then offers only its Null backend, which renders nothing. volgraph refuses it —
# exit 1, one line naming it, no image — unless VOLGRAPH_WEBGPU_ALLOW_FALLBACK=1; any
# other value of that variable is bad usage (exit 2).
#   no_vulkan_driver_test.sh VOLGRAPH CONFIG
volgraph=$1
config=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export VK_ICD_FILENAMES="$tmp/no-such-driver.json"

render() { "$volgraph" render "$config" --backend webgpu --size 64x36 -o "$tmp/out.pfm" >"$tmp/stdout" 2>"$tmp/err"; }

render
code=$?
[ "$code" -eq 1 ] || fail "no Vulkan driver: exit $code (expected 1); stderr: $(cat "$tmp/err")"
expected="volgraph: no usable GPU: Dawn offers only the Null backend (no Vulkan driver was found), which renders nothing"
grep -qF -- "$expected" "$tmp/err" || fail "no Vulkan driver: expected '$expected', got: $(cat "$tmp/err")"
[ "$(grep -c '^volgraph:' "$tmp/err")" -eq 1 ] || fail "more than one volgraph line: $(cat "$tmp/err")"
[ ! -e "$tmp/out.pfm" ] || fail "no Vulkan driver: an image was written"

VOLGRAPH_WEBGPU_ALLOW_FALLBACK=1 render || fail "VOLGRAPH_WEBGPU_ALLOW_FALLBACK=1: exit $?; $(cat "$tmp/err")"
[ "$(head -c 2 "$tmp/out.pfm")" = "PF" ] || fail "VOLGRAPH_WEBGPU_ALLOW_FALLBACK=1 wrote no PFM"
rm -f "$tmp/out.pfm"

VOLGRAPH_WEBGPU_ALLOW_FALLBACK=yes render
code=$?
[ "$code" -eq 2 ] || fail "VOLGRAPH_WEBGPU_ALLOW_FALLBACK=yes: exit $code (expected 2); $(cat "$tmp/err")"
grep -qF "VOLGRAPH_WEBGPU_ALLOW_FALLBACK must be 1 or 0" "$tmp/err" || fail "VOLGRAPH_WEBGPU_ALLOW_FALLBACK=yes: $(cat "$tmp/err")"
[ ! -e "$tmp/out.pfm" ] || fail "VOLGRAPH_WEBGPU_ALLOW_FALLBACK=yes: an image was written"
echo "ok"
