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

# section REPORT PREFIX OUT: copies the part of a report the book discusses
# into its own file, which a page includes, so that no measured number is
# retyped. The part starts at the first line that begins with PREFIX and
# runs up to a blank line, a line indented no deeper than the first one, or
# the report's "wrote N files" list. tests/project/book_numbers.rs checks
# that every such file is a verbatim part of its report.
section() {
  awk -v t="$2" '
    !on && index($0, t) == 1 { on = 1; match($0, /^ */); ind = RLENGTH; print; next }
    on { match($0, /^ */); if ($0 == "" || RLENGTH <= ind || $0 ~ /^  wrote [0-9]+ files?:/) exit; print }
  ' "$1" > "$3"
  if [ ! -s "$3" ]; then
    echo "figures.sh: no part starting with '$2' in $1" >&2
    exit 1
  fi
}

# part REPORT FROM UPTO OUT: copies the lines of a report from the first
# that begins with FROM up to, not including, the next that begins with
# UPTO (to the end when UPTO is empty), for a listing too long to show
# whole: a page shows it in parts, each a verbatim run of the report.
part() {
  awk -v f="$2" -v u="$3" '
    !on && index($0, f) == 1 { on = 1; print; next }
    on && u != "" && index($0, u) == 1 { exit }
    on { print }
  ' "$1" > "$4"
  if [ ! -s "$4" ]; then
    echo "figures.sh: no part starting with '$2' in $1" >&2
    exit 1
  fi
}

# blocks_to_table IN OUT: a report table printed one block per row (too
# wide for one line, "  - first: value" then "      column: value" lines)
# as a Markdown table, for a page to include outside a code block.
blocks_to_table() {
  awk '
    function flush() { if (n) { line = "|"; for (i = 1; i <= n; i++) line = line " " val[i] " |"; rows[++r] = line } n = 0 }
    /^  - / { flush(); started = 1; sub(/^  - /, "") }
    /^      [^ ]/ { sub(/^ +/, "") }
    started && /^[^ ]/ && /: / {
      k = substr($0, 1, index($0, ": ") - 1); v = substr($0, index($0, ": ") + 2)
      n++; val[n] = v
      if (!r) { head[n] = k; cols = n }
    }
    END {
      flush()
      line = "|"; sep = "|"
      for (i = 1; i <= cols; i++) { line = line " " head[i] " |"; sep = sep "---|" }
      print line; print sep
      for (j = 1; j <= r; j++) print rows[j]
    }
  ' "$1" > "$2"
}

# The diagrams (SVG), drawn from the functions that compute each idea, and
# the wrong pictures (a plausible bug's render beside the right one).
"$bin/diagrams" --out "$out" > /dev/null
"$bin/diagrams" --wrong --out "$out" > /dev/null

# Chapter 1: wireframes, depth and points of every shipped scene; the
# precision study and stiff cases of the tetrahedron (CSV and report).
for scene in tetrahedron railroad bunny cornell-box; do
  "$bin/ch1" --scene "scenes/$scene.toml" --out "$out" > /dev/null
done
"$bin/ch1" --scene scenes/tetrahedron.toml --report --out "$out" > "$out/ch1-tetrahedron-report.txt"
section "$out/ch1-tetrahedron-report.txt" "Error against run time" "$out/ch1-error-time.txt"
part "$out/ch1-tetrahedron-report.txt" "Stiff and extreme cases" "  - case: edge with NaN ends" "$out/ch1-stiff-1.txt"
part "$out/ch1-tetrahedron-report.txt" "  - case: edge with NaN ends" "  wrote " "$out/ch1-stiff-2.txt"

# Chapter 2: every view of the tetrahedron, the interpenetrating scene and
# the Cornell box at 16 samples per pixel; the anti-aliasing study, stiff
# cases and the checkered floor, affine against perspective-correct (CSV,
# the report's text and ch2-checker-floor*.png).
for scene in tetrahedron interpenetrating cornell-box; do
  "$bin/ch2" --scene "scenes/$scene.toml" --spp 16 --out "$out" > /dev/null
done
"$bin/ch2" --scene scenes/tetrahedron.toml --spp 16 --report --out "$out" > "$out/ch2-tetrahedron-report.txt"
section "$out/ch2-tetrahedron-report.txt" "  checker floor:" "$out/ch2-checker.txt"
section "$out/ch2-tetrahedron-report.txt" "Error against run time" "$out/ch2-error-time.txt"

# Chapter 3: every view of the bunny at 16 samples per pixel, with the
# report (naive loop against BVH, leaks, the three tests, error against
# time, stiff cases).
"$bin/ch3" --scene scenes/bunny.toml --spp 16 --report --out "$out" > "$out/ch3-bunny-report.txt"
section "$out/ch3-bunny-report.txt" "The three ray-triangle tests" "$out/ch3-three-tests.txt"
section "$out/ch3-bunny-report.txt" "Leaks:" "$out/ch3-leaks.txt"
section "$out/ch3-bunny-report.txt" "Naive loop against BVH" "$out/ch3-naive-bvh.txt"
section "$out/ch3-bunny-report.txt" "Relative error of t" "$out/ch3-t-error.txt"
# The appendix's benchmark (Mrays/s of the stage, its variants and obvhs
# alone; about a minute), as printed and as a table.
"$bin/ch3" --bench > "$out/ch3-bench.txt"
blocks_to_table "$out/ch3-bench.txt" "$out/ch3-bench.md"

# Chapter 4: every view of the SDF shapes with the report (error against
# time, stiff cases); the Lipschitz scene with holes, then fixed.
"$bin/ch4" --scene scenes/sdf-shapes.toml --report --out "$out" > "$out/ch4-sdf-shapes-report.txt"
section "$out/ch4-sdf-shapes-report.txt" "Error against run time" "$out/ch4-error-time.txt"
section "$out/ch4-sdf-shapes-report.txt" "Stiff and extreme cases" "$out/ch4-stiff.txt"
part "$out/ch4-error-time.txt" "Error against run time" "  sphere tracing, budget" "$out/ch4-error-eps.txt"
part "$out/ch4-error-time.txt" "  sphere tracing, budget" "" "$out/ch4-error-budget.txt"
part "$out/ch4-stiff.txt" "Stiff and extreme cases" "  - case: sphere 1e5" "$out/ch4-stiff-1.txt"
part "$out/ch4-stiff.txt" "  - case: sphere 1e5" "" "$out/ch4-stiff-2.txt"
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
section "$out/ch6-cornell-box-report.txt" "Strategies:" "$out/ch6-strategies.txt"
section "$out/ch6-cornell-box-report.txt" "Stiff and extreme cases" "$out/ch6-stiff.txt"
# The appendix's benchmark: the path tracer's speed and error at 256x256,
# 64 spp (the default roulette, roulette from the third scattering, and
# roulette's two scales).
"$bin/ch6" --bench --threads 2 > "$out/ch6-bench.txt"
"$bin/ch6" --bench --threads 2 --rr-after 3 > "$out/ch6-bench-rr-after-3.txt"
# Roulette's scale, 1 and 2, for both samplers (each sampler's default is one of them).
"$bin/ch6" --bench --threads 2 --rr-scale 1 > "$out/ch6-bench-rr-scale-1.txt"
"$bin/ch6" --bench --threads 2 --rr-scale 2 > "$out/ch6-bench-rr-scale-2.txt"
# Both engines on three scene sizes (the appendix's fast-engine section).
"$bin/ch6" --bench-scenes --threads 2 > "$out/ch6-bench-scenes.txt"
# The benchmark on the glass-ball box (its stored reference), where the
# fast engine runs the lesson's path loop.
"$bin/ch6" --bench --threads 2 --scene scenes/cornell-glassball.toml > "$out/ch6-bench-glass.txt"

# The main program's headless summary (running.md), run where its images
# land in a scratch folder so the listing shows the plain `out/` paths.
tmp=$(mktemp -d)
(cd "$tmp" && "$bin/raystep" --headless) > "$out/headless.txt"
rm -rf "$tmp"
