#!/usr/bin/env bash
# Builds the book and opens every page in a real browser (headless
# Chromium) at a phone's width, 375 CSS pixels: each page must load with
# no broken image, no include left unresolved, no link to a heading of the
# same page that is missing, and no horizontal scroll. The links between
# pages and the includes are also checked without a browser by `cargo
# test` (tests/project/book.rs and book_links.rs).
#
# Usage: bash book/check.sh   (installs mdBook with cargo if it is missing;
# skips the browser part, saying so, where no Chromium can be had)
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v mdbook >/dev/null 2>&1; then
  echo "book/check.sh: installing mdBook (cargo install mdbook, about a minute)"
  # Only what `mdbook build` needs: without the default `serve` and `watch`
  # (a web server and a file watcher) it compiles in half the time.
  cargo install mdbook --locked --quiet --no-default-features --features search
fi
log=$(mktemp)
if ! mdbook build book >"$log" 2>&1; then
  cat "$log" >&2
  echo "book/check.sh: mdbook build failed" >&2
  exit 1
fi
if grep -E "WARN|ERROR" "$log" >&2; then
  echo "book/check.sh: mdbook build printed warnings (above)" >&2
  exit 1
fi
echo "book/check.sh: mdbook build book: clean"

browser=""
for b in chromium chromium-browser google-chrome; do
  if command -v "$b" >/dev/null 2>&1; then browser="$b"; break; fi
done
if [ -z "$browser" ]; then
  echo "book/check.sh: SKIPPED the browser check: no chromium, chromium-browser or google-chrome on PATH (apt-get install chromium)"
  exit 0
fi

out=book/book
pages=$(cd "$out" && ls *.html | grep -v -E '^(print|toc|404)\.html$' | sed 's/.*/"&",/' | tr -d '\n')
checker="$out/browser-check.html"
cat > "$checker" <<HTML
<!doctype html><html><body><pre id="out">running</pre>
<script>
const pages = [${pages}];
const out = [];
let i = 0;
function check(name, d) {
  for (const im of d.images) {
    if (!im.complete || im.naturalWidth === 0) out.push("BROKEN-IMAGE " + name + " " + im.getAttribute("src"));
  }
  const w = d.documentElement.scrollWidth, cw = d.documentElement.clientWidth;
  if (w > cw + 1) {
    let widest = "";
    for (const e of d.querySelectorAll("main *")) {
      const r = e.getBoundingClientRect();
      if (r.right > cw + 1 && !widest) widest = e.tagName + " " + (e.textContent || e.getAttribute("src") || "").slice(0, 60);
    }
    out.push("HSCROLL " + name + " " + w + " > " + cw + " (first too wide: " + widest + ")");
  }
  if (d.body.innerText.includes("{{#include")) out.push("INCLUDE " + name + " shows an unresolved include");
  for (const a of d.querySelectorAll("main a[href^='#']")) {
    const id = decodeURIComponent(a.getAttribute("href").slice(1));
    if (id && !d.getElementById(id)) out.push("ANCHOR " + name + " #" + id);
  }
  out.push("PAGE " + name);
}
function next() {
  if (i >= pages.length) { document.getElementById("out").textContent = "DONE\n" + out.join("\n"); return; }
  const name = pages[i++];
  const f = document.createElement("iframe");
  f.style.width = "375px"; f.style.height = "800px";
  f.onload = () => setTimeout(() => {
    try { check(name, f.contentDocument); } catch (e) { out.push("ERROR " + name + " " + e); }
    f.remove(); next();
  }, 500);
  f.src = name;
  document.body.appendChild(f);
}
next();
</script></body></html>
HTML
result=$("$browser" --headless --no-sandbox --disable-gpu --allow-file-access-from-files \
  --virtual-time-budget=120000 --dump-dom "file://$(pwd)/$checker" 2>/dev/null || true)
rm -f "$checker"
report=$(printf '%s\n' "$result" | sed -n '/DONE/,/<\/pre>/p' | sed 's/<\/pre>.*//; s/&gt;/>/g; s/&lt;/</g; s/&amp;/\&/g')
if [ -z "$report" ]; then
  echo "book/check.sh: the browser did not finish the check" >&2
  exit 1
fi
n=$(printf '%s\n' "$report" | grep -c '^PAGE ' || true)
problems=$(printf '%s\n' "$report" | grep -E '^(BROKEN-IMAGE|HSCROLL|INCLUDE|ANCHOR|ERROR) ' || true)
if [ -n "$problems" ]; then
  printf '%s\n' "$problems" >&2
  echo "book/check.sh: $(printf '%s\n' "$problems" | wc -l) problems in $n pages ($browser, 375 px wide)" >&2
  exit 1
fi
echo "book/check.sh: $n pages load in $browser at 375 px: no broken image, include or same-page link, no horizontal scroll"
