#!/usr/bin/env bash
# sixel-screens.sh: screenshots of the terminal UI's views in a real sixel
# terminal (xterm as a VT340) on a virtual X server, for issue notes and
# the book. A manual tool: CI does not run it.
#
# What it does: starts Xvfb on a free display, then, once per scenario,
# an xterm in VT340 mode (sixel graphics, 256 colour registers) running
# the UI, waits for the render, types keys and drags the mouse with
# xdotool, and saves a PNG of the xterm window after each step, with the
# screen's text beside it (NN-name.png, NN-name.txt) and one line per shot
# in OUTDIR/index.md. It waits on the screen's text (xterm's
# print-immediate, bound to F12 here), not on fixed sleeps, so a slow
# machine only makes it slower. A shot whose text shows half blocks (▀▄)
# instead of a sixel picture is flagged with a warning.
#
# sixelScrolling must stay true: false is DEC's sixel display mode, in
# which xterm draws every picture at the screen's top left corner.
#
# Needs (Debian): xvfb xterm xdotool imagemagick x11-utils
# fonts-dejavu-core; a release binary (cargo build --release).
#
# Run from the repository root (the UI finds scenes/ there):
#   tests/tui/sixel-screens.sh [BINARY] [OUTDIR]
# defaults target/release/raystep and target/screens. The environment can
# set:
#   ONLY=regex      run only the scenarios whose name matches (see `main`)
#   KEEP=1          keep OUTDIR's old PNGs (by default they are removed)
#   GRAPHICS=auto   the --graphics flag (auto: the UI asks xterm, which
#                   says sixel; `sixel` forces it)
#   GEOMETRY=160x48 FONT_SIZE=12   the terminal's size in cells and font
#   SLOW=1          multiplies every wait's time-out (2 on a busy machine)
#   SHOT_DISPLAY=99 the X display to use (default: the first free from 99)
#
# The UI runs with a fresh RAYSTEP_CONFIG_DIR and `--out` in a temporary
# folder, so out/ and the remembered chapter are left alone. The mouse
# drags are in cells of the default 160x48 layout.
#
# A new view is one line in a scenario: `keys ...` (xdotool key names,
# e.g. r, bracketright, shift+l, Escape) or `typed 'rr'`, then `settle` or
# `wait_for REGEX` (a regex on the screen's text), then
# `shoot NAME "what it shows"`; for instance
#   keys r && wait_for 'compare: z' 5 && settle && shoot ch6-z "the z view"
# `shoot -o` for a view under an overlay, which the UI draws in half
# blocks on purpose (the help, the warp test). A new scenario is a
# function starting with `launch ARGS...`, named in `main`'s list.

set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)

abs() { case $1 in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$PWD/$1" ;; esac; }
BIN=$(abs "${1:-target/release/raystep}")
OUT=$(abs "${2:-target/screens}")
# Defaults are relative to the repository root, whatever the cwd.
[[ $# -ge 1 ]] || BIN=$root/target/release/raystep
[[ $# -ge 2 ]] || OUT=$root/target/screens

ONLY=${ONLY:-.}
GRAPHICS=${GRAPHICS:-auto}
GEOMETRY=${GEOMETRY:-160x48}
FONT_SIZE=${FONT_SIZE:-12}
SLOW=${SLOW:-1}
COLS=${GEOMETRY%x*}
ROWS=${GEOMETRY#*x}

for tool in Xvfb xterm xdotool import xwininfo; do
    command -v "$tool" >/dev/null || {
        echo "sixel-screens: $tool is missing (apt-get install xvfb xterm xdotool imagemagick x11-utils)" >&2
        exit 1
    }
done
[[ -x $BIN ]] || { echo "sixel-screens: no binary at $BIN (cargo build --release)" >&2; exit 1; }

mkdir -p "$OUT"
[[ ${KEEP:-0} == 1 ]] || rm -f "$OUT"/*.png "$OUT"/*.txt "$OUT"/index.md
WORK=$(mktemp -d /tmp/sixel-screens.XXXXXX)
XVFB_PID='' XTERM_PID='' WIN='' SHOT=0 WARNINGS=0

cleanup() {
    set +e
    [[ -n $XTERM_PID ]] && kill "$XTERM_PID" 2>/dev/null
    [[ -n $XVFB_PID ]] && kill "$XVFB_PID" 2>/dev/null
    wait 2>/dev/null
    rm -rf "$WORK"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

say() { printf 'sixel-screens: %s\n' "$*" >&2; }
warn() { say "WARNING: $*"; WARNINGS=$((WARNINGS + 1)); }
# Seconds, scaled by SLOW.
scaled() { awk -v t="$1" -v s="$SLOW" 'BEGIN { print t * s }'; }

# --- the X server -------------------------------------------------------

start_x() {
    local n=${SHOT_DISPLAY:-99}
    if [[ -z ${SHOT_DISPLAY:-} ]]; then
        while [[ -e /tmp/.X$n-lock || -e /tmp/.X11-unix/X$n ]]; do n=$((n + 1)); done
    fi
    export DISPLAY=:$n
    Xvfb "$DISPLAY" -screen 0 1920x1200x24 -nolisten tcp >"$WORK/xvfb.log" 2>&1 &
    XVFB_PID=$!
    local i
    for i in $(seq 50); do
        xdpyinfo >/dev/null 2>&1 && break
        xwininfo -root >/dev/null 2>&1 && break
        sleep 0.1
    done
    xwininfo -root >/dev/null 2>&1 || { cat "$WORK/xvfb.log" >&2; exit 1; }
    say "Xvfb on $DISPLAY"
}

# --- the terminal and the UI --------------------------------------------

# launch ARGS...: a fresh xterm running the UI with ARGS (and a fresh
# config folder, so no remembered chapter or view leaks between runs).
launch() {
    stop_ui
    local cfg=$WORK/config.$SHOT graphics=(--graphics "$GRAPHICS")
    mkdir -p "$cfg" "$WORK/out" "$WORK/text"
    [[ " $* " == *" --graphics "* || " $* " == *" --halfblocks "* ]] && graphics=()
    (cd "$root" && exec env RAYSTEP_CONFIG_DIR="$cfg" TERM=xterm-256color \
        xterm -u8 -ti vt340 -b 0 -geometry "${GEOMETRY}+0+0" \
        -fa 'DejaVu Sans Mono' -fs "$FONT_SIZE" -title raystep-shot \
        -xrm 'XTerm*decTerminalID: vt340' \
        -xrm 'XTerm*numColorRegisters: 256' \
        -xrm 'XTerm*maxGraphicSize: 4000x4000' \
        -xrm 'XTerm*sixelScrolling: true' \
        -xrm 'XTerm*scrollBar: false' \
        -xrm 'XTerm*background: black' -xrm 'XTerm*foreground: gray90' \
        -xrm "XTerm*printFileImmediate: $WORK/text/screen" \
        -xrm 'XTerm*printOptsImmediate: 0' \
        -xrm 'XTerm*printModeImmediate: 0' \
        -xrm 'XTerm*VT100.translations: #override <Key>F12: print-immediate()' \
        -e "$BIN" "${graphics[@]}" --out "$WORK/out" "$@") \
        >"$WORK/xterm.log" 2>&1 &
    XTERM_PID=$!
    WIN=''
    local i
    for i in $(seq 100); do
        WIN=$(xdotool search --pid "$XTERM_PID" 2>/dev/null | tail -1 || true)
        [[ -n $WIN ]] && break
        sleep 0.1
    done
    [[ -n $WIN ]] || { cat "$WORK/xterm.log" >&2; say "no xterm window"; exit 1; }
    # The pointer waits off the window: over the picture it would write
    # the pixel readout onto the message line.
    xdotool mousemove 1900 1180
    # The chapter list's title: the UI is up (the message line may hold
    # a note instead of the key hints).
    wait_for 'chapters' 20
    say "launched: raystep $* (window $WIN)"
}

# stop_ui: quit the UI (q) and wait for its xterm to close.
stop_ui() {
    [[ -n $XTERM_PID ]] || return 0
    if kill -0 "$XTERM_PID" 2>/dev/null; then
        xdotool windowfocus --sync "$WIN" 2>/dev/null || true
        xdotool key --clearmodifiers Escape Escape q 2>/dev/null || true
        local i
        for i in $(seq 50); do kill -0 "$XTERM_PID" 2>/dev/null || break; sleep 0.1; done
        kill "$XTERM_PID" 2>/dev/null || true
    fi
    wait "$XTERM_PID" 2>/dev/null || true
    XTERM_PID=''
}

# keys KEY...: xdotool key names, one after another.
keys() {
    xdotool windowfocus --sync "$WIN" 2>/dev/null || true
    xdotool key --delay 120 "$@"
}

# typed TEXT: the characters of TEXT as keys.
typed() {
    xdotool windowfocus --sync "$WIN" 2>/dev/null || true
    xdotool type --delay 120 -- "$1"
}

# screen_text: the terminal's screen as text (xterm's print-immediate).
screen_text() {
    rm -f "$WORK"/text/screen*
    xdotool windowfocus --sync "$WIN" 2>/dev/null || true
    xdotool key F12
    local i f
    for i in $(seq 30); do
        f=$(ls "$WORK"/text/screen* 2>/dev/null | head -1 || true)
        if [[ -n $f && -s $f ]]; then sleep 0.05; cat "$f"; return 0; fi
        sleep 0.05
    done
    return 1
}

# wait_for REGEX [SECONDS]: until the screen's text matches (extended
# regex); a warning, not a failure, after SECONDS (default 30, scaled).
wait_for() {
    local re=$1 limit end
    limit=$(scaled "${2:-30}")
    end=$(awk -v l="$limit" -v n="$(date +%s.%N)" 'BEGIN { printf "%.3f", n + l }')
    while :; do
        if screen_text 2>/dev/null | grep -Eq -- "$re"; then return 0; fi
        if awk -v e="$end" -v n="$(date +%s.%N)" 'BEGIN { exit !(n > e) }'; then
            warn "timed out after ${limit}s waiting for /$re/"
            return 0
        fi
        sleep 0.5
    done
}

# wait_done [SECONDS]: until the render stops (clean, budget spent, done,
# or all its passes).
wait_done() { wait_for '· (clean|budget spent|done)|[^0-9]([0-9]+)/\2 passes' "${1:-90}"; }

# settle: time for a key's redraw and its sixel picture to arrive.
settle() { sleep "$(scaled "${1:-1.5}")"; }

# hover COLUMN ROW / drag C0 R0 C1 R1 / park: the mouse, in cells.
cell_px() {
    local geo w h
    geo=$(xwininfo -id "$WIN")
    w=$(awk '/Width:/ { print $2 }' <<<"$geo")
    h=$(awk '/Height:/ { print $2 }' <<<"$geo")
    echo $(($1 * w / COLS + w / COLS / 2)) $(($2 * h / ROWS + h / ROWS / 2))
}
hover() {
    # shellcheck disable=SC2046
    xdotool mousemove --window "$WIN" $(cell_px "$1" "$2")
}
drag() {
    hover "$1" "$2"
    sleep 0.2
    xdotool mousedown 1
    sleep 0.2
    local i
    for i in 1 2 3; do
        # shellcheck disable=SC2046
        xdotool mousemove --window "$WIN" $(cell_px $(($1 + ($3 - $1) * i / 3)) $(($2 + ($4 - $2) * i / 3)))
        sleep 0.15
    done
    xdotool mouseup 1
}
park() { xdotool mousemove 1900 1180; }

# shoot [-o] NAME [DESCRIPTION]: a PNG of the xterm window, its text,
# and a line in index.md. -o: an overlay (help, warp test) covers the
# preview, which the UI then draws in half blocks on purpose.
shoot() {
    local overlay=0
    [[ $1 == -o ]] && { overlay=1; shift; }
    SHOT=$((SHOT + 1))
    local base text
    base=$(printf '%02d-%s' "$SHOT" "$1")
    text=$(screen_text || true)
    printf '%s\n' "$text" >"$OUT/$base.txt"
    import -window "$WIN" "$OUT/$base.png"
    printf -- '- `%s.png`: %s\n' "$base" "${2:-}" >>"$OUT/index.md"
    # A run of half blocks is a picture (a histogram's ▄ alone is not).
    if [[ $overlay == 0 ]] && grep -qE '(▀|▄){8,}' <<<"$text"; then
        warn "$base: half blocks on screen, not a sixel picture"
    fi
    say "shot $base.png"
}

# --- the scenarios ------------------------------------------------------

chapters_1_to_5() {
    local n
    for n in 1 2 3 4 5; do
        launch --chapter "$n"
        wait_done 120
        settle
        shoot "ch$n" "chapter $n's preview, drawn with sixel, once rendered"
    done
}

ch6_compare() {
    launch --chapter 6
    wait_done
    settle
    shoot ch6-render "chapter 6's Cornell box (mis-sobol), converged to the noise target"
    keys r && wait_for 'compare: reference' 5 && settle
    shoot ch6-reference "compare step 2: the stored reference"
    keys r && wait_for 'compare: difference' 5 && settle
    shoot ch6-difference "compare step 3: render - reference, with the legend and tev's metrics"
    hover 100 20 && settle 1
    shoot ch6-difference-hover "the difference, with the pointer's readout on the message line"
    park
    keys r && wait_for 'compare: relative' 5 && settle
    shoot ch6-relative "compare step 4: (render - reference) / reference"
    keys r && wait_for 'compare: z' 5 && settle
    shoot ch6-z "compare step 5: the z view, legend ±5σ and the verdict"
    keys r && wait_for 'compare: render' 5 && settle
    keys question && settle
    shoot -o ch6-help "the key help over the UI"
    keys question && settle
    keys v && wait_for 'view 2/' 5 && settle
    shoot ch6-stderr-auto "the stderr view with automatic exposure (on by default)"
    keys a && settle
    shoot ch6-stderr-auto-off "the stderr view, automatic exposure off"
    keys a v v && wait_for 'view 1/' 5 && settle
    keys bracketright && settle
    shoot ch6-bounces-0 "up to 0 bounces: direct illumination"
    keys bracketright m && settle
    shoot ch6-bounce-1-alone "bounce 1 alone (m), with automatic exposure"
    keys a && settle
    shoot ch6-bounce-1-alone-auto-off "bounce 1 alone, automatic exposure off"
}

ch6_pin() {
    launch --chapter 6
    wait_done
    keys p && wait_for 'pinned' 5 && settle
    shoot ch6-pinned "a converged mis-sobol render pinned (p): the message line says so"
    keys E && wait_for 'estimator 7/' 5
    wait_done
    settle
    shoot ch6-chart-two-estimators "the previous estimator (E), converged: the chart keeps both curves"
    keys r r && wait_for 'compare: difference' 5 && settle
    shoot ch6-pin-difference "the new estimator's render minus the pinned one"
    keys r r && wait_for 'compare: z' 5 && settle
    shoot ch6-pin-z "the z view against the pinned render, with its verdict"
    keys r && wait_for 'compare: render' 5
    keys e e && wait_for 'estimator 1/' 5
    sleep "$(scaled 20)"
    shoot ch6-chart-three-estimators "uniform sampling (e e) after 20 s: a third, higher curve"
    keys r r r r && wait_for 'compare: z' 5 && settle
    shoot ch6-pin-z-uniform "the z view of uniform sampling against the pinned render"
}

ch6_views() {
    launch --chapter 6
    wait_done
    keys v v && wait_for 'non-finite' 5 && settle
    shoot ch6-non-finite "the non-finite view (v v): the image dimmed, the legend says none was caught"
    keys v && wait_for 'render' 5
    keys p && wait_for 'pinned' 5
    keys E && wait_for 'estimator 7/' 5
    keys bar && wait_for 'split' 5
    wait_done
    settle
    shoot ch6-split "the split (|): pinned mis-sobol on the left, mis-independent at equal time on the right"
}

ch6_inspect() {
    launch --chapter 6
    wait_done
    keys i && settle
    shoot ch6-inspect "inspect mode (i): the cursor at the centre and the pixel panel"
    keys shift+h shift+h shift+j shift+j b && settle 0.5
    keys shift+l shift+l shift+l shift+j shift+j shift+j b && settle
    shoot ch6-region-keys "a region marked with b, the cursor moved, b: its statistics"
    keys b t && wait_for 'traced sample' 20 && settle
    shoot ch6-trace "a path traced from the cursor's pixel (t): the path table"
    keys t && wait_for 'traced sample 1' 20 && settle
    shoot ch6-trace-next "t again: the pixel's next sample"
    keys Escape Escape && settle
    drag 70 8 90 20 && settle
    park
    shoot ch6-region-drag "a region dragged with the mouse over the picture, from inspect mode off"
    keys b && settle 0.5
    drag 70 8 90 20 && settle
    park
    shoot ch6-region-drag-inspecting "the same drag (cells 70,8 to 90,20) with inspect mode already on"
}

warp() {
    launch --chapter 5
    wait_done 120
    keys w && settle 3
    shoot -o warp "the warp test (w): a sampling routine against its pdf, with χ²"
    keys l && settle 3
    shoot -o warp-next "the warp test's next routine (l)"
}

forced() {
    # The note lasts 6 s on the message line.
    launch --chapter 6 --graphics sixel
    wait_for 'did not say' 5
    wait_for 'spp [0-9]{2,}' 5 && settle 1
    shoot ch6-forced-sixel "--graphics sixel forced: the sixel picture, and the note on the message line"
}

main() {
    start_x
    if [[ ${KEEP:-0} == 1 ]]; then
        # Go on numbering after the shots kept.
        local last
        last=$(find "$OUT" -maxdepth 1 -name '[0-9][0-9]-*.png' -printf '%f\n' | sort | tail -1)
        last=${last%%-*}
        SHOT=$((10#${last:-0}))
    else
        : >"$OUT/index.md"
    fi
    local s
    for s in ch6_compare ch6_views ch6_pin ch6_inspect warp chapters_1_to_5 forced; do
        [[ $s =~ $ONLY ]] || continue
        say "scenario $s"
        "$s"
    done
    stop_ui
    say "$SHOT shots in $OUT ($WARNINGS warnings)"
}

main
