#!/usr/bin/env bash
# Regenerates the book's comparison with Mitsuba 3 (the page "Against
# Mitsuba 3"): the peer harness's tables, one file each, in
# book/src/figures/sbs-*.txt. Not part of figures.sh and never run by CI:
# it needs Mitsuba (../shared/peers/mitsuba/setup.sh, once) and a quiet
# machine, since the harness times both renderers in turn and only the
# ratios of one interleaved run count. About ten minutes on 2 cores (plus
# Mitsuba's references the first time: 6 to 8 minutes per scene).
# Usage: bash book/side-by-side.sh [ROUNDS]   (default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
out=book/src/figures
rounds=${1:-3}
harness=${PEER_HARNESS:-../shared/peers/mitsuba/side-by-side.sh}
if [ ! -x "$harness" ] && [ ! -f "$harness" ]; then
  echo "side-by-side.sh: no peer harness at $harness (set PEER_HARNESS)" >&2
  exit 2
fi
cargo build --release --bin ch6

# run OUT [ENV=VALUE ...] -- [ch6 --bench flags]: one comparison into OUT,
# which must end with the harness's two ratios.
run() {
  local file=$1
  shift
  local env=()
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    env+=("$1")
    shift
  done
  shift
  env "${env[@]}" bash "$harness" "$rounds" "$@" > "$file.tmp"
  if ! grep -q '^efficiency ratio' "$file.tmp"; then
    echo "side-by-side.sh: the harness printed no ratios for $file:" >&2
    cat "$file.tmp" >&2
    rm -f "$file.tmp"
    exit 1
  fi
  mv "$file.tmp" "$file"
}

# The Cornell box: the default roulette, Mitsuba's (from the fifth
# scattering), the portable vectors (what an aarch64 laptop runs, here
# with SSE2) and AVX2's, which the portable path is measured against; then
# the glass-ball box, where the glass ball's vertices run the lesson's
# steps inside the wavefront.
run "$out/sbs-cornell.txt" PEER_SCENE=cornell --
run "$out/sbs-cornell-rr5.txt" PEER_SCENE=cornell -- --rr-after 5
run "$out/sbs-cornell-portable.txt" PEER_SCENE=cornell RAYSTEP_SIMD=portable --
run "$out/sbs-cornell-avx2.txt" PEER_SCENE=cornell RAYSTEP_SIMD=avx2 --
run "$out/sbs-glass.txt" PEER_SCENE=glass --

# How many samples per pixel each of Mitsuba's samplers draws when the
# harness asks for 64 (its orthogonal sampler takes the square of a prime),
# as Mitsuba itself reports it: built as the harness builds it, then given
# the count as `mi.render(..., spp=64)` gives it.
py=${PEER_DIR:-target/peer}/.venv/bin/python
"$py" - > "$out/sbs-samplers.txt.tmp" <<'PY'
import mitsuba as mi
mi.set_variant("llvm_ad_rgb")
mi.set_log_level(mi.LogLevel.Error)
print("samples per pixel Mitsuba 3 draws when asked for 64")
for name in ("independent", "multijitter", "orthogonal"):
    sampler = mi.load_dict({"type": name, "sample_count": 64})
    sampler.set_sample_count(64)
    print(f"{name:<12}  {sampler.sample_count()}")
PY
mv "$out/sbs-samplers.txt.tmp" "$out/sbs-samplers.txt"
