#!/usr/bin/env bash
# Launch benchmark: time from starting `rgbsub edit FILE` to its first frame, and to the frame that
# shows the file (read in the background meanwhile), under Xvfb with software GL. Makes the file when
# it is missing: the bunny at level 5 inside a sphere around its body, about 2M triangles.
# Usage: first_frame.sh RGBSUB [FILE.obj] [RUNS]    (run it under xvfb-run, or with DISPLAY set)
set -euo pipefail
rgbsub=$1
file=${2:-${TMPDIR:-/tmp}/rgbsub_first_frame_2M.obj}
runs=${3:-3}
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
if [ ! -f "$file" ]; then
  "$rgbsub" refine "$source_dir/assets/bunny.obj" -o "$file" --level 5 --sphere 0,4.8,0,4.5 >/dev/null
fi
"$rgbsub" info "$file" | grep -E '^faces:'
state=$(mktemp -d)
trap 'rm -rf "$state"' EXIT
for _ in $(seq "$runs"); do
  XDG_STATE_HOME="$state" "$rgbsub" edit "$file" --frames 2 | tr '\n' ' '
  echo
done
