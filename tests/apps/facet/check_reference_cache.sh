#!/bin/bash
# facet parity's reference cache (docs/parity.md, "The reference cache"):
# a second run of the same command takes the CPU reference from the cache
# folder and reaches the same verdict with the same numbers; another flag
# or a changed file renders it anew, and --fresh-reference always does.
#   check_reference_cache.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "check_reference_cache: FAILED: $*" >&2; exit 1; }
export FACET_CACHE_DIR=$work/cache
cp "$repo/scenes/examples/gold_cube.gltf" .  # its buffer is inside it
env=$repo/scenes/environments/courtyard_256x128.hdr

# run NAME ARGS...: facet parity on the copied cube, its JSON kept as NAME.json.
run() {
  local name=$1
  shift
  "$facet" parity gold_cube.gltf --size 16x12 --env "$env" --ibl sampled --ibl-samples 1 --renders 4 --json "$@" \
    >"$name.json" || fail "$name: exit $?"
}
# cached NAME: the reference of NAME.json came from the cache ("true") or was rendered ("false").
cached() { /usr/bin/python3 -c "import json,sys; print(str(json.load(open(sys.argv[1]))['scenes'][0]['reference']['cached']).lower())" "$1.json"; }
# beauty NAME: the beauty AOV's errors and verdict, which a cached reference must leave as they were.
beauty() { /usr/bin/python3 -c "import json,sys; a=json.load(open(sys.argv[1]))['scenes'][0]['runs'][0]['aovs']; print([x for x in a if x['name']=='beauty'])" "$1.json"; }

run first
[ "$(cached first)" = false ] || fail "the first run found a reference in an empty cache"
run second
[ "$(cached second)" = true ] || fail "the second run rendered the reference again"
[ "$(beauty second)" = "$(beauty first)" ] || fail "the cached reference changed the verdict: $(beauty first) / $(beauty second)"
run fresh --fresh-reference
[ "$(cached fresh)" = false ] || fail "--fresh-reference took the cached reference"
run other_flag --env-rotation 30
[ "$(cached other_flag)" = false ] || fail "another flag took the cached reference"
run other_seed --seed 7
[ "$(cached other_seed)" = false ] || fail "another seed took the cached reference"
# The same path with other contents: the cube's roughness edited in place.
/usr/bin/python3 - <<'PY'
import json, pathlib
path = pathlib.Path("gold_cube.gltf")
gltf = json.loads(path.read_text())
gltf["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 0.123
path.write_text(json.dumps(gltf))
PY
run edited
[ "$(cached edited)" = false ] || fail "an edited scene file took the cached reference"
echo "check_reference_cache: reused where nothing changed, rendered anew where anything did"
