#!/usr/bin/env bash
# One entry point for the README's two commands:
#   tools/setup.sh main   install what is missing, build, render the default scene
#   tools/setup.sh test   install what is missing, build, run every test
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="${FACET_BUILD_DIR:-$here/build}"
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
  test) ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)" ;;
esac
