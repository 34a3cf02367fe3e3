#!/bin/sh
# Runs the real f2-viewer under Xvfb, grabs the X screen once it has rendered,
# and checks that the picture is not blank.
#   screenshot.sh F2_VIEWER OUTPUT.png [SCENE] [extra f2-viewer options...]
# Exit 77 (CTest SKIP_RETURN_CODE) when xvfb-run or ImageMagick is missing.
set -eu

viewer=$1
out=$2
shift 2

for tool in xvfb-run import convert; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        echo "SKIP: '$tool' not found (install xvfb and imagemagick to run this test)"
        exit 77
    fi
done

# Distinct colours the centre of the picture must have: a blank or failed
# view is one flat colour there, a shaded scene has hundreds. (The menus and
# status bar are left out: their antialiased text alone gives ~250 colours.)
min_colours=${F2_SCREENSHOT_MIN_COLOURS:-64}
# Seconds to let the window map and render before grabbing.
settle=${F2_SCREENSHOT_SETTLE:-5}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM
# Keep the user's settings (recent files, render scale) out of it.
export XDG_CONFIG_HOME="$work/config"
export XDG_RUNTIME_DIR="$work/runtime"
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"

cat >"$work/run.sh" <<SCRIPT
#!/bin/sh
"\$@" --quit-after $((settle + 20)) --stats &
pid=\$!
sleep $settle
import -window root "$work/screen.png"
status=\$?
kill \$pid 2>/dev/null
wait \$pid 2>/dev/null
exit \$status
SCRIPT
chmod +x "$work/run.sh"

xvfb-run -a -s "-screen 0 1400x800x24" "$work/run.sh" "$viewer" "$@"

# Crop to the window (it sits at the top-left; Xvfb has no window manager).
convert "$work/screen.png" -trim +repage "$out"
size=$(identify -format '%wx%h' "$out")
# The middle half of the width and 40 % of the height: inside the picture area.
colours=$(convert "$out" -gravity center -crop 50%x40%+0+0 +repage -format '%k' info:)
echo "screenshot: $out ($size, $colours distinct colours in the centre)"
if [ "$colours" -lt "$min_colours" ]; then
    echo "FAIL: the picture looks blank ($colours < $min_colours distinct colours in the centre)"
    exit 1
fi
echo "PASS"
