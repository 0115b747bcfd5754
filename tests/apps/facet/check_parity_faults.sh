#!/bin/bash
# The gate proven on faults injected on purpose (FACET_FAULT, docs/parity.md
# "Proving the gate"): facet parity fails each fault that changes the GPU's
# image beyond its tolerances, naming the AOV it broke and the fault in the
# device's name, passes a healthy GPU and a one-ulp change, and refuses a
# fault it does not know.
#   check_parity_faults.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "check_parity_faults: FAILED: $*" >&2; exit 1; }
scene=$repo/scenes/examples/superball.obj

# verdict FAULT EXIT_CODE FAILED_AOVS: the exit code, and the AOVs that failed (comma-separated, or "").
verdict() {
  local fault=$1 expected=$2 aovs=$3
  set +e
  FACET_FAULT=$fault "$facet" parity "$scene" --size 48x32 --json >"$fault.json" 2>"$fault.err"
  local code=$?
  set -e
  [ "$code" = "$expected" ] || fail "FACET_FAULT=$fault: exit code $code, not $expected: $(cat "$fault.err")"
  /usr/bin/python3 - "$fault" "$aovs" <<'PY' || fail "FACET_FAULT=$1: the wrong AOVs failed"
import json, sys
fault, expected = sys.argv[1], sys.argv[2]
run = json.load(open(f"{fault}.json"))["scenes"][0]["runs"][0]
failed = [a["name"] for a in run["aovs"] if not a.get("pass", True)] + ([] if run["coverage"]["pass"] else ["coverage"])
wanted = expected.split(",") if expected else []
assert all(name in failed for name in wanted) and bool(failed) == bool(wanted), (fault, failed, wanted)
device = run["adapter"]["device"]
assert (f"FACET_FAULT={fault}" in device) == bool(fault), device
PY
}

verdict "" 0 ""
verdict beauty-ulp 0 ""
verdict beauty-bias 5 beauty
verdict dropped-tile 5 beauty
verdict flipped-normal 5 "shading normal"
verdict shifted-pixel 5 depth

set +e
FACET_FAULT=nonsense "$facet" parity "$scene" --size 8x8 >/dev/null 2>err.txt
code=$?
set -e
[ "$code" = 1 ] || fail "an unknown fault: exit code $code"
grep -q "^facet: error: FACET_FAULT 'nonsense': expected one of: beauty-bias, dropped-tile, shifted-pixel, flipped-normal, beauty-ulp" err.txt ||
  fail "an unknown fault: $(cat err.txt)"
echo "check_parity_faults: every fault caught, a healthy GPU and one ulp passed"
