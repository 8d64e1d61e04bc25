#!/usr/bin/env bash
# The appendix's comparison with Mitsuba 3 (book/src/making-it-fast.md):
# runs the peer harness's side-by-side script with each renderer's default
# roulette, then with raystep's roulette from the fifth scattering, and
# writes both tables into book/src/figures. Needs the peer renderer
# (../shared/peers/mitsuba/setup.sh, once) and a machine with nothing else
# running; not part of figures.sh, and never run by CI.
# Usage: bash book/side-by-side.sh [ROUNDS]   (from anywhere; a few minutes)
set -euo pipefail
cd "$(dirname "$0")/.."
peer=${PEER_SCRIPTS:-../shared/peers/mitsuba}
[ -x "$peer/side-by-side.sh" ] || { echo "side-by-side.sh: no peer harness at $peer (set PEER_SCRIPTS)" >&2; exit 2; }
rounds=${1:-3}
cargo build --release --bin ch6
out=book/src/figures
# run FILE [FLAGS]: one side-by-side run, its table into FILE (only when
# the run finished: a failed one leaves the old table).
run() {
  local file=$1; shift
  local tmp; tmp=$(mktemp)
  { echo "\$ side-by-side.sh $rounds $*"; "$peer/side-by-side.sh" "$rounds" "$@"; } > "$tmp"
  grep -q "efficiency ratio" "$tmp" || { cat "$tmp" >&2; rm -f "$tmp"; exit 1; }
  mv "$tmp" "$file"
}
run "$out/side-by-side.txt"
run "$out/side-by-side-rr-after-5.txt" --rr-after 5
