"""The preview stage from Python: a frame's pictures and sheet as numpy
arrays, the sheet facet preview writes byte for byte, and its flags' rules
under their Python names."""
import os
import pathlib
import subprocess
import unittest

import numpy as np

import facet

FACET = os.environ["FACET_BINARY"]
EXAMPLES = pathlib.Path(os.environ["FACET_EXAMPLES_DIR"])
WORK = pathlib.Path(os.environ["FACET_WORK_DIR"]) / "preview"
CUBE = EXAMPLES.parent / "cages" / "cube.obj"
QUICK = dict(size=(24, 16), max_spp=8, backend="cpu")


class Preview(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        cls.renderer = facet.Renderer()

    def test_a_frame_is_each_materials_picture_and_the_sheet(self):
        frame = self.renderer.preview(CUBE, ["gold", "copper"], **QUICK)
        self.assertEqual([p["label"] for p in frame["pictures"]], ["gold", "copper"])
        for picture in frame["pictures"]:
            self.assertEqual(picture["rgba"].shape, (16, 24, 4))
            self.assertEqual(picture["rgba"].dtype, np.uint8)
            self.assertEqual(picture["image"]["beauty"].shape, (16, 24, 4))
            self.assertLessEqual(picture["adaptive"]["spp_max"], 8)
        self.assertFalse(np.array_equal(frame["pictures"][0]["rgba"], frame["pictures"][1]["rgba"]))
        self.assertEqual(frame["sheet"].ndim, 3)
        self.assertGreater(frame["sheet"].shape[1], 2 * 24)

    def test_write_preview_writes_the_command_lines_sheet(self):
        cli, api = WORK / "cli.png", WORK / "api.png"
        subprocess.run([FACET, "preview", "gold", "copper", "--model", str(CUBE), "--size", "24x16", "--max-spp", "8",
                        "--backend", "cpu", "--time-limit", "86400", "--quiet", "-o", str(cli)], check=True)
        self.renderer.write_preview(CUBE, ["gold", "copper"], api, **QUICK)
        self.assertEqual(api.read_bytes(), cli.read_bytes())

    def test_a_turntable_turns_the_model_before_the_fixed_light(self):
        # The cube has the symmetry of a quarter turn; the environment's lamps do not.
        turning = dict(QUICK, turntable=4, ground=False)
        still = self.renderer.preview(CUBE, ["gold"], frame=0, **turning)["pictures"][0]["image"]["beauty"]
        model = self.renderer.preview(CUBE, ["gold"], frame=1, **turning)["pictures"][0]["image"]["beauty"]
        light = self.renderer.preview(CUBE, ["gold"], frame=1, turn="environment",
                                      **turning)["pictures"][0]["image"]["beauty"]
        self.assertAlmostEqual(model[..., :3].mean(), still[..., :3].mean(), delta=1e-3 * still[..., :3].mean())
        self.assertGreater(abs(light[..., :3].mean() - still[..., :3].mean()), 0.02 * still[..., :3].mean())

    def test_bad_settings_raise_the_flags_rules(self):
        with self.assertRaisesRegex(facet.Error, r"^preview settings: noiseThreshold: expected a number in \(0, 1\]"):
            self.renderer.preview(CUBE, ["gold"], noise_threshold=0, **QUICK)
        with self.assertRaisesRegex(facet.Error, r"^turn 'sideways': expected one of: model, environment"):
            self.renderer.preview(CUBE, ["gold"], turn="sideways", **QUICK)
        with self.assertRaisesRegex(facet.Error, r"^material 'unobtainium': "):
            self.renderer.preview(CUBE, ["unobtainium"], **QUICK)


if __name__ == "__main__":
    unittest.main()
