#!/bin/sh
# Makes the Chromium reference renderings of colour glyphs (chromium/*.png, manifest.tsv) that
# tests/colour_golden_test.cpp compares bezel with. Run once after a deliberate change (a new
# glyph, a new cell geometry), from anywhere; review the pictures, commit them with the reason.
# Needs Debian's chromium and /usr/bin/python3 with fontTools and numpy (python3-fonttools,
# python3-numpy); the page and its steps are described in make_goldens.py.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
chromium=${CHROMIUM:-/usr/bin/chromium}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

version=$("$chromium" --version 2>/dev/null | sed 's/ built on.*//')
/usr/bin/python3 "$here/make_goldens.py" page "$work/page.html"
# Device pixel ratio 1 (a canvas pixel is a CSS pixel); software rendering, so that no GPU
# rasterizer's own anti-aliasing enters; the virtual time budget lets the page's asynchronous
# font loading finish before the DOM is dumped.
"$chromium" --headless --no-sandbox --disable-gpu --force-device-scale-factor=1 \
    --user-data-dir="$work/profile" --virtual-time-budget=60000 \
    --dump-dom "file://$work/page.html" >"$work/dom.html" 2>"$work/chromium.log" || {
    cat "$work/chromium.log" >&2
    exit 1
}
/usr/bin/python3 "$here/make_goldens.py" extract "$work/dom.html" "$version"
