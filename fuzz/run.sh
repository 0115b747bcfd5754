#!/usr/bin/env bash
# Runs every libFuzzer harness of a FACET_FUZZ build in turn, each on its
# seeds and on a corpus that grows in <build>/fuzz/corpus/<harness>. The
# arguments after the build folder go to libFuzzer:
#   fuzz/run.sh build-sanitize -max_total_time=30
#   nice -n 19 fuzz/run.sh build-sanitize -runs=1000000
# An input that crashes is saved in <build>/fuzz/findings/<harness>/ and
# stops the run with libFuzzer's non-zero exit.
set -euo pipefail
build=$(cd "$1" && pwd)
shift
# The harnesses write each input to a scratch file: in memory where the
# machine has a memory filesystem, ten times faster than on disk.
if [[ -d /dev/shm && -w /dev/shm ]]; then export TMPDIR=/dev/shm; fi
for fuzzer in "$build"/fuzz/*_fuzz; do
  harness=$(basename "$fuzzer" _fuzz)
  mkdir -p "$build/fuzz/corpus/$harness" "$build/fuzz/findings/$harness"
  echo "fuzz: $harness"
  "$fuzzer" -artifact_prefix="$build/fuzz/findings/$harness/" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    "$@" "$build/fuzz/corpus/$harness" "$build/fuzz/seeds/$harness"
done
