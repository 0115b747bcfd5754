#!/bin/bash
# At the texture scale bound (scenes/texture.h, kMaxTextureScale: 1e6 for
# KHR_texture_transform's scale and for normalTexture.scale) the GPU's float
# texture coordinates and the CPU reference's doubles still agree: the
# textured cushion with every slot scaled by +-1e6 passes facet parity, and
# one step past the bound is refused at load.
#   check_texture_scale_bound.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cp "$repo"/scenes/examples/textured/cushion.* "$repo"/scenes/examples/textured/*.png "$work"
cd "$work"
fail() { echo "check_texture_scale_bound: FAILED: $*" >&2; exit 1; }
python3 - <<'PY'
import json
for name, scale in (('bound', 1e6), ('past', 1.000001e6)):
    d = json.load(open('cushion.gltf'))
    m = d['materials'][0]
    for slot in (m['pbrMetallicRoughness']['baseColorTexture'], m['pbrMetallicRoughness']['metallicRoughnessTexture'],
                 m['normalTexture']):
        slot['extensions'] = {'KHR_texture_transform': {'scale': [scale, -scale]}}
    m['normalTexture']['scale'] = scale
    d['extensionsUsed'] = d.get('extensionsUsed', []) + ['KHR_texture_transform']
    json.dump(d, open(name + '.gltf', 'w'))
PY
"$facet" parity bound.gltf --size 64x48 >parity.txt 2>&1 || fail "parity at the bound: $(cat parity.txt)"
grep -q "parity: within tolerance" parity.txt || fail "parity at the bound: $(cat parity.txt)"
set +e
"$facet" render past.gltf -o past.exr --backend cpu --size 8x8 >out.txt 2>err.txt
rc=$?
set -e
[[ $rc == 1 ]] || fail "past the bound: exit $rc, expected 1: $(cat err.txt)"
grep -q "^facet: error: past.gltf: materials\[0\]\..*scale.*: must be within -1e6 to 1e6" err.txt ||
  fail "past the bound: $(cat err.txt)"
echo "check_texture_scale_bound: parity at 1e6, refused past it"
