#!/usr/bin/env bash
# The window's push (arrows) and jump (j) keys under Xvfb, in numbers: the run starts paused at
# step 0 (--steps 0) with its meshes exported 10 times a second, a key is pressed, p runs on, and
# the exported surfaces say how the jelly moved. Usage: window_keys_test.sh JELLO SCENES_DIR.
# Exit 77 (CTest's skip) when Xvfb or xdotool is missing.
set -u
jello=$1 scenes=$2
source "$(dirname "$0")/window_support.sh"
# window_support's, saying what jello said in the folder the run is in.
fail() { echo "FAILED: $*"; [ -f err ] && sed 's/^/  jello: /' err; exit 1; }

# The mean of an OBJ file's vertices, "x y z".
centroid() { awk '$1 == "v" { x += $2; y += $3; z += $4; n++ } END { printf "%.6f %.6f %.6f", x / n, y / n, z / n }' "$1"; }
# awk's test of "$1" (an expression in a b c d e f: two centroids), or fail saying $2.
check() { awk -v a="$3" -v b="$4" "BEGIN { split(a, p); split(b, q); exit !($1) }" || fail "$2 ($3 -> $4)"; }

# KEY SCENE FOLDER: the scene paused at its start, KEY pressed, then 0.2 s of its run exported.
run_after_key() {
  mkdir "$3" && cd "$3"
  start_jello --steps 0 --fps 10 --export meshes "$scenes/$2"
  wait_for 'grep -q "reached --steps 0" err && [ -s meshes/0000.obj ]' || fail "$2 did not pause at step 0"
  key "$1"
  wait_for 'grep -q "m/s added to every free point" err' || fail "$1 said nothing"
  key p
  wait_for '[ -s meshes/0002.obj ]' || fail "$2 did not run on after p"
  quit_jello
  [ "$status" -eq 0 ] || fail "jello exited with $status"
  cd "$work"
}

cd "$work"
# Right, seen from the default camera (azimuth 30 degrees, +z up): (-sin 30, cos 30, 0). The
# jelly in free fall for 0.2 s moves 1 m/s * 0.2 s = 0.2 m that way, none away from the camera,
# and falls g t^2 / 2 = 0.196 m.
run_after_key Right sphere-drop.toml push
a=$(centroid push/meshes/0000.obj) b=$(centroid push/meshes/0002.obj)
check '(q[1]-p[1]) * -0.5 + (q[2]-p[2]) * 0.8660254 > 0.19 && (q[1]-p[1]) * -0.5 + (q[2]-p[2]) * 0.8660254 < 0.21' "Right did not push 0.2 m to the right" "$a" "$b"
check '(q[1]-p[1]) * 0.8660254 + (q[2]-p[2]) * 0.5 < 0.005 && (q[1]-p[1]) * 0.8660254 + (q[2]-p[2]) * 0.5 > -0.005' "Right pushed toward or away from the camera" "$a" "$b"
check 'q[3]-p[3] < -0.18 && q[3]-p[3] > -0.21' "the pushed jelly did not fall as before" "$a" "$b"

# j: 3 m/s up. Free, the jelly would be 3 * 0.2 - 0.196 = 0.4 m higher 0.2 s later; hanging from
# two pinned corners (vertices 8 and 64 of the surface), which do not move at all, it swings up
# about them, its centroid 0.12 m higher. (That the key leaves the pinned points' velocities at
# zero is tested in Simulation.AddVelocity...: the integrators would keep them in place anyway.)
run_after_key j hanging.toml jump
a=$(centroid jump/meshes/0000.obj) b=$(centroid jump/meshes/0002.obj)
check 'q[3]-p[3] > 0.1' "j did not lift the jelly" "$a" "$b"
for vertex in 8 64; do
  [ "$(awk '$1 == "v"' jump/meshes/0000.obj | sed -n "${vertex}p")" = \
    "$(awk '$1 == "v"' jump/meshes/0002.obj | sed -n "${vertex}p")" ] || fail "pinned vertex $vertex moved"
done
echo "push: $(centroid push/meshes/0000.obj) -> $(centroid push/meshes/0002.obj); jump: $a -> $b"
