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
