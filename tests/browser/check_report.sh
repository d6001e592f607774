#!/bin/sh
# Opens REPORT_DIR/report.html in headless Chromium and checks what a reader would see:
# the page logs "report ready" and nothing else on the console (no error, no blocked
# fetch, no uncaught exception); the viewer shows a.png left of the split and b.png
# right of it (#split=0.5, the default), only b.png after #show=b (the B toggle's click
# handler), a.png on the left quarter after #split=0.25 (the slider's input handler),
# reference.png (b.png without one) | a.png magnified 4 times after
# #left=reference&right=a&zoom=4 (the selects' change and the zoom buttons' handlers);
# the metrics table is not blank. The page logs the boxes of the viewer and the table
# ("report ready viewer=x,y,w,h metrics=x,y,w,h"), so this works on any report.
#
# usage: check_report.sh REPORT_DIR [REPORT_PIXELS]
#   REPORT_PIXELS: the pixel checker (tests/browser/report_pixels.cpp); default
#   $REPORT_PIXELS, else build/tests/browser/report_pixels beside this script's checkout.
#   CHROMIUM: the browser (default chromium). SHOTS_DIR: keep the screenshots there.
# Exit 0 when every check holds, 1 when one fails, 77 (skipped) without Chromium.
set -eu

fail() { echo "check_report: $*" >&2; exit 1; }

[ $# -ge 1 ] || { echo "usage: check_report.sh REPORT_DIR [REPORT_PIXELS]" >&2; exit 2; }
[ -f "$1/report.html" ] || fail "$1/report.html: no such file"
dir=$(cd "$1" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
pixels=${2:-${REPORT_PIXELS:-$here/../../build/tests/browser/report_pixels}}
[ -x "$pixels" ] || fail "$pixels: the pixel checker is not built (ninja -C build report_pixels)"
chromium=${CHROMIUM:-chromium}
command -v "$chromium" >/dev/null 2>&1 || { echo "check_report: $chromium not found; skipped" >&2; exit 77; }
for image in a.png b.png; do [ -f "$dir/$image" ] || fail "$dir/$image: no such file"; done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
width=1280
height=2400

# shoot NAME FRAGMENT: a screenshot of report.html#FRAGMENT into $work/NAME.png, the
# console into $work/NAME.console; sets $layout to what the page logged.
shoot() {
  timeout 120 "$chromium" --headless --no-sandbox --disable-gpu --enable-logging=stderr --v=0 \
    --hide-scrollbars --force-device-scale-factor=1 --force-color-profile=srgb --no-first-run \
    --user-data-dir="$work/profile-$1" --window-size=$width,$height --screenshot="$work/$1.png" \
    "file://$dir/report.html#$2" >"$work/$1.out" 2>&1 || fail "#$2: chromium failed: $(tail -n 5 "$work/$1.out")"
  [ -s "$work/$1.png" ] || fail "#$2: chromium wrote no screenshot"
  grep 'INFO:CONSOLE' "$work/$1.out" >"$work/$1.console" || true
  others=$(grep -v '"report ready viewer=[0-9,]* metrics=[0-9,]*", source: ' "$work/$1.console" || true)
  [ -z "$others" ] || fail "#$2: the console is not clean:
$others"
  layout=$(sed -n 's/.*"report ready \(viewer=[0-9,]* metrics=[0-9,]*\)".*/\1/p' "$work/$1.console")
  [ -n "$layout" ] || fail "#$2: the page never logged \"report ready\" (its script failed or never ran)"
  if [ -n "${SHOTS_DIR:-}" ]; then mkdir -p "$SHOTS_DIR" && cp "$work/$1.png" "$SHOTS_DIR/"; fi
}

box_of() { echo "$layout" | sed -n "s/.*$1=\([0-9,]*\).*/\1/p"; }

shoot default ""
viewer=$(box_of viewer)
metrics=$(box_of metrics)
"$pixels" match "$work/default.png" "$viewer" "$dir/a.png" "$dir/b.png" 0.5 || fail "default view: not A | B split at 0.5"
"$pixels" not-blank "$work/default.png" "$metrics" || fail "the metrics table is blank"

shoot show_b "show=b"
[ "$(box_of viewer)" = "$viewer" ] || fail "#show=b moved the viewer ($(box_of viewer), was $viewer)"
"$pixels" match "$work/show_b.png" "$viewer" "$dir/b.png" "$dir/b.png" 0.5 || fail "#show=b: the viewer does not show B alone"
if ! cmp -s "$dir/a.png" "$dir/b.png"; then
  "$pixels" differ "$work/default.png" "$work/show_b.png" "$viewer" || fail "#show=b looks like the default view"
fi

shoot split_quarter "split=0.25"
"$pixels" match "$work/split_quarter.png" "$viewer" "$dir/a.png" "$dir/b.png" 0.25 || fail "#split=0.25: not A | B split at 0.25"

other=b
[ -f "$dir/reference.png" ] && other=reference
shoot zoomed "left=$other&right=a&zoom=4"
"$pixels" match "$work/zoomed.png" "$viewer" "$dir/$other.png" "$dir/a.png" 0.5 4 ||
  fail "#left=$other&right=a&zoom=4: not $other | A magnified 4 times about the centre"

echo "check_report: $dir/report.html: console clean; viewer $viewer shows A|B, B alone, A|B at 0.25, $other|A at zoom 4; metrics table $metrics not blank"
