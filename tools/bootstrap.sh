#!/usr/bin/env bash
# Installs the Debian packages volgraph builds with, when any is missing.
# Idempotent: one dpkg query when everything is there.
set -euo pipefail

packages=(
  cmake ninja-build ccache clang libclang-rt-14-dev
  nlohmann-json3-dev googletest libgtest-dev libbenchmark-dev
  graphviz
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "volgraph bootstrap: installing ${missing[*]}" >&2
sudo=()
[ "$(id -u)" -ne 0 ] && sudo=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq >&2
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
