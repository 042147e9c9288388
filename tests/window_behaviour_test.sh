#!/usr/bin/env bash
# The window's behaviour a user meets in the first hour (README: The viewer), under Xvfb:
# --time pauses the window at the run's end with frames saved by the headless run's clock, a
# diverging run keeps answering keys while it is diagnosed, the help key, a missed grab, and
# space recording a second time into a new folder.
# Usage: window_behaviour_test.sh JELLO JPEG_DIFFERENCE STILL_WORLD MOVING_WORLD. Exit 77 (CTest's
# skip) when Xvfb or xdotool is missing.
set -u
jello=$1 difference=$2 still=$3 moving=$4
source "$(dirname "$0")/window_support.sh"
said() { grep -qF -- "$1" err; }

# --time: the window pauses on the run's last frame and says so; its frames are the headless
# run's, frame for frame, though it draws every 10 steps (a frame is due every 66 or 67, and a
# step late is a picture 0.2 apart); so are the meshes of --export, written beside them (the
# same folder: .jpg and .obj) and byte for byte the headless run's; p runs on.
mkdir "$work/time" && cd "$work/time"
meshes_in() { ls "$1" 2>/dev/null | grep -c '^[0-9][0-9][0-9][0-9]\.obj$'; }
start_jello --time 0.2 --n 10 --frames window --export window "$moving"
wait_for 'said "reached --time 0.2 s (step 400): paused"' || fail "--time 0.2 did not end the run"
sleep 0.5  # the last frame is saved when it is drawn, just after the end is said
ended=$(frames_in window)
sleep 1
[ "$(frames_in window)" -eq "$ended" ] || fail "frames kept coming after the run's end"
"$jello" --headless --time 0.2 --frames headless --export headless "$moving" >/dev/null 2>>err ||
  fail "headless run"
[ "$ended" -eq "$(frames_in headless)" ] ||
  fail "the window saved $ended frames, the headless run $(frames_in headless)"
[ "$(meshes_in window)" -eq "$ended" ] || fail "the window saved $(meshes_in window) meshes"
for mesh in headless/*.obj; do
  cmp -s "window/${mesh#headless/}" "$mesh" || fail "window/${mesh#headless/} is not $mesh"
done
for frame in headless/*.jpg; do
  "$difference" "window/${frame#headless/}" "$frame" 0.1 >/dev/null ||
    fail "window/${frame#headless/} is not the headless run's frame"
done
if "$difference" window/0000.jpg "window/$(printf '%04d' $((ended - 1))).jpg" 0.2 >/dev/null; then
  fail "the frames of a moving world do not move"
fi
key p
wait_for '[ "$(frames_in window)" -gt "$ended" ]' || fail "p did not run on after the end"
quit_jello
[ "$status" -eq 0 ] || fail "jello exited with status $status after --time"

# The help key, seen in pictures of the window (w) of a run paused at its start; a missed grab.
mkdir "$work/help" && cd "$work/help"
start_jello --steps 0 "$still"
wait_for 'said "reached --steps 0"' || fail "--steps 0 did not pause"
shot() {
  local before
  before=$(ls jello-window-*.jpg 2>/dev/null | wc -l)
  key "$1"
  wait_for '[ "$(ls jello-window-*.jpg 2>/dev/null | wc -l)" -gt '"$before"' ]' 5 ||
    fail "w saved no picture of the window"
}
shot w
shot w
key question
shot w
key question
shot w
"$difference" jello-window-002.jpg jello-window-003.jpg 3 >/dev/null && fail "? showed no help"
"$difference" jello-window-002.jpg jello-window-004.jpg 0.5 >/dev/null || fail "? did not hide it"
key k
shot w
"$difference" jello-window-004.jpg jello-window-005.jpg 3 >/dev/null && fail "k showed no help"
xdotool mousemove --window "$window" 5 470 click 1
wait_for 'said "no point of the jelly near the cursor"' 5 || fail "a missed grab was not said"
quit_jello
[ "$status" -eq 0 ] || fail "jello exited with status $status after the help"

# A diverging run: the window answers keys while the divergence is diagnosed, and closes at
# once on ESC; the advice comes (on stderr, and in the window when it stays open).
mkdir "$work/diverge" && cd "$work/diverge"
start_jello --dt 0.05 "$moving"
wait_for 'said "diverged at step"' || fail "--dt 0.05 did not diverge"
said "diagnosing" || fail "no word of the diagnosis under way"
key w
wait_for '[ -f jello-window-001.jpg ]' 1 || fail "w was not answered within 1 s of the divergence"
key Escape
wait_for '[ -z "$(find_window)" ]' 1 || fail "ESC did not close the window within 1 s"
wait_for '! kill -0 $app 2>/dev/null' 60 || fail "jello did not end after the diagnosis"
wait "$app"
status=$?
app=
[ "$status" -eq 1 ] || fail "a diverged run exited with status $status, not 1"
said "stable limit" || fail "no advice for the divergence"

# Space records a second time, in a second session, into a new folder named after the world,
# and once --max-frames is reached, into another.
mkdir "$work/again" && cd "$work/again"
start_jello "$still"
key space
wait_for '[ "$(frames_in animation)" -ge 3 ]' || fail "space did not record into animation/"
quit_jello
first=$(frames_in animation)
start_jello --max-frames 3 "$still"
key space
wait_for 'said "saving frames into animation/still-001/"' 5 ||
  fail "the second recording did not go to animation/still-001/"
wait_for 'said "the most --max-frames 3 allows"' || fail "reaching --max-frames was not said"
[ "$(frames_in animation/still-001)" -eq 3 ] || fail "animation/still-001/ does not hold 3 frames"
key space
wait_for '[ "$(frames_in animation/still-002)" -eq 3 ]' ||
  fail "space after --max-frames did not record into animation/still-002/"
[ "$(frames_in animation)" -eq "$first" ] || fail "animation/'s own frames changed"
quit_jello
[ "$status" -eq 0 ] || fail "jello exited with status $status after recording"
echo "window behaviour test passed"
