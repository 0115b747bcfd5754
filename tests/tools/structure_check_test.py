"""tools/check_structure.py on tiny trees built for each case: it accepts a
tree that keeps the layering and rejects each way of breaking it.

    python3 -m unittest tests/tools/structure_check_test.py
"""

import contextlib
import importlib.util
import io
import os
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "check_structure.py")
spec = importlib.util.spec_from_file_location("check_structure", SCRIPT)
check_structure = importlib.util.module_from_spec(spec)
spec.loader.exec_module(check_structure)


def includes(*names):
    return "".join(f'#include "{name}"\n' for name in names)


# A tree that keeps the real table's layering, with each kind of include the
# script has to resolve: root-relative, beside the including file, the public
# API as "facet/...", and generated SPIR-V headers that exist in no folder;
# inside compute/raycast/, an include down the rooms.
GOOD_TREE = {
    "materials/material.h": "#pragma once\n#include <vector>\n",
    "scenes/scene.h": includes("materials/material.h"),
    "engine/camera/camera.h": includes("scenes/scene.h", "camera_math.h"),
    "engine/camera/camera_math.h": "",
    "engine/gpu_backend/renderer.cpp": includes("engine/camera/camera.h", "detail/packing.h", "facet_kernels/spirv.h"),
    "engine/gpu_backend/detail/packing.h": "",
    "compute/raycast/traversal/trace.comp": includes("compute/shared/layout.h", "compute/raycast/common/ray.glsl"),
    "compute/raycast/common/ray.glsl": "",
    "compute/shared/layout.h": "",
    "include/facet/scene.h": "",
    "apps/facet/main.cpp": includes("facet/scene.h", "facet/version.h", "engine/camera/camera.h"),
    "benchmarks/ceiling/bench.cpp": includes("ceiling_kernels/spirv.h", "compute/shared/layout.h"),
    "tools/helper.py": "print('not parsed for includes')\n",
    # Tests are not checked: they may include anything and be any length.
    "tests/materials/material_test.cpp": includes("apps/facet/main.cpp") + "\n" * 600,
}


class StructureCheckTest(unittest.TestCase):
    def check(self, changes):
        """(violations, cycles, exit status, output) for GOOD_TREE with changes
        (a path mapped to None is left out)."""
        files = {**GOOD_TREE, **changes}
        with tempfile.TemporaryDirectory() as root:
            for path, text in files.items():
                if text is None:
                    continue
                os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
                with open(os.path.join(root, path), "w") as file:
                    file.write(text)
            violations, cycles, _ = check_structure.check(root)
            violations += check_structure.long_function_violations(root)
            violations += check_structure.wall_clock_violations(root)
            output = io.StringIO()
            with contextlib.redirect_stdout(output):
                status = check_structure.main([root])
        return violations, cycles, status, output.getvalue()

    def test_accepts_a_tree_that_keeps_the_layering(self):
        violations, cycles, status, output = self.check({})
        self.assertEqual(violations, [])
        self.assertEqual(cycles, [])
        self.assertEqual(status, 0)
        self.assertRegex(output, r"^check_structure: 13 files, 13 includes, \d+ layers")

    def test_rejects_an_include_that_points_up(self):
        violations, _, status, output = self.check({"materials/material.h": includes("scenes/scene.h")})
        expected = ('materials/material.h:1: includes "scenes/scene.h" (layer materials, rank 1) -> '
                    "layer scenes (rank 2): includes must point down")
        self.assertEqual(violations, [expected])
        self.assertEqual(status, 1)
        self.assertIn(expected, output)

    def test_rejects_an_include_between_two_layers_of_the_same_rank(self):
        # The CPU reference and the GPU kernels are peers: neither may see the other.
        violations, _, _, _ = self.check({"engine/cpu/intersect.cpp": "\n" + includes("compute/shared/layout.h")})
        self.assertEqual(violations, ['engine/cpu/intersect.cpp:2: includes "compute/shared/layout.h" (layer '
                                      "engine/cpu, rank 4) -> layer compute (rank 4): includes must point down"])

    def test_reports_a_cycle_between_layers(self):
        violations, cycles, status, output = self.check({
            "compute/raycast/shading/shade.comp": includes("engine/cpu/shade.h"),
            "engine/cpu/shade.h": includes("compute/shared/layout.h"),
        })
        self.assertEqual(len(violations), 2)
        self.assertEqual(cycles, [[("compute", "engine/cpu", "compute/raycast/shading/shade.comp:1"),
                                   ("engine/cpu", "compute", "engine/cpu/shade.h:1")]])
        self.assertEqual(status, 1)
        self.assertIn("layer cycle: compute -> engine/cpu -> compute", output)

    def test_rejects_a_sideways_include_between_rooms(self):
        violations, cycles, status, _ = self.check({
            "compute/raycast/dicing/dice.comp": includes("compute/raycast/shading/textures.glsl"),
            "compute/raycast/shading/textures.glsl": "",
        })
        self.assertEqual(violations, ['compute/raycast/dicing/dice.comp:1: includes '
                                      '"compute/raycast/shading/textures.glsl" (room compute/raycast/dicing, rank 1) '
                                      "-> room compute/raycast/shading (rank 1): includes must point down"])
        self.assertEqual(cycles, [])
        self.assertEqual(status, 1)

    def test_rejects_an_include_up_the_rooms(self):
        violations, _, _, _ = self.check({
            "compute/raycast/common/ray.glsl": includes("compute/raycast/traversal/trace.comp"),
        })
        self.assertEqual(len(violations), 1)
        self.assertIn("(room compute/raycast/common, rank 0) -> room compute/raycast/traversal (rank 2)", violations[0])

    def test_reports_a_cycle_between_rooms(self):
        violations, cycles, status, output = self.check({
            "compute/raycast/traversal/trace.comp": includes("compute/raycast/finish/finish.glsl"),
            "compute/raycast/finish/finish.glsl": includes("compute/raycast/traversal/trace.glsl"),
            "compute/raycast/traversal/trace.glsl": "",
        })
        self.assertEqual(len(violations), 1)
        finish, traversal = "compute/raycast/finish", "compute/raycast/traversal"
        self.assertEqual(cycles, [[(finish, traversal, f"{finish}/finish.glsl:1"),
                                   (traversal, finish, f"{traversal}/trace.comp:1")]])
        self.assertEqual(status, 1)
        self.assertIn(f"room cycle: {finish} -> {traversal} -> {finish}", output)

    def test_rejects_a_file_in_no_room(self):
        violations, _, status, _ = self.check({"compute/raycast/lighting/light.glsl": "",
                                               "compute/raycast/loose.glsl": ""})
        self.assertEqual(status, 1)
        self.assertEqual(len(violations), 2)
        self.assertIn("compute/raycast/lighting/light.glsl: in no room of compute/raycast", violations[0])
        self.assertIn("compute/raycast/loose.glsl: in no room of compute/raycast", violations[1])

    def test_rejects_a_rule_without_its_guard_or_its_lines_in_the_instance(self):
        def rule(guard, body=""):
            return f"// A rule.\n\n#ifndef {guard}\n#define {guard}\n{body}\n#endif\n"
        violations, _, status, _ = self.check({
            "rules/math.h": rule("FACET_RULE_MATH"),
            "rules/shading/brdf.h": rule("FACET_RULE_SHADING_BRDF", includes("rules/math.h")),
            "rules/shading/sheen.h": rule("FACET_RULE_BRDF"),
            "rules/instance.h": includes("rules/math.h", "rules/shading/brdf.h", "rules/shading/sheen.h")
                                + "#undef FACET_RULE_MATH\n#undef FACET_RULE_SHADING_SHEEN\n",
        })
        self.assertEqual(status, 1)
        self.assertEqual(violations, [
            'rules/instance.h: lacks #include "rules/shading/brdf.h" or, at its end, #undef FACET_RULE_SHADING_BRDF',
            "rules/shading/sheen.h: not inside its guard #ifndef FACET_RULE_SHADING_SHEEN / "
            "#define FACET_RULE_SHADING_SHEEN / ... / #endif",
        ])

    def test_rejects_a_folder_in_no_layer(self):
        violations, _, status, _ = self.check({
            "widgets/widget.h": "",
            "scenes/scene.cpp": includes("widgets/widget.h"),
            # engine/ is split into layers, so a new subfolder must be named too.
            "engine/newpart/part.h": "",
        })
        self.assertEqual(status, 1)
        self.assertEqual(len(violations), 3)
        self.assertIn("engine/newpart/part.h: in no layer", violations[0])
        self.assertIn('scenes/scene.cpp:1: includes "widgets/widget.h" (layer scenes, rank 2) -> widgets/widget.h, '
                      "in no layer", violations[1])
        self.assertIn("widgets/widget.h: in no layer", violations[2])

    def test_a_root_relative_file_wins_over_one_beside_the_includer(self):
        # engine/gpu/scenes/scene.h exists, but "scenes/scene.h" means the root's, one rank up.
        violations, _, _, _ = self.check({"engine/gpu/scenes/scene.h": "",
                                          "engine/gpu/device.cpp": includes("scenes/scene.h")})
        self.assertEqual(len(violations), 1)
        self.assertIn("-> layer scenes (rank 2)", violations[0])

    def test_accepts_450_lines_and_rejects_451(self):
        violations, _, _, _ = self.check({"scenes/long.cpp": "x\n" * 450, "apps/facet/long.cpp": "x\n" * 451,
                                          "tools/long.py": "x\n" * 450 + "x"})
        self.assertEqual(violations, ["apps/facet/long.cpp: 451 lines > 450", "tools/long.py: 451 lines > 450"])

    def test_accepts_a_100_line_function_and_rejects_101(self):
        def function(signature, lines, body="  x();\n"):
            return signature + " {\n" + body * (lines - 2) + "}\n"
        violations, _, status, _ = self.check({
            "scenes/long.cpp": function("namespace {\nint fits(int a)", 100)
                               + "}  // namespace\n\n" + function("int\nScene::tooLong(int a,\n    int b) const", 99),
            "compute/raycast/shading/shade.comp": "layout(local_size_x = 64) in;\n" + function("void main()", 101),
            # The constructor's first line counts, and the members' {} are not its body.
            "engine/camera/camera.cpp": function("Camera::Camera(int a)\n    : a_{a}, b_(a)", 100),
            "tools/long.py": "def fits():\n" + "    x()\n" * 99 + "\n\nclass A:\n    def long(self):\n"
                             + "        x()\n" * 100,
            "tests/scenes/long_test.cpp": function("TEST(Scene, Long)", 300),
        })
        self.assertEqual(status, 1)
        self.assertEqual(violations, [
            "compute/raycast/shading/shade.comp:2: main is 101 lines > 100: split it into functions of one concept each",
            "engine/camera/camera.cpp:1: Camera::Camera is 101 lines > 100: split it into functions of one concept each",
            "scenes/long.cpp:104: Scene::tooLong is 101 lines > 100: split it into functions of one concept each",
            "tools/long.py:104: A.long is 101 lines > 100: split it into functions of one concept each",
        ])

    def test_braces_in_comments_strings_and_blocks_are_not_functions(self):
        body = ('  auto open = "{{{";  // }\n'
                "  char close = '}';\n"
                "  /* } } */\n"
                '  auto raw = R"x(})x";\n'
                "  auto call = [](int a) { return a; };\n"
                "  if (open) {\n  }\n")
        text = ("#define BRACE {\n"
                "struct Pair { int a{1}; int b = 2; };\n"
                "enum class E { A, B };\n"
                "const int table[] = {1, 2, 3};\n"
                'extern "C" {\nint f(int a) {\n' + body * 14 + "}\n}\n")
        # f is lines 6 to 105: 100 lines, which a brace too few or too many would change.
        self.assertEqual(check_structure.brace_functions(text), [("f", 6, 105)])
        violations, _, _, _ = self.check({"scenes/braces.cpp": text})
        self.assertEqual(violations, [])

    def test_rejects_a_time_limit_a_busy_machine_can_reach(self):
        violations, _, status, _ = self.check({
            "tests/engine/render_test.cpp": "s.timeLimitSeconds = 600;\ns.timeLimitSeconds = 86400;\n",
            "tests/apps/check.sh": 'common=(--time-limit 60)\nbad --time-limit -1\nbad --time-limit nan\n',
        })
        self.assertEqual(status, 1)
        self.assertEqual(len(violations), 2)
        self.assertIn("tests/apps/check.sh:1: a time limit of 60 s", violations[0])
        self.assertIn("tests/engine/render_test.cpp:1: a time limit of 600 s", violations[1])

    def test_rejects_facet_preview_without_a_time_limit(self):
        violations, _, _, _ = self.check({"tests/apps/check.sh": (
            '"$facet" preview gold -o a.png\n'
            '"$facet" preview gold --time-limit 86400 -o b.png\n'
            "# facet preview in a comment runs nothing\n")})
        self.assertEqual(len(violations), 1)
        self.assertIn("tests/apps/check.sh:1: runs facet preview without --time-limit", violations[0])

    def test_rejects_a_test_that_reads_the_clock_unless_allowed(self):
        violations, _, _, _ = self.check({
            "tests/engine/speed_test.cpp": "auto start = std::chrono::steady_clock::now();\n",
            "tests/apps/wait.sh": "\nsleep 1\n",
            "tests/python/wait_test.py": "import time\nstarted = time.monotonic()\n",
            # Allowed: it prints the time and asserts nothing on it.
            "tests/engine/cpu/intersect_exact_test.cpp": "auto start = std::chrono::steady_clock::now();\n",
        })
        self.assertEqual(len(violations), 3)
        self.assertIn('tests/apps/wait.sh:2: reads the wall clock ("sleep 1")', violations[0])
        self.assertIn("tests/engine/speed_test.cpp:1: reads the wall clock", violations[1])
        self.assertIn("tests/python/wait_test.py:2: reads the wall clock", violations[2])

    def test_rejects_an_allowance_no_longer_needed(self):
        violations, _, _, _ = self.check({"tests/engine/cpu/intersect_exact_test.cpp": "int main() {}\n"})
        self.assertEqual(len(violations), 1)
        self.assertIn("tests/engine/cpu/intersect_exact_test.cpp: tests/engine/cpu/intersect_exact_test.cpp is in "
                      "ALLOWED_CLOCK_READS but no longer needed there", violations[0])


if __name__ == "__main__":
    unittest.main()
