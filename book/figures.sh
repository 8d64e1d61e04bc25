#!/usr/bin/env bash
# Regenerates every figure and table of the book, all six chapters, from the
# chapter binaries. tests/project/figures.rs checks that every image the book
# shows is in book/src/figures and is made by a line of this script.
# Usage: bash book/figures.sh   (from anywhere; several minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
out=book/src/figures
cargo build --release --bins
bin=$(cd "${CARGO_TARGET_DIR:-target}/release" && pwd)

# Chapter 1: wireframes, depth and points of every shipped scene; the
# precision study and stiff cases of the tetrahedron (CSV and report).
for scene in tetrahedron railroad bunny cornell-box; do
  "$bin/ch1" --scene "scenes/$scene.toml" --out "$out" > /dev/null
done
"$bin/ch1" --scene scenes/tetrahedron.toml --report --out "$out" > "$out/ch1-tetrahedron-report.txt"

# Chapter 2: every view of the tetrahedron, the interpenetrating scene and
# the Cornell box at 16 samples per pixel; the anti-aliasing study, stiff
# cases and the checkered floor, affine against perspective-correct (CSV,
# the report's text and ch2-checker-floor*.png).
for scene in tetrahedron interpenetrating cornell-box; do
  "$bin/ch2" --scene "scenes/$scene.toml" --spp 16 --out "$out" > /dev/null
done
"$bin/ch2" --scene scenes/tetrahedron.toml --spp 16 --report --out "$out" > "$out/ch2-tetrahedron-report.txt"

# Chapter 3: every view of the bunny at 16 samples per pixel, with the
# report (naive loop against BVH, leaks, the three tests, error against
# time, stiff cases).
"$bin/ch3" --scene scenes/bunny.toml --spp 16 --report --out "$out" > "$out/ch3-bunny-report.txt"

# Chapter 4: every view of the SDF shapes with the report (error against
# time, stiff cases); the Lipschitz scene with holes, then fixed.
"$bin/ch4" --scene scenes/sdf-shapes.toml --report --out "$out" > "$out/ch4-sdf-shapes-report.txt"
"$bin/ch4" --scene scenes/sdf-lipschitz.toml --out "$out" > /dev/null
"$bin/ch4" --scene scenes/sdf-lipschitz.toml --step-factor 0.1 --max-steps 2048 --max-distance 20 --out "$out/ch4-lipschitz-fixed" > /dev/null

# Chapter 5: the lights gallery, the BRDF row, the Cornell box (direct light
# only), the SDFs lit, and the Lambertian sphere with the strategy study
# (its two error-against-time plots).
"$bin/ch5" --scene scenes/lights-gallery.toml --spp 64 --out "$out" > /dev/null
"$bin/ch5" --scene scenes/brdf-row.toml --spp 64 --out "$out" > /dev/null
"$bin/ch5" --scene scenes/cornell-box.toml --spp 32 --out "$out" > /dev/null
"$bin/ch5" --scene scenes/sdf-lit.toml --spp 8 --out "$out" > /dev/null
"$bin/ch5" --scene scenes/lambert-sphere.toml --spp 16 --report --out "$out" > "$out/ch5-lambert-sphere-report.txt"

# Chapter 6: the Cornell box at 128 spp (final image, noise image, bounce
# strip), the spp strip, and the strategy study (table and plots).
"$bin/ch6" --scene scenes/cornell-box.toml --spp 128 --spp-figure 128 --report --threads 2 --out "$out" > "$out/ch6-cornell-box-report.txt"

# The main program's headless summary (running.md), run where its images
# land in a scratch folder so the listing shows the plain `out/` paths.
tmp=$(mktemp -d)
(cd "$tmp" && "$bin/raystep" --headless) > "$out/headless.txt"
rm -rf "$tmp"
