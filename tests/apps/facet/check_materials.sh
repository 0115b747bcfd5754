#!/bin/bash
# facet render's --material and --set end to end, on the CPU backend: each
# changes the picture where it should and nowhere else.
#   - --material PRESET and --material FILE on a bare OBJ and on a glTF;
#   - --material OBJECT=... on one object of a scene of two;
#   - --set on a JSON scene's object, and on a model's render settings;
#   - the material library scene renders.
#   check_materials.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "check_materials: FAILED: $*" >&2; exit 1; }
ball=$repo/scenes/examples/superball.obj
library=$repo/scenes/examples/materials
common=(--size 32x32 --spp 1 --backend cpu --quiet)  # one pass: the checks compare renders pixel by pixel
# Mean of channel $2 (0 R, 1 G, 2 B) of PNG $1, in 0..1, over the crop $3
# (WxH+X+Y; the whole 32x32 image by default).
mean() { oiiotool "$1" --cut "${3:-32x32+0+0}" --printstats | awk -v c=$(($2 + 3)) '/Stats Avg/ {print $c}'; }
# Whether the mean of channel $2 exceeds that of channel $3 by more than $4 (over crop $5).
warmer() { awk -v a="$(mean "$1" "$2" ${5:-})" -v b="$(mean "$1" "$3" ${5:-})" -v d="$4" 'BEGIN {exit !(a - b > d)}'; }
neutral() { awk -v r="$(mean "$1" 0 ${2:-})" -v b="$(mean "$1" 2 ${2:-})" 'BEGIN {exit !(r - b < 0.02 && b - r < 0.02)}'; }

"$facet" render "$ball" "${common[@]}" -o default.png
neutral default.png || fail "the default grey plastic is not neutral"
# Before the model: each --material takes one value, not the model too.
"$facet" render --material gold "$ball" "${common[@]}" -o gold.png
warmer gold.png 0 2 0.05 || fail "--material gold: the ball is not gold (R $(mean gold.png 0), B $(mean gold.png 2))"
"$facet" render "$ball" "${common[@]}" -o plastic.png --material "$library/red_plastic.json"
warmer plastic.png 0 1 0.05 || fail "--material red_plastic.json: the ball is not red"

# glTF: the cube's own gold, then a file's ceramic on the object by name.
cube=$repo/scenes/examples/gold_cube.gltf
"$facet" render "$cube" "${common[@]}" -o cube.png
warmer cube.png 0 2 0.05 || fail "the glTF cube is not gold to begin with"
"$facet" render "$cube" "${common[@]}" -o cube_ceramic.png --material "cube=$library/white_ceramic.json"
neutral cube_ceramic.png || fail "--material cube=white_ceramic.json: the cube is still coloured"

# Two balls, left and right: a material on one by name, then by --set.
cat >two.json <<JSON
{"camera": {"eye": [0, 0, 9], "target": [0, 0, 0], "fov": 30},
 "objects": [{"name": "left", "mesh": "$ball", "transform": {"translate": [-1.3, 0, 0]}},
             {"name": "right", "mesh": "$ball", "transform": {"translate": [1.3, 0, 0]}}]}
JSON
"$facet" render two.json "${common[@]}" -o two.png --material left=gold
warmer two.png 0 2 0.05 16x32+0+0 || fail "--material left=gold: the left ball is not gold"
neutral two.png 16x32+16+0 || fail "--material left=gold: the right ball changed"
"$facet" render two.json "${common[@]}" -o two_set.png --set 'objects[1].material=gold'
warmer two_set.png 0 2 0.05 16x32+16+0 || fail "--set objects[1].material=gold: the right ball is not gold"
neutral two_set.png 16x32+0+0 || fail "--set objects[1].material=gold: the left ball changed"
# Every object's material, and one object's over it whatever the order.
"$facet" render two.json "${common[@]}" -o two_both.png --material right=silver --material gold
warmer two_both.png 0 2 0.05 16x32+0+0 || fail "--material gold: the left ball is not gold"
neutral two_both.png 16x32+16+0 || fail "--material right=silver: the right ball is not silver"

# --set on a bare model's render settings, seen in --json.
"$facet" render --set render.spp=4 --set camera.fov=30 "$ball" --size 8x8 --backend cpu -o spp.exr --json >spp.json
python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); assert s["spp"] == 4, s' spp.json ||
  fail "--set render.spp=4 is not the render's spp"

"$facet" render "$repo/scenes/examples/material_library.json" "${common[@]}" -o library.png
warmer library.png 0 2 0.02 8x16+0+8 || fail "the library's gold ball is not gold"
echo "check_materials: passed"
