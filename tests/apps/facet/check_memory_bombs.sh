#!/bin/bash
# Images whose headers declare more texels than memory holds are refused
# from the header, before a texel is decoded: under a 3 GB address-space cap
# (ulimit -v), a 16000 x 16000 PNG and JPEG of a few hundred bytes, named
# as a scene's texture, end in one `facet: error:` naming the file, exit 1,
# and leave no output. Without the cap the same files fit (16000 is within
# the 16384 size limit), so only the estimate can refuse them.
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
  set +e
  cap "$facet" render "scene_${image%.*}.json" -o out.exr --backend cpu >out.txt 2>err.txt
  rc=$?
  set -e
  [[ $rc == 1 ]] || fail "$image: exit $rc, expected 1: $(cat err.txt)"
  grep -q "^facet: error: .*$image: image: a 16000 x 16000 texture needs about .* GB of memory to build and the limit is .* ($source_text)" err.txt ||
    fail "$image: the error does not name the estimate: $(cat err.txt)"
  [[ $(wc -l <err.txt) == 1 ]] || fail "$image: more than one line on stderr: $(cat err.txt)"
  [[ ! -e out.exr ]] || fail "$image: an output was written"
done
echo "check_memory_bombs: both images refused from their headers"
