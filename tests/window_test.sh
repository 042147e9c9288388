#!/usr/bin/env bash
# The real window under Xvfb: start ./jello, press keys with xdotool, check the frames it saves
# and its exit status, and compare a saved frame with the off-screen frame of the same state.
# Usage: window_test.sh JELLO JPEG_DIFFERENCE STILL_WORLD. Exit 77 (CTest's skip) when Xvfb or
# xdotool is missing.
set -u
jello=$1 difference=$2 world=$3
source "$(dirname "$0")/window_support.sh"
frames() { frames_in "$work/animation"; }

cd "$work"
start_jello --max-frames 5000 "$world"

# The classic keys, none of which may upset the viewer.
for k in z x e v v s h b s h b c c c c r r; do key "$k"; done
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

quit_jello
[ "$status" -eq 0 ] || fail "jello exited with status $status"
echo "window test passed: $(frames) frames saved, keys and the mouse answered"
