#!/usr/bin/env bash
# Regenerates every figure of the book from the chapter binaries.
# Usage: bash book/figures.sh   (from anywhere; takes a few minutes)
set -euo pipefail
cd "$(dirname "$0")/.."
out=book/src/figures
cargo build --release --bins

# Chapter 1: wireframes, depth and points of every shipped scene; the
# precision study and stiff cases of the tetrahedron (CSV).
for scene in tetrahedron railroad bunny cornell-box; do
  target/release/ch1 --scene "scenes/$scene.toml" --out "$out" > /dev/null
done
target/release/ch1 --scene scenes/tetrahedron.toml --report --out "$out" > "$out/ch1-tetrahedron-report.txt"

# Chapter 2: every view of the tetrahedron and the interpenetrating scene at
# 16 samples per pixel; the anti-aliasing study and stiff cases (CSV and
# the report's text).
for scene in tetrahedron interpenetrating; do
  target/release/ch2 --scene "scenes/$scene.toml" --spp 16 --out "$out" > /dev/null
done
target/release/ch2 --scene scenes/tetrahedron.toml --spp 16 --report --out "$out" > "$out/ch2-tetrahedron-report.txt"

# Chapter 4: every view of the SDF shapes with the report (error against
# time, stiff cases); the Lipschitz scene with holes, then fixed.
target/release/ch4 --scene scenes/sdf-shapes.toml --report --out "$out" > "$out/ch4-sdf-shapes-report.txt"
target/release/ch4 --scene scenes/sdf-lipschitz.toml --out "$out" > /dev/null
target/release/ch4 --scene scenes/sdf-lipschitz.toml --step-factor 0.1 --max-steps 2048 --max-distance 20 --out "$out/ch4-lipschitz-fixed" > /dev/null
