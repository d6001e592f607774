#!/usr/bin/env bash
# The comparison commands end to end, one case per call, at tiny sizes:
#   compare_test.sh VOLGRAPH ab_variants SOURCE_DIR     ab wronski against hillaire with the CPU reference:
#                                                       report files, figures in report.json, the summary
#   compare_test.sh VOLGRAPH ab_graphs SOURCE_DIR       ab of whole techniques (--a-graph/--b-graph): the froxel
#                                                       chain, raymarch_fog and light_volume on one scene
#   compare_test.sh VOLGRAPH webgpu SOURCE_DIR          ab and a sweep with --backend webgpu (Dawn)
#   compare_test.sh VOLGRAPH ab_bad SOURCE_DIR          bad ab command lines: exit 2, one message, no report
#   compare_test.sh VOLGRAPH sweep_resume SOURCE_DIR    a sweep interrupted by SIGINT keeps its finished points
#                                                       and a second run does only the rest
#   compare_test.sh VOLGRAPH sweep_jobs SOURCE_DIR      --emit-jobs run by GNU parallel (3 workers), --merge
#                                                       twice gives the same files, the same points as a serial run
#   compare_test.sh VOLGRAPH sweep_failures SOURCE_DIR  every point failing (a simulated device loss) is saved
#                                                       with its error, the sweep goes on, exit 1
#   compare_test.sh VOLGRAPH sweep_bad SOURCE_DIR       a broken spec: exit 2, one message naming the pointer
#   compare_test.sh VOLGRAPH shipped SPEC               a shipped sweep spec runs at 32x18, one run
#   compare_test.sh VOLGRAPH sweep_identity SOURCE_DIR  a folder is one spec's at one set of settings: another
#                                                       spec's run, tune or merge is refused (exit 2, naming both);
#                                                       a merge without SPEC reports the folders' figures; the
#                                                       jobs of --emit-jobs keep --size and --runs; a damaged
#                                                       folder is bad input (exit 2)
#   compare_test.sh VOLGRAPH outputs_not_inputs SOURCE_DIR  an input inside -o DIR under an output's name (a spec
#                                                       results.json, a config report.json, tuned.json, a link to
#                                                       one) is refused, exit 2, and left as it was
#   compare_test.sh VOLGRAPH bad_reference SOURCE_DIR  a reference with NaN or Inf, a FIFO, a PFM whose header
#                                                       claims more than the file holds: exit 2, no report
#   compare_test.sh VOLGRAPH tune SOURCE_DIR            tune on a sweep whose answer is known (a fixture folder)
set -uo pipefail
volgraph=$1 mode=$2 arg=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/cli/test_lib.sh
. "$(dirname "$0")/test_lib.sh"

# json_value FILE EXPR: a Python expression over the parsed JSON `j`, printed.
json_value() { python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print($2)" "$1"; }

# A spec of demo_fog points (fog_media.slices 8 and 16, or those given) at 32x18 (or SIZE),
# one run.
tiny_spec() {
  cat >"$tmp/tiny.json" <<EOF
{ "config": "$arg/configs/demo_fog.json", "size": ${2:-[32, 18]}, "runs": 1, "warmup": 0, "reference": "cpu",
  "metric": "rel_rmse", "mask": "fog_only",
  "series": [ { "name": "slices", "vary": { "fog_media.slices": [${1:-8, 16}] } } ] }
EOF
}

points_in() { ls "$1/points" 2>/dev/null | grep -c '\.json$'; }

case "$mode" in
  ab_variants)
    "$volgraph" ab "$arg/configs/demo_fog.json" --pass fog_integral --a wronski --b hillaire,  --reference cpu \
      --size 48x27 --runs 2 --validation -o "$tmp/ab" >"$tmp/out" 2>"$tmp/err" && fail "a trailing comma in --b was accepted"
    "$volgraph" ab "$arg/configs/demo_fog.json" --pass fog_integral --a wronski --b hillaire --reference cpu \
      --size 48x27 --runs 2 --validation -o "$tmp/ab" >"$tmp/out" 2>"$tmp/err" || fail "ab exit $?: $(cat "$tmp/err")"
    for f in report.json report.html a.png a.pfm b.png b.pfm reference.png reference.pfm; do
      [ -s "$tmp/ab/$f" ] || fail "no $f in the report folder: $(ls "$tmp/ab")"
    done
    ls "$tmp/ab" | grep -q '^flip_.*\.png$' || fail "no FLIP heatmap: $(ls "$tmp/ab")"
    grep -q "lavapipe (CPU)" "$tmp/out" || fail "the summary does not say lavapipe is a CPU: $(cat "$tmp/out")"
    # Every comparison has its figures, finite where the images are; A and B differ from the reference.
    [ "$(json_value "$tmp/ab/report.json" "len(j['comparisons'])")" = 2 ] || fail "expected 2 comparisons in report.json"
    python3 - "$tmp/ab/report.json" <<'PY' || fail "report.json figures"
import json, math, sys
j = json.load(open(sys.argv[1]))
text = json.dumps(j)
for key in ("rmse", "relative_rmse", "psnr_db", "ssim", "flip", "max_abs_error", "nan_values", "inf_values"):
    assert key in text, key
assert "wronski" in text and "hillaire" in text, "the settings are named"
assert "volgraph ab" in text or "ab " in text, "the command line is recorded"
PY
    ;;
  ab_graphs)
    scene="$arg/configs/demo_light_volume.json"
    for pair in "froxel_fog raymarch_fog" "raymarch_fog light_volume_fog" "froxel_fog light_volume_fog"; do
      set -- $pair
      "$volgraph" ab "$scene" --a-graph "$arg/configs/graphs/$1.json" --b-graph "$arg/configs/graphs/$2.json" --reference cpu \
        --size 40x24 --runs 1 --validation -o "$tmp/$1-$2" >"$tmp/out" 2>"$tmp/err" || fail "ab $pair exit $?: $(cat "$tmp/err")"
      grep -q "graph .*$1.json" "$tmp/$1-$2/report.json" || fail "report.json does not name A's graph $1"
      grep -q "graph .*$2.json" "$tmp/$1-$2/report.json" || fail "report.json does not name B's graph $2"
    done
    ;;
  webgpu)
    "$volgraph" ab "$arg/configs/demo_fog.json" --pass fog_integral --a wronski --b hillaire --reference cpu --size 48x27 \
      --runs 1 --backend webgpu -o "$tmp/ab" >"$tmp/out" 2>"$tmp/err" || fail "ab on webgpu exit $?: $(cat "$tmp/err")"
    [ "$(json_value "$tmp/ab/report.json" "j['backend']")" = webgpu ] || fail "report.json does not say webgpu"
    tiny_spec
    "$volgraph" sweep "$tmp/tiny.json" --backend webgpu -o "$tmp/s" >"$tmp/out" 2>"$tmp/err" || fail "sweep on webgpu: $(cat "$tmp/err")"
    grep -q '"backend": "webgpu"' "$tmp"/s/points/*.json || fail "the points do not say webgpu"
    ;;
  ab_bad)
    config="$arg/configs/demo_fog.json"
    expect_exit 2 "--a names a variant; expected --pass NAME too" "$volgraph" ab "$config" --a wronski --b hillaire -o "$tmp/r"
    expect_exit 2 "ab compares two settings" "$volgraph" ab "$config" -o "$tmp/r"
    expect_exit 2 "--reference expects cpu or a .pfm image" "$volgraph" ab "$config" --pass fog_integral --a wronski --b hillaire --reference x.png -o "$tmp/r"
    expect_exit 2 "no pass named \"fog_integrl\"" "$volgraph" ab "$config" --pass fog_integrl --a wronski --b hillaire -o "$tmp/r"
    expect_exit 2 "variant" "$volgraph" ab "$config" --pass fog_integral --a wronski --b bogus -o "$tmp/r"
    touch "$tmp/file"
    expect_exit 2 "exists and is not a folder" "$volgraph" ab "$config" --pass fog_integral --a wronski --b hillaire -o "$tmp/file"
    expect_exit 2 "does not exist" "$volgraph" ab "$config" --pass fog_integral --a wronski --b hillaire -o "$tmp/no/such/dir"
    [ -z "$(ls -A "$tmp/r" 2>/dev/null)" ] || fail "a refused ab left files: $(ls -A "$tmp/r")"
    ;;
  sweep_resume)
    tiny_spec "8, 16, 24, 32, 40, 48, 56, 64" "[96, 54]"
    set -m  # job control: a background job of a script ignores SIGINT otherwise
    "$volgraph" sweep "$tmp/tiny.json" -o "$tmp/s" >"$tmp/out" 2>"$tmp/err" &
    pid=$!
    set +m
    for _ in $(seq 3000); do [ "$(points_in "$tmp/s")" -ge 1 ] && break; sleep 0.02; done
    kill -INT $pid
    wait $pid
    code=$?
    [ $code = 130 ] || fail "an interrupted sweep should exit 130 (128 + SIGINT), got $code: $(cat "$tmp/err")"
    grep -q "interrupted; every finished point is saved" "$tmp/err" || fail "no interruption message: $(cat "$tmp/err")"
    done_first=$(points_in "$tmp/s")
    [ "$done_first" -ge 1 ] && [ "$done_first" -lt 8 ] || fail "after SIGINT: $done_first points saved (expected 1–7: interrupt too late?)"
    ls -A "$tmp/s/points" | grep -v '\.json$' && fail "temporaries left in points/"
    ls -A "$tmp/s" | grep -q 'tmp' && fail "temporaries left in the sweep folder: $(ls -A "$tmp/s")"
    [ "$(json_value "$tmp/s/results.json" "len(j['points'])")" = "$done_first" ] || fail "results.json does not hold the $done_first points saved"
    "$volgraph" sweep "$tmp/tiny.json" -o "$tmp/s" >"$tmp/out" 2>"$tmp/err" || fail "resumed sweep exit $?: $(cat "$tmp/err")"
    grep -q "$((8 - done_first)) points run, $done_first already done" "$tmp/out" || fail "resume: $(cat "$tmp/out")"
    [ "$(points_in "$tmp/s")" = 8 ] || fail "expected 8 points after the resume"
    for f in results.json results.csv report.html; do [ -s "$tmp/s/$f" ] || fail "no $f"; done
    [ "$(grep -c . "$tmp/s/results.csv")" = 9 ] || fail "results.csv: a header and 8 rows expected: $(cat "$tmp/s/results.csv")"
    "$volgraph" sweep "$tmp/tiny.json" --size 16x9 -o "$tmp/s" >"$tmp/out" 2>"$tmp/err"
    [ $? = 2 ] && grep -q "measured with other settings" "$tmp/err" || fail "a resume at another size was not refused: $(cat "$tmp/err")"
    ;;
  sweep_jobs)
    tiny_spec "8, 12, 16"
    command -v parallel >/dev/null || fail "GNU parallel is missing (tools/bootstrap.sh installs it)"
    "$volgraph" sweep "$tmp/tiny.json" --emit-jobs -o "$tmp/jobs" >"$tmp/out" 2>"$tmp/err" || fail "emit-jobs exit $?: $(cat "$tmp/err")"
    [ "$(grep -c . "$tmp/jobs/jobs.txt")" = 3 ] || fail "expected 3 jobs: $(cat "$tmp/jobs/jobs.txt")"
    [ -s "$tmp/jobs/manifest.json" ] && [ -s "$tmp/jobs/reference.pfm" ] || fail "no manifest or kept reference"
    parallel --will-cite -j 3 <"$tmp/jobs/jobs.txt" >"$tmp/par.out" 2>&1 || fail "a job failed: $(cat "$tmp/par.out")"
    [ "$(points_in "$tmp/jobs")" = 3 ] || fail "the jobs saved $(points_in "$tmp/jobs") points"
    "$volgraph" sweep "$tmp/tiny.json" --merge "$tmp/jobs" -o "$tmp/merged" >"$tmp/out" 2>"$tmp/err" || fail "merge exit $?: $(cat "$tmp/err")"
    cp -r "$tmp/merged" "$tmp/merged_once"
    "$volgraph" sweep "$tmp/tiny.json" --merge "$tmp/jobs" --merge "$tmp/merged" -o "$tmp/merged" >"$tmp/out" 2>"$tmp/err" || fail "second merge: $(cat "$tmp/err")"
    diff -r "$tmp/merged_once" "$tmp/merged" >/dev/null || fail "merging again changed the files: $(diff -r "$tmp/merged_once" "$tmp/merged" | head)"
    "$volgraph" sweep "$tmp/tiny.json" -o "$tmp/serial" >"$tmp/out" 2>"$tmp/err" || fail "serial sweep: $(cat "$tmp/err")"
    [ "$(ls "$tmp/serial/points")" = "$(ls "$tmp/merged/points")" ] || fail "the jobs' points differ from a serial run's"
    ;;
  sweep_failures)
    tiny_spec "8, 16"
    VOLGRAPH_SIMULATE_FAULT=device_lost "$volgraph" sweep "$tmp/tiny.json" -o "$tmp/f" >"$tmp/out" 2>"$tmp/err"
    [ $? = 1 ] || fail "a sweep whose points all fail should exit 1: $(cat "$tmp/err")"
    [ "$(points_in "$tmp/f")" = 2 ] || fail "both failed points should be saved"
    grep -l '"ok": false' "$tmp"/f/points/*.json | wc -l | grep -qx 2 || fail "the points are not marked failed"
    grep -l 'DEVICE_LOST' "$tmp"/f/points/*.json | wc -l | grep -qx 2 || fail "the error is not recorded"
    grep -l '"device": "llvmpipe' "$tmp"/f/points/*.json | wc -l | grep -qx 2 || fail "the failed points do not name their device"
    ;;
  sweep_bad)
    tiny_spec
    sed 's/"fog_media.slices"/"fog_media.slicez"/' "$tmp/tiny.json" >"$tmp/bad.json"
    expect_exit 2 "bad.json" "$volgraph" sweep "$tmp/bad.json" -o "$tmp/b"
    grep -q "/series/0" "$tmp/err" || fail "the message does not point at the series: $(cat "$tmp/err")"
    [ "$(grep -c . "$tmp/err")" -le 2 ] || fail "more than one message: $(cat "$tmp/err")"
    expect_exit 2 "sweep needs a SPEC" "$volgraph" sweep -o "$tmp/b"
    ;;
  shipped)
    "$volgraph" sweep "$arg" --size 32x18 --runs 1 --warmup 0 -o "$tmp/s" >"$tmp/out" 2>"$tmp/err" || fail "exit $?: $(tail -c 3000 "$tmp/err")"
    grep -q " 0 failed" "$tmp/out" || fail "$(cat "$tmp/out")"
    grep -q '"pareto": true' "$tmp/s/results.json" || fail "no point on the Pareto front"
    ;;
  sweep_identity)
    tiny_spec "8, 16"
    cp "$tmp/tiny.json" "$tmp/other.json"
    "$volgraph" sweep "$tmp/tiny.json" --size 16x9 -o "$tmp/a" >"$tmp/out" 2>"$tmp/err" || fail "sweep: $(cat "$tmp/err")"
    expect_exit 2 "measured with other settings" "$volgraph" sweep "$tmp/other.json" --size 16x9 -o "$tmp/a"
    grep -q "tiny.json against .*other.json" "$tmp/err" || fail "the refusal does not name both specs: $(cat "$tmp/err")"
    expect_exit 2 "measured with other settings" "$volgraph" tune "$tmp/other.json" --size 16x9 --max-error 1 -o "$tmp/a"
    [ -e "$tmp/a/tuned.txt" ] && fail "tune wrote another spec's choice"
    "$volgraph" sweep "$tmp/other.json" --size 16x9 -o "$tmp/b" >"$tmp/out" 2>"$tmp/err" || fail "sweep b: $(cat "$tmp/err")"
    expect_exit 2 "holds another sweep" "$volgraph" sweep --merge "$tmp/a" --merge "$tmp/b" -o "$tmp/m"
    grep -q "tiny.json against .*other.json" "$tmp/err" || fail "the merge refusal does not name both: $(cat "$tmp/err")"
    expect_exit 2 "holds another sweep" "$volgraph" sweep "$tmp/tiny.json" --merge "$tmp/a" -o "$tmp/m"  # SPEC at 32x18
    [ -z "$(ls -A "$tmp/m" 2>/dev/null)" ] || fail "a refused merge left files: $(ls -A "$tmp/m")"
    "$volgraph" sweep --merge "$tmp/a" -o "$tmp/m" >"$tmp/out" 2>"$tmp/err" || fail "merge without SPEC: $(cat "$tmp/err")"
    grep -q "16x9, median of 1 frames after 0 warm-up" "$tmp/m/results.md" || fail "results.md misstates: $(head -3 "$tmp/m/results.md")"
    [ "$(json_value "$tmp/m/results.json" "j['size'], j['runs'], j['spec_points']")" = "[16, 9] 1 2" ] ||
      fail "results.json misstates the sweep: $(head -c 600 "$tmp/m/results.json")"
    "$volgraph" sweep "$tmp/tiny.json" --size 16x9 --runs 2 --emit-jobs -o "$tmp/j" >"$tmp/out" 2>"$tmp/err" || fail "emit: $(cat "$tmp/err")"
    bash -c "$(head -n 1 "$tmp/j/jobs.txt")" >"$tmp/out" 2>"$tmp/err" || fail "a job of a sweep emitted with --size failed: $(cat "$tmp/err")"
    [ "$(json_value "$tmp/j/points/$(ls "$tmp/j/points" | head -n 1)" "j['timing']['runs']")" = 2 ] || fail "the job dropped --runs 2"
    # A damaged folder is bad input naming the file: a point file cut short, `points` a file.
    first=$(ls "$tmp/a/points" | head -n 1)
    head -c 100 "$tmp/a/points/$first" >"$tmp/cut" && mv "$tmp/cut" "$tmp/a/points/$first"
    expect_exit 2 "points/$first: error: not JSON" "$volgraph" sweep "$tmp/tiny.json" --size 16x9 -o "$tmp/a"
    expect_exit 2 "points/$first: error: not JSON" "$volgraph" sweep --merge "$tmp/a" -o "$tmp/m2"
    rm -r "$tmp/a/points" && echo x >"$tmp/a/points"
    expect_exit 2 "points: error: is not a folder" "$volgraph" tune "$tmp/tiny.json" --size 16x9 --max-error 1 -o "$tmp/a"
    ;;
  outputs_not_inputs)
    tiny_spec "8, 16"
    mkdir -p "$tmp/o" "$tmp/elsewhere"
    for name in results.json tuned.json manifest.json sweep_settings.txt; do
      cp "$tmp/tiny.json" "$tmp/o/$name"
      expect_exit 2 "would overwrite the spec" "$volgraph" sweep "$tmp/o/$name" --size 16x9 -o "$tmp/o"
      cmp -s "$tmp/tiny.json" "$tmp/o/$name" || fail "the spec $name was overwritten"
      rm "$tmp/o/$name"
    done
    cp "$tmp/tiny.json" "$tmp/o/tuned.json"
    expect_exit 2 "would overwrite the spec" "$volgraph" tune "$tmp/o/tuned.json" --max-error 1 -o "$tmp/o"
    expect_exit 2 "would overwrite the spec" "$volgraph" sweep "$tmp/o/tuned.json" --emit-jobs -o "$tmp/o/../o"
    ln -s "$tmp/o/tuned.json" "$tmp/elsewhere/spec.json"  # another name of the same file
    expect_exit 2 "would overwrite the spec" "$volgraph" tune "$tmp/elsewhere/spec.json" --max-error 1 -o "$tmp/o"
    cmp -s "$tmp/tiny.json" "$tmp/o/tuned.json" || fail "tune overwrote its spec"
    rm -r "$tmp/o"; mkdir -p "$tmp/o/points"
    cp "$tmp/tiny.json" "$tmp/o/points/spec.json"
    expect_exit 2 "would overwrite the spec" "$volgraph" sweep "$tmp/o/points/spec.json" -o "$tmp/o"
    sed "s|$arg/configs/demo_fog.json|$tmp/o/results.md|" "$tmp/tiny.json" >"$tmp/cfg_in_o.json"
    cp "$arg/configs/demo_fog.json" "$tmp/o/results.md"
    cp -r "$arg/configs/graphs" "$tmp/o/graphs"  # what the config includes
    expect_exit 2 "would overwrite the spec's config" "$volgraph" sweep "$tmp/cfg_in_o.json" -o "$tmp/o"
    cp "$arg/configs/demo_fog.json" "$tmp/o/report.json"
    expect_exit 2 "would overwrite the config" "$volgraph" ab "$tmp/o/report.json" --pass fog_integral --a wronski --b hillaire -o "$tmp/o"
    cmp -s "$arg/configs/demo_fog.json" "$tmp/o/report.json" || fail "ab overwrote its config"
    ;;
  bad_reference)
    tiny_spec "8, 16"
    # pfm FILE W H VALUE [HEADER_ONLY]: a colour PFM of one value (nan, inf, 0.5), or its header alone.
    pfm() { python3 -c "import struct,sys; w,h=int(sys.argv[2]),int(sys.argv[3]); f=open(sys.argv[1],'wb'); f.write(b'PF\\n%d %d\\n-1.0\\n'%(w,h));
if len(sys.argv)<6: f.write(struct.pack('<f',float(sys.argv[4]))*(w*h*3))" "$@"; }
    config="$arg/configs/demo_fog.json"
    for value in nan inf -inf; do
      pfm "$tmp/ref.pfm" 16 9 "$value"
      expect_exit 2 "non-finite value" "$volgraph" ab "$config" --pass fog_integral --a wronski --b hillaire --size 16x9 --runs 1 --reference "$tmp/ref.pfm" -o "$tmp/ab"
      expect_exit 2 "non-finite value" "$volgraph" tune "$tmp/tiny.json" --size 16x9 --reference "$tmp/ref.pfm" --max-error 1 -o "$tmp/t_$value"
      [ -e "$tmp/t_$value/tuned.txt" ] && fail "tune accepted a $value reference"
    done
    python3 -c "import struct; open('$tmp/one.pfm','wb').write(b'PF\\n16 9\\n-1.0\\n' + struct.pack('<f', 0.5)*(16*9*3-1) + struct.pack('<f', float('nan')))"
    expect_exit 2 "1 non-finite value(s) (NaN or Inf), the first at pixel (15, 0)" "$volgraph" ab "$config" --pass fog_integral --a wronski --b hillaire --size 16x9 --runs 1 --reference "$tmp/one.pfm" -o "$tmp/ab"
    mkfifo "$tmp/fifo.pfm"
    expect_exit 2 "not a regular file" timeout 60 "$volgraph" ab "$config" --pass fog_integral --a wronski --b hillaire --size 16x9 --runs 1 --reference "$tmp/fifo.pfm" -o "$tmp/ab"
    pfm "$tmp/huge.pfm" 65536 65536 0 header-only
    expect_exit 2 "truncated: its header says 65536x65536" "$volgraph" ab "$config" --pass fog_integral --a wronski --b hillaire --size 16x9 --runs 1 --reference "$tmp/huge.pfm" -o "$tmp/ab"
    [ -z "$(ls -A "$tmp/ab" 2>/dev/null)" ] || fail "a refused reference left a report: $(ls -A "$tmp/ab")"
    ;;
  tune)
    tiny_spec "8, 16"
    "$volgraph" sweep "$tmp/tiny.json" -o "$tmp/t" >"$tmp/out" 2>"$tmp/err" || fail "sweep: $(cat "$tmp/err")"
    # Make the answer known: rewrite the two points' figures (slices 8: fast, error 0.2;
    # slices 16: slow, error 0.1), then a budget of 0.15 must choose slices 16, and 0.25 slices 8.
    python3 - "$tmp/t/points" <<'PY' || fail "rewriting the fixture"
import json, os, sys
for name in os.listdir(sys.argv[1]):
    path = os.path.join(sys.argv[1], name)
    p = json.load(open(path))
    fast = "=8" in p["label"]
    p["timing"]["frame_wall_ms"]["median"] = 1.0 if fast else 2.0
    p["metrics"]["relative_rmse"] = 0.2 if fast else 0.1
    json.dump(p, open(path, "w"))
PY
    "$volgraph" tune "$tmp/tiny.json" --max-error 0.15 -o "$tmp/t" >"$tmp/out" 2>"$tmp/err" || fail "tune exit $?: $(cat "$tmp/err")"
    grep -q -- "--set fog_media.slices=16" "$tmp/out" || fail "budget 0.15 should choose 16 slices: $(cat "$tmp/out")"
    "$volgraph" validate "$tmp/t/tuned.json" >/dev/null || fail "tuned.json is not a valid config"
    grep -q '"params": *{ *"slices": *16' "$tmp/t/tuned.json" || fail "tuned.json does not set 16 slices: $(cat "$tmp/t/tuned.json")"
    "$volgraph" tune "$tmp/tiny.json" --max-error 0.25 -o "$tmp/t" >"$tmp/out" 2>"$tmp/err" || fail "tune exit $?: $(cat "$tmp/err")"
    grep -q -- "--set fog_media.slices=8" "$tmp/out" || fail "budget 0.25 should choose 8 slices: $(cat "$tmp/out")"
    "$volgraph" tune "$tmp/tiny.json" --max-error 0.05 -o "$tmp/t" >"$tmp/out" 2>"$tmp/err"
    [ $? = 1 ] && grep -q "no point .*; the closest is \"fog_media.slices=16\" (series slices) at 0.1" "$tmp/err" ||
      fail "a budget no point meets should exit 1 naming the closest: $(cat "$tmp/err")"
    expect_exit 2 "--metric expects an error metric" "$volgraph" tune "$tmp/tiny.json" --max-error 0.1 --metric psnr -o "$tmp/t"
    ;;
  *) fail "unknown mode $mode" ;;
esac
echo PASS
