#!/bin/bash
# A Blender whose renders fail: as tools/blender/cycles_scene.py would, it
# writes an image per sample count and per converged seed, and their times,
# but every pixel is infinite. `facet bench` must refuse to measure them.
set -euo pipefail
samples= converged=0 output= scene=
while [ $# -gt 0 ]; do
  case $1 in
    --samples) samples=$2; shift ;;
    --converged) converged=$2; shift ;;
    --output) output=$2; shift ;;
    --scene) scene=$2; shift ;;
  esac
  shift
done
size=$(/usr/bin/python3 -c 'import json, sys; w, h = json.load(open(sys.argv[1]))["size"]; print(f"{w}x{h}")' "$scene")
broken() { oiiotool --pattern constant:color=0,0,0,1 "$size" 4 --powc -1,-1,-1,1 -d float -o "$1"; }
echo "samples,seconds" >"$output/cycles_times.csv"
for n in ${samples//,/ }; do
  broken "$output/cycles_${n}spp.exr"
  echo "$n,0.5" >>"$output/cycles_times.csv"
done
if [ "$converged" -gt 0 ]; then
  for seed in 1 2; do broken "$output/cycles_converged_seed$seed.exr"; done
fi
