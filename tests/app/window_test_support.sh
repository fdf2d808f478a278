# Shared by the Xvfb window tests (editor_window_test.sh, editor_dense_mesh_window_test.sh), sourced
# after `set -euo pipefail`.

# under_xvfb PACKAGES TOOL... -- "$0" "$@": a missing tool is an error of the machine, reported
# with the Debian packages to install rather than skipped; then the script runs again, once, under a
# virtual X server of its own.
under_xvfb() {
  local packages=$1 tool
  shift
  while [[ "$1" != -- ]]; do
    tool=$1
    shift
    if ! command -v "$tool" >/dev/null; then
      echo "$(basename "$0"): $tool is missing: install the Debian packages $packages" \
           "(third_party/debian_packages.sh, RGBSUB_TEST_PACKAGES)" >&2
      exit 1
    fi
  done
  shift
  if [[ -z "${RGBSUB_UNDER_XVFB:-}" ]]; then
    RGBSUB_UNDER_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$@"
  fi
}

# drag_stroke WINDOW X0 Y0 X1: a left-button stroke along the row Y0, as a hand paints it: the press
# after the pointer rests, then a move every 20 pixels, and a second for the work it starts.
drag_stroke() {
  local window=$1 x0=$2 y0=$3 x1=$4 x
  xdotool mousemove --window "$window" "$x0" "$y0"
  sleep 0.3
  xdotool mousedown 1
  sleep 0.2
  for x in $(seq $((x0 + 20)) 20 "$x1"); do
    xdotool mousemove --window "$window" "$x" "$y0"
    sleep 0.05
  done
  sleep 0.2
  xdotool mouseup 1
  sleep 1
}
