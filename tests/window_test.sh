#!/usr/bin/env bash
# The real window under Xvfb: start ./jello, press keys with xdotool, check the frames it saves
# and its exit status, and compare a saved frame with the off-screen frame of the same state.
# Usage: window_test.sh JELLO JPEG_DIFFERENCE STILL_WORLD. Exit 77 (CTest's skip) when Xvfb or
# xdotool is missing.
set -u
jello=$1 difference=$2 world=$3
for tool in Xvfb xdotool; do
  command -v "$tool" >/dev/null || { echo "skipped: $tool is not installed"; exit 77; }
done

fail() { echo "FAILED: $*"; [ -f "$work/err" ] && sed 's/^/  jello: /' "$work/err"; exit 1; }
work=$(mktemp -d)
cleanup() {
  [ -n "${app:-}" ] && kill "$app" 2>/dev/null
  if [ -n "${xvfb:-}" ]; then kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null; fi
  rm -rf "$work"
}
trap cleanup EXIT

# Xvfb picks a free display itself and writes its number once it accepts connections.
exec {displayfd}>"$work/display"
Xvfb -displayfd "$displayfd" -screen 0 1024x768x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || fail "Xvfb did not start"
export DISPLAY=":$(head -1 "$work/display")"
for _ in $(seq 100); do xdotool getmouselocation >/dev/null 2>&1 && break; sleep 0.1; done
xdotool getmouselocation >/dev/null 2>&1 || fail "Xvfb on $DISPLAY does not answer"

# Waits up to 15 s for a shell condition.
wait_for() { for _ in $(seq 150); do eval "$1" && return 0; sleep 0.1; done; return 1; }
frames() { ls "$work/animation" 2>/dev/null | grep -c '^[0-9][0-9][0-9][0-9]\.jpg$'; }

cd "$work"
# In a sanitized build, the GLX driver that the window dlopens keeps its buffers to exit and is
# unloaded by then, so LeakSanitizer cannot name (or be told to ignore) it: leaks are checked
# in the off-screen runs, not in the window's.
start_jello() {
  ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" "$jello" --max-frames 5000 "$world" >out 2>err &
  app=$!
  wait_for 'window=$(xdotool search --name "^Jello cube$" 2>/dev/null | head -1); [ -n "$window" ]'
}
# Once more if the first start found no window (a display that was still settling, seen once).
start_jello || { kill "$app" 2>/dev/null; wait "$app" 2>/dev/null; start_jello; } || fail "no window titled 'Jello cube'"
key() { xdotool key --window "$window" "$@"; }

# The classic keys, none of which may upset the viewer.
for k in z x e v v s h b s h b c c c r r; do key "$k"; done
[ "$(frames)" -eq 0 ] || fail "frames were saved before space was pressed"
key space
wait_for '[ "$(frames)" -ge 10 ]' || fail "space did not start saving frames"
key p
sleep 0.5
paused=$(frames)
sleep 1
[ "$(frames)" -eq "$paused" ] || fail "frames kept coming while paused ($paused, then $(frames))"
key p
wait_for '[ "$(frames)" -gt "$paused" ]' || fail "p did not resume"
key space
sleep 0.3
still=$(frames)
last=$(printf '%04d.jpg' $((still - 1)))
[ -f "animation/0000.jpg" ] && [ -f "animation/$last" ] || fail "frames are not numbered 0000..$last"

# The window's frames against the off-screen frame of the same (still) state.
"$jello" --headless --steps 0 --frames offscreen "$world" >/dev/null 2>>err || fail "off-screen frame failed"
"$difference" animation/0000.jpg offscreen/0000.jpg 2 || fail "window and off-screen frames differ"
"$difference" "animation/$last" offscreen/0000.jpg 2 || fail "the still cube moved"

# Left-drag from the cube (at the window's centre, where the camera looks) pulls it along.
xdotool mousemove --window "$window" 320 240 mousedown 1 mousemove --window "$window" 450 200
key space
wait_for '[ "$(frames)" -gt $((still + 20)) ]' || fail "no frames while pulling"
xdotool mouseup 1
key space
pulled=$(printf '%04d.jpg' $(($(frames) - 1)))
if "$difference" "animation/$pulled" offscreen/0000.jpg 0.3; then fail "left-drag did not move the cube"; fi

key Escape
wait_for '! kill -0 $app 2>/dev/null' || fail "ESC did not close the window"
wait "$app"
status=$?
app=
[ "$status" -eq 0 ] || fail "jello exited with status $status"
echo "window test passed: $(frames) frames saved, keys and the mouse answered"
