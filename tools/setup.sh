#!/usr/bin/env bash
# One entry point for the README's two commands:
#   tools/setup.sh main   install what is missing, build, render the default scene
#   tools/setup.sh test   install what is missing, build, run every test; then
#                         the same suite built with clang under ASan + UBSan, and
#                         a short run of each fuzz harness (docs/reliability.md)
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${FACET_BUILD_DIR:-$here/build}"
sanitized="${FACET_SANITIZE_BUILD_DIR:-$here/build-sanitize}"
mode="${1:-}"

case "$mode" in
  main|test) ;;
  *) echo "usage: tools/setup.sh main|test" >&2; exit 2 ;;
esac

mapfile -t wanted < <(grep -v '^#' "$here/tools/packages.txt" | grep .)
missing=()
for pkg in "${wanted[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' || missing+=("$pkg")
done
if ((${#missing[@]})); then
  if [[ $(id -u) -ne 0 ]]; then
    echo "facet: these Debian packages are missing and installing them needs root:" >&2
    echo "  sudo apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
  echo "facet: installing ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" --parallel "$(nproc)"

case "$mode" in
  main)
    "$build/facet" info
    "$build/facet" render "$here/scenes/examples/preview.json" -o "$build/preview.exr" --png "$build/preview.png"
    ;;
  test)
    ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)"
    # Any sanitizer report is fatal; leaks of the Vulkan driver stack are
    # suppressed, facet's own are not. The build runs test binaries too
    # (test discovery), so the settings hold from here on.
    export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1
    export LSAN_OPTIONS="suppressions=$here/tools/sanitizers/lsan.supp:print_suppressions=0"
    export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
    # No Python module here: the interpreter is not instrumented, and ASan
    # must be the first library of a process.
    cmake -S "$here" -B "$sanitized" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
      -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only -DNDEBUG" \
      -DFACET_SANITIZE=ON -DFACET_FUZZ=ON -DFACET_BUILD_BENCHMARKS=OFF -DFACET_BUILD_PYTHON=OFF
    cmake --build "$sanitized" --parallel "$(nproc)"
    # LeakSanitizer scans the memory of loaded libraries only, and the Vulkan
    # loader unloads lavapipe when an instance ends: what lavapipe's globals
    # still held would read as leaked, so it stays loaded in every test.
    lavapipe=$(sed -n 's/.*"library_path": *"\(.*\)".*/\1/p' /usr/share/vulkan/icd.d/lvp_icd.*.json)
    LD_PRELOAD="$lavapipe" ctest --test-dir "$sanitized" --output-on-failure --parallel "$(nproc)"
    bash "$here/fuzz/run.sh" "$sanitized" -max_total_time=30
    ;;
esac
