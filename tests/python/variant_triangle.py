"""A glTF triangle in material "red", which its variant "blue" maps to "blue"
(KHR_materials_variants), each material of its own colour."""
import json

TRIANGLE = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"  # (0,0,0), (1,0,0), (0,1,0) as floats


def write_variant_triangle(path):
    variants = {"KHR_materials_variants": {"mappings": [{"material": 1, "variants": [0]}]}}
    path.write_text(json.dumps({
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_materials_variants"],
        "extensions": {"KHR_materials_variants": {"variants": [{"name": "blue"}]}},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0, "extensions": variants}]}],
        "materials": [{"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1]}},
                      {"name": "blue", "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.1, 0.8, 1]}}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64," + TRIANGLE}]}))
    return path
