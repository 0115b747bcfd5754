#!/usr/bin/env bash
# Runs every libFuzzer harness of a FACET_FUZZ build, as many at once as the
# machine has cores, each on its seeds and on a corpus that grows in
# <build>/fuzz/corpus/<harness>. The arguments after the build folder go to
# libFuzzer:
#   fuzz/run.sh build-sanitize -max_total_time=30
#   nice -n 19 fuzz/run.sh build-sanitize -runs=1000000
# Each harness's output is printed whole when it ends. An input that crashes
# is saved in <build>/fuzz/findings/<harness>/, and the run exits non-zero
# once every harness has ended.
set -euo pipefail
build=$(cd "$1" && pwd)
shift
# The harnesses write each input to a scratch file: in memory where the
# machine has a memory filesystem, ten times faster than on disk.
if [[ -d /dev/shm && -w /dev/shm ]]; then export TMPDIR=/dev/shm; fi
logs=$build/fuzz/logs
mkdir -p "$logs"

run_harness() {
  local fuzzer=$1 harness
  harness=$(basename "$fuzzer" _fuzz)
  shift
  mkdir -p "$build/fuzz/corpus/$harness" "$build/fuzz/findings/$harness"
  "$fuzzer" -artifact_prefix="$build/fuzz/findings/$harness/" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    "$@" "$build/fuzz/corpus/$harness" "$build/fuzz/seeds/$harness" >"$logs/$harness.log" 2>&1
}

declare -A running=()  # pid -> harness
failed=()
finish_one() {
  local pid status=0
  wait -n -p pid || status=$?
  local harness=${running[$pid]}
  unset "running[$pid]"
  echo "fuzz: $harness (exit $status)"
  cat "$logs/$harness.log"
  [[ $status == 0 ]] || failed+=("$harness")
}
for fuzzer in "$build"/fuzz/*_fuzz; do
  while ((${#running[@]} >= $(nproc))); do finish_one; done
  run_harness "$fuzzer" "$@" &
  running[$!]=$(basename "$fuzzer" _fuzz)
done
while ((${#running[@]} > 0)); do finish_one; done
if ((${#failed[@]} > 0)); then
  echo "fuzz: findings in ${failed[*]} (inputs in $build/fuzz/findings/)" >&2
  exit 1
fi
