#!/usr/bin/env bash
# Command-line behaviour, one case per call:
#   cli_test.sh VOLGRAPH good CONFIG      validate and plan (text, --json, --dot through graphviz) succeed
#   cli_test.sh VOLGRAPH bad CONFIG       exit 2, one diagnostic naming file, line and pointer, nothing on stdout
#   cli_test.sh VOLGRAPH render CONFIG    render writes a PFM, or names the pass with no GPU implementation
#                                         yet (exit 1) and writes nothing
#   cli_test.sh VOLGRAPH usage            bad command lines exit 2 with one message
#   cli_test.sh VOLGRAPH dump CONFIG      --dump writes intermediates; a bad --dump exits 2 and writes nothing
#   cli_test.sh VOLGRAPH reference CONFIG the CPU reference writes PFM and PNG with its time line; bad
#                                         command lines and a broken model exit 2 and write nothing
#   cli_test.sh VOLGRAPH webgpu CONFIG    render --backend webgpu (64x36) writes a PFM, timings and a --dump;
#                                         simulated driver failures exit 1 with their message, no file
#   cli_test.sh VOLGRAPH frames CONFIG PASS.SLOT [webgpu]  a fog demo over 5 frames under validation (and
#                                         on WebGPU), PASS.SLOT (a history output) dumped after them; plan
#                                         lists the history pairs
set -uo pipefail
volgraph=$1 mode=$2 config=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

case "$mode" in
  good)
    "$volgraph" validate "$config" >"$tmp/out" 2>"$tmp/err" || fail "validate $config: $(cat "$tmp/err")"
    grep -q "valid" "$tmp/out" || fail "validate printed: $(cat "$tmp/out")"
    for flags in "" "--json" "--dot" "--no-cull" "--no-alias" "--serialize" "--size 320x180"; do
      # shellcheck disable=SC2086
      "$volgraph" plan "$config" $flags >"$tmp/plan" 2>"$tmp/err" || fail "plan $flags $config: $(cat "$tmp/err")"
      [ -s "$tmp/plan" ] || fail "plan $flags printed nothing"
    done
    "$volgraph" plan "$config" --dot >"$tmp/plan.dot" || fail "plan --dot"
    dot -Tsvg "$tmp/plan.dot" >"$tmp/plan.svg" 2>"$tmp/err" || fail "graphviz rejects the dot output: $(cat "$tmp/err")"
    grep -q "<svg" "$tmp/plan.svg" || fail "no svg from dot"
    ;;
  bad)
    expect=$(cat "${config%.json}.expect")
    dir=$(dirname "$config")
    (cd "$dir" && "$volgraph" validate "$(basename "$config")" >"$tmp/out" 2>"$tmp/err")
    code=$?
    [ "$code" -eq 2 ] || fail "exit $code (expected 2) for $config; stderr: $(cat "$tmp/err")"
    [ ! -s "$tmp/out" ] || fail "stdout not empty: $(cat "$tmp/out")"
    head -n 1 "$tmp/err" | grep -qF -- "$expect" || fail "expected: $expect
got: $(cat "$tmp/err")"
    [ "$(wc -l <"$tmp/err")" -eq 1 ] || fail "expected one message, got: $(cat "$tmp/err")"
    (cd "$dir" && "$volgraph" plan "$(basename "$config")" >/dev/null 2>&1)
    [ $? -eq 2 ] || fail "plan does not exit 2 for $config"
    ;;
  render)
    "$volgraph" render "$config" -o "$tmp/out.pfm" --timings >"$tmp/out" 2>"$tmp/err"
    code=$?
    if [ "$code" -eq 0 ]; then
      [ "$(head -c 2 "$tmp/out.pfm")" = "PF" ] || fail "render wrote no PFM"
      grep -q '"gpu_ms"' "$tmp/out" || fail "--timings printed: $(cat "$tmp/out")"
    else
      [ "$code" -eq 1 ] || fail "render exit $code; stderr: $(cat "$tmp/err")"
      grep -q "no GPU implementation yet" "$tmp/err" || fail "render message: $(cat "$tmp/err")"
      [ ! -e "$tmp/out.pfm" ] || fail "render wrote a file though it failed"
    fi
    [ -z "$(ls "$tmp" | grep tmp-)" ] || fail "a temporary file was left"
    ;;
  usage)
    for args in "" "frobnicate x.json" "plan" "plan $config --bogus" "plan $config --size 0x10" \
                "plan $config --size 20000x10" "plan $config --set" "render $config" "render $config -o $tmp/x.jpg" \
                "render $config -o $tmp/x.png --frames 0" "render $config -o $tmp/x.png --backend metal"; do
      # shellcheck disable=SC2086
      "$volgraph" $args >"$tmp/out" 2>"$tmp/err"
      code=$?
      [ "$code" -eq 2 ] || fail "'volgraph $args' exit $code (expected 2)"
    done
    [ -z "$(ls "$tmp" | grep -v -e '^out$' -e '^err$')" ] || fail "bad command lines left files: $(ls "$tmp")"
    "$volgraph" --help >"$tmp/out" || fail "--help"
    grep -q "usage: volgraph" "$tmp/out" || fail "--help text"
    "$volgraph" plan /no/such.json 2>"$tmp/err"
    [ $? -eq 2 ] || fail "missing config must exit 2"
    grep -q "/no/such.json: error: cannot read" "$tmp/err" || fail "missing config message: $(cat "$tmp/err")"
    ;;
  dump)
    "$volgraph" render "$config" -o "$tmp/frame.pfm" --size 64x36 --dump lit.color="$tmp/lit.pfm" \
      --dump sun_shadow.depth="$tmp/depth.pfm" --dump sun_shadow.light_view="$tmp/view.bin" 2>"$tmp/err" ||
      fail "render with --dump: $(cat "$tmp/err")"
    [ "$(head -c 2 "$tmp/lit.pfm")" = "PF" ] && [ "$(head -c 2 "$tmp/depth.pfm")" = "PF" ] || fail "dumped images missing"
    [ "$(wc -c <"$tmp/view.bin")" -eq 256 ] || fail "light_view dump is not 256 bytes"
    rm -f "$tmp"/*.pfm "$tmp"/*.bin
    for bad in "lit.colour=$tmp/x.pfm" "nobody.color=$tmp/x.pfm" "lit.color=$tmp/x.bin" "sun_shadow.light_view=$tmp/x.png" "lit.color"; do
      "$volgraph" render "$config" -o "$tmp/frame.pfm" --size 64x36 --dump "$bad" >/dev/null 2>"$tmp/err"
      code=$?
      [ "$code" -eq 2 ] || fail "--dump $bad: exit $code (expected 2)"
    done
    [ -z "$(ls "$tmp" | grep -v '^err$')" ] || fail "a bad --dump left files: $(ls "$tmp")"
    ;;
  driver)
    # Driver failures are exit 1 with the failure named, and leave no file behind.
    check_driver_failure() {  # expected-message, then the render's extra arguments
      expected=$1
      shift
      "$volgraph" render "$config" -o "$tmp/frame.pfm" "$@" >"$tmp/out" 2>"$tmp/err"
      code=$?
      [ "$code" -eq 1 ] || fail "render $*: exit $code (expected 1); stderr: $(cat "$tmp/err")"
      grep -qF -- "$expected" "$tmp/err" || fail "render $*: expected '$expected', got: $(cat "$tmp/err")"
      [ -z "$(ls "$tmp" | grep -v -e '^out$' -e '^err$')" ] || fail "render $* left files: $(ls "$tmp")"
    }
    VOLGRAPH_SIMULATE_FAULT=out_of_memory check_driver_failure "volgraph: out of device memory: vkAllocateMemory" --size 64x36
    VOLGRAPH_SIMULATE_FAULT=device_lost check_driver_failure "volgraph: device lost" --size 64x36
    # A real one: a frame whose memory one allocation cannot hold on lavapipe (2 GiB).
    check_driver_failure "volgraph: out of device memory: transient heap 0 needs" --size 16384x12000
    VOLGRAPH_SIMULATE_FAULT=sometimes "$volgraph" render "$config" -o "$tmp/frame.pfm" --size 64x36 2>"$tmp/err"
    [ $? -eq 2 ] || fail "an unknown VOLGRAPH_SIMULATE_FAULT must exit 2"
    ;;
  reference)
    "$volgraph" reference "$config" -o "$tmp/ref.pfm" --size 32x18 --threads 2 --spp 4 2>"$tmp/err" ||
      fail "reference: $(cat "$tmp/err")"
    [ "$(head -c 2 "$tmp/ref.pfm")" = "PF" ] || fail "reference wrote no PFM"
    grep -q "^reference: 32×18 in .* s$" "$tmp/err" || fail "reference time line: $(cat "$tmp/err")"
    "$volgraph" reference "$config" -o "$tmp/ref.png" --size 32x18 2>"$tmp/err" || fail "reference .png: $(cat "$tmp/err")"
    rm -f "$tmp/ref.pfm" "$tmp/ref.png"
    bad_gltf=$(dirname "$0")/bad/malformed_gltf.json
    for args in "reference $config" "reference $config -o $tmp/x.jpg" "reference $config -o $tmp/x.pfm --spp 3" \
                "reference $config -o $tmp/x.pfm --threads 0" "reference $config -o $tmp/x.pfm --tolerance 2" \
                "reference /no/such.json -o $tmp/x.pfm" "reference $bad_gltf -o $tmp/x.pfm"; do
      # shellcheck disable=SC2086
      "$volgraph" $args >"$tmp/out" 2>"$tmp/err"
      code=$?
      [ "$code" -eq 2 ] || fail "'volgraph $args' exit $code (expected 2); stderr: $(cat "$tmp/err")"
    done
    [ -z "$(ls "$tmp" | grep -v -e '^out$' -e '^err$')" ] || fail "bad reference command lines left files: $(ls "$tmp")"
    ;;
  webgpu)
    "$volgraph" render "$config" --backend webgpu -o "$tmp/out.pfm" --size 64x36 --timings \
      --dump lit.color="$tmp/lit.pfm" >"$tmp/out" 2>"$tmp/err" || fail "render --backend webgpu: $(cat "$tmp/err")"
    [ "$(head -c 2 "$tmp/out.pfm")" = "PF" ] && [ "$(head -c 2 "$tmp/lit.pfm")" = "PF" ] || fail "webgpu wrote no PFM"
    grep -q '"backend": "webgpu"' "$tmp/out" && grep -q '"gpu_ms"' "$tmp/out" || fail "--timings printed: $(cat "$tmp/out")"
    "$volgraph" plan "$config" --backend webgpu >"$tmp/out" || fail "plan --backend webgpu"
    head -1 "$tmp/out" | grep -q "backend webgpu: no placed memory" || fail "plan --backend webgpu: $(head -1 "$tmp/out")"
    rm -f "$tmp"/*.pfm
    for fault in out_of_memory:"out of device memory: Dawn" device_lost:"device lost (the driver stopped or was reset): Dawn"; do
      VOLGRAPH_SIMULATE_FAULT=${fault%%:*} "$volgraph" render "$config" --backend webgpu -o "$tmp/frame.pfm" --size 64x36 \
        >"$tmp/out" 2>"$tmp/err"
      code=$?
      [ "$code" -eq 1 ] || fail "simulated ${fault%%:*}: exit $code (expected 1); stderr: $(cat "$tmp/err")"
      grep -qF -- "${fault#*:}" "$tmp/err" || fail "simulated ${fault%%:*}: got $(cat "$tmp/err")"
      [ ! -e "$tmp/frame.pfm" ] || fail "simulated ${fault%%:*} wrote a file"
    done
    ;;
  frames)
    # --frames N on a fog demo: the history pairs swap every frame, under the validation
    # layer (any message fails the render) and on WebGPU when built; the last frame is
    # written, --timings says how many ran, --dump reads a history output (PASS.SLOT, the
    # fourth argument) after them; the plan lists the pairs as persistent, own memory,
    # with their bytes and their initial barriers.
    history=$4
    shift 4
    for backend in vulkan "$@"; do
      extra=()
      [ "$backend" = vulkan ] && extra=(--validation)
      "$volgraph" render "$config" --backend "$backend" "${extra[@]}" --size 64x36 --frames 5 --timings -o "$tmp/out.pfm" \
        --dump "$history=$tmp/history.pfm" >"$tmp/out" 2>"$tmp/err"
      code=$?
      [ "$code" -eq 0 ] || fail "render --frames 5 on $backend: exit $code; $(cat "$tmp/err")"
      [ "$(head -c 2 "$tmp/out.pfm")" = "PF" ] && [ "$(head -c 2 "$tmp/history.pfm")" = "PF" ] || fail "no PFM from $backend"
      grep -q '"frames": 5' "$tmp/out" || fail "--timings on $backend: $(cat "$tmp/out")"
      # a cached pass (demo_fog's opacity_shadow_map) is skipped on the last frame; others run
      if grep -q '"type": "opacity_shadow_map"' "$tmp/out"; then
        grep '"type": "opacity_shadow_map"' "$tmp/out" | grep -q '"cached": true' || fail "opacity_shadow_map not cached on $backend: $(cat "$tmp/out")"
        grep '"type": "scene"' "$tmp/out" | grep -q '"cached": false' || fail "scene said cached on $backend"
      fi
      rm -f "$tmp"/*.pfm
    done
    "$volgraph" plan "$config" >"$tmp/plan" || fail "plan"
    pass=${history%%.*}
    grep -q "persistent, own memory, history pair with $pass" "$tmp/plan" || fail "plan lists no history pair: $(cat "$tmp/plan")"
    grep -q "(history [1-9]" "$tmp/plan" || fail "plan gives no history bytes"
    if grep -q "(opacity_shadow_map/" "$tmp/plan"; then
      grep "(opacity_shadow_map/" "$tmp/plan" | grep -q "cached: skipped while its key holds" || fail "plan does not say the opacity map is cached"
    fi
    sed -n "/^before the first frame:/,/^$/p" "$tmp/plan" | grep -q "barrier $pass" || fail "plan lists no initial barrier"
    "$volgraph" plan "$config" --json >"$tmp/plan.json" || fail "plan --json"
    grep -q '"role": "previous"' "$tmp/plan.json" && grep -q '"history_bytes": [1-9]' "$tmp/plan.json" &&
      grep -q '"initial_barriers": \[$' "$tmp/plan.json" || fail "plan --json lacks the history pair"
    ;;
  *) fail "unknown mode $mode" ;;
esac
echo "ok"
