#!/bin/bash
# facet merge keeps every tile open while it streams: it raises its soft
# limit of open files up to the hard one when the tiles need it, and past
# the hard limit refuses the merge before opening a tile, naming the limit
# (not "Too many open files" blamed on the last tile).
#   check_merge_open_files.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "check_merge_open_files: FAILED: $*" >&2; exit 1; }
for i in $(seq 0 7); do
  "$facet" render "$repo/scenes/examples/superball.obj" --size 16x8 --tile "$i/8" -o "tile$i.exr" --backend cpu --quiet
done
# A soft limit below what 8 tiles need, a hard one above it: raised, merged.
(ulimit -Sn 12 && "$facet" merge tile*.exr -o raised.exr --quiet) || fail "the soft limit was not raised"
[[ -s raised.exr ]] || fail "no merged image"
# A hard limit below it: refused up front, and nothing written.
set +e
(ulimit -n 20 && "$facet" merge tile*.exr -o refused.exr) 2>err.txt
rc=$?
set -e
[[ $rc == 1 ]] || fail "exit $rc, expected 1: $(cat err.txt)"
grep -q "^facet: error: merge: 8 tiles are read at once and need 24 open files; this process may open 20 (ulimit -n)" err.txt ||
  fail "the error does not name the limit: $(cat err.txt)"
[[ ! -e refused.exr ]] || fail "an output was written"
echo "check_merge_open_files: raised to merge, refused past the hard limit"
