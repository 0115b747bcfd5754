#!/bin/bash
# facet preview end to end at 32x32 per cell, on the CPU backend except
# where sampled lighting makes the reference slow (the GPU's adaptive rounds
# decide the same way):
#   - the contact sheet's size, and each render's reported tile errors below
#     the threshold unless it says a cap stopped it;
#   - a noisier lighting method takes more samples than a smoother one;
#   - --env lights the model by the map it names;
#   - the ground (on by default; the other checks turn it off) darkens the
#     background right under the ball and leaves the ball and the backdrop
#     above it as --no-ground renders them;
#   - one error line for each bad adaptive flag;
#   - --movie: without ffmpeg on PATH, or with a TMPDIR that cannot hold the
#     frames, one error naming it and exit code 2,
#     nothing written; with a fake ffmpeg that records its arguments, the
#     frames in order, each the picture alone, a quoted name written as
#     given; a failing ffmpeg leaves no movie; a hung one is ended at the
#     time limit, and SIGTERM to facet ends it too, nothing left behind.
#   check_preview_stage.sh FACET REPOSITORY WORK_FOLDER
set -euo pipefail
facet=$1 repo=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "check_preview_stage: FAILED: $*" >&2; exit 1; }
library=$repo/scenes/examples/materials
# Every render here: the longest --time-limit the flag takes, a day, which no
# render here comes near, so how busy the machine is cannot change its rounds.
preview() { "$facet" preview --time-limit 86400 "$@"; }
common=(--size 32x32 --backend cpu --no-ground)

# The sheet: two cells side by side, labelled; every render's verdict checked.
preview gold "$library/red_plastic.json" "${common[@]}" --noise-threshold 0.03 --json -o sheet.png >sheet.json
/usr/bin/python3 - sheet.json sheet.png <<'PY' || fail "the sheet's report or size"
import json, struct, sys
report = json.load(open(sys.argv[1]))
png = open(sys.argv[2], "rb").read()
width, height = struct.unpack(">II", png[16:24])
assert (width, height) == (report["width"], report["height"]), (width, height)
assert width > 2 * 32 and height > 32, "two 32x32 cells and their label strips"
assert [r["material"] for r in report["renders"]] == ["gold", "red_plastic"]
for r in report["renders"]:
    assert r["stop"] in ("converged", "sample cap", "time limit"), r["stop"]
    if r["stop"] == "converged":
        assert max(r["tile_errors"]) <= r["noise_threshold"], r
    assert r["spp_max"] <= 256
PY

# A noisier estimator of the same picture takes more samples.
samples() { /usr/bin/python3 -c 'import json,sys; print(sum(r["samples"] for r in json.load(open(sys.argv[1]))["renders"]))' "$1"; }
on_gpu=(--size 32x32 --backend gpu --no-ground)
preview gold "${on_gpu[@]}" --noise-threshold 0.02 --json -o smooth.png >smooth.json
preview gold "${on_gpu[@]}" --noise-threshold 0.02 --ibl sampled --json -o noisy.png >noisy.json
[ "$(samples noisy.json)" -gt "$(samples smooth.json)" ] ||
  fail "sampled lighting took $(samples noisy.json) samples, prefiltered $(samples smooth.json)"

# A cap that stops it is said.
preview gold "${on_gpu[@]}" --ibl sampled --noise-threshold 0.0001 --max-spp 8 -o capped.png >capped.txt
grep -q "sample cap" capped.txt || fail "a render stopped by --max-spp does not say so: $(cat capped.txt)"

# --env lights the model by a map instead of the studio: the cell is nearer
# to `facet render --env` of the same map than to the studio's preview.
map=$repo/scenes/environments/studio.exr
preview gold "${on_gpu[@]}" --max-spp 16 --env "$map" --env-rotation 90 -o mapped.png --quiet
preview gold "${on_gpu[@]}" --max-spp 16 -o studio.png --quiet
"$facet" render "$repo/scenes/examples/superball.obj" --material gold --size 32x32 --spp 16 --env "$map" \
  --env-rotation 90 -o rendered.png --quiet
/usr/bin/python3 - <<'PY' || fail "--env does not light the preview"
import OpenImageIO as oiio, numpy as np
def pixels(path):
    return oiio.ImageInput.open(path).read_image(format="float")[..., :3]
rendered = pixels("rendered.png")
mapped, studio = (float(np.abs(pixels(p)[2:34, 2:34] - rendered).mean()) for p in ("mapped.png", "studio.png"))
assert mapped < 0.5 * studio, (mapped, studio)
PY

# The ground: two rounds for every tile either way, so the same samples.
ground=(gold --size 32x32 --backend gpu --max-spp 8 --noise-threshold 0.0001 --json)
preview "${ground[@]}" -o ground.png >ground.json
preview "${ground[@]}" --no-ground -o bare.png >bare.json
/usr/bin/python3 - <<'PY' || fail "the ground's shadow"
import json, OpenImageIO as oiio, numpy as np
assert json.load(open("ground.json"))["ground"] is True
assert json.load(open("bare.json"))["ground"] is False
for name in ("ground.json", "bare.json"):
    assert [r["stop"] for r in json.load(open(name))["renders"]] == ["sample cap"], name
def cell(path):  # the first cell, linear display values
    v = oiio.ImageInput.open(path).read_image(format="float")[:32, :32, :3]
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)
ground, bare = cell("ground.png"), cell("bare.png")
gold = bare[..., 0] - bare[..., 2] > 0.1  # the ball, its silhouette's partial pixels too
rows = np.nonzero(gold[:, 16])[0]
low = rows.max()
assert low < 30, low
luminance = lambda v: v @ np.array([0.2126, 0.7152, 0.0722])
under = luminance(ground[low + 2 : low + 4, 15:18]).mean() / luminance(bare[low + 2 : low + 4, 15:18]).mean()
assert under < 0.7, f"under the ball: {under} of the background"
inner = gold & np.roll(gold, 1, 0) & np.roll(gold, -1, 0) & np.roll(gold, 1, 1) & np.roll(gold, -1, 1)
assert np.array_equal(ground[inner], bare[inner]), "the ball's own pixels changed"
assert np.array_equal(ground[:4], bare[:4]), "the backdrop above the ball changed"
PY

# Bad values: one line each, exit code 1, no sheet.
bad() {
  local expected=$1
  shift
  set +e
  "$facet" preview gold --size 32x32 --backend cpu -o bad.png "$@" >out.txt 2>err.txt
  local code=$?
  set -e
  [ "$code" = 1 ] || fail "$*: exit code $code"
  [ "$(wc -l <err.txt)" = 1 ] || fail "$*: not one line: $(cat err.txt)"
  grep -q "^facet: error: $expected" err.txt || fail "$*: $(cat err.txt)"
  [ ! -e bad.png ] || fail "$*: a sheet was written"
}
bad "--noise-threshold '0': expected a number in (0, 1]" --noise-threshold 0
bad "--noise-threshold '2': expected a number in (0, 1]" --noise-threshold 2
bad "--max-spp '4': expected a whole number" --max-spp 4
bad "--time-limit '-1': expected a number of seconds" --time-limit -1
bad "--time-limit" --time-limit nan
bad "--movie 'turn.mov': the extension chooses the format" --turntable 2 --movie turn.mov
bad "material 'nosuch': preset: unknown preset 'nosuch'" nosuch
bad "--env: File does not exist: nosuch.exr" --env nosuch.exr

# No ffmpeg on PATH: one line naming it and how to install it, exit code 2, nothing written.
set +e
PATH=/nonexistent preview gold "${common[@]}" --turntable 2 --movie turn.mp4 >out.txt 2>err.txt
code=$?
set -e
[ "$code" = 2 ] || fail "no ffmpeg: exit code $code: $(cat err.txt)"
[ "$(wc -l <err.txt)" = 1 ] || fail "no ffmpeg: not one line: $(cat err.txt)"
grep -q "^facet: error: --movie 'turn.mp4': ffmpeg is not on PATH; install it (Debian: apt-get install ffmpeg)$" err.txt ||
  fail "no ffmpeg: $(cat err.txt)"
[ ! -e turn.mp4 ] || fail "no ffmpeg: a movie was written"

# A fake ffmpeg: records its arguments, copies the frames in the order its
# pattern numbers them, writes its output; `fail` as $FAKE_FFMPEG fails.
mkdir -p bin recorded
cat >bin/ffmpeg <<'SH'
#!/bin/bash
if [ "${FAKE_FFMPEG:-}" = hang ]; then
  echo $$ >"$RECORD/hung.pid"
  [ ! -p "$RECORD/started" ] || echo started >"$RECORD/started"
  exec tail -f /dev/null  # never returns
fi
printf '%s\n' "$@" >"$RECORD/args.txt"
pattern= frames= previous=
for a in "$@"; do
  [ "$previous" = -i ] && pattern=$a
  [ "$previous" = -frames:v ] && frames=$a
  previous=$a
done
for ((i = 0; i < frames; i++)); do cp "$(printf "$pattern" "$i")" "$RECORD/$i.png" || exit 9; done
echo "movie of $frames frames" >"$a"
[ "${FAKE_FFMPEG:-}" != fail ] || exit 3
SH
chmod +x bin/ffmpeg
export RECORD=$work/recorded
movie="it's \"quoted\" \$(touch injected).gif"
PATH=$work/bin:$PATH preview gold "${common[@]}" --turntable 4 --turn environment --movie "$movie" --quiet
[ -f "$movie" ] || fail "the fake ffmpeg's movie is not at the name given"
[ ! -e injected ] || fail "a file name ran a command"
grep -qx -- "-frames:v" recorded/args.txt || fail "no -frames:v in $(cat recorded/args.txt)"
[ "$(ls recorded/*.png | wc -l)" = 4 ] || fail "ffmpeg was handed $(ls recorded/*.png | wc -l) frames, not 4"
# Frame k handed over is frame k, the picture alone (one material: no
# border, no label): each is nearest to `facet render --turntable 4 --frame k`
# of the same ball, material and turn. The ball has the symmetry of a quarter
# turn, so its environment turns.
for k in 0 1 2 3; do
  "$facet" render "$repo/scenes/examples/superball.obj" --material gold --size 32x32 --backend cpu --spp 16 \
    --turntable 4 --turn environment --frame "$k" -o "turn_$k.png" --quiet
done
/usr/bin/python3 - <<'PY' || fail "the frames reached ffmpeg out of order"
import OpenImageIO as oiio, numpy as np
def pixels(path):
    return oiio.ImageInput.open(path).read_image(format="float")[..., :3]
rendered = [pixels(f"turn_{k}.png") for k in range(4)]
for i in range(4):
    cell = pixels(f"recorded/{i}.png")
    assert cell.shape[:2] == (32, 32), cell.shape
    differences = [float(np.abs(cell - r).mean()) for r in rendered]
    assert int(np.argmin(differences)) == i, (i, differences)
PY
# An unusable TMPDIR for the frames: one error naming it, exit code 2, no movie.
set +e
TMPDIR=$work/no_such_folder PATH=$work/bin:$PATH preview gold "${common[@]}" --turntable 2 --movie tmpdir.mp4 \
  --quiet >out.txt 2>err.txt
code=$?
set -e
[ "$code" = 2 ] || fail "a bad TMPDIR: exit code $code: $(cat err.txt)"
[ "$(wc -l <err.txt)" = 1 ] || fail "a bad TMPDIR: not one line: $(cat err.txt)"
grep -qF "facet: error: --movie: cannot make a folder for the turntable's frames in the temporary folder \
'$work/no_such_folder' (TMPDIR): no such folder; set TMPDIR to a writable folder" err.txt ||
  fail "a bad TMPDIR: $(cat err.txt)"
[ ! -e tmpdir.mp4 ] || fail "a bad TMPDIR: a movie was written"
# ffmpeg fails: one error line, exit code 2, no movie and no temporary left.
set +e
FAKE_FFMPEG=fail PATH=$work/bin:$PATH preview gold "${common[@]}" --turntable 2 --movie failed.mp4 \
  --quiet >out.txt 2>err.txt
code=$?
set -e
[ "$code" = 2 ] || fail "a failing ffmpeg: exit code $code: $(cat err.txt)"
grep -q "^facet: error: --movie 'failed.mp4': .*ffmpeg exited with status 3$" err.txt || fail "$(cat err.txt)"
[ ! -e failed.mp4 ] || fail "a failing ffmpeg left a movie"
! ls failed.mp4.tmp-* >/dev/null 2>&1 || fail "a failing ffmpeg left a temporary"

# An ffmpeg that never returns: ended at the time limit, one error line, exit
# code 2, no movie, no frames and no ffmpeg left behind.
mkdir -p tmp
set +e
FAKE_FFMPEG=hang FACET_CHILD_TIME_LIMIT=1 TMPDIR=$work/tmp PATH=$work/bin:$PATH preview gold "${common[@]}" \
  --turntable 2 --movie hung.mp4 --quiet >out.txt 2>err.txt
code=$?
set -e
[ "$code" = 2 ] || fail "a hung ffmpeg: exit code $code: $(cat err.txt)"
grep -q "^facet: error: --movie 'hung.mp4': .*ffmpeg did not finish within 1 s, and was ended$" err.txt ||
  fail "a hung ffmpeg: $(cat err.txt)"
! kill -0 "$(cat recorded/hung.pid)" 2>/dev/null || fail "a hung ffmpeg was left running"
[ ! -e hung.mp4 ] && [ -z "$(ls tmp)" ] || fail "a hung ffmpeg left a movie or frames: $(ls tmp)"

# SIGTERM to facet while ffmpeg runs: passed on to ffmpeg, the frames removed,
# and facet ends by the signal (exit status 128 + 15).
rm -f recorded/hung.pid
mkfifo recorded/started
exec 3<>recorded/started  # opened both ways, so that neither side waits to open it
FAKE_FFMPEG=hang TMPDIR=$work/tmp PATH=$work/bin:$PATH "$facet" preview --time-limit 86400 gold "${common[@]}" \
  --turntable 2 --movie killed.mp4 --quiet >out.txt 2>err.txt &
facet_pid=$!
read -r -t 600 _ <&3 || fail "the fake ffmpeg never started: $(cat err.txt)"
kill -TERM "$facet_pid"
set +e
wait "$facet_pid"
code=$?
set -e
[ "$code" = 143 ] || fail "SIGTERM during ffmpeg: exit status $code: $(cat err.txt)"
grep -q "^facet: error: Terminated while .*ffmpeg ran: it was ended$" err.txt || fail "SIGTERM: $(cat err.txt)"
! kill -0 "$(cat recorded/hung.pid)" 2>/dev/null || fail "SIGTERM left ffmpeg running"
[ ! -e killed.mp4 ] && [ -z "$(ls tmp)" ] || fail "SIGTERM left a movie or frames: $(ls tmp)"
echo "check_preview_stage: ok"
