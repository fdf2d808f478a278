#!/usr/bin/env bash
# End-to-end: opening a dense mesh in the real editor window under Xvfb, driven by xdotool, with
# `rgbsub edit --cage-above 5000` so that a bumped torus of 6,400 triangles counts as dense:
#   1. "Open it as a base mesh" opens the file unchanged (Ctrl+S writes it back: the same mesh);
#   2. "Make a cage" on a torus of 90,000 triangles shows the progress bar, and Esc stops it: the
#      document stays as it was (untitled, unchanged), nothing is written, a clean quit;
#   3. "Make a cage" on the 6,400-triangle torus: the cage appears as an unsaved untitled document, a
#      stroke refines it towards the detail, Ctrl+S opens the browser on dense_cage.obj beside the input
#      (never over it), Enter saves there. From outside: `rgbsub info` reads the file back and says it
#      carries detail to a level, the stroke refined it above level 0, every saved vertex lies on the
#      dense mesh (a closest-point check of dense_mesh_window.py's own), and the input is untouched.
# With RGBSUB_TEST_SCREENSHOTS=FOLDER the screen is kept there as PNGs at each step, to look at.
# Usage (ctest runs it): editor_dense_mesh_window_test.sh RGBSUB
set -euo pipefail

source "$(dirname "$0")/window_test_support.sh"
under_xvfb "xvfb xauth xdotool python3-meshio (numpy)" xvfb-run xauth xdotool /usr/bin/python3 -- "$0" "$@"

rgbsub=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
helper="/usr/bin/python3 $here/dense_mesh_window.py"
started=$(date +%s%N)
work=$(mktemp -d)
editor_pid=
trap 'if [[ -n "$editor_pid" ]]; then kill "$editor_pid" 2>/dev/null || true; fi; rm -rf "$work"' EXIT
export XDG_STATE_HOME="$work/state"  # the recovery copy stays in here
export XDG_CONFIG_HOME="$work/config"  # the settings too, the user's own untouched
mkdir -p "$work/files"
cd "$work/files"  # relative names: the dialog's text, and so its layout, does not depend on $TMPDIR
$helper torus 80 40 dense.obj  # 6,400 triangles: the cage is made in about a second
cp dense.obj base.obj
$helper torus 300 150 big.obj  # 90,000: its cage takes seconds, long enough to be stopped
cp dense.obj dense_input.obj

failed=0
# Progress with the milliseconds since the start, to see where a slow run spends its time.
step() { echo "[$((($(date +%s%N) - started) / 1000000)) ms] $*"; }
fail() {
  echo "FAILED: $*"
  failed=1
}
shot() {
  if [[ -n "${RGBSUB_TEST_SCREENSHOTS:-}" ]]; then $helper grab "$RGBSUB_TEST_SCREENSHOTS/$1.png"; fi
}
# The mean colour of a rectangle of the window (the window sits at the screen's corner).
shade() { /usr/bin/python3 "$here/screen_pixels.py" "$@"; }
# The question's buttons, where its layout (centred, as wide as its fixed text) puts them.
make_x=380 make_y=439 base_x=380 base_y=462
# Waits (up to a minute: the sanitizer build is slow) for the window's title.
wait_title() {
  local title deadline=$((SECONDS + 60))
  while (( SECONDS < deadline )); do
    title=$(xdotool getwindowname "$window")
    [[ "$title" == "$1" ]] && return 0
    sleep 0.1
  done
  fail "the window's title stayed '$title', not '$1'"
  return 1
}
# Starts the editor on FILE and waits for the question: both buttons in their own colour.
start() {
  "$rgbsub" edit "$1" --cage-above 5000 >"$work/editor.log" 2>&1 &
  editor_pid=$!
  window=$(timeout 30 xdotool search --sync --name '^untitled - rgbsub$' | head -n 1) || true
  if [[ -z "$window" ]]; then
    fail "no editor window on $1:"
    cat "$work/editor.log"
    return 1
  fi
  # The pointer rests in the window first: a click that arrives with the pointer from outside the
  # window is not a button press for ImGui (xdotool's jump, not a user's hand).
  xdotool mousemove --window "$window" 200 600
  local deadline=$((SECONDS + 60))
  while (( SECONDS < deadline )); do
    if [[ "$(shade 374 431 2 2)" == "46 80 120" && "$(shade 374 454 2 2)" == "46 80 120" ]]; then
      shot "$2"
      return 0
    fi
    sleep 0.1
  done
  fail "no dense-mesh question on $1"
  shot "$2"
  return 1
}
click() {
  xdotool mousemove --window "$window" "$1" "$2"
  sleep 0.3
  xdotool click 1
}
quit() {
  xdotool key --clearmodifiers ctrl+q
  for _ in $(seq 100); do kill -0 "$editor_pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$editor_pid" 2>/dev/null; then
    fail "the editor did not quit on Ctrl+Q"
    kill "$editor_pid"
  fi
  if ! wait "$editor_pid"; then
    fail "the editor exited with an error:"
    cat "$work/editor.log"
  fi
  editor_pid=
  if [[ -n "$(ls -A "$XDG_STATE_HOME/rgbsub" 2>/dev/null)" ]]; then fail "a clean exit left a recovery copy"; fi
  rm -rf "$XDG_STATE_HOME/rgbsub"  # after a failure, no recovery question in the next part
}
inputs="base.obj big.obj dense.obj dense_input.obj"

step "meshes written"
# 1. As a base mesh: the file as it was, its own document; Ctrl+S writes it back over itself.
if start base.obj 1-question; then
  click $base_x $base_y
  if wait_title "base.obj - rgbsub"; then
    before=$(stat -c '%i %y' base.obj)
    for _ in $(seq 30); do
      xdotool key --clearmodifiers ctrl+s
      sleep 0.5
      [[ "$(stat -c '%i %y' base.obj)" != "$before" ]] && break
    done
    $helper same_mesh dense.obj base.obj || fail "opened as a base mesh and saved, base.obj is not the mesh it was"
  fi
fi
quit
[[ "$(ls | xargs)" == "$inputs" ]] || fail "files after opening as a base mesh: $(ls | xargs)"

step "opened as a base mesh"
# 2. Make a cage, and stop it while the progress bar moves.
if start big.obj 2-question; then
  click $make_x $make_y
  # The progress bar's left end turns ImGui's yellow as the work goes on; Esc as soon as it does.
  progress=no
  deadline=$((SECONDS + 60))
  while (( SECONDS < deadline )); do
    read -r red green blue <<<"$(shade 432 408 6 6)"
    if (( red > 180 && green > 130 && blue < 60 )); then
      progress=yes
      break
    fi
  done
  shot 2-progress
  xdotool key Escape
  [[ "$progress" == yes ]] || fail "no progress bar while the cage of big.obj was made"
  sleep 0.5
  shot 2-stopped
  title=$(xdotool getwindowname "$window")
  [[ "$title" == "untitled - rgbsub" ]] || fail "after Esc on the cage's progress the window is '$title', not the untitled document it was"
  # Nothing on screen where the dialog was: the empty view's light background.
  read -r red green blue <<<"$(shade 540 360 200 100)"
  (( red > 200 && green > 200 && blue > 200 )) || fail "after Esc the middle of the window shows $red $green $blue, not the empty view"
fi
quit
[[ "$(ls | xargs)" == "$inputs" ]] || fail "a stopped cage wrote files: $(ls | xargs)"

step "stopped the cage"
# 3. Make a cage, paint, save where the editor proposes.
if start dense.obj 3-question; then
  click $make_x $make_y
  if wait_title "untitled* - rgbsub"; then
    # The progress dialog leaves the screen without further input: where it was, the cage or the
    # light background, not its dark box.
    sleep 0.5
    shot 3-cage
    read -r red green blue <<<"$(shade 450 370 380 70)"
    (( red > 120 && green > 120 && blue > 120 )) ||
      fail "half a second after the cage was made, the middle of the window shows $red $green $blue: the progress dialog left on screen?"
    step "cage made"
    # A stroke across the torus's left side, left of the panel.
    x0=260 y0=420 x1=460
    drag_stroke "$window" $x0 $y0 $x1
    shot 3-painted
    # The first save of a made document asks where, proposing NAME_cage.obj beside the input.
    xdotool key --clearmodifiers ctrl+s
    sleep 1
    shot 3-save-as
    xdotool key Return
    wait_title "dense_cage.obj - rgbsub" && shot 3-saved
  fi
fi
quit
step "saved the cage"
[[ "$(ls | xargs)" == "base.obj big.obj dense.obj dense_cage.obj dense_input.obj" ]] || fail "files after saving the cage: $(ls | xargs)"
cmp -s dense.obj dense_input.obj || fail "the dense input changed"
if [[ -f dense_cage.obj ]]; then
  info=$("$rgbsub" info dense_cage.obj) || fail "rgbsub info cannot read dense_cage.obj back"
  echo "$info" | grep -E "^adaptive state: restored from the file's #rgb lines" ||
    fail "rgbsub info does not restore dense_cage.obj's adaptive state"
  echo "$info" | grep -E "^detail: from dense.obj \(6400 triangles\), stored to levels" ||
    fail "rgbsub info does not say that dense_cage.obj carries the detail of dense.obj"
  echo "$info" | grep -E "^triangles per level:.* [1-9][0-9]*:" || fail "the stroke refined nothing above level 0"
  $helper on_mesh dense.obj dense_cage.obj || fail "vertices of dense_cage.obj lie off the dense mesh"
fi
step "checked the saved cage"
exit "$failed"
