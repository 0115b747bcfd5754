"""Renderer.watch from Python: each pass reaches the callback, a change to
the file renders the changed scene, a glTF file is watched in the material
variant named, a refused load goes to on_bad_input, and an exception in the
callback stops the watch and is raised."""
import json
import os
import pathlib
import unittest

import numpy as np

import facet

EXAMPLES = pathlib.Path(os.environ["FACET_EXAMPLES_DIR"])
WORK = pathlib.Path(os.environ["FACET_WORK_DIR"]) / "watch"
# A glTF triangle in material "red", which its variant "blue" maps to "blue", each of its own colour.
VARIANT_TRIANGLE = pathlib.Path(__file__).resolve().parent.parent / "scenes" / "data" / "variant_triangle.gltf"
CUBE = EXAMPLES.parent / "cages" / "cube.obj"
QUICK = dict(size=(16, 16), backend="cpu", spp=1)


def scene_file(name, fov):
    path = WORK / name
    path.write_text(json.dumps({"camera": {"eye": [2.5, 2, 3], "target": [0, 0, 0], "fov": fov},
                                "objects": [{"mesh": str(CUBE)}]}))
    return path


class Watch(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        cls.renderer = facet.Renderer()

    def test_a_change_renders_the_changed_scene(self):
        path = scene_file("watched.json", 40)
        seen = []

        def on_pass(p):
            seen.append(p)
            if p["picture"] == 0:
                scene_file("watched.json", 25.5)

        self.renderer.watch(path, on_pass, passes=1, changes=1, **QUICK)
        self.assertEqual([p["picture"] for p in seen], [0, 1])
        expected = self.renderer.render(path, **QUICK)["beauty"]
        np.testing.assert_array_equal(seen[1]["image"]["beauty"], expected)

    def test_a_refused_load_goes_to_on_bad_input(self):
        path = scene_file("refused.json", 40)
        refusals = []

        def on_pass(p):
            if p["picture"] == 0:
                path.write_text("{\"objects\": [")

        def on_bad_input(message):
            refusals.append(message)
            scene_file("refused.json", 30)

        self.renderer.watch(path, on_pass, passes=1, changes=2, on_bad_input=on_bad_input, **QUICK)
        self.assertEqual(len(refusals), 1)
        self.assertTrue(refusals[0].startswith(f"{path}: not valid JSON"), refusals[0])

    def test_an_exception_in_on_bad_input_stops_the_watch(self):
        path = scene_file("raising.json", 40)

        def on_pass(p):
            path.write_text("{\"objects\": [")

        def on_bad_input(message):
            raise RuntimeError("from on_bad_input")

        with self.assertRaisesRegex(RuntimeError, "from on_bad_input"):
            self.renderer.watch(path, on_pass, passes=1, on_bad_input=on_bad_input, **QUICK)

    def test_a_gltf_is_watched_in_the_material_variant_named(self):
        path = VARIANT_TRIANGLE
        seen = []
        self.renderer.watch(path, lambda p: seen.append(p) or False, passes=1, variant="blue", **QUICK)
        blue = self.renderer.render(facet.load_scene(path, variant="blue"), **QUICK)["beauty"]
        red = self.renderer.render(path, **QUICK)["beauty"]
        np.testing.assert_array_equal(seen[0]["image"]["beauty"], blue)
        self.assertFalse(np.array_equal(blue, red))

    def test_the_callback_stops_it_or_raises_through_it(self):
        path = scene_file("stopped.json", 40)
        passes = []
        self.renderer.watch(path, lambda p: passes.append(p) or False, passes=4, **QUICK)
        self.assertEqual(len(passes), 1)

        def broken(p):
            raise KeyError("from the callback")

        with self.assertRaisesRegex(KeyError, "from the callback"):
            self.renderer.watch(path, broken, passes=4, **QUICK)


if __name__ == "__main__":
    unittest.main()
