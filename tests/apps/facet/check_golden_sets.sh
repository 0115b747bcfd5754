#!/bin/bash
# facet compare on golden sets (docs/parity.md, "facet compare"): K renders
# of a Monte Carlo estimate seeds apart on the CPU reference, K on the GPU
# with the same seeds (render --seed, --seeds), paired by seed (in any order
# on the command line) and judged by the paired t-test; a dropped tile fails; a set made with other
# settings, another scene or other seeds is not comparable (exit 6, named);
# sets that cannot be paired are bad input (exit 1).
#   check_golden_sets.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "check_golden_sets: FAILED: $*" >&2; exit 1; }
scene=$repo/scenes/examples/gold_cube.gltf
lit=(--size 16x12 --env "$repo/scenes/environments/courtyard_256x128.hdr" --ibl sampled --ibl-samples 1)

# render FOLDER A-B SPP [FLAGS...]: one EXR a seed, named by the seed, in one process (--seeds).
render() {
  local folder=$1 seeds=$2 spp=$3
  shift 3
  mkdir -p "$folder"
  "$facet" render "$scene" "${lit[@]}" --spp "$spp" --seeds "$seeds" -o "$folder/#.exr" --quiet "$@"
}
# expect CODE PATTERN ARGS...: facet compare ARGS exits CODE, its output matching PATTERN.
expect() {
  local code=$1 pattern=$2
  shift 2
  set +e
  "$facet" compare "$@" >out.txt 2>&1
  local got=$?
  set -e
  [ "$got" = "$code" ] || fail "compare $*: exit $got, not $code: $(cat out.txt)"
  grep -Eq -- "$pattern" out.txt || fail "compare $*: no '$pattern' in: $(cat out.txt)"
}

# The golden set a process a seed (--seed), the others a process a set (--seeds): the same renders.
mkdir -p golden
for seed in 0 1 2 3; do
  "$facet" render "$scene" "${lit[@]}" --spp 1 --seed "$seed" -o "golden/$seed.exr" --quiet --backend cpu
done
render gpu 0-3 1
# Refusals read headers alone: these sets need no GPU.
render other_spp 0-3 4 --backend cpu
render other_seeds 1-4 1 --backend cpu
render rotated 0-3 1 --env-rotation 90 --backend cpu
FACET_FAULT=dropped-tile render dropped 0-3 1

expect 0 "ok: paired t-test over 4 renders" golden/{0,1,2,3}.exr gpu/{0,1,2,3}.exr
# Paired by seed, not by place: the candidates reversed pair as before.
expect 0 "ok: paired t-test over 4 renders" golden/{0,1,2,3}.exr gpu/{3,2,1,0}.exr
expect 5 "is out of tolerance" golden/{0,1,2,3}.exr dropped/{0,1,2,3}.exr
expect 6 "^facet: error: compare: other_spp/0.exr: not comparable with golden/0.exr: spp 4 against 1$" \
  golden/{0,1,2,3}.exr other_spp/{0,1,2,3}.exr
expect 6 "not comparable with golden/0.exr: seeds 1, 2, 3, 4 against 0, 1, 2, 3: each candidate is paired" \
  golden/{0,1,2,3}.exr other_seeds/{1,2,3,4}.exr
expect 6 "not comparable with golden/0.exr: the scene differs .*facetPictureDigest [0-9a-f]{16} against" \
  golden/{0,1,2,3}.exr rotated/{0,1,2,3}.exr
expect 1 "are both seed 0: renders of one set are paired by their seeds" golden/{0,0}.exr gpu/{0,1}.exr
expect 1 "are not renders of one picture: spp 4 against 1" golden/{0,1}.exr other_spp/0.exr gpu/{0,1,2}.exr
expect 1 "3 files: give the references, then as many candidates" golden/{0,1}.exr gpu/0.exr
# One pair of an estimate is judged pixel by pixel, and says so.
expect 0 "warning: .*one render of a Monte Carlo estimate is judged pixel by pixel" golden/0.exr golden/0.exr

# The seed as the scene file states it is the flag's: the same settings, the same pixels.
"$facet" render "$scene" "${lit[@]}" --spp 1 --set "environment.file=$repo/scenes/environments/courtyard_256x128.hdr" \
  --set environment.seed=3 -o set3.exr --quiet --backend cpu
expect 0 "parity: within tolerance" golden/3.exr set3.exr
grep -q "iblSeed=3" <(/usr/bin/python3 -c "import OpenImageIO as o; print(o.ImageInput.open('set3.exr').spec().getattribute('facetRenderSettings'))") ||
  fail "--set environment.seed=3 did not reach the settings"
# A scene without an environment draws fixed numbers: --seed says it changes nothing.
"$facet" render "$scene" --size 16x12 --seed 5 -o unlit.exr --backend cpu 2>err.txt
grep -q "^facet: warning: --seed 5: changes nothing here: without an environment the scene's random numbers are fixed" err.txt ||
  fail "--seed without an environment: $(cat err.txt)"
# --seeds renders what --seed renders, seed by seed.
render cpu_set 0-3 1 --backend cpu
/usr/bin/python3 - <<'PY' || fail "--seeds 0-3 did not render what --seed renders"
import sys
import numpy as np
import OpenImageIO as oiio
for seed in range(4):
    a, b = (oiio.ImageBuf(f"{folder}/{seed}.exr") for folder in ("golden", "cpu_set"))
    if a.has_error or b.has_error or not np.array_equal(a.get_pixels(), b.get_pixels()):
        sys.exit(f"seed {seed}: {a.geterror()} {b.geterror()}")
PY
echo "check_golden_sets: paired by seed, a fault caught, every other picture refused"
