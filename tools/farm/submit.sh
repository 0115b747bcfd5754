#!/bin/bash
# Submits a facet render to Slurm as a job array (README.md, "Rendering on a farm"):
#   submit.sh [--wait] tiles N OUT.exr [--png OUT.png] -- RENDER_ARGS...
#       N array tasks render the tiles (--tile i/N), then a job that starts
#       after all of them succeed (--dependency=afterok) merges them into OUT.exr.
#   submit.sh [--wait] frames A-B[:STEP] OUT_####.exr -- RENDER_ARGS...
#       one array task per frame (--frame i); '#' in OUT is the frame number.
# RENDER_ARGS are facet render's: the scene and its flags, without -o.
# Environment: FACET, the facet binary (default: facet on PATH);
# FACET_SBATCH_OPTIONS, more sbatch options for every job, e.g.
# "--partition=render --cpus-per-task=8". Prints the job ids; with --wait,
# returns when the last job ends: 0 only if every task completed.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
task=$here/facet_task.sbatch
wait=()
if [[ ${1:-} == --wait ]]; then
  wait=(--wait)
  shift
fi
usage() {
  sed -n '2,12p' "$0" >&2
  exit 1
}
[[ $# -ge 4 ]] || usage
mode=$1 range=$2 out=$3
shift 3
png=
if [[ ${1:-} == --png ]]; then
  png=$2
  shift 2
fi
[[ ${1:-} == -- ]] || usage
# sbatch --wait reports 0 for a job cancelled before it ran (the merge, when a
# tile failed), so with --wait every task's final state is read back.
finished() {
  [[ ${#wait[@]} -gt 0 ]] || return 0
  local states
  states=$(scontrol show job "$1" -o | grep -o 'JobState=[A-Z_]*' | sort -u | tr '\n' ' ')
  [[ $states == "JobState=COMPLETED " ]] || { echo "submit.sh: job $1 ended as: ${states//JobState=/}" >&2; exit 1; }
}
export FACET=${FACET:-facet}
read -r -a options <<<"${FACET_SBATCH_OPTIONS:-}"
logs=(--output="$(dirname "$out")/facet-%A_%a.log")
case "$mode" in
  tiles)
    [[ $range =~ ^[1-9][0-9]*$ ]] || usage
    array=$(sbatch --parsable "${options[@]}" "${logs[@]}" --array="0-$((range - 1))" "$task" tile "$range" "$out" "$@")
    echo "tiles: job $array"
    merge=$(sbatch --parsable "${wait[@]}" "${options[@]}" --output="$(dirname "$out")/facet-%j.log" \
      --dependency="afterok:$array" --kill-on-invalid-dep=yes "$task" merge "$range" "$out" $png)
    echo "merge: job $merge"
    finished "$merge"
    ;;
  frames)
    [[ $range =~ ^[0-9]+-[0-9]+(:[0-9]+)?$ ]] || usage
    [[ -z $png ]] || usage
    frames=$(sbatch --parsable "${wait[@]}" "${options[@]}" "${logs[@]}" --array="$range" "$task" frame "$out" "$@")
    echo "frames: job $frames"
    finished "$frames"
    ;;
  *) usage ;;
esac
