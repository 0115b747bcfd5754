#!/bin/bash
# No command writes over a file it reads: an output that names one of the
# render's inputs (the environment map, a texture, by another name or a
# hard link) is refused with exit 2 before anything renders, in render,
# render --watch and preview, and the input is left byte for byte.
#   check_inputs_kept.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
fail() { echo "check_inputs_kept: FAILED: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work" && cd "$work"
cp "$repo/scenes/environments/courtyard_256x128.hdr" courtyard.hdr
cp -r "$repo/scenes/examples/textured" textured
cat >lit.json <<JSON
{"camera": {"eye": [0, 0, 6], "target": [0, 0, 0], "fov": 35},
 "environment": {"file": "courtyard.hdr", "method": "prefiltered"},
 "materials": {"gold": {"preset": "gold", "roughness": 0.4}},
 "objects": [{"name": "ball", "mesh": "$repo/scenes/examples/superball.obj", "material": "gold"}]}
JSON
cp courtyard.hdr courtyard.kept
cp textured/cushion_base_color.png base_color.kept
common=(--size 16x16 --spp 1 --backend cpu --quiet)

# expect_refused NAME INPUT KEPT COMMAND...: exit 2, the rule named, INPUT as it was.
expect_refused() {
  local name=$1 input=$2 kept=$3 rc=0
  shift 3
  "$@" 2>err.txt >/dev/null || rc=$?
  [[ $rc == 2 ]] || fail "$name: exit $rc, expected 2: $(cat err.txt)"
  grep -q "which this command reads: an output never replaces an input" err.txt ||
    fail "$name: the error does not name the rule: $(cat err.txt)"
  cmp -s "$input" "$kept" || fail "$name: the input was changed"
}

# The environment map as the EXR -o, by its name, by another spelling and by a hard link.
cp "$repo/scenes/environments/studio.exr" court.exr && cp court.exr court.kept
sed 's/courtyard.hdr/court.exr/' lit.json >lit_exr.json
expect_refused "render -o the environment" court.exr court.kept \
  "$facet" render lit_exr.json "${common[@]}" -o court.exr
expect_refused "render -o the environment by another path" court.exr court.kept \
  "$facet" render lit_exr.json "${common[@]}" -o "../$(basename "$work")/./court.exr"
ln court.exr hard.exr
expect_refused "render -o a hard link to the environment" court.exr court.kept \
  "$facet" render lit_exr.json "${common[@]}" -o hard.exr
grep -q "names 'court.exr'" err.txt || fail "the error does not name the input: $(cat err.txt)"
expect_refused "render --watch -o the environment" court.exr court.kept \
  "$facet" render lit_exr.json "${common[@]}" -o court.exr --watch --watch-limit 1

# A texture of a glTF model as a PNG output.
gltf=textured/cushion.gltf
expect_refused "render --png a texture" textured/cushion_base_color.png base_color.kept \
  "$facet" render "$gltf" "${common[@]}" -o cushion.exr --png textured/cushion_base_color.png
[[ ! -e cushion.exr ]] || fail "a refused render wrote its EXR"
expect_refused "preview -o the model's texture" textured/cushion_base_color.png base_color.kept \
  "$facet" preview gold --model "$gltf" --size 16x16 --backend cpu --time-limit 86400 --quiet \
  -o textured/cushion_base_color.png

# Outputs beside the inputs are written as before.
"$facet" render lit.json "${common[@]}" -o beside.exr --png beside.png
[[ -s beside.exr && -s beside.png ]] || fail "a render beside its inputs wrote nothing"
cmp -s courtyard.hdr courtyard.kept || fail "a render changed its environment map"
echo "check_inputs_kept: passed"
