#!/bin/bash
# facet parity's reference cache (docs/parity.md, "The reference cache"):
# a second run of the same command takes the CPU reference from the cache
# folder and reaches the same verdict with the same numbers; each flag that
# edits the scene, another number of renders, a file the scene reads edited
# in place and --fresh-reference render it anew.
#   check_reference_cache.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "check_reference_cache: FAILED: $*" >&2; exit 1; }
export FACET_CACHE_DIR=$work/cache
cp "$repo/scenes/cages/cube.obj" cage.obj
cat >scene.json <<JSON
{"camera": {"eye": [2, 1.5, 3], "target": [0, 0, 0]},
 "materials": {"metal": {"preset": "gold", "roughness": 0.4}},
 "environment": {"file": "$repo/scenes/environments/courtyard_256x128.hdr", "method": "sampled", "samples": 1},
 "objects": [{"name": "cube", "mesh": "cage.obj", "material": "metal"}]}
JSON

# run NAME ARGS...: facet parity on the scene, its JSON kept as NAME.json.
run() {
  local name=$1
  shift
  "$facet" parity scene.json --size 16x12 --json "$@" >"$name.json" || fail "$name: exit $?"
}
# cached NAME: "true" where NAME's reference came from the cache, "false" where it was rendered.
cached() {
  /usr/bin/python3 -c "import json,sys; print(str(json.load(open(sys.argv[1]))['scenes'][0]['reference']['cached']).lower())" "$1.json"
}
# beauty NAME: the beauty AOV's errors and verdict, which a cached reference must leave as they were.
beauty() {
  /usr/bin/python3 -c "import json,sys; a=json.load(open(sys.argv[1]))['scenes'][0]['runs'][0]['aovs']; print([x for x in a if x['name']=='beauty'])" "$1.json"
}
# renders_anew NAME ARGS...: the run rendered its reference.
renders_anew() {
  local name=$1
  run "$@"
  [ "$(cached "$name")" = false ] || fail "$name took the cached reference"
}

run first
[ "$(cached first)" = false ] || fail "the first run found a reference in an empty cache"
run second
[ "$(cached second)" = true ] || fail "the second run rendered the reference again"
[ "$(beauty second)" = "$(beauty first)" ] || fail "the cached reference changed the verdict: $(beauty first) / $(beauty second)"
renders_anew fresh --fresh-reference
renders_anew material --material silver
renders_anew set --set materials.metal.roughness=0.3
renders_anew seed --seed 7
renders_anew renders --renders 8
# The cage the scene names, edited in place: the same path and flags, another surface.
sed -i 's/^v -1 -1 -1$/v -1 -1 -1.25/' cage.obj
renders_anew edited_cage
run edited_again
[ "$(cached edited_again)" = true ] || fail "the edited cage's reference was not kept"
echo "check_reference_cache: reused where nothing changed, rendered anew where anything did"
