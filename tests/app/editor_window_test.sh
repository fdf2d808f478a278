#!/usr/bin/env bash
# End-to-end: the real editor window under Xvfb, driven by xdotool. Saves the unchanged bunny
# (Ctrl+S), paints a stroke on it and saves, undoes (Ctrl+Z) and saves, redoes with Ctrl+Shift+Z and
# with Ctrl+Y and saves each time, then quits. Undo must give back the unchanged file and both redos
# the painted one, byte for byte; saved_files_check judges the painted file.
# Usage (ctest runs it): editor_window_test.sh RGBSUB SAVED_FILES_CHECK BUNNY.obj
set -euo pipefail

# A missing tool is an error of the machine, reported as such rather than skipped.
for tool in xvfb-run xauth xdotool; do
  if ! command -v "$tool" >/dev/null; then
    echo "editor_window_test.sh: $tool is missing: install the Debian packages xvfb xauth xdotool" \
         "(third_party/debian_packages.sh, RGBSUB_TEST_PACKAGES)" >&2
    exit 1
  fi
done
if [[ -z "${RGBSUB_UNDER_XVFB:-}" ]]; then
  RGBSUB_UNDER_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"
fi

rgbsub=$1 check=$2 bunny=$3
work=$(mktemp -d)
editor_pid=
trap 'if [[ -n "$editor_pid" ]]; then kill "$editor_pid" 2>/dev/null || true; fi; rm -rf "$work"' EXIT
cp "$bunny" "$work/mesh.obj"

"$rgbsub" edit "$work/mesh.obj" >"$work/editor.log" 2>&1 &
editor_pid=$!
window=$(timeout 30 xdotool search --sync --name '^mesh.obj - rgbsub$' | head -n 1)
sleep 1

# Ctrl+S, then keep a copy: the editor saves over its own file. Ctrl+S writes even an unchanged mesh.
save_as() {
  xdotool key --clearmodifiers ctrl+s
  sleep 1
  cp "$work/mesh.obj" "$work/$1.obj"
}
key() {
  xdotool key --clearmodifiers "$1"
  sleep 1
}

save_as opened
x0=540 y0=440 x1=760 y1=440
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
key ctrl+z
save_as undone
key ctrl+shift+z
save_as redone
key ctrl+z
key ctrl+y
save_as redone_with_y
key ctrl+q
for _ in $(seq 50); do kill -0 "$editor_pid" 2>/dev/null || break; sleep 0.2; done
if kill -0 "$editor_pid" 2>/dev/null; then
  echo "the editor did not quit on Ctrl+Q after saving" >&2
  exit 1
fi
wait "$editor_pid" || { echo "the editor exited with an error:" >&2; cat "$work/editor.log" >&2; exit 1; }
editor_pid=

failed=0
same_bytes() {
  if cmp -s "$work/$1.obj" "$work/$2.obj"; then
    echo "ok: $1.obj and $2.obj are the same bytes"
  else
    echo "FAILED: $1.obj and $2.obj differ ($3)"
    failed=1
  fi
}
same_bytes undone opened "Ctrl+Z restores the mesh as opened"
same_bytes redone painted "Ctrl+Shift+Z restores the painted mesh"
same_bytes redone_with_y painted "Ctrl+Y restores the painted mesh"
"$check" "$bunny" "$work/painted.obj" $x0 $y0 $x1 $y1 || failed=1
exit "$failed"
