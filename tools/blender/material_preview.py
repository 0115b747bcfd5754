# Blender Cycles' side of `facet bench`'s Cycles section: the material
# preview (one metallic cage, Catmull-Clark, lit by an equirectangular map
# alone) rendered at several sample counts, each render call timed.
#
#   blender -b --factory-startup -t 2 --python material_preview.py -- \
#       --cage cage.obj --env courtyard.hdr --eye 0 0 6 --target 0 0 0 --up 0 1 0 \
#       --fov 34.4 --size 512 512 --f0 1 0.71 0.29 --roughness 0.5 --threads 2 \
#       --samples 4,16,64,256 --repeats 3 --output DIR
#
# Coordinates are facet's (y up); Blender is z up. The surface is facet's
# cage under Blender's Catmull-Clark modifier, its vertices on the limit
# surface (BENCHMARKS.md, "Cycles", states what the levels cost). Writes
# DIR/cycles_<N>spp.exr (linear float RGBA, the first render of each N) and
# DIR/cycles_times.csv (one row per timed render call).
import argparse
import math
import sys
import time

import bpy
from mathutils import Matrix, Vector


def arguments():
    parser = argparse.ArgumentParser(prog="material_preview.py")
    parser.add_argument("--cage", required=True, help="OBJ control cage, facet's world space")
    parser.add_argument("--env", required=True, help="equirectangular map")
    parser.add_argument("--intensity", type=float, default=1.0)
    parser.add_argument("--eye", type=float, nargs=3, required=True)
    parser.add_argument("--target", type=float, nargs=3, required=True)
    parser.add_argument("--up", type=float, nargs=3, required=True)
    parser.add_argument("--fov", type=float, required=True, help="vertical field of view, degrees")
    parser.add_argument("--size", type=int, nargs=2, required=True, metavar=("WIDTH", "HEIGHT"))
    parser.add_argument("--f0", type=float, nargs=3, required=True, help="metallic base colour (linear)")
    parser.add_argument("--roughness", type=float, required=True, help="perceptual roughness; alpha = roughness^2")
    parser.add_argument("--levels", type=int, default=7, help="subdivision levels, vertices on the limit surface")
    parser.add_argument("--threads", type=int, required=True)
    parser.add_argument("--samples", required=True, help="comma-separated samples per pixel")
    parser.add_argument("--repeats", type=int, default=1, help="timed renders per sample count")
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


def add_surface(scene, args):
    positions, faces = read_obj(args.cage)
    mesh = bpy.data.meshes.new("cage")
    mesh.from_pydata(positions, [], faces)
    mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
    obj = bpy.data.objects.new("surface", mesh)
    scene.collection.objects.link(obj)
    subsurf = obj.modifiers.new("subdivision", "SUBSURF")
    subsurf.subdivision_type = "CATMULL_CLARK"
    subsurf.levels = subsurf.render_levels = args.levels
    subsurf.use_limit_surface = True
    subsurf.use_creases = False
    subsurf.boundary_smooth = "ALL"
    # Applied here, so that no render call pays for the subdivision.
    bpy.context.view_layer.objects.active = obj
    bpy.ops.object.modifier_apply(modifier=subsurf.name)

    material = bpy.data.materials.new("metal")
    material.use_nodes = True
    principled = material.node_tree.nodes["Principled BSDF"]
    principled.distribution = "GGX"  # single scattering, not multiscatter GGX
    principled.inputs["Base Color"].default_value = (*args.f0, 1.0)
    principled.inputs["Metallic"].default_value = 1.0
    principled.inputs["Roughness"].default_value = args.roughness
    mesh.materials.append(material)


def add_world(scene, args):
    world = bpy.data.worlds.new("environment")
    world.use_nodes = True
    nodes = world.node_tree.nodes
    texture = nodes.new("ShaderNodeTexEnvironment")
    texture.image = bpy.data.images.load(args.env)
    texture.image.colorspace_settings.name = "Linear"
    texture.interpolation = "Linear"
    texture.projection = "EQUIRECTANGULAR"
    background = nodes["Background"]
    background.inputs["Strength"].default_value = args.intensity
    world.node_tree.links.new(texture.outputs["Color"], background.inputs["Color"])
    scene.world = world


def add_camera(scene, args):
    camera = bpy.data.cameras.new("camera")
    camera.type = "PERSP"
    camera.sensor_fit = "VERTICAL"
    camera.angle_y = math.radians(args.fov)
    camera.clip_start = 1e-3
    eye, target, up = to_blender(args.eye), to_blender(args.target), to_blender(args.up)
    forward = (target - eye).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    # A Blender camera looks down its local -z with +y up.
    rotation = Matrix((right, true_up, -forward)).transposed()
    obj = bpy.data.objects.new("camera", camera)
    obj.matrix_world = Matrix.Translation(eye) @ rotation.to_4x4()
    scene.collection.objects.link(obj)
    scene.camera = obj


def configure(scene, args):
    render = scene.render
    render.engine = "CYCLES"
    render.resolution_x, render.resolution_y = args.size
    render.resolution_percentage = 100
    render.pixel_aspect_x = render.pixel_aspect_y = 1
    render.film_transparent = False  # camera rays that miss see the map, as in facet
    render.threads_mode = "FIXED"
    render.threads = args.threads
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
    cycles.film_exposure = 1.0
    cycles.seed = 0
    cycles.use_animated_seed = False


def render_once(scene, samples):
    scene.cycles.samples = samples
    # With persistent data the render would otherwise keep the previous sample count.
    scene.update_tag()
    bpy.context.view_layer.update()
    start = time.perf_counter()
    bpy.ops.render.render()
    return time.perf_counter() - start


def main():
    args = arguments()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    configure(scene, args)
    add_surface(scene, args)
    add_world(scene, args)
    add_camera(scene, args)
    render_once(scene, 1)  # untimed: loads the map, builds the BVH and the world's sampling table
    rows = []
    for samples in [int(n) for n in args.samples.split(",")]:
        for repeat in range(args.repeats):
            seconds = render_once(scene, samples)
            rows.append(f"{samples},{seconds:.6f}")
            if repeat == 0:
                bpy.data.images["Render Result"].save_render(f"{args.output}/cycles_{samples}spp.exr", scene=scene)
            print(f"cycles: {samples} spp: {seconds:.3f} s", flush=True)
    with open(f"{args.output}/cycles_times.csv", "w") as csv:
        csv.write("samples,seconds\n" + "\n".join(rows) + "\n")


main()
