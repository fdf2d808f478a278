#!/usr/bin/env bash
# End-to-end: the real editor window under Xvfb, driven by xdotool, on a copy of the bunny:
#   1. the unchanged bunny is saved (Ctrl+S writes even an unchanged mesh);
#   2. the pointer jumps onto the panel and drags there at once: nothing is painted (saved);
#   3. a stroke (saved), then the session's strokes saved as a script (Ctrl+E, Enter);
#   4. undo (saved), redo with Ctrl+Shift+Z (saved), undo and redo with Ctrl+Y (saved), the file
#      browser opened by a quick click on the panel (seen on screen, tests/app/screen_pixels.py)
#      and closed by a tapped Esc, Ctrl+Q: a clean exit leaves no recovery copy;
#   5. `rgbsub apply` replays the script on the bunny, whole and in two halves with a save and a
#      reload between.
# Undo must give back the file as opened and both redos the painted one, byte for byte, and so must
# the drag on the panel; saved_files_check judges the files as meshes.
# Usage (ctest runs it): editor_window_test.sh RGBSUB SAVED_FILES_CHECK BUNNY.obj
set -euo pipefail

source "$(dirname "$0")/window_test_support.sh"
under_xvfb "xvfb xauth xdotool" xvfb-run xauth xdotool -- "$0" "$@"

rgbsub=$1 check=$2 bunny=$3
work=$(mktemp -d)
editor_pid=
trap 'if [[ -n "$editor_pid" ]]; then kill "$editor_pid" 2>/dev/null || true; fi; rm -rf "$work"' EXIT
cp "$bunny" "$work/mesh.obj"
export XDG_STATE_HOME="$work/state"  # the recovery copy stays in here
export XDG_CONFIG_HOME="$work/config"  # the settings too, the user's own untouched
# The sections above File start folded, as a user's settings can keep them, so that rows added to
# them do not move File's "..." button that step 4 clicks.
mkdir -p "$XDG_CONFIG_HOME/rgbsub"
printf 'panel.section.%s = false\n' Brush 'Whole mesh' 'Detail by size, accuracy, view' \
  >"$XDG_CONFIG_HOME/rgbsub/settings.txt"

"$rgbsub" edit "$work/mesh.obj" >"$work/editor.log" 2>&1 &
editor_pid=$!
window=$(timeout 30 xdotool search --sync --name '^mesh.obj - rgbsub$' | head -n 1)
sleep 1

# Save, then keep a copy: the editor saves over its own file. A save asked for while a job (a stroke
# or an undo) still runs is refused, so on a slow machine it is asked again until the file is
# replaced (a save writes a new file and renames it over the old one: a new inode).
save_as() {
  local before
  before=$(stat -c '%i %y' "$work/mesh.obj")
  for _ in $(seq 30); do
    xdotool key --clearmodifiers ctrl+s
    sleep 1
    [[ "$(stat -c '%i %y' "$work/mesh.obj")" != "$before" ]] && break
  done
  cp "$work/mesh.obj" "$work/$1.obj"
}
key() {
  xdotool key --clearmodifiers "$1"
  sleep 1
}
# Whether the middle of the screen, where the file browser opens, shows its dark listing.
browser_area_dark() {
  eval "$(xdotool getwindowgeometry --shell "$window")"
  local shade
  shade=$(python3 "$(dirname "$0")/screen_pixels.py" $((X + 380)) $((Y + 300)) 20 20) || { echo unreadable; return; }
  read -r red green blue <<<"$shade"
  if (( red < 80 && green < 80 && blue < 80 )); then echo yes; else echo no; fi
}

# 1.
save_as opened

# 2. Onto the panel's empty lower part and pressed in the same instant, then dragged.
xdotool mousemove --window "$window" 1110 730 mousedown 1 mousemove --window "$window" 1160 700 mouseup 1
sleep 0.5
save_as panel

# 3. A stroke across the bunny (left of the panel).
x0=340 y0=440 x1=560 y1=440
drag_stroke "$window" $x0 $y0 $x1
save_as painted
xdotool key --clearmodifiers ctrl+e
sleep 0.5
# Tapped at once (press and release between two frames): the window's queue hands both to ImGui.
xdotool key Return
sleep 0.5

# 4.
key ctrl+z
save_as undone
key ctrl+shift+z
save_as redone
key ctrl+z
key ctrl+y
save_as redone_with_y
# The file browser, by a quick click on the panel's "..." with the pointer left resting there, shows
# without further input, and a tapped Esc closes it (else it would keep Ctrl+Q from the editor).
# The panel's rows do not move with the document's state; only the crease rows, outside any section,
# lie above the button.
xdotool mousemove --window "$window" 1197 262 click 1
sleep 1
browser_shown=$(browser_area_dark)
key Escape
browser_left=$(browser_area_dark)
xdotool key --clearmodifiers ctrl+q
for _ in $(seq 50); do kill -0 "$editor_pid" 2>/dev/null || break; sleep 0.2; done
if kill -0 "$editor_pid" 2>/dev/null; then
  echo "the editor did not quit on Ctrl+Q after saving" >&2
  exit 1
fi
wait "$editor_pid" || { echo "the editor exited with an error:" >&2; cat "$work/editor.log" >&2; exit 1; }
editor_pid=
if [ -n "$(ls -A "$XDG_STATE_HOME/rgbsub" 2>/dev/null)" ]; then
  echo "a clean exit left a recovery copy: $(ls "$XDG_STATE_HOME/rgbsub")" >&2
  exit 1
fi
# The settings outlive the session: the file opened heads the recent files.
if ! grep -qxF "recent = $work/mesh.obj" "$XDG_CONFIG_HOME/rgbsub/settings.txt" 2>/dev/null; then
  echo "the editor kept no settings naming $work/mesh.obj as recent" >&2
  exit 1
fi

# 5. The script, whole and cut at the brush line nearest its middle.
script="$work/mesh.lod"
[ -s "$script" ] || { echo "Ctrl+E, Enter wrote no script" >&2; exit 1; }
"$rgbsub" apply "$bunny" "$script" -o "$work/replayed.obj" >/dev/null
middle=$(($(wc -l <"$script") / 2))
cut=$(awk -v m="$middle" 'NR > m && /^brush / { print NR; exit }' "$script")
head -n $((cut - 1)) "$script" >"$work/first.lod"
tail -n +"$cut" "$script" >"$work/second.lod"
"$rgbsub" apply "$bunny" "$work/first.lod" -o "$work/half.obj" >/dev/null
"$rgbsub" apply "$work/half.obj" "$work/second.lod" -o "$work/halves.obj" >/dev/null

failed=0
same_bytes() {
  if cmp -s "$work/$1.obj" "$work/$2.obj"; then
    echo "ok: $1.obj and $2.obj are the same bytes"
  else
    echo "FAILED: $1.obj and $2.obj differ ($3)"
    failed=1
  fi
}
if [[ "$browser_shown" == yes && "$browser_left" == no ]]; then
  echo "ok: a quick click shows the file browser at once and a tapped Esc closes it"
else
  echo "FAILED: the file browser after a quick click: shown=$browser_shown; after Esc: shown=$browser_left"
  failed=1
fi
same_bytes panel opened "a drag on the panel paints nothing"
same_bytes undone opened "Ctrl+Z restores the mesh as opened"
same_bytes redone painted "Ctrl+Shift+Z restores the painted mesh"
same_bytes redone_with_y painted "Ctrl+Y restores the painted mesh"
"$check" "$bunny" "$work/panel.obj" "$work/painted.obj" "$work/undone.obj" "$work/redone.obj" \
  "$work/replayed.obj" "$work/halves.obj" $x0 $y0 $x1 $y1 || failed=1
exit "$failed"
