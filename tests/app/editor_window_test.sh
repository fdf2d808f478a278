#!/usr/bin/env bash
# End-to-end: the real editor window under Xvfb, driven by xdotool, on a copy of the bunny:
#   1. the pointer jumps onto the panel and drags there at once: nothing is painted (saved);
#   2. a stroke (saved), then the session's strokes saved as a script (Ctrl+E, Enter);
#   3. undo (saved), redo (saved), Ctrl+Q: a clean exit leaves no recovery copy;
#   4. `rgbsub apply` replays the script on the bunny, whole and in two halves with a save and a
#      reload between.
# saved_files_check judges the files.
# Usage (ctest runs it): editor_window_test.sh RGBSUB SAVED_FILES_CHECK BUNNY.obj
set -euo pipefail
rgbsub=$1 check=$2 bunny=$3
work=$(mktemp -d)
trap 'kill "$editor_pid" 2>/dev/null || true; rm -rf "$work"' EXIT
editor_pid=
cp "$bunny" "$work/mesh.obj"
export XDG_STATE_HOME="$work/state"  # the recovery copy stays in here

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

# 1. Onto the panel's empty lower part and pressed in the same instant, then dragged.
xdotool mousemove --window "$window" 1110 730 mousedown 1 mousemove --window "$window" 1160 700 mouseup 1
sleep 0.5
save_as panel

# 2. A stroke across the bunny (left of the panel).
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
xdotool key --clearmodifiers ctrl+e
sleep 0.5
# Held for a while: ImGui 1.86 sees a key only if it is down when a frame starts.
xdotool keydown Return
sleep 0.3
xdotool keyup Return
sleep 0.5

# 3.
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
if [ -n "$(ls -A "$XDG_STATE_HOME/rgbsub" 2>/dev/null)" ]; then
  echo "a clean exit left a recovery copy: $(ls "$XDG_STATE_HOME/rgbsub")" >&2
  exit 1
fi

# 4. The script, whole and cut at the brush line nearest its middle.
script="$work/mesh.lod"
[ -s "$script" ] || { echo "Ctrl+E, Enter wrote no script" >&2; exit 1; }
"$rgbsub" apply "$bunny" "$script" -o "$work/replayed.obj" >/dev/null
middle=$(($(wc -l <"$script") / 2))
cut=$(awk -v m="$middle" 'NR > m && /^brush / { print NR; exit }' "$script")
head -n $((cut - 1)) "$script" >"$work/first.lod"
tail -n +"$cut" "$script" >"$work/second.lod"
"$rgbsub" apply "$bunny" "$work/first.lod" -o "$work/half.obj" >/dev/null
"$rgbsub" apply "$work/half.obj" "$work/second.lod" -o "$work/halves.obj" >/dev/null

"$check" "$bunny" "$work/panel.obj" "$work/painted.obj" "$work/undone.obj" "$work/redone.obj" \
  "$work/replayed.obj" "$work/halves.obj" $x0 $y0 $x1 $y1
