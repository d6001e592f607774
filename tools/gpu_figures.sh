#!/bin/bash
# The figures of a machine, in one run: every demo rendered FRAMES frames at its own size
# on each backend (the last frame's wall time from submit to completion and its GPU time
# stamps, and the whole command's seconds: device, pipelines, first frame with every LUT),
# Bruneton's tables at their defaults (a first frame), and the benchmarks at their
# documented sizes. Writes OUT/demos.md (a table), OUT/*.timings.json, OUT/*.png and
# OUT/bench_*.txt.
#   tools/gpu_figures.sh OUT [FRAMES]     env: VOLGRAPH (binary; build/tools/volgraph),
#                                          BENCH (folder; build/bench), BACKENDS ("vulkan webgpu"),
#                                          DEMOS (configs/demo_*.json), BRUNETON_DEFAULTS (1; 0 skips
#                                          it: tens of minutes on lavapipe), BENCHMARKS (1)
set -u
out=${1:?usage: tools/gpu_figures.sh OUT [FRAMES]}
frames=${2:-8}
volgraph=${VOLGRAPH:-build/tools/volgraph}
bench=${BENCH:-build/bench}
backends=${BACKENDS:-vulkan webgpu}
demos=${DEMOS:-configs/demo_*.json}
mkdir -p "$out"

"$volgraph" devices >"$out/devices.txt" 2>&1
cat "$out/devices.txt"

# One render: its seconds, then the timings file's frame wall and total GPU ms.
render() {
  local config=$1 backend=$2 name=$3
  shift 3
  local start end
  start=$(date +%s.%N)
  if ! "$volgraph" render "$config" -o "$out/$name.png" --backend "$backend" --frames "$frames" \
      --timings-out "$out/$name.timings.json" "$@" >"$out/$name.log" 2>&1; then
    echo "| $name | $backend | failed: $(tail -1 "$out/$name.log") | | |" >>"$out/demos.md"
    return
  fi
  end=$(date +%s.%N)
  python3 - "$out/$name.timings.json" "$name" "$backend" "$start" "$end" >>"$out/demos.md" <<'EOF'
import json, sys
path, name, backend, start, end = sys.argv[1:]
t = json.load(open(path))
print(f"| {name} | {backend} | {float(end) - float(start):.2f} | {t['frame_wall_ms']:.2f} | {t['total_gpu_ms']:.2f} |")
EOF
}

{
  echo "Device: $(head -1 "$out/devices.txt"); $frames frames each; $(date -u +%Y-%m-%dT%H:%MZ)"
  echo
  echo "| demo | backend | command s (first frame incl.) | last frame wall ms | last frame GPU ms |"
  echo "|---|---|---|---|---|"
} >"$out/demos.md"
for config in $demos; do
  demo=$(basename "$config" .json)
  for backend in $backends; do render "$config" "$backend" "$demo.$backend"; done
done
# Bruneton's tables at the pass's defaults (the demos use 4 × 16 × 32 × 8): one frame.
if [ "${BRUNETON_DEFAULTS:-1}" = 1 ]; then
frames_saved=$frames
frames=1
render configs/demo_atmosphere_noon_bruneton.json vulkan bruneton_default_tables.vulkan \
  --set atmosphere_bruneton.nu=8 --set atmosphere_bruneton.nu_mu_s=512 --set atmosphere_bruneton.mu=128 --set atmosphere_bruneton.r=64
frames=$frames_saved
fi
cat "$out/demos.md"

[ "${BENCHMARKS:-1}" = 1 ] || exit 0
[ -x "$bench/bench_backends" ] && "$bench/bench_backends" 15 640x360 >"$out/bench_backends_640x360.txt" 2>&1
[ -x "$bench/bench_backends" ] && "$bench/bench_backends" 15 1920x1080 >"$out/bench_backends_1920x1080.txt" 2>&1
[ -x "$bench/bench_pass_cache" ] && "$bench/bench_pass_cache" 5 8 1280x720 >"$out/bench_pass_cache.txt" 2>&1
[ -x "$bench/bench_empty_froxels" ] && "$bench/bench_empty_froxels" 9 1280x720 32 >"$out/bench_empty_froxels.txt" 2>&1
tail -n 5 "$out"/bench_*.txt 2>/dev/null
exit 0
