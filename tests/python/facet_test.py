"""The installed Python module against the installed `facet` binary: the
same numbers from both, and facet's own messages in Python's exceptions."""
import json
import os
import pathlib
import re
import subprocess
import threading
import unittest

import numpy as np
import OpenImageIO as oiio

import facet

FACET = os.environ["FACET_BINARY"]
EXAMPLES = pathlib.Path(os.environ["FACET_EXAMPLES_DIR"])
WORK = pathlib.Path(os.environ["FACET_WORK_DIR"])
# A glTF triangle in material "red", which its variant "blue" maps to "blue", each of its own colour.
VARIANT_TRIANGLE = pathlib.Path(__file__).resolve().parent.parent / "scenes" / "data" / "variant_triangle.gltf"


def cli(*args):
    return subprocess.run([FACET, *map(str, args)], capture_output=True, text=True)


def cli_error(*args):
    """The message `facet` prints for a failure, without its prefix."""
    run = cli(*args)
    assert run.returncode != 0, run.stdout
    return run.stderr.strip().removeprefix("facet: error: ")


def read_exr(path):
    """{channel: (height, width) array} of an EXR, each in its stored type."""
    exr = oiio.ImageInput.open(str(path))
    assert exr, oiio.geterror()
    spec = exr.spec()
    planes = {name: exr.read_image(0, 0, index, index + 1, spec.channelformats[index])[..., 0]
              for index, name in enumerate(spec.channelnames)}
    exr.close()
    return planes


def box(low, high, creases=()):
    """The cage of an axis-aligned box from corner `low` to corner `high`."""
    corners = np.array([[(low, high)[bool(i & bit)][axis] for axis, bit in enumerate((1, 2, 4))] for i in range(8)],
                       dtype=float)
    quads = [0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5]
    return facet.Cage(corners, [4] * 6, quads, creases=list(creases))


def cube(sharp_edge=True):
    return box((-1, -1, -1), (1, 1, 1), creases=[(0, 1, 10.0)] if sharp_edge else [])


class Render(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        cls.renderer = facet.Renderer()

    @classmethod
    def tearDownClass(cls):
        del cls.renderer

    def test_render_of_a_file_is_the_command_lines(self):
        scene = EXAMPLES / "gold_cube.gltf"
        exr = WORK / "gold_cube.exr"
        run = cli("render", scene, "-o", exr, "--size", "40x30", "--backend", "cpu")
        self.assertEqual(run.returncode, 0, run.stderr)
        image = self.renderer.render(str(scene), size=(40, 30), backend="cpu")
        self.assertEqual(image["beauty"].shape, (30, 40, 4))
        self.assertEqual(image["beauty"].dtype, np.float32)
        self.assertEqual(image["patch_id"].dtype, np.uint32)
        self.assertEqual(image["depth"].shape, (30, 40))
        # A view of the render's plane, not a copy.
        self.assertFalse(image["beauty"].flags.owndata)
        reference = read_exr(exr)
        for channel, name, index in (("R", "beauty", 0), ("G", "beauty", 1), ("B", "beauty", 2), ("A", "beauty", 3),
                                     ("Z", "depth", None), ("N.Y", "shading_normal", 1), ("uv.U", "uv", 0)):
            plane = image[name] if index is None else image[name][..., index]
            np.testing.assert_array_equal(plane, reference[channel], err_msg=channel)
        np.testing.assert_array_equal(image["face_id"], reference["faceId"])
        covered = image["beauty"][..., 3] > 0
        self.assertGreater(covered.sum(), 100)
        self.assertTrue(np.isinf(image["depth"][~covered]).all())

    def test_the_files_it_writes_are_the_command_lines_byte_for_byte(self):
        # The gold cube renders direct light by adaptive rounds; the teacup's paths are chosen (one pass, to
        # stay quick); the superball's stated bounces cast none (it is convex): each file records what was rendered.
        flags = {"exposure": 1.5, "tonemap": "aces", "background": (0.2, 0.3, 0.4), "aovs": "beauty,depth"}
        for scene, bounces, spp in ((EXAMPLES / "gold_cube.gltf", None, None),
                                    (EXAMPLES.parent / "cages" / "newell_teacup.obj", None, 1),
                                    (EXAMPLES / "superball.obj", 4, 1)):
            stated = [] if bounces is None else ["--bounces", str(bounces)]
            stated += [] if spp is None else ["--spp", str(spp)]
            run = cli("render", scene, "-o", WORK / "cli.exr", "--png", WORK / "cli.png", "--size", "24x16",
                      "--backend", "cpu", "--exposure", "1.5", "--tonemap", "aces", "--background", "0.2,0.3,0.4",
                      "--aovs", "beauty,depth", *stated)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.renderer.render(str(scene), size=(24, 16), backend="cpu", bounces=bounces, spp=spp,
                                 exr=str(WORK / "api.exr"), png=str(WORK / "api.png"), **flags)
            for kind in ("exr", "png"):
                self.assertEqual((WORK / f"api.{kind}").read_bytes(), (WORK / f"cli.{kind}").read_bytes(),
                                 f"{scene.name} {kind}")
        # Written as a set: a PNG that cannot be written leaves the EXR as it was.
        (WORK / "keep.exr").write_bytes(b"an earlier EXR")
        with self.assertRaisesRegex(facet.Error, "pngPath '.*no_such_folder/keep.png'"):
            self.renderer.render(str(EXAMPLES / "gold_cube.gltf"), size=(8, 8), backend="cpu", spp=1,
                                 exr=str(WORK / "keep.exr"), png=str(WORK / "no_such_folder" / "keep.png"))
        self.assertEqual((WORK / "keep.exr").read_bytes(), b"an earlier EXR")
        with self.assertRaisesRegex(facet.Error, "tonemap 'filmic': expected one of: pbr-neutral, aces, clamp"):
            self.renderer.render(str(scene), size=(8, 8), backend="cpu", png=str(WORK / "bad.png"), tonemap="filmic")
        self.assertFalse((WORK / "bad.png").exists())

    def test_a_cage_built_in_python_renders_on_the_gpu_as_on_the_cpu(self):
        scene = facet.Scene([facet.Object(cube(), name="cube")],
                            materials=[facet.Material(preset="gold", roughness=0.4)],
                            lights=[facet.Light("directional", direction=(-1, -1, -1), color=(2, 2, 2))],
                            camera=facet.Camera(eye=(3, 2.5, 4), fov=35), size=(48, 32))
        self.assertEqual(scene.size, (48, 32))
        image = self.renderer.render(scene, spp=1)  # one sample per pixel: its centre gives beauty and IDs alike
        beauty = image["beauty"]
        covered = beauty[..., 3] > 0
        self.assertGreater(covered.mean(), 0.1)
        self.assertTrue(np.isfinite(beauty).all())
        self.assertGreater(beauty[covered, :3].mean(), 0)
        # Seen from a corner: at least the three faces turned to the eye, all of the cage's six.
        faces = set(image["face_id"][covered].tolist())
        self.assertGreaterEqual(len(faces), 3)
        self.assertTrue(faces <= set(range(6)), faces)
        self.assertTrue((image["face_id"][~covered] == 0xFFFFFFFF).all())
        report = self.renderer.parity(scene)
        self.assertTrue(report["pass"], report["summary"])
        self.assertEqual(report["verdict"], "pass")
        run = report["runs"][0]
        self.assertLessEqual(abs(run["coveredOnBoth"] - int(covered.sum())), run["coverage"]["mismatches"])
        aovs = {aov["name"]: aov for aov in run["aovs"]}
        self.assertIn("beauty", aovs)
        self.assertLessEqual(aovs["depth"]["maxRelative"], aovs["depth"]["tolerance"]["relative"])

    def test_one_renderer_shared_by_threads_renders_each_scene_as_alone(self):
        scene = facet.Scene([facet.Object(cube(), name="cube")], materials=[facet.Material(preset="copper", roughness=0.4)],
                            lights=[facet.Light("directional", direction=(-1, -2, -1), color=(2, 2, 2))],
                            camera=facet.Camera(eye=(3, 2.5, 4), fov=35), size=(24, 16))
        backends = ["gpu", "cpu"] * 3
        alone = {backend: self.renderer.render(scene, backend=backend, spp=1)["beauty"] for backend in set(backends)}
        results = [None] * len(backends)
        shared = facet.Renderer()  # its GPU context is made by whichever thread comes first

        def render(i):
            results[i] = shared.render(scene, backend=backends[i], spp=1)["beauty"]

        threads = [threading.Thread(target=render, args=(i,)) for i in range(len(backends))]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        for backend, beauty in zip(backends, results):
            np.testing.assert_array_equal(beauty, alone[backend], err_msg=backend)

    def test_transmission_fields_are_the_scene_files(self):
        material = facet.Material(preset="glass-high-ruby", roughness=0.0, thin_walled=False,
                                  attenuation_color=(0.9, 0.1, 0.1), attenuation_distance=2.0)
        self.assertEqual(material.attenuation_distance, 2.0)
        self.assertEqual(material.transmission, None)  # the preset's: 1
        scene = facet.Scene([facet.Object(cube(sharp_edge=False), name="cube")], materials=[material], size=(8, 8))
        # One pass each: the backends trace the same samples, where adaptive rounds may stop at different noise.
        on_gpu = self.renderer.render(scene, backend="gpu", spp=1)["beauty"]
        on_cpu = self.renderer.render(scene, backend="cpu", spp=1)["beauty"]
        self.assertAlmostEqual(float(on_gpu[..., :3].sum() / on_cpu[..., :3].sum()), 1.0, delta=0.01)
        with self.assertRaisesRegex(Exception, "attenuation_distance: must be > 0"):
            facet.Scene([facet.Object(cube(sharp_edge=False), name="cube")],
                        materials=[facet.Material(preset="water", roughness=0.0, attenuation_distance=0.0)])

    def test_energy_compensation_brightens_a_rough_metal_on_both_backends(self):
        def scene(compensated):
            material = facet.Material(preset="gold", roughness=0.9, energy_compensation=compensated)
            self.assertEqual(material.energy_compensation, compensated)
            return facet.Scene([facet.Object(cube(sharp_edge=False), name="cube")], materials=[material],
                               lights=[facet.Light("directional", direction=(-1, -1, -1), color=(2, 2, 2))],
                               camera=facet.Camera(eye=(3, 2.5, 4), fov=35), size=(48, 32))
        # One pass each, the same samples: adaptive rounds would stop each render at its own noise.
        single = self.renderer.render(scene(False), backend="cpu", spp=1)["beauty"]
        compensated = self.renderer.render(scene(True), backend="cpu", spp=1)["beauty"]
        lit = single[..., :3].sum(axis=-1) > 0
        self.assertGreater(lit.sum(), 100)
        ratio = compensated[lit, :3].sum() / single[lit, :3].sum()
        # A rough gold loses a sizeable share of its light to single scattering.
        self.assertGreater(ratio, 1.05)
        self.assertTrue((compensated[..., :3] >= single[..., :3]).all())
        report = self.renderer.parity(scene(True))
        self.assertTrue(report["pass"], report["summary"])

    def test_one_bounce_on_the_cpu_adds_the_light_between_objects(self):
        # A cube on a slab under a sampled, shadowed environment: continuations from each find the other.
        def scene(method):
            environment = facet.Environment(EXAMPLES.parent / "environments" / "courtyard_256x128.hdr",
                                            method=method, samples=4, occlusion=True)
            objects = [facet.Object(box((-1, -1, -1), (1, 1, 1)), subdivided=False),
                       facet.Object(box((-4, -1.5, -4), (4, -1, 4)), subdivided=False)]
            return facet.Scene(objects,
                               camera=facet.Camera(eye=(3, 2.5, 4), target=(0, -0.5, 0), fov=50),
                               environment=environment, size=(16, 16))
        direct = self.renderer.render(scene("sampled"), backend="cpu", spp=1, bounces=0)
        paths = self.renderer.render(scene("sampled"), backend="cpu", spp=1, bounces=1)
        self.assertNotIn("rays_per_bounce", direct)
        self.assertEqual([sorted(rays) for rays in paths["rays_per_bounce"]], [["hits", "rays", "shadow_rays"]] * 2)
        self.assertEqual(paths["rays_per_bounce"][0]["rays"], 16 * 16)
        self.assertGreater(paths["rays_per_bounce"][1]["hits"], 0)
        self.assertGreater(paths["beauty"][..., :3].sum(), direct["beauty"][..., :3].sum())
        with self.assertRaisesRegex(facet.Error, "render settings: bounces: bounces above 0 need the environment"):
            self.renderer.render(scene("prefiltered"), backend="cpu", bounces=1)
        with self.assertRaisesRegex(facet.Error, r"render settings: bounces: must be in \[0, 64\]"):
            self.renderer.render(scene("sampled"), backend="cpu", bounces=65)
        on_gpu = self.renderer.render(scene("sampled"), backend="gpu", spp=1, bounces=1)
        self.assertEqual(on_gpu["rays_per_bounce"][1]["rays"], paths["rays_per_bounce"][1]["rays"])

    def test_the_light_transport_is_chosen_where_nothing_states_it(self):
        environment = facet.Environment(EXAMPLES.parent / "environments" / "courtyard_256x128.hdr", samples=2)
        self.assertIsNone(environment.method)
        objects = [facet.Object(box((-1, -1, -1), (1, 1, 1)), subdivided=False),
                   facet.Object(box((-4, -1.5, -4), (4, -1, 4)), subdivided=False)]
        scene = facet.Scene(objects, camera=facet.Camera(eye=(3, 2.5, 4), target=(0, -0.5, 0), fov=50),
                            environment=environment, size=(12, 12))
        chosen = self.renderer.render(scene, backend="cpu", spp=1)
        self.assertEqual(chosen["bounces"], 12)
        self.assertEqual(chosen["light_transport"], "paths: 12 bounces (diffuse 4, glossy 4, transmission 12), "
                                                    "environment sampled: 2 objects can see each other")
        self.assertGreater(chosen["rays_per_bounce"][1]["hits"], 0)
        stated = self.renderer.render(scene, backend="cpu", spp=1, bounces=0)
        self.assertEqual((stated["bounces"], stated["light_transport"]), (0, ""))
        self.assertNotIn("rays_per_bounce", stated)
        # The sampling, as `facet render --json` reports it: stated, or chosen and why.
        self.assertEqual(stated["spp"], 1)
        self.assertNotIn("sampling", stated)
        one_pass = self.renderer.render(scene, backend="cpu", bounces=0)
        self.assertEqual((one_pass["spp"], one_pass["sampling"]), (16, "no light is sampled at random"))
        self.assertNotIn("adaptive", one_pass)
        sampled = facet.Scene(objects, camera=facet.Camera(eye=(3, 2.5, 4), target=(0, -0.5, 0), fov=50),
                              environment=environment.replace(method="sampled"), size=(12, 12))
        rounds = self.renderer.render(sampled, backend="cpu", bounces=0)
        self.assertNotIn("spp", rounds)
        self.assertIn("random", rounds["sampling"])
        adaptive = rounds["adaptive"]
        self.assertGreaterEqual(adaptive["rounds"], 4)
        self.assertLessEqual(adaptive["spp_min"], adaptive["spp_mean"])
        self.assertLessEqual(adaptive["spp_mean"], adaptive["spp_max"])
        self.assertEqual(adaptive["noise_threshold"], 0.02)
        if adaptive["stop"] == "converged":
            self.assertLessEqual(adaptive["max_tile_error"], 0.02)
        else:
            self.assertEqual(adaptive["stop"], "sample cap")

    def test_render_settings_are_checked(self):
        with self.assertRaisesRegex(facet.Error, r"render settings: width: must be in \[1, 16384\]"):
            self.renderer.render(str(EXAMPLES / "gold_cube.gltf"), size=(0, 10))
        with self.assertRaisesRegex(facet.Error, "backend 'vulkan': expected one of: gpu, cpu"):
            self.renderer.render(str(EXAMPLES / "gold_cube.gltf"), backend="vulkan")
        with self.assertRaisesRegex(facet.Error, "square number"):
            self.renderer.render(str(EXAMPLES / "gold_cube.gltf"), spp=3)


class Scenes(unittest.TestCase):
    def test_a_bad_scene_file_gives_the_command_lines_message(self):
        WORK.mkdir(parents=True, exist_ok=True)
        bad = WORK / "bad_fov.json"
        cage = EXAMPLES.parent / "cages" / "cube.obj"
        bad.write_text(json.dumps({"camera": {"fov": 500}, "objects": [{"mesh": str(cage)}]}))
        expected = cli_error("render", bad, "-o", WORK / "bad.exr")
        self.assertIn("camera.fov", expected)
        with self.assertRaises(facet.Error) as raised:
            facet.load_scene(bad)
        self.assertEqual(str(raised.exception), expected)
        self.assertEqual(raised.exception.exit_code, 1)

    def test_a_gltf_loads_in_the_material_variant_named_as_on_the_command_line(self):
        WORK.mkdir(parents=True, exist_ok=True)
        path = VARIANT_TRIANGLE
        self.assertEqual(facet.load_scene(path).objects[0].material, "red")
        self.assertEqual(facet.load_scene(path, variant="blue").objects[0].material, "blue")
        expected = cli_error("render", path, "--variant", "green", "-o", WORK / "variant.exr")
        self.assertIn("no material variant is named 'green'", expected)
        with self.assertRaises(facet.Error) as raised:
            facet.load_scene(path, variant="green")
        self.assertEqual(str(raised.exception), expected)

    def test_a_missing_adapter_is_a_gpu_failure_as_on_the_command_line(self):
        scene = EXAMPLES / "gold_cube.gltf"
        run = cli("render", scene, "-o", WORK / "none.exr", "--adapter", "no-such-adapter")
        with self.assertRaises(facet.Error) as raised:
            facet.render(scene, adapter="no-such-adapter")
        self.assertEqual(raised.exception.exit_code, run.returncode)
        self.assertEqual(run.returncode, 3)
        self.assertEqual("facet: error: " + str(raised.exception), run.stderr.strip())

    def test_bad_cages_and_materials_name_the_field(self):
        corners = np.zeros((4, 3))
        with self.assertRaisesRegex(facet.Error, r"objects\[0\].cage.faceVertexIndices\[3\]: vertex 7 is out of range"):
            facet.Scene([facet.Object(facet.Cage(corners, [4], [0, 1, 2, 7]))])
        with self.assertRaisesRegex(facet.Error, r"objects\[0\].cage.faceVertexCounts\[0\]: a face needs at least 3"):
            facet.Scene([facet.Object(facet.Cage(corners, [2], [0, 1]))])
        with self.assertRaisesRegex(facet.Error, r"objects\[0\].material: must be in \[0, 0\]"):
            facet.Scene([facet.Object(cube(), material=1)])
        with self.assertRaisesRegex(facet.Error, r"materials\[0\].*alpha"):
            facet.Scene([facet.Object(cube())], materials=[facet.Material(alpha=2.0)])
        with self.assertRaisesRegex(facet.Error, r"materials\[0\].anisotropy: must be in \[0, 1\]"):
            facet.Scene([facet.Object(cube())], materials=[facet.Material(roughness=0.3, anisotropy=1.5)])
        brushed = facet.Material(preset="aluminum", roughness=0.3, anisotropy=0.6, anisotropy_rotation=0.5)
        self.assertEqual((brushed.anisotropy, brushed.anisotropy_rotation), (0.6, 0.5))
        facet.Scene([facet.Object(cube())], materials=[brushed])  # within the rules
        with self.assertRaisesRegex(facet.Error, r"materials\[0\].clearcoat_roughness: must be in \[0, 1\]"):
            facet.Scene([facet.Object(cube())],
                        materials=[facet.Material(roughness=0.3, clearcoat=1.0, clearcoat_roughness=-0.1)])
        lacquer = facet.Material(roughness=0.5, diffuse=(0.5, 0.5, 0.5), clearcoat=0.8, clearcoat_roughness=0.05)
        self.assertEqual((lacquer.clearcoat, lacquer.clearcoat_roughness), (0.8, 0.05))
        facet.Scene([facet.Object(cube())], materials=[lacquer])  # within the rules
        with self.assertRaisesRegex(facet.Error, r"materials\[0\].sheen_color: each channel must be in \[0, 1\]"):
            facet.Scene([facet.Object(cube())], materials=[facet.Material(roughness=0.5, sheen_color=(0.5, 1.2, 0.5))])
        velvet = facet.Material(roughness=0.8, diffuse=(0.2, 0.02, 0.04), sheen_color=(0.8, 0.3, 0.35),
                                sheen_roughness=0.4)
        self.assertEqual((tuple(velvet.sheen_color), velvet.sheen_roughness), ((0.8, 0.3, 0.35), 0.4))
        facet.Scene([facet.Object(cube())], materials=[velvet])  # within the rules
        with self.assertRaisesRegex(facet.Error, r"materials\[0\].diffuse: is not combined with base_color"):
            facet.Scene([facet.Object(cube())],
                        materials=[facet.Material(roughness=0.5, base_color=(0.5, 0.5, 0.5), metallic=0.0,
                                                  diffuse=(0.5, 0.5, 0.5))])
        rubber = facet.Material(roughness=0.65, base_color=(0.025, 0.025, 0.025), metallic=0.0)
        self.assertEqual((tuple(rubber.base_color), rubber.metallic), ((0.025, 0.025, 0.025), 0.0))
        facet.Scene([facet.Object(cube())], materials=[rubber])  # within the rules
        with self.assertRaisesRegex(facet.Error, "camera: eye and target must differ"):
            facet.Scene([facet.Object(cube())], camera=facet.Camera(eye=(0, 0, 0)))
        with self.assertRaisesRegex(facet.Error, "environment.file"):
            facet.Scene([facet.Object(cube())], environment=facet.Environment(WORK / "missing.exr"))

    def test_every_material_keyword_reaches_its_property_and_the_scene_rules_under_its_name(self):
        """Each parameter keyword, given a value out of place, is the field the scene's error names."""
        signature = facet.Material.__init__.__doc__.splitlines()[0]
        kinds = dict(re.findall(r"(\w+): (?:Optional\[)?(float|bool|tuple)", signature))
        parameters = [k for k in kinds if k not in ("name", "preset", "distribution", "geometry", "fresnel")]
        self.assertEqual(parameters[0], "alpha")
        companions = {"metallic": {"base_color": (0.5, 0.5, 0.5)}, "base_color": {"metallic": 0.0}}
        # energy_compensation has no value out of place: every material, opaque or transmissive, takes it.
        for key in [k for k in parameters if k != "energy_compensation"]:
            value = {"float": float("nan"), "bool": True, "tuple": (float("nan"),) * 3}[kinds[key]]
            given = {} if key in ("alpha", "roughness") else {"alpha": 0.1}
            material = facet.Material(**given, **companions.get(key, {}), **{key: value})
            read = getattr(material, key)
            self.assertTrue(read is True if value is True else np.isnan(read).all(), key)
            with self.assertRaisesRegex(facet.Error, rf"materials\[0\]\.{key}: ", msg=key):
                facet.Scene([facet.Object(cube())], materials=[material])

    def test_index_arrays_are_integers_within_range_never_wrapped_or_truncated(self):
        corners = np.array([[i & 1, i >> 1 & 1, i >> 2 & 1] for i in range(8)], dtype=float)
        quads = [0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5]
        for dtype in (np.int8, np.int64, np.uint16, np.uint64):
            cage = facet.Cage(corners, np.array([4] * 6, dtype=dtype), np.array(quads, dtype=dtype))
            facet.Scene([facet.Object(cage)])  # a valid closed cube, whatever the index type
        with self.assertRaisesRegex(facet.Error, r"face_vertex_indices\[1\]: 4294967296 is out of range for an index"):
            facet.Cage(corners, [4], np.array([0, 2**32, 2, 3], dtype=np.int64))
        with self.assertRaisesRegex(facet.Error, r"face_vertex_counts\[0\]: 18446744073709551615 is out of range"):
            facet.Cage(corners, np.array([2**64 - 1], dtype=np.uint64), [0, 1, 2, 3])
        with self.assertRaisesRegex(facet.Error, "face_vertex_indices: expected integers, got an array of dtype float64"):
            facet.Cage(corners, [4], [0, 1, 2.5, 3])
        with self.assertRaisesRegex(facet.Error, "face_vertex_counts: expected integers, got an array of dtype bool"):
            facet.Cage(corners, [True], [0, 1, 2, 3])


class Brdf(unittest.TestCase):
    def test_brdf_is_the_command_lines_at_every_direction(self):
        material = dict(distribution="ggx", geometry="smith-ggx-correlated", fresnel="schlick", alpha=0.3,
                        f0=(0.9, 0.6, 0.3), diffuse=(0.1, 0.2, 0.3))
        cases = [(45, 45, 180), (10, 70, 90), (80, 5, 0), (30, 60, 135)]

        def direction(theta, phi):
            t, p = np.radians(theta), np.radians(phi)
            return [np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)]

        l = np.array([direction(tl, 0) for tl, _, _ in cases])
        v = np.array([direction(tv, phi) for _, tv, phi in cases])
        values = facet.brdf(l, v, **material)
        self.assertEqual(values["f"].shape, (len(cases), 3))
        self.assertEqual(values["D"].shape, (len(cases),))
        for i, (theta_l, theta_v, phi) in enumerate(cases):
            run = cli("brdf", "--d", "ggx", "--g", "smith-ggx-correlated", "--f", "schlick", "--alpha", 0.3,
                      "--f0", "0.9,0.6,0.3", "--diffuse", "0.1,0.2,0.3", "--theta-l", theta_l, "--theta-v", theta_v,
                      "--phi", phi, "--json")
            self.assertEqual(run.returncode, 0, run.stderr)
            expected = json.loads(run.stdout)
            for key in ("f", "specular", "diffuse", "F", "D", "G"):
                np.testing.assert_allclose(values[key][i], expected[key], rtol=1e-12, atol=1e-15, err_msg=key)

    def test_directions_broadcast_as_numpy_does(self):
        theta = np.radians(np.linspace(0, 80, 9))
        l = np.stack([np.sin(theta), np.zeros_like(theta), np.cos(theta)], axis=-1).reshape(3, 3, 3)
        v = np.array([0.0, 0.0, 1.0])
        grid = facet.brdf(l, v, preset="copper", roughness=0.5)
        self.assertEqual(grid["f"].shape, (3, 3, 3))
        one = facet.brdf(l[1, 2], v, preset="copper", roughness=0.5)
        np.testing.assert_array_equal(grid["f"][1, 2], one["f"])
        self.assertEqual(one["D"].shape, ())
        # Reciprocity: f(l, v) = f(v, l).
        swapped = facet.brdf(v, l, preset="copper", roughness=0.5)
        np.testing.assert_allclose(swapped["f"], grid["f"], rtol=1e-12)

    def test_bad_arguments_raise_facets_messages(self):
        expected = cli_error("brdf", "--preset", "unobtainium")
        with self.assertRaises(facet.Error) as raised:
            facet.brdf([0, 0, 1], [0, 0, 1], preset="unobtainium")
        self.assertIn("unobtainium", str(raised.exception))
        self.assertIn(str(raised.exception).split(": ", 1)[1], expected)
        with self.assertRaisesRegex(facet.Error, r"l: expected an array of shape \(\.\.\., 3\)"):
            facet.brdf(np.zeros((4, 2)), [0, 0, 1], preset="gold", roughness=0.3)
        with self.assertRaisesRegex(facet.Error, "l: a direction must be finite and not the zero vector"):
            facet.brdf([0, 0, 0], [0, 0, 1], preset="gold", roughness=0.3)
        with self.assertRaises(ValueError):  # facet.Error is a ValueError
            facet.brdf([0, 0, 1], [0, 0, 1], alpha=-1)



class ChangedScenes(unittest.TestCase):
    """A loaded scene changed by attribute renders as the scene file that says the same."""

    CUBE = EXAMPLES.parent / "cages" / "cube.obj"
    COURTYARD = EXAMPLES.parent / "environments" / "courtyard_256x128.hdr"

    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        cls.renderer = facet.Renderer()

    def render(self, scene):
        return self.renderer.render(scene, size=(24, 24), backend="cpu", spp=1)

    def mean_covered(self, image):
        covered = image["beauty"][..., 3] > 0
        self.assertGreater(covered.mean(), 1 / 8)
        return image["beauty"][covered, :3].mean(axis=0)

    def scene_file(self, name, document):
        path = WORK / name
        path.write_text(json.dumps(document))
        return path

    def test_a_red_diffuse_material_turns_the_object_red(self):
        scene = facet.load_scene(self.CUBE)
        grey = self.mean_covered(self.render(scene))
        self.assertAlmostEqual(grey[0] / grey[1], 1.0, delta=0.05)
        scene.objects[0].material = facet.Material(diffuse=(0.8, 0.05, 0.05), f0=(0.04, 0.04, 0.04), roughness=0.6)
        red = self.mean_covered(self.render(scene))
        self.assertGreater(red[0], 2 * red[1])
        scene.objects[0].material = "gold"
        self.assertEqual(scene.objects[0].material, "gold")
        gold = self.mean_covered(self.render(scene))
        self.assertGreater(gold[0], gold[2] + 0.05)

    def test_a_changed_scene_renders_as_the_scene_file_that_says_the_same(self):
        scene = facet.load_scene(self.CUBE)
        scene.camera = facet.Camera(eye=(2.5, 2, 3), target=(0, 0.1, 0), fov=35)
        scene.lights = [facet.Light("directional", direction=(-1, -2, -1), color=(2, 1.8, 1.6)),
                        facet.Light("point", position=(0, 3, 2), color=(6, 6, 6))]
        scene.environment = facet.Environment(self.COURTYARD, intensity=0.5, rotation=30, method="filtered",
                                              samples=4)
        scene.objects[0].material = "copper"
        document = {
            "camera": {"eye": [2.5, 2, 3], "target": [0, 0.1, 0], "up": [0, 1, 0], "fov": 35},
            "objects": [{"mesh": str(self.CUBE), "material": "copper"}],
            "lights": [{"type": "directional", "direction": [-1, -2, -1], "color": [2, 1.8, 1.6]},
                       {"type": "point", "position": [0, 3, 2], "color": [6, 6, 6]}],
            "environment": {"file": str(self.COURTYARD), "intensity": 0.5, "rotation": 30, "method": "filtered",
                            "samples": 4},
        }
        edited = self.render(scene)
        from_file = self.render(facet.load_scene(self.scene_file("changed.json", document)))
        self.assertEqual(edited.keys(), from_file.keys())
        for name in edited:
            np.testing.assert_array_equal(edited[name], from_file[name], err_msg=name)
        self.assertEqual(scene.camera.fov, 35)
        self.assertEqual(scene.environment.method, "filtered")
        self.assertEqual([light.type for light in scene.lights], ["directional", "point"])

    def test_a_refused_change_gives_the_files_error_and_changes_nothing(self):
        scene = facet.load_scene(self.CUBE)
        fov = scene.camera.fov
        bad = self.scene_file("bad_fov.json", {"camera": {"fov": 500}, "objects": [{"mesh": str(self.CUBE)}]})
        from_file = cli_error("render", bad, "-o", WORK / "bad.exr").removeprefix(f"{bad}: ")
        with self.assertRaises(facet.Error) as raised:
            scene.camera = facet.Camera(fov=500)
        self.assertEqual(str(raised.exception), "scene: " + from_file)
        self.assertEqual(scene.camera.fov, fov)
        with self.assertRaisesRegex(facet.Error, r"^scene: objects\[0\]\.material\.preset: unknown preset 'golld'"):
            scene.objects[0].material = "golld"
        with self.assertRaisesRegex(facet.Error, r"^scene: lights\[0\]\.outer_cone: must be in \[0, "):
            scene.lights = [facet.Light("spot", outer_cone=200)]
        with self.assertRaisesRegex(facet.Error, r"^scene: environment\.file: "):
            scene.environment = facet.Environment(WORK / "no_such_map.exr")
        self.assertEqual(scene.lights, ())
        with self.assertRaises(AttributeError):
            scene.camera.fov = 20
        scene.camera = scene.camera.replace(fov=20)
        self.assertEqual(scene.camera.fov, 20)
        self.assertEqual(scene.environment.replace(method="sampled", samples=2).method, "sampled")
        # Unsaid samples stay unsaid, so that facet chooses them with the paths.
        self.assertIsNone(scene.environment.samples)
        self.assertEqual(scene.environment.replace(samples=3).samples, 3)
        scene.environment = scene.environment.replace(samples=3)
        self.assertEqual(scene.environment.samples, 3)
        self.assertEqual(facet.Light("spot").replace(outer_cone=60).outer_cone, 60)
        with self.assertRaisesRegex(facet.Error, "method 'cheap': expected one of: prefiltered, sampled, filtered"):
            scene.environment.replace(method="cheap")

    def test_a_loaded_cage_builds_the_scene_its_file_loads_as(self):
        cage = facet.load_cage(self.CUBE)
        self.assertEqual(cage.positions.shape, (8, 3))
        self.assertEqual(len(cage.face_vertex_counts), 6)
        built = self.render(facet.Scene([facet.Object(cage)]))
        loaded = self.render(facet.load_scene(self.CUBE))
        np.testing.assert_array_equal(built["beauty"], loaded["beauty"])

    def test_a_loaded_scene_states_its_warnings(self):
        gltf = pathlib.Path(__file__).resolve().parents[1] / "scenes" / "data" / "ignored_features.gltf"
        warnings = facet.load_scene(gltf).warnings
        self.assertTrue(any("only COLOR_0 is read" in w for w in warnings), warnings)
        self.assertEqual(facet.load_scene(self.CUBE).warnings, ())


if __name__ == "__main__":
    unittest.main()
