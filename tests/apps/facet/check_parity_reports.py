"""Runs a `facet parity` or `facet compare` command with --junit and --json,
checks its exit code, and parses what it wrote: a JUnit XML file with a
test case per scene, adapter and AOV (and one for coverage), and JSON with
the facet version, the settings digest, the adapter and worst pixels. A
scene that errored is a suite of one "render" case holding an <error> with
facet's message, and a JSON scene with that "error" and no runs; an exit
code other than 0 and 5 (a broken run) needs at least one.

usage: check_parity_reports.py EXIT_CODE JUNIT_FILE EXPECT_FAILURES facet ARGS...
EXPECT_FAILURES: 'none', 'some', or the failure type every failure must have.
"""
import json
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

AOVS = ["coverage", "depth", "shading normal", "beauty", "alpha", "position", "geometric normal", "uv", "texcoord",
        "patchId", "faceId"]
GATED = {"coverage", "depth", "shading normal", "beauty"}


def fail(message):
    print(message, file=sys.stderr)
    sys.exit(1)


def main():
    exit_code, junit, expect, command = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4:]
    run = subprocess.run(command + ["--junit", junit, "--json"], capture_output=True, text=True)
    if run.returncode != exit_code:
        fail(f"exit {run.returncode}, expected {exit_code}:\n{run.stdout}{run.stderr}")
    report = json.loads(run.stdout)
    if not report.get("facetVersion"):
        fail("the JSON has no facetVersion")
    errored = [scene["scene"] for scene in report["scenes"] if "error" in scene]
    for scene in report["scenes"]:
        if "error" in scene:
            if scene["runs"] or not scene["error"]:
                fail(f"{scene['scene']}: an error with runs, or without a message: {scene}")
            continue
        if "parity" in command[1] and len(scene["settings"].get("digest", "")) != 16:
            fail(f"no settings digest: {scene['settings']}")
        for run_report in scene["runs"]:
            if "parity" in command[1] and not run_report["adapter"].get("driver"):
                fail(f"no driver: {run_report['adapter']}")
            for aov in run_report["aovs"]:
                if aov["gated"] != (aov["name"] in GATED):
                    fail(f"{aov['name']}: gated is {aov['gated']}")
                if not aov["gated"] and ("pass" in aov or "tolerance" in aov):
                    fail(f"{aov['name']} is not gated but has a verdict or tolerance: {aov}")
                if aov["gated"] and not {"absolute", "relative", "passShare", "rule"} <= aov["tolerance"].keys():
                    fail(f"{aov['name']}: tolerance without its parts: {aov['tolerance']}")
                for pixel in aov["worstPixels"]:
                    if not {"x", "y", "reference", "candidate", "error"} <= pixel.keys():
                        fail(f"{aov['name']}: worst pixel without coordinates: {pixel}")

    suites = ElementTree.parse(junit).getroot()
    if suites.tag != "testsuites":
        fail(f"root is <{suites.tag}>")
    failures, errors = [], []
    for suite in suites.iter("testsuite"):
        cases = suite.findall("testcase")
        if suite.get("name") in errored:
            error = cases[0].find("error") if len(cases) == 1 and cases[0].get("name") == "render" else None
            if error is None or not error.get("message") or suite.get("errors") != "1":
                fail(f"{suite.get('name')}: errored, but not as one render case with an <error>")
            errors.append(error.get("message"))
            continue
        if [case.get("name") for case in cases] != AOVS:
            fail(f"test cases {[case.get('name') for case in cases]}, expected {AOVS}")
        for case in cases:
            skipped = case.find("skipped")
            if case.get("name") not in GATED and (skipped is None or "not gated" not in skipped.get("message")):
                fail(f"{case.get('name')} is not gated and not skipped")
            failures += case.findall("failure")
        if int(suite.get("failures")) != sum(len(case.findall("failure")) for case in cases):
            fail("the suite's failure count differs from its failures")
    if int(suites.get("tests")) != len(AOVS) * (len(suites.findall("testsuite")) - len(errors)) + len(errors):
        fail(f"tests=\"{suites.get('tests')}\"")
    if int(suites.get("errors")) != len(errors) or len(errors) != len(errored):
        fail(f"errors=\"{suites.get('errors')}\", {len(errors)} <error> cases, {len(errored)} scenes with an error")
    if exit_code not in (0, 5) and not errors:
        fail(f"exit {exit_code} and no <error> in the JUnit file")
    for message in errors:
        if message not in run.stderr:
            fail(f"the <error> message is not facet's: {message}")
    if expect == "none" and failures:
        fail(f"unexpected failures: {[f.get('message') for f in failures]}")
    if expect != "none" and not failures:
        fail("no <failure> in the JUnit file")
    if expect not in ("none", "some") and any(f.get("type") != expect for f in failures):
        fail(f"failure types {[f.get('type') for f in failures]}, expected '{expect}'")
    print(f"{len(suites.findall('testsuite'))} suites, {len(failures)} failures, {len(errors)} errors")


main()
