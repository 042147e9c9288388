#!/usr/bin/env bash
# The window's panel (graphics/panel.h) under Xvfb, driven by synthetic input (xdotool: the mouse
# clicks its fields and buttons, the keyboard types into them; JELLO_PANEL_TRACE=1 makes jello
# print where each widget is): g closes and opens it; an unstable dt is flagged before it is
# applied; a dt typed into the panel changes the run as --dt does, bit for bit; "save as" writes a
# scene that runs on bit for bit as the session did; frames saved with the panel open are the
# off-screen frames, without it.
# Usage: window_panel_test.sh JELLO JPEG_DIFFERENCE SCENES_DIR. Exit 77 (CTest's skip) when Xvfb
# or xdotool is missing, or when this jello has no panel.
set -u
jello=$1 difference=$2 scenes=$3
source "$(dirname "$0")/window_support.sh"
fail() { echo "FAILED: $*"; [ -f "$work/err" ] && sed 's/^/  jello: /' "$work/err"; exit 1; }
export JELLO_PANEL_TRACE=1
scene=$scenes/sphere-drop.toml  # RK4, dt 0.0002 s, 25 steps a frame

# The widget's centre from the trace's last line for it: "panel-trace: NAME X Y W H".
place() { grep "^panel-trace: $1 " err | tail -1 | awk '{ printf "%d %d", $3 + 12, $4 + $6 / 2 }'; }
# Clicks the widget where it is once it stays put for 0.3 s (a verdict arriving moves nothing
# below it, but the trace of a frame drawn after it may come a moment later).
click() {
  wait_for "[ -n \"\$(place $1)\" ]" 5 || fail "the panel has no $1"
  local at=
  for _ in 1 2 3 4 5; do
    at=$(place "$1")
    read -r x y <<<"$at"
    xdotool mousemove --window "$window" "$x" "$y" >/dev/null 2>&1
    sleep 0.3
    [ "$(place "$1")" = "$at" ] && break
  done
  xdotool click 1 >/dev/null 2>&1
  sleep 0.3
}
# FIELD TEXT: types TEXT into the field in place of what it holds, then Return.
type_into() {
  click "$1"
  key End
  for _ in $(seq 24); do key BackSpace; done
  xdotool type --window "$window" "$2" >/dev/null 2>&1
  key Return
}
said() { grep -c -- "$1" err; }

cd "$work"
start_jello --size 1000x700 --steps 0 --frames recorded "$scene"
wait_for 'grep -q "reached --steps 0" err && [ -s recorded/0000.jpg ]' ||
  fail "the scene did not pause at step 0"
if grep -q "has no panel" err || ! wait_for 'grep -q "^panel-trace: run.dt " err' 10; then
  key g
  sleep 0.5
  grep -q "built without Dear ImGui" err && { echo "skipped: this jello has no panel"; exit 77; }
  fail "the panel is not open in a 1000x700 window"
fi
key space  # the recording stops: its one frame was taken with the panel open

# g closes and opens the panel.
key g
wait_for 'grep -q "panel: closed" err' 5 || fail "g did not close the panel"
key g
wait_for 'grep -q "panel: open" err' 5 || fail "g did not open the panel again"
wait_for 'grep -q "setup.s verdict after .*: stable" err' 15 || fail "no verdict on the setup"

# An unstable step is flagged before it is applied, and not applied.
type_into run.dt 0.01
wait_for 'grep -q "change.s verdict after .*: unstable: dt 0.01 s is above RK4.s limit" err' 15 ||
  fail "dt 0.01 s was not flagged unstable"
[ "$(said "applied:")" -eq 0 ] || fail "the unstable dt was applied before it was asked"
click discard
wait_for 'grep -q "the changes were discarded" err' 5 || fail "discard did nothing"

# dt 0.0001 through the panel, then four frames of 25 steps: the run of --dt 0.0001 --steps 100.
type_into run.dt 0.0001
wait_for 'grep -q "change.s verdict after .*: stable: dt 0.0001 s" err' 15 || fail "no verdict on dt 0.0001"
click apply
wait_for 'grep -q "applied the changes: the run goes on with RK4 at dt 0.0001 s" err' 5 || fail "apply did not apply dt 0.0001"
for frame in 1 2 3 4; do
  click run.step
  wait_for "grep -q 'stepped 25 steps to step $((25 * frame))\$' err" 10 || fail "step a frame did not reach step $((25 * frame))"
done
type_into save.name session.toml
click save
wait_for 'grep -q "saved session.toml (with session.w and session.csv beside it) at step 100" err' 10 ||
  fail "save as did not save session.toml"
"$jello" --headless --dt 0.0001 --steps 100 --save-state ref.csv "$scene" >/dev/null 2>&1 ||
  fail "the headless run failed"
cmp -s session.csv ref.csv || fail "the panel's dt 0.0001 did not run as --dt 0.0001 (session.csv, ref.csv)"

# Two frames more in the window, saved again: the saved scene run 50 steps is the same state.
click run.step
click run.step
wait_for "grep -q 'stepped 25 steps to step 150\$' err" 10 || fail "step a frame did not reach step 150"
type_into save.name later.toml
click save
wait_for 'grep -q "saved later.toml" err' 10 || fail "save as did not save later.toml"
"$jello" --headless --steps 50 --save-state again.csv session.toml >/dev/null 2>&1 ||
  fail "the saved scene does not run: $("$jello" --headless --steps 50 session.toml 2>&1 | tail -1)"
cmp -s again.csv later.csv || fail "the saved scene did not run on as the session did (again.csv, later.csv)"

# The frame saved with the panel open is the off-screen frame of the same state.
"$jello" --headless --steps 0 --size 1000x700 --frames offscreen "$scene" >/dev/null 2>&1 ||
  fail "the off-screen frame failed"
"$difference" recorded/0000.jpg offscreen/0000.jpg 2 || fail "a frame saved with the panel open is not the off-screen frame"

quit_jello
[ "$status" -eq 0 ] || fail "jello exited with $status"
grep -o "panel: .*verdict after [0-9.]* s" err | sed 's/^/  /'
echo "panel: closed and opened, dt flagged and applied, saved scene bit for bit"
