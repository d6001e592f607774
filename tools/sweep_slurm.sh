#!/usr/bin/env bash
# One point of a sweep a Slurm array task: task N runs line N of DIR/jobs.txt with
# `bash -c` (each line is a complete shell command that renders one point and writes its
# file DIR/points/<id>.json; `volgraph sweep SPEC --emit-jobs -o DIR` writes the list and
# DIR/manifest.json beside it).
#
#   volgraph sweep configs/sweeps/SPEC.json --emit-jobs -o DIR
#   sbatch --array=1-$(wc -l < DIR/jobs.txt) tools/sweep_slurm.sh DIR
#   # (add %K to the range to run at most K tasks at once: --array=1-40%8)
#   # when every task has finished, gather the points and rewrite the aggregates
#   # (results.json, results.csv, report.html, pareto.svg, pareto.png):
#   volgraph sweep --merge DIR -o DIR
#
# Tasks that wrote to different folders (node-local disks) merge the same way:
# `volgraph sweep --merge DIR1 DIR2 … -o OUT`. A task that failed leaves its point
# missing or saved as failed; rerun that one line (sbatch --array=N …) and merge again.
# The same list runs without Slurm: `parallel < DIR/jobs.txt` (GNU parallel).
#
# Slurm reads the #SBATCH lines below (sbatch's flags override them).
#SBATCH --job-name=volgraph-sweep
#SBATCH --output=volgraph-sweep-%A_%a.out
#SBATCH --ntasks=1
set -euo pipefail

usage="usage: sbatch --array=1-N tools/sweep_slurm.sh DIR   (N: the lines of DIR/jobs.txt)"
dir=${1:?$usage}
task=${SLURM_ARRAY_TASK_ID:-}
jobs=$dir/jobs.txt

if [[ -z $task ]]; then
  echo "sweep_slurm.sh: SLURM_ARRAY_TASK_ID is not set: not a Slurm array task; $usage" >&2
  exit 2
fi
if [[ ! $task =~ ^[1-9][0-9]*$ ]]; then
  echo "sweep_slurm.sh: SLURM_ARRAY_TASK_ID=$task: expected a line number from 1" >&2
  exit 2
fi
if [[ ! -f $jobs ]]; then
  echo "sweep_slurm.sh: $jobs: no such file (volgraph sweep SPEC --emit-jobs -o $dir writes it)" >&2
  exit 2
fi
count=$(wc -l < "$jobs")
if (( task > count )); then
  echo "sweep_slurm.sh: task $task, but $jobs has $count line(s): --array=1-$count" >&2
  exit 2
fi

command=$(sed -n "${task}p" "$jobs")
echo "sweep_slurm.sh: task $task of $count: $command" >&2
exec bash -c "$command"
