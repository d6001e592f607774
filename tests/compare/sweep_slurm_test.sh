#!/usr/bin/env bash
# tools/sweep_slurm.sh without Slurm: task 2 runs exactly line 2 of a jobs file (through
# bash -c: quotes and pipes work), a task past the end and a missing task id exit 2.
set -euo pipefail
script=${1:?usage: sweep_slurm_test.sh tools/sweep_slurm.sh}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cat > "$dir/jobs.txt" <<JOBS
echo one >> "$dir/ran"
echo "two words" | tr a-z A-Z >> "$dir/ran"
echo three >> "$dir/ran"
JOBS

SLURM_ARRAY_TASK_ID=2 bash "$script" "$dir" 2> "$dir/stderr" || fail "task 2 exited $?: $(cat "$dir/stderr")"
[[ $(cat "$dir/ran") == "TWO WORDS" ]] || fail "task 2 ran: $(cat "$dir/ran")"
grep -q "task 2 of 3" "$dir/stderr" || fail "no 'task 2 of 3' on stderr: $(cat "$dir/stderr")"

status=0
SLURM_ARRAY_TASK_ID=4 bash "$script" "$dir" 2> "$dir/stderr" || status=$?
[[ $status == 2 ]] || fail "task 4 of 3 exited $status"
grep -q "has 3 line(s)" "$dir/stderr" || fail "task 4: $(cat "$dir/stderr")"

status=0
env -u SLURM_ARRAY_TASK_ID bash "$script" "$dir" 2> "$dir/stderr" || status=$?
[[ $status == 2 ]] || fail "no task id exited $status"
grep -q "not a Slurm array task" "$dir/stderr" || fail "no task id: $(cat "$dir/stderr")"

[[ $(cat "$dir/ran") == "TWO WORDS" ]] || fail "a refused task ran something: $(cat "$dir/ran")"
echo "sweep_slurm.sh: task 2 ran line 2 only; bad tasks refused"
