#!/bin/bash
# facet render's farm flags end to end, on the CPU backend:
#   - 4 tiles merged by facet merge equal the whole render, bit for bit;
#     merge never writes over an input tile, and -o's extension is .exr;
#   - a frame rendered alone equals the same frame of a range (turntable
#     and camera keys), and '#' pads the frame number;
#   - render --json prints the documented summary;
#   - progress shows in a log, and --quiet prints nothing.
#   check_farm.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "check_farm: FAILED: $*" >&2; exit 1; }
same_pixels() { idiff -q -fail 0 -failpercent 0 -warn 0 "$1" "$2" >/dev/null 2>&1; }
ball=$repo/scenes/examples/superball.obj
common=(--size 40x34 --spp 4 --backend cpu --quiet)

"$facet" render "$ball" "${common[@]}" -o whole.exr
for i in 0 1 2 3; do "$facet" render "$ball" "${common[@]}" --tile "$i/4" -o "tile$i.exr"; done
"$facet" merge --quiet tile0.exr tile1.exr tile2.exr tile3.exr -o merged.exr --png merged.png
same_pixels whole.exr merged.exr || fail "the merged tiles differ from the whole render"
[[ -s merged.png ]] || fail "merge wrote no PNG"
"$facet" render "$ball" "${common[@]}" --crop 5,3,31,20 -o crop.exr
"$facet" merge --quiet crop.exr tile0.exr -o never.exr 2>/dev/null && fail "overlapping tiles were merged"
[[ ! -e never.exr ]] || fail "a refused merge left a file"
cp tile1.exr tile1.kept
"$facet" merge --quiet tile0.exr tile1.exr tile2.exr tile3.exr -o ./tile1.exr 2>/dev/null &&
  fail "merge overwrote one of its input tiles"
cmp -s tile1.exr tile1.kept || fail "a refused merge changed its input tile"
"$facet" merge --quiet tile0.exr tile1.exr tile2.exr tile3.exr -o merged.png 2>/dev/null &&
  fail "merge wrote EXR data into a .png"
[[ $(head -c 4 merged.png | od -An -tx1 | tr -d ' ') == 89504e47 ]] ||
  fail "a refused merge replaced merged.png"

"$facet" render "$ball" "${common[@]}" --turntable 6 --frames 1-5:2 -o 'turn_##.exr' --png 'turn_##.png'
for f in 01 03 05; do [[ -f turn_$f.exr && -f turn_$f.png ]] || fail "frame $f of the range is missing"; done
[[ ! -e turn_02.exr ]] || fail "the step skipped no frame"
"$facet" render "$ball" "${common[@]}" --turntable 6 --frame 3 -o alone.exr
same_pixels turn_03.exr alone.exr || fail "frame 3 alone differs from frame 3 of the range"
same_pixels turn_01.exr turn_03.exr && fail "the turntable's frames are the same image"

cp "$ball" ball.obj
cat >keys.json <<'JSON'
{"objects": [{"mesh": "ball.obj"}], "camera": {"eye": [0, 0, 6]},
 "camera_keys": [{"frame": 0}, {"frame": 4, "eye": [0, 3, 5], "fov": 30}]}
JSON
"$facet" render keys.json "${common[@]}" --frames 0-4 -o 'keys_#.exr'
"$facet" render keys.json "${common[@]}" --frame 2 -o keys_alone.exr
same_pixels keys_2.exr keys_alone.exr || fail "keyed frame 2 alone differs from frame 2 of the range"
same_pixels keys_1.exr keys_2.exr && fail "the keyed camera does not move"

"$facet" render "$ball" --size 40x34 --backend cpu --crop 0,17,40,34 --frames 0-1 --turntable 4 -o 'json_#.exr' --png 'json_#.png' \
  --noise-threshold 0.05 --json >summary.json
python3 - summary.json <<'PY' || fail "render --json is not the documented summary"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["backend"] == "cpu" and s["width"] == 40 and s["height"] == 34 and s["spp"] == "adaptive", s
assert "CPU reference" in s["adapter"], s["adapter"]
assert s["peak_resident_bytes"] > 0
assert [r["frame"] for r in s["renders"]] == [0, 1]
for r in s["renders"]:
    assert r["crop"] == [0, 17, 40, 34], r["crop"]
    assert r["outputs"] == ["json_%d.exr" % r["frame"], "json_%d.png" % r["frame"]], r["outputs"]
    a = r["adaptive"]
    assert a["stop"] == "converged" and a["max_tile_error"] <= a["noise_threshold"] == 0.05, a
    assert 16 <= a["spp_min"] <= a["spp_mean"] <= a["spp_max"] <= 256 and a["rounds"] >= 4, a
    assert a["samples"] == 40 * 17 * a["spp_mean"] <= r["primary_rays"] and r["rays_per_second"] > 0
    assert set(r["stages_ms"]) == {"refine + BVH", "environment", "trace + shade"} and r["wall_ms"] > 0
    assert r["gpu_bytes"] == 0
PY
# Progress in a log: a line at most every 10 s and one at the end, so a
# render of under 10 s logs one line; --quiet: nothing at all.
"$facet" render "$ball" --size 40x34 --backend cpu -o progress.exr >/dev/null 2>progress.log
grep -Eq "^rendering 100%, [0-9.]+ s elapsed$" progress.log || fail "no closing progress line in a log"
lines=$(grep -c "%" progress.log)
[[ $lines == 1 ]] || fail "$lines progress lines for a render of under 10 s, expected 1: $(cat progress.log)"
"$facet" render "$ball" "${common[@]}" -o quiet.exr >quiet.out 2>&1
[[ ! -s quiet.out ]] || fail "--quiet printed: $(cat quiet.out)"
echo "check_farm: passed"
