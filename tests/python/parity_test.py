"""facet.parity judges as `facet parity` does, by one implementation: the
same verdict, statistics and JSON for the same scene and options."""
import json
import os
import pathlib
import subprocess
import unittest

import facet

FACET = os.environ["FACET_BINARY"]
EXAMPLES = pathlib.Path(os.environ["FACET_EXAMPLES_DIR"])
WORK = pathlib.Path(os.environ["FACET_WORK_DIR"]) / "parity"


def comparable(run):
    """A run's JSON without what names or times it."""
    return {key: value for key, value in run.items() if key not in ("name", "adapter", "milliseconds")}


class Parity(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        WORK.mkdir(parents=True, exist_ok=True)
        # Sampled lighting: a Monte Carlo beauty, judged by the paired t-test over renders seeds apart.
        cls.scene = WORK / "sampled.json"
        cls.scene.write_text(json.dumps({
            "camera": {"eye": [2.5, 2, 3], "target": [0, 0, 0], "fov": 40},
            "objects": [{"mesh": str(EXAMPLES.parent / "cages" / "cube.obj"), "material": "copper"}],
            "environment": {"file": str(EXAMPLES.parent / "environments" / "courtyard_256x128.hdr"),
                            "method": "sampled", "samples": 2}}))

    def test_the_report_is_the_command_lines(self):
        options = ["--size", "24x16", "--renders", "3", "--tolerance", "depth=0,2e-4", "--min-coverage", "8"]
        cli = subprocess.run([FACET, "parity", str(self.scene), "--json", *options], capture_output=True, text=True)
        self.assertEqual(cli.returncode, 0, cli.stderr)
        expected = json.loads(cli.stdout)["scenes"][0]
        report = facet.parity(self.scene, size=(24, 16), renders=3, tolerances=["depth=0,2e-4"], min_coverage=8)
        self.assertEqual(report["settings"], expected["settings"])
        self.assertEqual(comparable(report["runs"][0]), comparable(expected["runs"][0]))
        self.assertEqual(report["renders"], 3)
        beauty = next(aov for aov in report["runs"][0]["aovs"] if aov["name"] == "beauty")
        self.assertEqual(beauty["test"], "paired t-test")
        depth = next(aov for aov in report["runs"][0]["aovs"] if aov["name"] == "depth")
        self.assertEqual(depth["tolerance"]["relative"], 2e-4)

    def test_bad_options_are_the_command_lines_rules(self):
        with self.assertRaisesRegex(facet.Error, r"^parity options: tolerances 'depth=x': expected AOV=ABS,REL"):
            facet.parity(self.scene, size=(8, 8), tolerances=["depth=x"])
        with self.assertRaisesRegex(facet.Error, r"^parity options: renders: expected renders per backend"):
            facet.parity(self.scene, size=(8, 8), renders=0)
        report = facet.parity(self.scene, size=(8, 8), renders=1, min_coverage=100000)
        self.assertEqual(report["verdict"], "insufficient coverage")
        self.assertFalse(report["pass"])


if __name__ == "__main__":
    unittest.main()
