#!/bin/bash
# Images whose headers declare more texels than memory holds are refused
# from the header, before a texel is decoded: under a 3 GB address-space cap
# (ulimit -v), a 16000 x 16000 PNG and JPEG of a few hundred bytes, named
# as a scene's texture, end in one `facet: error:` naming the file, exit 1,
# and leave no output. Without the cap the same files fit (16000 is within
# the 16384 size limit), so only the estimate can refuse them. The same
# images named by a glTF file (an external uri, and embedded in a GLB's
# binary chunk) are refused alike, by facet's decoder before tinygltf's could
# allocate: the error names the glTF file and the image.
# AddressSanitizer reserves terabytes of shadow address space at start-up, so
# a sanitized facet cannot run under ulimit -v at all; there the same 3 GB cap
# comes from FACET_MEMORY_LIMIT instead (LIMIT=environment).
#   check_memory_bombs.sh FACET REPOSITORY WORK_FOLDER [address-space|environment]
set -euo pipefail
facet=$1 repo=$2 work=$3 limit=${4:-address-space}
case $limit in
  address-space) cap() { (ulimit -v 3000000 && "$@"); }
                 source_text='3/4 of the address-space limit (ulimit -v)' ;;
  environment) cap() { FACET_MEMORY_LIMIT=2197 "$@"; }
               source_text='FACET_MEMORY_LIMIT' ;;
  *) echo "check_memory_bombs: unknown limit '$limit'" >&2; exit 2 ;;
esac
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "check_memory_bombs: FAILED: $*" >&2; exit 1; }
# refused SCENE WHERE: rendering SCENE ends in exit 1 and one error line in
# which WHERE (a regular expression) names the image, then the estimate; no output.
refused() {
  set +e
  cap "$facet" render "$1" -o out.exr --backend cpu >out.txt 2>err.txt
  local rc=$?
  set -e
  [[ $rc == 1 ]] || fail "$1: exit $rc, expected 1: $(cat err.txt)"
  grep -q "^facet: error: .*$2: a 16000 x 16000 texture needs about .* GB of memory to build and the limit is .* ($source_text)" err.txt ||
    fail "$1: the error does not name the image and the estimate: $(cat err.txt)"
  [[ $(wc -l <err.txt) == 1 ]] || fail "$1: more than one line on stderr: $(cat err.txt)"
  [[ ! -e out.exr ]] || fail "$1: an output was written"
}

python3 - <<'PY'
import struct, zlib
def chunk(kind, data):
    return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data))
header = struct.pack('>IIBBBBB', 16000, 16000, 8, 6, 0, 0, 0)  # 8-bit RGBA
open('bomb.png', 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', header) +
                             chunk(b'IDAT', zlib.compress(b'\0' * 4096)) + chunk(b'IEND', b''))
frame = struct.pack('>BHHB', 8, 16000, 16000, 3) + b''.join(bytes([c, 0x11, 0]) for c in (1, 2, 3))
quant = b'\0' + bytes([1] * 64)
open('bomb.jpg', 'wb').write(b'\xff\xd8' + b'\xff\xdb' + struct.pack('>H', 2 + len(quant)) + quant +
                             b'\xff\xc0' + struct.pack('>H', 2 + len(frame)) + frame + b'\xff\xd9')
PY
for image in bomb.png bomb.jpg; do
  cat >"scene_${image%.*}.json" <<JSON
{"camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 40},
 "materials": {"painted": {"f0": 0.04, "roughness": 0.5, "diffuse_texture": "$image"}},
 "objects": [{"mesh": "$repo/scenes/examples/superball.obj", "material": "painted"}],
 "render": {"width": 16, "height": 16}}
JSON
  refused "scene_${image%.*}.json" "$image: image"
done

python3 - <<'PY'
import base64, json, struct
# One triangle with TEXCOORD_0, its base colour read from image 0.
geometry = struct.pack('<9f', 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack('<6f', 0, 0, 1, 0, 0, 1)
def document(image, views, buffer_length, buffer_uri=None):
    buffer = {'byteLength': buffer_length}
    if buffer_uri: buffer['uri'] = buffer_uri
    return {'asset': {'version': '2.0'}, 'scenes': [{'nodes': [0]}], 'nodes': [{'mesh': 0}],
            'meshes': [{'primitives': [{'attributes': {'POSITION': 0, 'TEXCOORD_0': 1}, 'material': 0}]}],
            'materials': [{'pbrMetallicRoughness': {'baseColorTexture': {'index': 0}}}],
            'textures': [{'source': 0}], 'images': [image],
            'accessors': [{'bufferView': 0, 'componentType': 5126, 'count': 3, 'type': 'VEC3',
                           'min': [0, 0, 0], 'max': [1, 1, 0]},
                          {'bufferView': 1, 'componentType': 5126, 'count': 3, 'type': 'VEC2'}],
            'bufferViews': [{'buffer': 0, 'byteOffset': 0, 'byteLength': 36},
                            {'buffer': 0, 'byteOffset': 36, 'byteLength': 24}] + views,
            'buffers': [buffer]}
uri = 'data:application/octet-stream;base64,' + base64.b64encode(geometry).decode()
open('scene_uri.gltf', 'w').write(json.dumps(document({'uri': 'bomb.png'}, [], len(geometry), uri)))
jpeg = open('bomb.jpg', 'rb').read()
binary = geometry + jpeg + b'\0' * (-len(geometry + jpeg) % 4)
text = json.dumps(document({'bufferView': 2, 'mimeType': 'image/jpeg'},
                           [{'buffer': 0, 'byteOffset': len(geometry), 'byteLength': len(jpeg)}], len(binary)))
text += ' ' * (-len(text) % 4)
chunks = struct.pack('<I', len(text)) + b'JSON' + text.encode() + struct.pack('<I', len(binary)) + b'BIN\0' + binary
open('scene_embedded.glb', 'wb').write(b'glTF' + struct.pack('<II', 2, 12 + len(chunks)) + chunks)
PY
for scene in scene_uri.gltf:"images\[0\] 'bomb.png'" scene_embedded.glb:'images\[0\]'; do
  refused "${scene%%:*}" "${scene%%:*}: ${scene#*:}"
done
echo "check_memory_bombs: both images refused from their headers, named by a scene or by a glTF"
