#!/bin/sh
# Runs the real f2-viewer under Xvfb with --screenshot: the viewer itself saves
# its window as soon as the picture is complete (on screen, rendered at the
# window's size, refined when paused) and exits — a condition it checks, not
# a delay — then this checks that the picture is not blank.
#   screenshot.sh F2_VIEWER OUTPUT.png [SCENE] [extra f2-viewer options...]
# Skipped (tests/skip.sh: skip_missing) when xvfb-run or ImageMagick is missing.
set -eu
. "$(dirname "$0")/../skip.sh"

viewer=$1
out=$2
shift 2

for tool in xvfb-run convert identify; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        skip_missing "'$tool' not found (install xvfb and imagemagick to run this test)"
    fi
done

# Distinct colours the centre of the picture must have: a blank or failed
# view is one flat colour there, a shaded scene has hundreds. (The menus and
# status bar are left out: their antialiased text alone gives ~250 colours.)
min_colours=${F2_SCREENSHOT_MIN_COLOURS:-64}
# Only a deadline for a viewer that never completes a picture (it then quits
# without a screenshot and the test fails); a working one is done in seconds.
deadline=${F2_SCREENSHOT_DEADLINE:-90}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM
# Keep the user's settings (recent files, render scale) and autosave copies out of it.
export XDG_CONFIG_HOME="$work/config"
export XDG_DATA_HOME="$work/data"
export XDG_RUNTIME_DIR="$work/runtime"
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"

status=0
xvfb-run -a -s "-screen 0 1400x800x24" \
    "$viewer" "$@" --screenshot "$work/window.png" --quit-after "$deadline" || status=$?
if [ "$status" -ne 0 ] || [ ! -s "$work/window.png" ]; then
    echo "FAIL: no screenshot (f2-viewer exit status $status; no complete picture within ${deadline} s?)"
    exit 1
fi
cp "$work/window.png" "$out"

size=$(identify -format '%wx%h' "$out")
# The picture area is the window's right part (the editor dock is on the
# left): the middle of its right half, 40 % of the height.
colours=$(convert "$out" -gravity east -crop 50%x100%+0+0 +repage -gravity center -crop 50%x40%+0+0 +repage \
    -format '%k' info:)
echo "screenshot: $out ($size, $colours distinct colours in the picture's centre)"
if [ "$colours" -lt "$min_colours" ]; then
    echo "FAIL: the picture looks blank ($colours < $min_colours distinct colours in the centre)"
    exit 1
fi
echo "PASS"
