#!/usr/bin/env bash
# Puts Dawn (libwebgpu_wrapper.so from the npm package bun-webgpu-linux-x64, pinned) into
# the build tree: BUILD/_deps/dawn/lib/libwebgpu_wrapper.so. Idempotent: nothing is
# fetched when the library is there with the recorded checksum.
#   tools/fetch_dawn.sh [BUILD_DIR]        (default: build/ beside tools/)
# The tarball is checked against the registry's sha512 integrity recorded here, the
# library against its sha256, so a changed package is refused rather than used.
set -euo pipefail

package="bun-webgpu-linux-x64"
version="0.1.7"
# npm's "integrity" of bun-webgpu-linux-x64-0.1.7.tgz (sha512, hex of the base64 value
# sha512-UEP7UZdEhx9otvkZczjsszL8ZVlrODANQvgl+C88/bNVmxDoFi7w1fWzGi1sZyakiETjmtFDq2/xCLhbSZxjqw==).
tarball_sha512="5043fb519744871f68b6f9197338ecb332fc65596b38300d42f825f82f3cfdb3559b10e8162ef0d5f5b31a2d6c6726a48844e39ad143ab6ff108b85b499c63ab"
library_sha256="3190c3777f2c07fcf6a0640833cbf5d0cde859dc53aed6d9083946d093198788"

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-${VOLGRAPH_BUILD_DIR:-$root/build}}"
dest="$build/_deps/dawn/lib"
library="$dest/libwebgpu_wrapper.so"

sha256_of() { sha256sum "$1" | cut -d' ' -f1; }

if [ -f "$library" ] && [ "$(sha256_of "$library")" = "$library_sha256" ]; then
  exit 0
fi
if ! command -v npm >/dev/null; then
  echo "volgraph fetch_dawn: npm is missing; WebGPU targets will be skipped" >&2
  exit 0
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "volgraph fetch_dawn: fetching $package@$version (Dawn) into $dest" >&2
(cd "$work" && npm pack --silent "$package@$version" >/dev/null 2>"$work/npm.log") || {
  cat "$work/npm.log" >&2
  echo "volgraph fetch_dawn: npm pack failed" >&2
  exit 1
}
tgz="$work/$package-$version.tgz"
if [ "$(sha512sum "$tgz" | cut -d' ' -f1)" != "$tarball_sha512" ]; then
  echo "volgraph fetch_dawn: $package-$version.tgz does not match its recorded sha512; refusing it" >&2
  exit 1
fi
tar -xzf "$tgz" -C "$work" package/libwebgpu_wrapper.so package/LICENSE
if [ "$(sha256_of "$work/package/libwebgpu_wrapper.so")" != "$library_sha256" ]; then
  echo "volgraph fetch_dawn: libwebgpu_wrapper.so does not match its recorded sha256; refusing it" >&2
  exit 1
fi
mkdir -p "$dest"
cp "$work/package/LICENSE" "$build/_deps/dawn/LICENSE-$package"
# Copy, then rename: a reader never sees a half-written library.
cp "$work/package/libwebgpu_wrapper.so" "$library.tmp"
mv "$library.tmp" "$library"
