#!/bin/bash
# facet render's PNG previews end to end, on the CPU backend:
#   - --png alone writes a PNG and no EXR; -o out.png chooses a PNG;
#   - a scene without lights or environment gets the default studio
#     environment, named in the summary and in --json;
#   - the default preview of every example scene is opaque, and the
#     studio's is nowhere black; --alpha writes
#     coverage, transparent where the rays miss;
#   - facet merge --png takes the same preview flags.
#   check_preview.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "check_preview: FAILED: $*" >&2; exit 1; }
ball=$repo/scenes/examples/superball.obj
common=(--size 40x34 --spp 1 --backend cpu)  # one pass: the checks compare renders pixel by pixel
# "min max" of channel $2 (0-based) of PNG $1, in 0..255.
channel_range() {
  oiiotool --stats "$1" | awk -v c=$(($2 + 3)) '/Stats Min/ {lo = $c} /Stats Max/ {hi = $c} END {print lo, hi}'
}

"$facet" render "$ball" "${common[@]}" --png alone.png >alone.out
grep -q "; lit by the default studio environment" alone.out || fail "the studio environment is not named: $(cat alone.out)"
[[ -s alone.png && -z $(ls ./*.exr 2>/dev/null) ]] || fail "--png alone must write the PNG only"
read -r lo hi <<<"$(channel_range alone.png 3)"
[[ $lo == 255 ]] || fail "the default preview is not opaque (alpha from $lo)"
for c in 0 1 2; do
  read -r lo hi <<<"$(channel_range alone.png $c)"
  [[ $lo -gt 0 && $hi -gt $lo ]] || fail "channel $c spans $lo..$hi: black somewhere, or flat"
done

for scene in "$repo"/scenes/examples/*.{json,obj,gltf} "$repo"/scenes/examples/*/*.gltf; do
  "$facet" render "$scene" --size 32x16 --spp 1 --backend cpu --quiet -o example.png
  read -r lo hi <<<"$(channel_range example.png 3)"
  [[ $lo == 255 ]] || fail "the preview of $scene is not opaque (alpha from $lo)"
done

"$facet" render "$ball" "${common[@]}" --quiet -o chosen.png --alpha --tonemap aces --exposure 0.5
read -r lo hi <<<"$(channel_range chosen.png 3)"
[[ $lo == 0 && $hi == 255 ]] || fail "--alpha: coverage spans $lo..$hi, expected 0..255"

"$facet" render "$ball" "${common[@]}" --quiet -o whole.exr --json >summary.json
python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); assert s["lighting"] == "default studio environment", s' \
  summary.json || fail "--json does not name the lighting"
for i in 0 1; do "$facet" render "$ball" "${common[@]}" --quiet --tile "$i/2" -o "tile$i.exr"; done
"$facet" merge --quiet tile0.exr tile1.exr -o merged.exr --png merged.png --background 0.2,0.2,0.2 --tonemap clamp
read -r lo hi <<<"$(channel_range merged.png 3)"
[[ $lo == 255 ]] || fail "the merged preview is not opaque"
echo "check_preview: passed"
