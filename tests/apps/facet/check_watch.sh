#!/bin/bash
# facet render --watch end to end, on the GPU backend at 32x32:
#   - the first picture, refined by a second pass (4 samples a pixel: its
#     silhouette anti-aliased), then a new one when the material file
#     changes (red, then green), with the geometry kept on the device;
#   - a broken material file: an error line, the process still running and
#     the picture untouched; fixed (blue), it renders again;
#   - SIGTERM: exit 0, the outputs complete, no temporaries;
#   - --watch-limit ends it by itself; an output swapped for a symbolic
#     link is refused before the next write; --watch with --frames,
#     --watch-limit without --watch, and a scene broken from the start are
#     refused.
# No wait decides the result by how long it took: each waits for its event
# while facet runs, and one deadline for the whole script, far beyond a run
# on a busy machine, has a watchdog kill a facet that hangs.
#   check_watch.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
pid=
fail() {
  echo "check_watch: FAILED: $*" >&2
  for f in log.txt err.txt; do [ -f $f ] && sed "s/^/  $f: /" $f >&2; done
  exit 1
}
trap '[ -n "$pid" ] && kill -KILL $pid 2>/dev/null; true' EXIT

cp "$repo/scenes/examples/superball.obj" ball.obj
material() { echo "{\"preset\": \"plastic-high\", \"roughness\": 0.3, \"diffuse\": [$1]}" >mat.tmp && mv mat.tmp mat.json; }
material "0.6, 0.02, 0.02"
cat >scene.json <<JSON
{"objects": [{"name": "ball", "mesh": "ball.obj", "material": "mat.json"}], "render": {"width": 32, "height": 32}}
JSON

# Mean of channel $2 (0 R, 1 G, 2 B) of PNG $1 over the ball's middle, in 0..1.
mean() { oiiotool "$1" --cut 12x12+10+10 --printstats | awk -v c=$(($2 + 3)) '/Stats Avg/ {print $c}'; }
# Whether channel $2 of PNG $1 exceeds channel $3 by more than 0.1.
above() { awk -v a="$(mean "$1" "$2")" -v b="$(mean "$1" "$3")" 'BEGIN {exit !(a - b > 0.1)}'; }
deadline=$((SECONDS + 600))  # below the test's ctest TIMEOUT, so that fail() reports
# Waits for the command $1 to succeed; fails once facet has ended without it.
await() {
  until eval "$1"; do
    kill -0 $pid 2>/dev/null || eval "$1" || return 1
    sleep 0.05
  done
}
pictures() { grep -c "refined to 2 passes" log.txt || true; }
# Kills process $1 should it outlive the deadline; ends with it.
watchdog() {
  (for _ in $(seq $(((deadline - SECONDS) * 10))); do
    sleep 0.1
    kill -0 $1 || exit 0
  done
  kill -KILL $1) >/dev/null 2>&1 &
}

"$facet" render scene.json --watch --watch-passes 2 -o out.exr --png out.png --backend gpu >log.txt 2>err.txt &
pid=$!
watchdog $pid

await '[ "$(pictures)" -ge 1 ]' || fail "no first picture"
grep -q "first picture of scene.json" log.txt || fail "the first picture's line does not name the scene"
above out.png 0 1 || fail "the first picture is not red (R $(mean out.png 0), G $(mean out.png 1))"
# One sample a pixel covers it or not; the refining pass's net covers the
# silhouette's pixels in part.
/usr/bin/python3 - <<'PY' || fail "the refined picture's silhouette is not anti-aliased"
import OpenImageIO as oiio, numpy
alpha = oiio.ImageBuf("out.exr").get_pixels(oiio.FLOAT)[:, :, 3]
spec = oiio.ImageBuf("out.exr").spec()
assert "watchPasses=2 watchSpp=4" in spec.get_string_attribute("facetRenderSettings"), spec.get_string_attribute("facetRenderSettings")
assert ((alpha > 0.01) & (alpha < 0.99)).sum() >= 8, ((alpha > 0.01) & (alpha < 0.99)).sum()
PY

material "0.02, 0.6, 0.02"
await '[ "$(pictures)" -ge 2 ]' || fail "no picture after the material changed"
above out.png 1 0 || fail "the material changed to green, the picture did not (R $(mean out.png 0), G $(mean out.png 1))"
grep -q "mat.json changed: .*geometry kept" log.txt || fail "a material change diced the geometry again"

cp out.png before.png
echo '{"preset": ' >mat.json
await 'grep -q "facet: error: .*mat.json: not valid JSON" err.txt' || fail "no error line for a broken material file"
await 'grep -q "not rendered; the outputs keep the last picture" log.txt' || fail "no line saying the picture is kept"
kill -0 $pid 2>/dev/null || fail "facet ended on a broken material file"
cmp -s out.png before.png || fail "a broken material file changed the picture"

material "0.02, 0.02, 0.6"
await '[ "$(pictures)" -ge 3 ]' || fail "no picture after the material file was fixed"
above out.png 2 0 || fail "the fixed material is blue, the picture is not (R $(mean out.png 0), B $(mean out.png 2))"

kill -TERM $pid
status=0
wait $pid || status=$?
pid=
[ $status -eq 0 ] || fail "SIGTERM: exit status $status, expected 0"
oiiotool out.png --printstats >/dev/null || fail "SIGTERM left an unreadable picture"
leftovers=$(ls -A | grep '\.tmp-' || true)
[ -z "$leftovers" ] || fail "temporaries left behind: $leftovers"

# --watch-limit 1: the first picture, one change, then it ends by itself.
"$facet" render scene.json --watch --watch-limit 1 --watch-passes 1 -o limit.exr --quiet >log.txt 2>err.txt &
pid=$!
watchdog $pid
await '[ -f limit.exr ]' || fail "--watch-limit: no first picture"
material "0.6, 0.6, 0.02"
status=0
wait $pid || status=$?
pid=
[ $status -eq 0 ] || fail "--watch-limit 1: exit status $status after one change, expected 0 (137: it did not end)"
[ ! -s log.txt ] || fail "--quiet printed: $(cat log.txt)"

# An output swapped for a symbolic link while the watch runs: the next write
# is refused (exit 2) and the link's target is kept.
"$facet" render scene.json --watch --watch-passes 1 -o link.png --quiet >log.txt 2>err.txt &
pid=$!
watchdog $pid
await '[ -f link.png ]' || fail "no first picture before the output became a link"
echo "not a picture" >target.txt
ln -sf target.txt link.png
material "0.3, 0.3, 0.6"
status=0
wait $pid || status=$?
pid=
[ $status -eq 2 ] || fail "an output swapped for a link: exit status $status, expected 2"
grep -q "facet: error: -o '.*link.png': .*symbolic link" err.txt || fail "an output swapped for a link: $(cat err.txt)"
[ "$(cat target.txt)" = "not a picture" ] || fail "the watch wrote through a symbolic link"

# Refusals, one line each.
refused() {
  local status=0
  "$facet" render scene.json -o refused.png "$@" 2>err.txt || status=$?
  [ $status -eq 1 ] || fail "$* exited $status, expected 1"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "$*: expected one error line"
}
refused --watch --frames 0-1
grep -q "facet: error: --watch: cannot be combined with --frames" err.txt || fail "--watch --frames: $(cat err.txt)"
refused --watch-limit 2
grep -q "facet: error: --watch-limit: needs --watch" err.txt || fail "--watch-limit alone: $(cat err.txt)"
# A scene that cannot be loaded at the start ends the command, as render does.
echo '{"objects": [{"mesh": "ball.obj", "material": "absent.json"}]}' >broken.json
status=0
timeout $((deadline - SECONDS)) "$facet" render broken.json --watch -o refused.png 2>err.txt || status=$?
[ $status -eq 1 ] || fail "--watch of a broken scene exited $status, expected 1"
grep -q "facet: error: .*absent.json" err.txt || fail "--watch of a broken scene: $(cat err.txt)"
[ ! -e refused.png ] || fail "a refused command wrote its output"
echo "check_watch: passed"
