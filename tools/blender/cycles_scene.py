# Blender Cycles' side of `facet bench`'s Cycles sections: a facet scene,
# described by the bench in a JSON file, rendered at several sample counts
# (each render call timed) and, optionally, at a converged count under two
# seeds.
#
#   blender -b --factory-startup -t 2 --python cycles_scene.py -- \
#       --scene scene.json --threads 2 --samples 4,16,64 --repeats 3 \
#       [--converged 4096] --output DIR
#
# scene.json, in facet's coordinates (y up; Blender is z up):
#   size [w, h]; camera {eye, target, up, fov (vertical, degrees)};
#   environment {file, intensity}, an equirectangular map;
#   bounces {total, diffuse, glossy, transmission}, Cycles' light paths;
#   objects [{cage (OBJ, world space), levels (Catmull-Clark levels with the
#   vertices on the limit surface; 0: the polygons as authored), material}]
#   with material one of
#     {kind: "metal", base [r, g, b], roughness}   Principled, metallic, GGX
#     {kind: "diffuse", albedo [r, g, b]}          Lambert
#     {kind: "glass", ior, roughness, absorption [r, g, b]}
#         Glass BSDF (sharp when roughness is 0), and inside the closed
#         surface absorption coefficients per unit length (Beer-Lambert).
# Writes DIR/cycles_<N>spp.exr (the first render of each N),
# DIR/cycles_times.csv (one row per timed render call) and, with
# --converged M, DIR/cycles_converged_seed1.exr and _seed2.exr (linear float
# RGBA).
import argparse
import json
import math
import sys
import time

import bpy
from mathutils import Matrix, Vector


def arguments():
    parser = argparse.ArgumentParser(prog="cycles_scene.py")
    parser.add_argument("--scene", required=True, help="the bench's JSON description")
    parser.add_argument("--threads", type=int, required=True)
    parser.add_argument("--samples", default="", help="comma-separated samples per pixel, timed")
    parser.add_argument("--repeats", type=int, default=1, help="timed renders per sample count")
    parser.add_argument("--converged", type=int, default=0, help="samples per pixel of two untimed renders, seeds 1, 2")
    parser.add_argument("--output", required=True)
    return parser.parse_args(sys.argv[sys.argv.index("--") + 1:])


def to_blender(p):
    """facet's y-up (x, y, z) is Blender's z-up (x, -z, y)."""
    return Vector((p[0], -p[2], p[1]))


def read_obj(path):
    positions, faces = [], []
    with open(path) as obj:
        for line in obj:
            fields = line.split()
            if not fields:
                continue
            if fields[0] == "v":
                positions.append(to_blender([float(x) for x in fields[1:4]]))
            elif fields[0] == "f":
                faces.append([int(f.split("/")[0]) - 1 for f in fields[1:]])
    return positions, faces


def metal(tree, output, description):
    principled = tree.nodes["Principled BSDF"]
    principled.distribution = "GGX"  # single scattering, not multiscatter GGX
    principled.inputs["Base Color"].default_value = (*description["base"], 1.0)
    principled.inputs["Metallic"].default_value = 1.0
    principled.inputs["Roughness"].default_value = description["roughness"]


def diffuse(tree, output, description):
    tree.nodes.remove(tree.nodes["Principled BSDF"])
    bsdf = tree.nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = (*description["albedo"], 1.0)
    bsdf.inputs["Roughness"].default_value = 0.0  # Lambert, not Oren-Nayar
    tree.links.new(bsdf.outputs["BSDF"], output.inputs["Surface"])


def glass(tree, output, description):
    tree.nodes.remove(tree.nodes["Principled BSDF"])
    bsdf = tree.nodes.new("ShaderNodeBsdfGlass")
    bsdf.distribution = "SHARP" if description["roughness"] == 0 else "GGX"
    bsdf.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    bsdf.inputs["Roughness"].default_value = description["roughness"]
    bsdf.inputs["IOR"].default_value = description["ior"]
    tree.links.new(bsdf.outputs["BSDF"], output.inputs["Surface"])
    sigma = description["absorption"]
    density = max(sigma)
    if density > 0:
        # Cycles' absorption coefficient is density x (1 - colour).
        volume = tree.nodes.new("ShaderNodeVolumeAbsorption")
        volume.inputs["Density"].default_value = density
        volume.inputs["Color"].default_value = (*[1.0 - s / density for s in sigma], 1.0)
        tree.links.new(volume.outputs["Volume"], output.inputs["Volume"])


MATERIALS = {"metal": metal, "diffuse": diffuse, "glass": glass}


def add_object(scene, index, description):
    positions, faces = read_obj(description["cage"])
    mesh = bpy.data.meshes.new(f"cage{index}")
    mesh.from_pydata(positions, [], faces)
    levels = description["levels"]
    mesh.polygons.foreach_set("use_smooth", [levels > 0] * len(mesh.polygons))
    obj = bpy.data.objects.new(f"object{index}", mesh)
    scene.collection.objects.link(obj)
    if levels > 0:
        subsurf = obj.modifiers.new("subdivision", "SUBSURF")
        subsurf.subdivision_type = "CATMULL_CLARK"
        subsurf.levels = subsurf.render_levels = levels
        subsurf.use_limit_surface = True
        subsurf.use_creases = False
        subsurf.boundary_smooth = "ALL"  # OpenSubdiv's edge-only boundary, facet's default
        # Applied here, so that no render call pays for the subdivision.
        bpy.context.view_layer.objects.active = obj
        bpy.ops.object.modifier_apply(modifier=subsurf.name)

    material = bpy.data.materials.new(f"material{index}")
    material.use_nodes = True
    tree = material.node_tree
    MATERIALS[description["material"]["kind"]](tree, tree.nodes["Material Output"], description["material"])
    mesh.materials.append(material)


def add_world(scene, description):
    world = bpy.data.worlds.new("environment")
    world.use_nodes = True
    nodes = world.node_tree.nodes
    texture = nodes.new("ShaderNodeTexEnvironment")
    texture.image = bpy.data.images.load(description["file"])
    texture.image.colorspace_settings.name = "Linear"
    texture.interpolation = "Linear"
    texture.projection = "EQUIRECTANGULAR"
    background = nodes["Background"]
    background.inputs["Strength"].default_value = description["intensity"]
    world.node_tree.links.new(texture.outputs["Color"], background.inputs["Color"])
    scene.world = world


def add_camera(scene, description):
    camera = bpy.data.cameras.new("camera")
    camera.type = "PERSP"
    camera.sensor_fit = "VERTICAL"
    camera.angle_y = math.radians(description["fov"])
    camera.clip_start = 1e-3
    eye, target, up = (to_blender(description[k]) for k in ("eye", "target", "up"))
    forward = (target - eye).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    # A Blender camera looks down its local -z with +y up.
    rotation = Matrix((right, true_up, -forward)).transposed()
    obj = bpy.data.objects.new("camera", camera)
    obj.matrix_world = Matrix.Translation(eye) @ rotation.to_4x4()
    scene.collection.objects.link(obj)
    scene.camera = obj


def configure(scene, description, threads):
    render = scene.render
    render.engine = "CYCLES"
    render.resolution_x, render.resolution_y = description["size"]
    render.resolution_percentage = 100
    render.pixel_aspect_x = render.pixel_aspect_y = 1
    render.film_transparent = False  # camera rays that miss see the map, as in facet
    render.threads_mode = "FIXED"
    render.threads = threads
    render.use_persistent_data = True  # repeated renders reuse the synced scene and its BVH
    render.image_settings.file_format = "OPEN_EXR"
    render.image_settings.color_depth = "32"
    render.image_settings.color_mode = "RGBA"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.blur_glossy = 0.0
    cycles.light_sampling_threshold = 0.0
    cycles.caustics_reflective = cycles.caustics_refractive = True
    bounces = description["bounces"]
    cycles.max_bounces = bounces["total"]
    cycles.diffuse_bounces = bounces["diffuse"]
    cycles.glossy_bounces = bounces["glossy"]
    cycles.transmission_bounces = bounces["transmission"]
    cycles.volume_bounces = 0  # absorption only: nothing scatters inside
    cycles.transparent_max_bounces = 0
    cycles.film_exposure = 1.0
    cycles.seed = 0
    cycles.use_animated_seed = False


def render_once(scene, samples, seed):
    scene.cycles.samples = samples
    scene.cycles.seed = seed
    # With persistent data the render would otherwise keep the previous settings.
    scene.update_tag()
    bpy.context.view_layer.update()
    start = time.perf_counter()
    bpy.ops.render.render()
    return time.perf_counter() - start


def save(scene, path):
    bpy.data.images["Render Result"].save_render(path, scene=scene)


def main():
    args = arguments()
    with open(args.scene) as file:
        description = json.load(file)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    configure(scene, description, args.threads)
    for index, obj in enumerate(description["objects"]):
        add_object(scene, index, obj)
    add_world(scene, description["environment"])
    add_camera(scene, description["camera"])
    render_once(scene, 1, 0)  # untimed: loads the map, builds the BVH and the world's sampling table
    rows = []
    for samples in [int(n) for n in args.samples.split(",") if n]:
        for repeat in range(args.repeats):
            seconds = render_once(scene, samples, 0)
            rows.append(f"{samples},{seconds:.6f}")
            if repeat == 0:
                save(scene, f"{args.output}/cycles_{samples}spp.exr")
            print(f"cycles: {samples} spp: {seconds:.3f} s", flush=True)
    with open(f"{args.output}/cycles_times.csv", "w") as csv:
        csv.write("samples,seconds\n" + "".join(row + "\n" for row in rows))
    if args.converged > 0:
        for seed in (1, 2):
            seconds = render_once(scene, args.converged, seed)
            save(scene, f"{args.output}/cycles_converged_seed{seed}.exr")
            print(f"cycles: converged, {args.converged} spp, seed {seed}: {seconds:.3f} s", flush=True)


main()
