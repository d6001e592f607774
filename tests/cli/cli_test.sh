#!/usr/bin/env bash
# Command-line behaviour, one case per call:
#   cli_test.sh VOLGRAPH good CONFIG      validate and plan (text, --json, --dot through graphviz) succeed
#   cli_test.sh VOLGRAPH bad CONFIG       exit 2, one diagnostic naming file, line and pointer, nothing on stdout
#   cli_test.sh VOLGRAPH render CONFIG    render writes a PFM, or names the pass with no GPU implementation
#                                         yet (exit 1) and writes nothing
#   cli_test.sh VOLGRAPH usage            bad command lines exit 2 with one message
#   cli_test.sh VOLGRAPH devices          lists each adapter with whether it offers dual-source blending;
#                                         plan --setup says what the translucency pass chose with it
#   cli_test.sh VOLGRAPH dump CONFIG      --dump writes intermediates; a bad --dump exits 2 and writes nothing
#   cli_test.sh VOLGRAPH reference CONFIG the CPU reference writes PFM and PNG with its time line; bad
#                                         command lines and a broken model exit 2 and write nothing
#   cli_test.sh VOLGRAPH webgpu CONFIG    render --backend webgpu (64x36) writes a PFM, timings and a --dump;
#                                         simulated driver failures exit 1 with their message, no file
#   cli_test.sh VOLGRAPH hostile CONFIG CASE  one hostile-user case (below): a clear message and exit 2 for bad
#                                         input, exit 1 for a failure that is not the input's, no file written,
#                                         no crash and no hang
#   cli_test.sh VOLGRAPH frames CONFIG PASS.SLOT [webgpu]  a fog demo over 5 frames under validation (and
#                                         on WebGPU), PASS.SLOT (a history output) dumped after them; plan
#                                         lists the history pairs
set -uo pipefail
volgraph=$1 mode=$2 config=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/cli/test_lib.sh
. "$(dirname "$0")/test_lib.sh"

# no_files_but LIST…: nothing in $tmp but the named files (and out, err).
no_files_but() {
  left=$(ls -A "$tmp" | grep -v -x -e out -e err $(printf -- ' -e %s' "$@"))
  [ -z "$left" ] || fail "files left behind: $left"
}

# A JSON scene of the config's graph with N boxes.
boxes_config() {
  python3 - "$config" "$1" <<'PY'
import json, sys
objects = [{"shape": "box", "size": [0.05, 0.05, 0.05], "material": "grey",
            "transform": {"translate": [(i % 90) * 0.1 - 4.5, 0.05, -(i // 90) * 0.1]}} for i in range(int(sys.argv[2]))]
print(json.dumps({"include": sys.argv[1], "scene": {"materials": {"grey": {}}, "objects": objects}}))
PY
}

hostile_case() {
  case "$1" in
    deep_nesting)  # 50,000 levels: refused before any reader recurses
      { printf '{"include": "%s", "scene": ' "$config"; head -c 50000 /dev/zero | tr '\0' '['; head -c 50000 /dev/zero | tr '\0' ']'; printf '}'; } >"$tmp/deep.json"
      for command in validate plan "render -o $tmp/x.pfm" "reference -o $tmp/x.pfm"; do
        # shellcheck disable=SC2086
        expect_exit 2 "deep.json:1: error: arrays and objects nest deeper than 256 levels" "$volgraph" $command "$tmp/deep.json"
      done
      no_files_but deep.json
      ;;
    nul_byte)  # nlohmann/json stops at a NUL: what follows would be ignored
      { printf '{"include": "%s"}\n' "$config"; printf '\0{"scene": 1}\n'; } >"$tmp/nul.json"
      expect_exit 2 "nul.json:2: error: a NUL byte at offset" "$volgraph" validate "$tmp/nul.json"
      ;;
    size)  # --size: digits only, each side in [1, 16384]; no wrap-around
      for size in 4294967360x36 +64x+36 " 64x36" "64x36 " 64x-36 0x36 16385x36 64x 64 64x36x2; do
        expect_exit 2 "volgraph: --size expects WxH, digits only" "$volgraph" plan "$config" --size "$size"
      done
      "$volgraph" plan "$config" --size 64x36 >/dev/null || fail "--size 64x36 refused"
      ;;
    threads)  # --threads is bounded; thread creation failing falls back to fewer threads
      expect_exit 2 "volgraph: --threads expects a whole number in [1, 256], got \"4096\"" \
        "$volgraph" reference "$config" -o "$tmp/x.pfm" --threads 4096
      no_files_but
      "$volgraph" reference "$config" -o "$tmp/x.pfm" --size 8x4 --threads 256 2>"$tmp/err" || fail "--threads 256: $(cat "$tmp/err")"
      ;;
    same_file)  # two outputs, or an output and the config, naming one file
      cp "$config" "$tmp/config.json"
      cp -r "$(dirname "$config")/scenes" "$(dirname "$config")/graphs" "$tmp/"
      expect_exit 2 "is the same file as -o" "$volgraph" render "$tmp/config.json" -o "$tmp/x.pfm" --timings-out "$tmp/x.pfm"
      expect_exit 2 "is the same file as -o" "$volgraph" render "$tmp/config.json" -o "$tmp/x.pfm" --dump "lit.color=$tmp/../$(basename "$tmp")/x.pfm"
      expect_exit 2 "is the same file as the config" "$volgraph" render "$tmp/config.json" -o "$tmp/x.pfm" --timings-out "$tmp/config.json"
      cmp -s "$config" "$tmp/config.json" || fail "the config was overwritten"
      no_files_but config.json scenes graphs
      ;;
    repeated_options)  # one file per option; a variant needs a name
      expect_exit 2 "volgraph: -o given twice" "$volgraph" render "$config" -o "$tmp/a.pfm" -o "$tmp/b.pfm"
      expect_exit 2 "volgraph: --timings-out given twice" "$volgraph" render "$config" -o "$tmp/a.pfm" --timings-out "$tmp/a.json" --timings-out "$tmp/b.json"
      expect_exit 2 "<command line>: error at --variant final=: expected --variant PASS=VARIANT with a variant's name" \
        "$volgraph" plan "$config" --variant final=
      no_files_but
      ;;
    missing_folder)  # an output into a folder that is not there: refused before rendering, nothing written
      expect_exit 2 "<command line>: error at --timings-out $tmp/no/t.json: folder $tmp/no does not exist" \
        "$volgraph" render "$config" --size 64x36 -o "$tmp/x.pfm" --timings-out "$tmp/no/t.json"
      expect_exit 2 "<command line>: error at --dump $tmp/no/lit.pfm: folder $tmp/no does not exist" \
        "$volgraph" render "$config" --size 64x36 -o "$tmp/x.pfm" --dump "lit.color=$tmp/no/lit.pfm"
      mkdir "$tmp/d.pfm"
      expect_exit 2 "<command line>: error at -o $tmp/d.pfm: is a directory" "$volgraph" render "$config" --size 64x36 -o "$tmp/d.pfm"
      no_files_but d.pfm
      ;;
    not_a_file)  # a config that is a folder, a FIFO or unreadable: said so, not "no such file"
      mkdir "$tmp/dir.json"
      expect_exit 2 "error: cannot read \"$tmp/dir.json\": is a directory" "$volgraph" validate "$tmp/dir.json"
      mkfifo "$tmp/fifo.json"
      expect_exit 2 "error: cannot read \"$tmp/fifo.json\": not a regular file" "$volgraph" validate "$tmp/fifo.json"
      if [ "$(id -u)" -ne 0 ]; then  # root reads any file
        cp "$config" "$tmp/locked.json" && chmod 000 "$tmp/locked.json"
        expect_exit 2 "error: cannot read \"$tmp/locked.json\": permission denied" "$volgraph" validate "$tmp/locked.json"
      fi
      ;;
    host_memory)  # the host out of memory: said so, exit 1 (not the input's fault)
      (ulimit -v 1000000 && exec "$volgraph" reference "$config" -o "$tmp/x.pfm" --size 16384x16384 --threads 1) >"$tmp/out" 2>"$tmp/err"
      code=$?
      [ "$code" -eq 1 ] || fail "exit $code (expected 1); stderr: $(cat "$tmp/err")"
      grep -qF "volgraph: out of host memory: the reference image, 16384×16384 pixels of 3 doubles (6144 MiB)" "$tmp/err" || fail "message: $(cat "$tmp/err")"
      no_files_but
      ;;
    too_many_objects)  # more objects than the backends bind: refused at validate with the maximum
      boxes_config 8200 >"$tmp/boxes.json"
      expect_exit 2 "boxes.json:1: error at /scene/objects/4093: the scene's objects make more than 4096 draws" "$volgraph" validate "$tmp/boxes.json"
      boxes_config 4000 >"$tmp/boxes.json"
      "$volgraph" validate "$tmp/boxes.json" >/dev/null || fail "4000 objects refused"
      ;;
    point_light_on_surface)  # the in-scattering integrand unbounded at a ray's end: the refinement still stops
      timeout 20 "$volgraph" reference "$(dirname "$0")/hostile/point_light_on_surface.json" -o "$tmp/x.pfm" --size 17x9 \
        --threads 2 2>"$tmp/err" || fail "reference exit $? (124: it ran past 20 s): $(cat "$tmp/err")"
      ;;
    fine_noise)  # under-resolved noise: warned about, and the time stays bounded
      timeout 20 "$volgraph" reference "$(dirname "$0")/hostile/fine_noise.json" -o "$tmp/x.pfm" --size 16x9 \
        --threads 2 2>"$tmp/err" || fail "reference exit $? (124: it ran past 20 s): $(cat "$tmp/err")"
      grep -q "warning: .*under-resolved" "$tmp/err" || fail "no under-resolved warning: $(cat "$tmp/err")"
      ;;
    undecodable_texture)  # a texture that fails only when decoded: bad input (exit 2) at render time, nothing written
      for command in render reference; do
        expect_exit 2 "textures/bad_zlib.png: error: not an image volgraph reads" \
          "$volgraph" $command "$(dirname "$0")/hostile/undecodable_texture.json" --size 32x18 -o "$tmp/x.pfm"
      done
      no_files_but
      ;;
    full_disk)  # a write that fails (a one-page tmpfs fills up): exit 1, the target named, no file left at all
      mkdir "$tmp/full"
      if ! mount -t tmpfs -o size=4k tmpfs "$tmp/full" 2>/dev/null; then
        echo "ok (skipped: cannot mount a tmpfs here)"
        exit 0
      fi
      trap 'umount "$tmp/full"; rm -rf "$tmp"' EXIT
      for out in x.png x.pfm x.exr; do
        expect_exit 1 "volgraph: cannot write $tmp/full/$out: No space left on device" \
          "$volgraph" render "$config" --size 320x180 -o "$tmp/full/$out"
        [ -z "$(ls -A "$tmp/full")" ] || fail "-o $out on a full disk left: $(ls -A "$tmp/full")"
      done
      # The frame fits (a page), the dump after it does not: neither is left.
      expect_exit 1 "volgraph: cannot write $tmp/full/lit.pfm: No space left on device" \
        "$volgraph" render "$config" --size 8x4 -o "$tmp/full/x.png" --dump "lit.color=$tmp/full/lit.pfm"
      [ -z "$(ls -A "$tmp/full")" ] || fail "a failed --dump left: $(ls -A "$tmp/full")"
      ;;
    device_index)  # --device N past the last device: bad input (exit 2), the count said, nothing written
      n=$("$volgraph" devices | grep -c '^[0-9][0-9]*: ')
      [ "$n" -ge 1 ] || fail "volgraph devices lists no Vulkan device"
      root=$(dirname "$config")/..
      expect_exit 2 "volgraph: --device $n: no such Vulkan device; there" "$volgraph" render "$config" -o "$tmp/x.png" --size 8x4 --device "$n"
      expect_exit 2 "volgraph: --device $n: no such Vulkan device; there" "$volgraph" ab "$config" --pass final --a aces --b reinhard \
        --size 8x4 --runs 1 --warmup 0 -o "$tmp/ab" --device "$n"
      expect_exit 2 "volgraph: --device $n: no such Vulkan device; there" "$volgraph" sweep "$root/configs/sweeps/froxel_far.json" \
        --size 8x4 -o "$tmp/sweep" --device "$n"
      expect_exit 2 "volgraph: --device 100000: no such Vulkan device; there" "$volgraph" render "$config" -o "$tmp/x.png" --device 100000
      [ "$(wc -l <"$tmp/err")" -le 2 ] || fail "more than one message: $(cat "$tmp/err")"
      no_files_but
      ;;
    long_output_name)  # a 250-byte file name (NAME_MAX is 255): its temporary still fits, the file is written, no temporary left
      name=$(head -c 246 /dev/zero | tr '\0' a).pfm timings=$(head -c 250 /dev/zero | tr '\0' t).json
      "$volgraph" render "$config" --size 8x4 -o "$tmp/$name" --timings-out "$tmp/$timings" 2>"$tmp/err" ||
        fail "render -o (250-byte name) exit $?: $(cat "$tmp/err")"
      [ "$(head -c 2 "$tmp/$name")" = "PF" ] || fail "no PFM written under the 250-byte name"
      [ -s "$tmp/$timings" ] || fail "no --timings-out written under a 255-byte name"
      no_files_but "$name" "$timings"
      ;;
    extra_arguments)  # commands that take no arguments refuse one: exit 2, one message
      for command in devices passes; do
        expect_exit 2 "volgraph: $command takes no arguments, got \"extra\"" "$volgraph" $command extra
        [ "$(wc -l <"$tmp/err")" -le 2 ] || fail "$command extra: more than one message: $(cat "$tmp/err")"
        [ ! -s "$tmp/out" ] || fail "$command extra printed: $(cat "$tmp/out")"
      done
      ;;
    *) fail "unknown hostile case $1" ;;
  esac
}

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
  devices)
    # Each adapter with what it offers for the translucency pass's coloured transmittance.
    "$volgraph" devices >"$tmp/out" 2>"$tmp/err" || fail "devices exit $?; stderr: $(cat "$tmp/err")"
    grep -Eq '^0: .*; dual-source blending \(dualSrcBlend\): (offered|not offered)$' "$tmp/out" ||
      fail "no Vulkan device line with dualSrcBlend: $(cat "$tmp/out")"
    grep -Eq '^webgpu: .*(DualSourceBlending\): (offered|not offered)|without Dawn)' "$tmp/out" ||
      fail "no WebGPU line with DualSourceBlending: $(cat "$tmp/out")"
    # plan --setup: the translucency pass says how many draws a layer takes on this device, and why.
    glass=$(dirname "$0")/../../configs/demo_stained_glass.json
    "$volgraph" plan "$glass" --setup --size 64x36 >"$tmp/out" 2>"$tmp/err" || fail "plan --setup exit $?; stderr: $(cat "$tmp/err")"
    if grep -Eq '^0: .*dualSrcBlend\): offered$' <("$volgraph" devices); then want='one draw a layer'; else want='two draws a layer'; fi
    grep -Eq "^  glass  $want .*(dual-source blending|dual_source)" "$tmp/out" || fail "plan --setup does not say \"$want\": $(cat "$tmp/out")"
    "$volgraph" plan "$glass" --setup --size 64x36 --set glass.dual_source=false >"$tmp/out" 2>"$tmp/err" || fail "plan --setup exit $?"
    grep -q '^  glass  two draws a layer (× transmittance, + radiance): dual_source is off$' "$tmp/out" ||
      fail "plan --setup with dual_source off: $(cat "$tmp/out")"
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
    # --device picks a Vulkan device: refused with the WebGPU backend, by render and view alike (exit 2, one message).
    for command in "render -o $tmp/refused.pfm" "view --frames 1"; do
      # shellcheck disable=SC2086  # the command and its own options, split on purpose
      "$volgraph" $command "$config" --backend webgpu --device 0 >"$tmp/out" 2>"$tmp/err"
      code=$?
      [ "$code" -eq 2 ] && grep -q "WebGPU uses Dawn's default adapter" "$tmp/err" && [ ! -e "$tmp/refused.pfm" ] ||
        fail "$command --backend webgpu --device 0: exit $code, stderr: $(cat "$tmp/err")"
    done
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
  atmosphere)
    # An atmosphere demo over two frames, under validation and on WebGPU when built: the
    # first frame fills the LUTs and the aerial-perspective volume, the second runs none of
    # them (--timings says cached) but still draws the sky and the air; the same graph over
    # a scene without an atmosphere plans no atmosphere pass at all.
    shift 3
    for backend in vulkan "$@"; do
      extra=()
      [ "$backend" = vulkan ] && extra=(--validation)
      "$volgraph" render "$config" --backend "$backend" "${extra[@]}" --size 64x36 --frames 2 --timings -o "$tmp/out.pfm" \
        >"$tmp/out" 2>"$tmp/err" || fail "render --frames 2 on $backend: $(cat "$tmp/err")"
      for type in atmosphere_transmittance_lut atmosphere_multiscattering_lut atmosphere_skyview_lut atmosphere_aerial_perspective; do
        grep "\"type\": \"$type\"" "$tmp/out" | grep -q '"cached": true' || fail "$type ran again on $backend's second frame: $(cat "$tmp/out")"
      done
      for type in sky aerial_perspective_apply; do
        grep "\"type\": \"$type\"" "$tmp/out" | grep -q '"cached": false' || fail "$type did not run on $backend's second frame"
      done
    done
    configs=$(cd "$(dirname "$config")" && pwd)
    # The reference's Monte Carlo paths for the air's higher orders: 0 leaves single
    # scattering alone (a darker sky), a bad count is refused with exit 2 and no image.
    "$volgraph" reference "$configs/tests/atmosphere_sky.json" --size 8x4 --paths 0 -o "$tmp/single.pfm" 2>/dev/null || fail "reference --paths 0"
    "$volgraph" reference "$configs/tests/atmosphere_sky.json" --size 8x4 --paths 4 -o "$tmp/orders.pfm" 2>/dev/null || fail "reference --paths 4"
    ! cmp -s "$tmp/single.pfm" "$tmp/orders.pfm" || fail "--paths changes nothing"
    code=0; "$volgraph" reference "$configs/tests/atmosphere_sky.json" --paths -1 -o "$tmp/bad.pfm" 2>"$tmp/err" || code=$?
    [ "$code" -eq 2 ] && [ ! -e "$tmp/bad.pfm" ] && grep -q -- "--paths expects" "$tmp/err" || fail "--paths -1: exit $code, $(cat "$tmp/err")"
    # Bruneton's variant of the same demo: an amendment unwires (null) the Hillaire LUTs the
    # bruneton variants do not read, so the compiler culls them.
    "$volgraph" plan "$configs/demo_atmosphere_noon_bruneton.json" >"$tmp/plan" || fail "plan of the bruneton demo"
    for pass in atmosphere_multiscattering atmosphere_sky_view; do
      grep -q "^  $pass  unused" "$tmp/plan" || fail "$pass is not culled under the bruneton variants: $(cat "$tmp/plan")"
    done
    grep -q "^  [0-9]*\. atmosphere_bruneton/direct_irradiance " "$tmp/plan" || fail "no atmosphere_bruneton_tables in the bruneton demo's plan"
    printf '{ "include": ["%s/scenes/primitives.json", "%s/graphs/atmosphere.json"] }' "$configs" "$configs" >"$tmp/no_air.json"
    "$volgraph" plan "$tmp/no_air.json" >"$tmp/plan" || fail "plan without an atmosphere: $(cat "$tmp/plan")"
    for pass in atmosphere_transmittance atmosphere_multiscattering atmosphere_sky_view atmosphere_aerial sky air; do
      grep -q "^  $pass  scene_lacks: scene has no atmosphere" "$tmp/plan" || fail "$pass is not culled for want of an atmosphere: $(cat "$tmp/plan")"
    done
    ! grep -q "^  [0-9]*\. \(atmosphere_\|sky \|air \)" "$tmp/plan" || fail "an atmosphere pass runs without an atmosphere"
    grep -q "^  [0-9]*\. final " "$tmp/plan" || fail "the frame's composite is culled with the sky: $(cat "$tmp/plan")"
    ;;
  hostile)
    hostile_case "$4"
    ;;
  *) fail "unknown mode $mode" ;;
esac
echo "ok"
