# Sourced by the window tests: Xvfb on a free display, a work folder, and helpers to start
# ./jello's window and drive it with xdotool. Exits 77 (CTest's skip) when Xvfb or xdotool is
# missing. Needs $jello set to the program.
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

# Xvfb picks a free display itself and writes its number once it accepts connections. -noreset:
# by default the server resets whenever its last client leaves, and refuses connections while it
# does; every xdotool call below is such a client, so a window's start could meet a reset (seen:
# "failed to open display" for jello, twice in a row, on a loaded machine).
exec {displayfd}>"$work/display"
Xvfb -displayfd "$displayfd" -screen 0 1024x768x24 -nolisten tcp -noreset >/dev/null 2>&1 &
xvfb=$!
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || fail "Xvfb did not start"
export DISPLAY=":$(head -1 "$work/display")"
for _ in $(seq 100); do xdotool getmouselocation >/dev/null 2>&1 && break; sleep 0.1; done
xdotool getmouselocation >/dev/null 2>&1 || fail "Xvfb on $DISPLAY does not answer"

# Waits up to $2 seconds (default 15) for a shell condition.
wait_for() { for _ in $(seq $((${2:-15} * 10))); do eval "$1" && return 0; sleep 0.1; done; return 1; }
# The frames (NNNN.jpg) in a folder.
frames_in() { ls "$1" 2>/dev/null | grep -c '^[0-9][0-9][0-9][0-9]\.jpg$'; }
# The window of jello on screen: only once it is mapped does it get the keys sent to it.
find_window() { xdotool search --onlyvisible --name "^Jello cube$" 2>/dev/null | head -1; }

# In a sanitized build, the GLX driver that the window dlopens keeps its buffers to exit and is
# unloaded by then, so LeakSanitizer cannot name (or be told to ignore) it: leaks are checked
# in the off-screen runs, not in the window's.
launch() {
  ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" "$jello" "$@" >out 2>err &
  app=$!
  wait_for 'window=$(find_window); [ -n "$window" ]'
}
# start_jello ARGS...: jello's window in the current folder, its stdout in out, stderr in err;
# sets $app and $window. Once more if the first start found no window (a display that was
# still settling, seen once).
start_jello() {
  launch "$@" || { kill "$app" 2>/dev/null; wait "$app" 2>/dev/null; launch "$@"; } ||
    fail "no window titled 'Jello cube' for jello $*"
}
key() { xdotool key --window "$window" "$@"; }
# ESC, then jello's exit status in $status.
quit_jello() {
  key Escape
  wait_for '! kill -0 $app 2>/dev/null' || fail "ESC did not close the window"
  wait "$app"
  status=$?
  app=
}
