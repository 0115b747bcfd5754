"""Scenes as values in Python: built from a dict as from its file, objects
added, removed, reordered and placed, set() as --set changes the file, and
no container that looks editable while it ignores an edit."""
import json
import os
import pathlib
import unittest

import numpy as np

import facet

EXAMPLES = pathlib.Path(os.environ["FACET_EXAMPLES_DIR"])
WORK = pathlib.Path(os.environ["FACET_WORK_DIR"]) / "scene_values"
CAGES = EXAMPLES.parent / "cages"
CUBE = CAGES / "cube.obj"


def document():
    return {
        "camera": {"eye": [2.5, 2, 3], "target": [0, 0, 0], "fov": 40},
        "materials": {"warm": {"preset": "copper", "roughness": 0.5}},
        "objects": [{"name": "left", "mesh": "cube.obj", "material": "warm",
                     "transform": {"translate": [0.6, 0, 0]}},
                    {"name": "right", "mesh": "cube.obj",
                     "transform": {"translate": [-0.8, 0, -0.5], "scale": 0.5}}],
        "lights": [{"type": "directional", "direction": [-1, -2, -1], "color": [2, 2, 2]}],
    }


class SceneValues(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        cls.renderer = facet.Renderer()

    def render(self, scene):
        return self.renderer.render(scene, size=(24, 24), backend="cpu", spp=1)["beauty"]

    def from_file(self, name, doc):
        """`doc` as a scene file beside the cages, loaded."""
        path = WORK / name
        doc = json.loads(json.dumps(doc))
        for o in doc["objects"]:
            o["mesh"] = str(CAGES / o["mesh"])
        path.write_text(json.dumps(doc))
        return facet.load_scene(path)

    def test_a_dict_is_the_scene_its_file_is(self):
        scene = facet.load_dict(document(), folder=CAGES)
        self.assertEqual([o.name for o in scene.objects], ["left", "right"])
        self.assertEqual(scene.objects[0].material, "warm")
        np.testing.assert_array_equal(self.render(scene), self.render(self.from_file("dict.json", document())))
        with self.assertRaisesRegex(facet.Error, r"^scene: objects\[0\]\.mesh: no such file: "):
            facet.load_dict({"objects": [{"mesh": "nowhere.obj"}]}, folder=CAGES)
        with self.assertRaisesRegex(facet.Error, r"^scene: objects\[0\]\.mesh_file: unknown field "):
            facet.load_dict({"objects": [{"mesh_file": "cube.obj"}]}, folder=CAGES)

    def test_set_changes_the_scene_as_the_same_change_to_its_file(self):
        scene = facet.load_dict(document(), folder=CAGES)
        scene.set("materials.warm.roughness", 0.2)
        scene.set("objects[1].material", "gold")
        scene.set("camera.fov", 30)
        changed = document()
        changed["materials"]["warm"]["roughness"] = 0.2
        changed["objects"][1]["material"] = "gold"
        changed["camera"]["fov"] = 30
        np.testing.assert_array_equal(self.render(scene), self.render(self.from_file("set.json", changed)))
        with self.assertRaisesRegex(facet.Error, r"^scene: materials\.warm\.roughness: "):
            scene.set("materials.warm.roughness", 3)
        self.assertEqual(scene.camera.fov, 30)

    def test_objects_are_added_removed_reordered_and_placed(self):
        scene = facet.load_dict(document(), folder=CAGES)
        before = self.render(scene)
        index = scene.add_object(facet.Object(facet.load_cage(CUBE), name="third",
                                              transform=facet.Transform(translate=(0, 1.2, 0), scale=(0.3, 0.3, 0.3))),
                                 material="silver")
        self.assertEqual(index, 2)
        self.assertEqual(scene.objects[2].material, "silver")
        self.assertEqual(scene.objects[2].transform.scale, (0.3, 0.3, 0.3))
        three = document()
        three["objects"].append({"name": "third", "mesh": "cube.obj", "material": "silver",
                                 "transform": {"translate": [0, 1.2, 0], "scale": 0.3}})
        np.testing.assert_array_equal(self.render(scene), self.render(self.from_file("three.json", three)))
        scene.move_object(2, 0)
        self.assertEqual([o.name for o in scene.objects], ["third", "left", "right"])
        scene.remove_object(0)
        np.testing.assert_array_equal(self.render(scene), before)

        scene.objects[1].transform = facet.Transform(rotate=(0, 30, 0))
        self.assertEqual(scene.objects[1].transform.rotate, (0, 30, 0))
        self.assertEqual(scene.objects[1].transform.translate, (0, 0, 0))
        with self.assertRaisesRegex(facet.Error, r"^scene: objects\[1\]\.transform\.scale: must not be zero"):
            scene.objects[1].transform = facet.Transform(scale=(0, 1, 1))
        with self.assertRaisesRegex(facet.Error, r"^scene: objects\[2\]\.material\.preset: unknown preset"):
            scene.add_object(facet.Object(facet.load_cage(CUBE)), material="unobtainium")
        self.assertEqual(len(scene.objects), 2, "a refused add leaves the scene as it was")

    def test_every_container_refuses_edits_it_would_ignore(self):
        scene = facet.load_dict(document(), folder=CAGES)
        for name in ("objects", "lights", "material_names", "warnings"):
            values = getattr(scene, name)
            self.assertIsInstance(values, tuple, name)
            with self.assertRaises(AttributeError, msg=name):
                values.append(None)
        with self.assertRaises(TypeError):
            scene.objects[0] = None
        cage = facet.load_cage(CUBE)
        with self.assertRaisesRegex(ValueError, "read-only"):
            cage.positions[0, 0] = 5.0
        for name in ("face_vertex_counts", "face_vertex_indices", "creases"):
            self.assertIsInstance(getattr(cage, name), tuple, name)
        # What does change them: assignment, and the scene's own edits.
        scene.lights = list(scene.lights) + [facet.Light("point", position=(0, 3, 0), color=(4, 4, 4))]
        self.assertEqual([light.type for light in scene.lights], ["directional", "point"])


class Keywords(unittest.TestCase):
    """A keyword facet does not take is named, with the one meant, as a facet.Error."""

    def test_a_typo_names_the_keyword_and_the_one_meant(self):
        cases = [
            (lambda: facet.Material(roughnes=0.5), "facet.Material: unknown keyword 'roughnes'; did you mean 'roughness'?"),
            (lambda: facet.Camera().replace(fv=30), "facet.Camera.replace: unknown keyword 'fv'; did you mean 'fov'?"),
            (lambda: facet.Transform(rotation=(0, 1, 0)), "facet.Transform: unknown keyword 'rotation'; did you mean 'rotate'?"),
            (lambda: facet.render(CUBE, sppp=4), "facet.render: unknown keyword 'sppp'; did you mean 'spp'?"),
        ]
        for call, message in cases:
            with self.assertRaises(facet.Error) as raised:
                call()
            self.assertTrue(str(raised.exception).startswith(message), str(raised.exception))
            self.assertEqual(raised.exception.exit_code, 1)

    def test_a_value_of_the_wrong_type_stays_a_type_error_naming_the_call(self):
        with self.assertRaisesRegex(TypeError, r"^facet\.Material: an argument is not of the type"):
            facet.Material(roughness="high")
        self.assertEqual(facet.Material(roughness=0.25).roughness, 0.25)


if __name__ == "__main__":
    unittest.main()
