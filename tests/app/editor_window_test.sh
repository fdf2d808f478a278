#!/usr/bin/env bash
# End-to-end: the real editor window under Xvfb, driven by xdotool. Paints a stroke on a copy of the
# bunny, saves (Ctrl+S), undoes, saves, redoes, saves, quits; saved_files_check judges the files.
# Usage (ctest runs it): editor_window_test.sh RGBSUB SAVED_FILES_CHECK BUNNY.obj
set -euo pipefail
rgbsub=$1 check=$2 bunny=$3
work=$(mktemp -d)
trap 'kill "$editor_pid" 2>/dev/null || true; rm -rf "$work"' EXIT
editor_pid=
cp "$bunny" "$work/mesh.obj"

"$rgbsub" edit "$work/mesh.obj" >"$work/editor.log" 2>&1 &
editor_pid=$!
window=$(timeout 30 xdotool search --sync --name '^mesh.obj - rgbsub$' | head -n 1)
sleep 1

# Save, then keep a copy: the editor saves over its own file.
save_as() {
  xdotool key --clearmodifiers ctrl+s
  sleep 1
  cp "$work/mesh.obj" "$work/$1.obj"
}

x0=340 y0=440 x1=560 y1=440
xdotool mousemove --window "$window" $x0 $y0
sleep 0.3
xdotool mousedown 1
sleep 0.2
for x in $(seq $((x0 + 20)) 20 $x1); do
  xdotool mousemove --window "$window" "$x" $y0
  sleep 0.05
done
sleep 0.2
xdotool mouseup 1
sleep 1
save_as painted
xdotool key --clearmodifiers ctrl+z
sleep 1
save_as undone
xdotool key --clearmodifiers ctrl+shift+z
sleep 1
save_as redone
xdotool key --clearmodifiers ctrl+q
for _ in $(seq 50); do kill -0 "$editor_pid" 2>/dev/null || break; sleep 0.2; done
if kill -0 "$editor_pid" 2>/dev/null; then
  echo "the editor did not quit on Ctrl+Q after saving" >&2
  exit 1
fi
wait "$editor_pid" || { echo "the editor exited with an error:" >&2; cat "$work/editor.log" >&2; exit 1; }
"$check" "$bunny" "$work/painted.obj" "$work/undone.obj" "$work/redone.obj" $x0 $y0 $x1 $y1
