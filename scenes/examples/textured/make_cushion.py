#!/usr/bin/env python3
"""Writes cushion.gltf, cushion.bin and its three textures, made for facet.

A box cage with one UV island per side (seams along the box's edges), meant
to be subdivided: facet render cushion.gltf --subdivision catmull-clark.
Each side is tiled as a painted checker of glazed tiles set in brass strips.
Run it again to reproduce the files byte for byte.
"""
import json
import pathlib
import struct
import zlib

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
CELL = 256              # texels per island cell of the atlas
MARGIN = 12             # texels between an island's UV edge and its cell's border
ATLAS = (3, 2)          # cells across and down
HALF = np.array([1.0, 0.45, 1.0])   # half extents of the cage
QUADS = np.array([2, 1, 2])         # cage quads along x, y, z: few, so the limit surface rounds
TILES = 2 * QUADS                   # tiles along x, y, z, their grout on and between cage edges
DEPTH = 0.05                        # height of a tile's glaze above its grout, in tile widths

# Each side: the axis it faces, its sign, the axes its (a, b) run along with
# their signs (b runs down the image), and its atlas cell.
SIDES = [
    (1, +1, (0, +1), (2, +1), (0, 0)),   # top
    (2, +1, (0, +1), (1, -1), (1, 0)),   # front
    (0, +1, (2, -1), (1, -1), (2, 0)),   # right
    (1, -1, (0, +1), (2, -1), (0, 1)),   # bottom
    (2, -1, (0, -1), (1, -1), (1, 1)),   # back
    (0, -1, (2, +1), (1, -1), (2, 1)),   # left
]


def write_png(path, pixels):
    """8-bit RGB PNG, filter 0 on every row (PNG 1.2, sections 4 and 6)."""
    height, width, _ = pixels.shape
    rows = b"".join(b"\x00" + pixels[y].astype(np.uint8).tobytes() for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9))
                     + chunk(b"IEND", b""))


def side_fields(tiles_a, tiles_b):
    """Per texel of one cell: base colour (sRGB 0..1), occlusion, roughness,
    metallic and height, for a checker of tiles_a x tiles_b glazed tiles set
    in brass strips."""
    span = CELL - 2 * MARGIN
    t = (np.arange(CELL) + 0.5 - MARGIN) / span       # island coordinate, beyond [0, 1] in the margin
    a, b = np.meshgrid(t * tiles_a, t * tiles_b)       # in tiles
    ia, ib = np.floor(a), np.floor(b)
    fa, fb = a - ia, b - ib
    light = (ia + ib) % 2 == 0
    # Distance to the nearest tile border in tile widths (the cage makes tiles about square).
    edge = np.minimum(np.minimum(fa, 1 - fa), np.minimum(fb, 1 - fb))
    strip_half, bevel = 0.05, 0.08
    in_tile = edge > strip_half
    tile_height = np.clip((edge - strip_half) / bevel, 0, 1)
    tile_height = tile_height * tile_height * (3 - 2 * tile_height)

    terracotta, cream, brass = np.array([0.72, 0.30, 0.17]), np.array([0.90, 0.84, 0.70]), np.array([0.95, 0.76, 0.42])
    base = np.where(light[..., None], cream, terracotta)
    # A faint painted mottle per tile, so the checker is not flat colour.
    mottle = 0.06 * np.sin(11.0 * a + 3.0 * np.sin(7.0 * b)) * np.sin(9.0 * b + 2.0 * ia)
    base = base * (1 + mottle[..., None])
    base = np.where(in_tile[..., None], base, brass)
    roughness = np.where(in_tile, np.where(light, 0.45, 0.8), 0.25)
    metallic = np.where(in_tile, 0.0, 1.0)
    occlusion = 0.7 + 0.3 * tile_height
    return base, occlusion, roughness, metallic, tile_height


def textures():
    width, height = ATLAS[0] * CELL, ATLAS[1] * CELL
    base = np.zeros((height, width, 3))
    orm = np.zeros((height, width, 3))
    normal = np.zeros((height, width, 3))
    for axis, _, (ax_a, _), (ax_b, _), (cx, cy) in SIDES:
        tiles_a, tiles_b = TILES[ax_a], TILES[ax_b]
        colour, occlusion, roughness, metallic, bump = side_fields(tiles_a, tiles_b)
        rows, cols = slice(cy * CELL, (cy + 1) * CELL), slice(cx * CELL, (cx + 1) * CELL)
        base[rows, cols] = colour
        orm[rows, cols] = np.stack([occlusion, roughness, metallic], axis=-1)
        # Tangent-space normal of the height field (glTF: +X right, +Y up the
        # image), its slopes per tile width; the relief is DEPTH tile widths.
        span = CELL - 2 * MARGIN
        dh_da = np.gradient(bump, axis=1) * span / tiles_a * DEPTH
        dh_db = np.gradient(bump, axis=0) * span / tiles_b * DEPTH
        n = np.stack([-dh_da, dh_db, np.ones_like(bump)], axis=-1)
        normal[rows, cols] = n / np.linalg.norm(n, axis=-1, keepdims=True)
    write_png(HERE / "cushion_base_color.png", np.round(np.clip(base, 0, 1) * 255))
    write_png(HERE / "cushion_orm.png", np.round(np.clip(orm, 0, 1) * 255))
    write_png(HERE / "cushion_normal.png", np.round((normal * 0.5 + 0.5) * 255))


def cage():
    """Positions, UVs and triangles: each cage quad split into four triangles
    about its centre, so the triangulation keeps the box's symmetry."""
    positions, uvs, triangles = [], [], []
    span = (CELL - 2 * MARGIN) / CELL
    for axis, sign, (ax_a, sa), (ax_b, sb), (cx, cy) in SIDES:
        na, nb = QUADS[ax_a], QUADS[ax_b]

        def vertex(a, b):
            p = np.zeros(3)
            p[axis] = sign * HALF[axis]
            p[ax_a] = sa * (2 * a - 1) * HALF[ax_a]
            p[ax_b] = sb * (2 * b - 1) * HALF[ax_b]
            positions.append(p)
            uvs.append(((cx + MARGIN / CELL + a * span) / ATLAS[0], (cy + MARGIN / CELL + b * span) / ATLAS[1]))
            return len(positions) - 1

        for i in range(na):
            for j in range(nb):
                corners = [vertex((i + di) / na, (j + dj) / nb) for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1))]
                centre = vertex((i + 0.5) / na, (j + 0.5) / nb)
                # Counter-clockwise seen from outside: (a, b) is right-handed
                # about the outward normal exactly when the side's frame is.
                frame = np.zeros((3, 3))
                frame[0, ax_a], frame[1, ax_b], frame[2, axis] = sa, sb, sign
                flip = np.linalg.det(frame) < 0
                for k in range(4):
                    u, v = corners[k], corners[(k + 1) % 4]
                    triangles.append((u, centre, v) if flip else (u, v, centre))
    return np.array(positions, np.float32), np.array(uvs, np.float32), np.array(triangles, np.uint16)


def gltf():
    positions, uvs, triangles = cage()
    blobs = [positions.tobytes(), uvs.tobytes(), triangles.tobytes()]
    offsets = np.cumsum([0] + [len(b) for b in blobs])
    (HERE / "cushion.bin").write_bytes(b"".join(blobs))
    views = [{"buffer": 0, "byteOffset": int(offsets[i]), "byteLength": len(blobs[i]),
              "target": 34962 if i < 2 else 34963} for i in range(3)]
    accessors = [
        {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
         "min": positions.min(0).tolist(), "max": positions.max(0).tolist()},
        {"bufferView": 1, "componentType": 5126, "count": len(uvs), "type": "VEC2"},
        {"bufferView": 2, "componentType": 5123, "count": triangles.size, "type": "SCALAR"},
    ]
    document = {
        "asset": {"version": "2.0", "generator": "facet scenes/examples/textured/make_cushion.py",
                  "copyright": "CC0 1.0, made for facet"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.62, "aspectRatio": 1.3333, "znear": 0.1}}],
        "nodes": [{"name": "cushion", "mesh": 0, "rotation": [0.0, 0.2588190451, 0.0, 0.9659258263]},
                  {"name": "camera", "camera": 0, "translation": [0.0, 2.5, 3.75],
                   "rotation": [-0.2897841487, 0.0, 0.0, 0.9570920265]}],
        "meshes": [{"name": "cushion", "primitives": [
            {"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
        "materials": [{
            "name": "glazed tiles with brass inlays",
            "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 1},
                                     "metallicFactor": 1.0, "roughnessFactor": 1.0},
            "normalTexture": {"index": 2, "scale": 1.0},
            "occlusionTexture": {"index": 1, "strength": 1.0},
        }],
        "textures": [{"source": i, "sampler": 0} for i in range(3)],
        "images": [{"uri": "cushion_base_color.png"}, {"uri": "cushion_orm.png"}, {"uri": "cushion_normal.png"}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 33071, "wrapT": 33071}],
        "buffers": [{"uri": "cushion.bin", "byteLength": int(offsets[-1])}],
        "bufferViews": views,
        "accessors": accessors,
    }
    (HERE / "cushion.gltf").write_text(json.dumps(document, indent=1) + "\n")


if __name__ == "__main__":
    textures()
    gltf()
