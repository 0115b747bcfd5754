#!/bin/bash
# facet render's EXR as OpenImageIO reads it (oiiotool --info -v):
#   - the header holds worldToCamera, worldToNDC, software, the render
#     settings and the Cryptomatte entries, and the ID channels are there;
#   - worldToNDC takes every hit's world position (P) to its pixel's centre,
#     and the box's centre to the centre of its silhouette;
#   - --aovs and --half choose the channel list;
#   - tiles with ID layers and a half beauty merge into the whole render,
#     header and all.
#   check_exr_outputs.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
fail() { echo "check_exr_outputs: FAILED: $*" >&2; exit 1; }
for tool in oiiotool idiff python3; do command -v "$tool" >/dev/null || fail "$tool is not installed"; done
rm -rf "$work" && mkdir -p "$work" && cd "$work"
channels() { oiiotool --info -v "$1" | sed -n 's/^ *channel list: //p'; }

cat >two.json <<JSON
{"camera": {"eye": [0.6, 0.4, 9], "target": [0.3, 0, 0], "fov": 35},
 "materials": {"gold": {"preset": "gold", "roughness": 0.4},
               "red paint": {"preset": "plastic-high", "roughness": 0.4, "diffuse": [0.5, 0.05, 0.04]}},
 "objects": [{"name": "ball", "mesh": "$repo/scenes/examples/superball.obj", "material": "gold",
              "transform": {"translate": [-1.3, 0.3, 0]}},
             {"name": "box", "mesh": "$repo/scenes/cages/cube.obj", "material": "red paint",
              "transform": {"translate": [1.4, -0.2, 0], "scale": 0.8}}]}
JSON
common=(--size 48x32 --spp 1 --backend cpu --quiet)  # one pass: its pixel centres give P
"$facet" render two.json "${common[@]}" -o all.exr
oiiotool --info -v all.exr >info.txt
version=$("$facet" --version)
for line in "worldToCamera: " "worldToNDC: " "software: \"$version\"" \
            "facetRenderSettings: \"backend=cpu size=48x32 spp=1 method=exact" \
            'cryptomatte/[0-9a-f]\{7\}/name: "CryptoObject"' 'cryptomatte/[0-9a-f]\{7\}/name: "CryptoMaterial"' \
            'cryptomatte/[0-9a-f]\{7\}/hash: "MurmurHash3_32"' 'cryptomatte/[0-9a-f]\{7\}/conversion: "uint32_to_float32"' \
            'cryptomatte/[0-9a-f]\{7\}/manifest: "{"ball":"[0-9a-f]\{8\}","box":"[0-9a-f]\{8\}"}"' \
            'cryptomatte/[0-9a-f]\{7\}/manifest: "{"gold":"[0-9a-f]\{8\}","red paint":"[0-9a-f]\{8\}"}"'; do
  grep -q "^ *$line" info.txt || fail "oiiotool --info -v shows no '$line' in all.exr"
done
all=$(channels all.exr)
for c in "R (float)" "Z (float)" "objectId (uint)" "materialId (uint)" "faceId (uint)" "CryptoObject00.R (float)" \
         "CryptoObject00.G (float)" "CryptoMaterial00.R (float)" "P.X (float)" "uv.U (float)"; do
  [[ ", $all, " == *", $c, "* ]] || fail "all.exr has no channel $c: $all"
done

# The positions as text, pixel by pixel, for the projection.
oiiotool all.exr --ch A,P.X,P.Y,P.Z -o positions.exr
oiiotool --dumpdata positions.exr >positions.txt
channels positions.exr >positions_channels.txt
python3 - <<'PY' || fail "worldToNDC does not project the render's points onto their pixels"
import re, sys
info = open("info.txt").read()
m = [float(v) for v in re.search(r"worldToNDC: (.*)", info).group(1).split(",")]
width, height = 48, 32
def ndc(p):  # Imath's row vector times the matrix, then the divide
    x, y, z = p
    row = [x * m[j] + y * m[4 + j] + z * m[8 + j] + m[12 + j] for j in range(4)]
    return row[0] / row[3] * width, row[1] / row[3] * height
names = [c.strip() for c in open("positions_channels.txt").read().split(",")]  # the file's order
worst, hits, box = 0.0, 0, []
for line in open("positions.txt"):
    found = re.match(r"\s*Pixel \((\d+), (\d+)\): (.*)", line)
    if not found:
        continue
    value = dict(zip(names, map(float, found.group(3).split())))
    if value["A"] == 0:
        continue
    i, j = int(found.group(1)), int(found.group(2))
    u, v = ndc([value["P.X"], value["P.Y"], value["P.Z"]])
    worst = max(worst, abs(u - (i + 0.5)), abs(v - (j + 0.5)))
    hits += 1
    if value["P.X"] > 0:  # the box, right of the ball
        box.append((i + 0.5, j + 0.5))
u, v = ndc((1.4, -0.2, 0.0))
cu, cv = sum(p[0] for p in box) / len(box), sum(p[1] for p in box) / len(box)
print(f"{hits} hits, worst {worst:.2e} px from their centres; box centre at ({u:.2f}, {v:.2f}), "
      f"its {len(box)} pixels' centroid ({cu:.2f}, {cv:.2f})")
sys.exit(0 if hits > 100 and worst < 1e-3 and len(box) > 20 and abs(u - cu) < 0.5 and abs(v - cv) < 0.5 else 1)
PY

"$facet" render two.json "${common[@]}" --aovs beauty --half -o beauty.exr
# One type for every channel: oiiotool names it once, on the first line.
[[ $(channels beauty.exr) == "R, G, B, A" ]] || fail "--aovs beauty --half: $(channels beauty.exr)"
oiiotool --info -v beauty.exr | grep -q "4 channel, half openexr" || fail "--half: the beauty is not half"
"$facet" render two.json "${common[@]}" --aovs depth,ids -o ids.exr
[[ $(channels ids.exr) == "R (float), G (float), B (float), A (float), Z (float), faceId (uint), materialId (uint), objectId (uint), patchId (uint)" ]] ||
  fail "--aovs depth,ids: $(channels ids.exr)"
if grep -q cryptomatte < <(oiiotool --info -v ids.exr); then fail "--aovs without crypto wrote Cryptomatte entries"; fi

layers=(--aovs ids,crypto,depth --half)
"$facet" render two.json "${common[@]}" "${layers[@]}" -o whole.exr
for i in 0 1 2; do "$facet" render two.json "${common[@]}" "${layers[@]}" --tile "$i/3" -o "tile$i.exr"; done
"$facet" merge --quiet tile0.exr tile1.exr tile2.exr -o merged.exr --png merged.png
idiff -q -fail 0 -failpercent 0 -warn 0 whole.exr merged.exr >/dev/null 2>&1 || fail "the merged tiles differ from the whole render"
header() { oiiotool --info -v "$1" | grep -v -e '^Reading' -e "^$1 "; }
diff <(header whole.exr) <(header merged.exr) >/dev/null || fail "the merge changed the header: $(diff <(header whole.exr) <(header merged.exr))"
echo "check_exr_outputs: all checks passed"
