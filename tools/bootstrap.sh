#!/usr/bin/env bash
# Installs the Debian packages volgraph builds and tests with, when any is missing:
# chromium loads the A/B reports in the browser test, GNU parallel runs emitted sweep
# jobs, rsvg-convert (librsvg2-bin) turns a sweep's SVG plot into its PNG; GLFW opens
# `volgraph view`'s window, which its tests open under xvfb-run (xvfb, xauth); Dear ImGui
# (libimgui-dev, with its GLFW and Vulkan backends) draws the viewer's overlay.
# Idempotent: a few dpkg queries when everything is there.
set -euo pipefail

packages=(
  cmake ninja-build ccache clang lld libclang-rt-14-dev
  nlohmann-json3-dev googletest libgtest-dev libbenchmark-dev
  graphviz
  libvulkan-dev vulkan-validationlayers glslang-tools spirv-tools
  libstb-dev libopenexr-dev libtinygltf-dev
  libglm-dev libcli11-dev libspirv-cross-c-shared-dev
  chromium parallel librsvg2-bin
  libglfw3-dev xvfb xauth libimgui-dev
)
# Dawn refuses bookworm's lavapipe (Mesa 22); Mesa 25 comes from bookworm-backports.
backports=(mesa-vulkan-drivers)

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
mesa_major() { dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null | cut -d. -f1; }

missing=()
for p in "${packages[@]}"; do installed "$p" || missing+=("$p"); done
need_backports=0
if ! installed mesa-vulkan-drivers || [ "$(mesa_major)" -lt 25 ]; then need_backports=1; fi
[ ${#missing[@]} -eq 0 ] && [ $need_backports -eq 0 ] && exit 0

sudo=()
[ "$(id -u)" -ne 0 ] && sudo=(sudo)
export DEBIAN_FRONTEND=noninteractive
if [ $need_backports -eq 1 ] && ! grep -rqs "bookworm-backports" /etc/apt/sources.list /etc/apt/sources.list.d/; then
  echo "volgraph bootstrap: adding bookworm-backports (for Mesa 25)" >&2
  printf 'Types: deb\nURIs: http://deb.debian.org/debian\nSuites: bookworm-backports\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' |
    "${sudo[@]}" tee /etc/apt/sources.list.d/volgraph-bookworm-backports.sources >/dev/null
fi
[ $need_backports -eq 1 ] && missing_text="${missing[*]} ${backports[*]} (backports)" || missing_text="${missing[*]}"
echo "volgraph bootstrap: installing $missing_text" >&2
"${sudo[@]}" apt-get update -qq >&2
[ ${#missing[@]} -gt 0 ] && "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
[ $need_backports -eq 1 ] && "${sudo[@]}" apt-get install -y -qq --no-install-recommends -t bookworm-backports "${backports[@]}" >&2
exit 0
