#!/usr/bin/env bash
# Saving and loading saved files of about 1M and 6M triangles, as whole rgbsub processes (issue 11
# item 15: `rgbsub info` on a saved file must take at most the time of the `rgbsub refine` that
# created it). For each size: `refine` (load a plain mesh, refine, save with state), `info` on the
# saved file and `refine --level 0` of it (load, coarsen, save), RUNS times each, interleaved so that
# a change in the machine's load hits all alike; wall and CPU seconds (min / median / max), peak
# memory, and the file's size split into its v/f lines and its #rgb state.
#
# Usage: tests/bench/saved_files_bench.sh BUILD_DIR [RUNS] [WORK_DIR]
#   BUILD_DIR holds the rgbsub binary; WORK_DIR (default: a new temporary folder, removed at the
#   end) receives the meshes (about 500 MB for the 6M case).
# Not a test: run it on demand, on a quiet machine (it prints the load average before and after).
set -euo pipefail

build=${1:?usage: saved_files_bench.sh BUILD_DIR [RUNS] [WORK_DIR]}
runs=${2:-5}
rgbsub=$(cd "$build" && pwd)/rgbsub
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
if [[ -n ${3:-} ]]; then
  work=$3
  mkdir -p "$work"
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi

# A torus of 54 x 54 quads cut into 5,832 triangles: level 5 gives 5,971,968.
torus() { awk -v m=54 -v n=54 -f "$source_dir/tests/bench/torus.awk"; }

# Prints "wall user+sys maxrss_kb" of one run of the command.
measure() {
  /usr/bin/time -o "$work/time.out" -f "%e %U %S %M" "$@" > /dev/null 2> /dev/null
  awk '{ printf "%.2f %.2f %d\n", $1, $2 + $3, $4 }' "$work/time.out"
}

# min / median / max of column $2 of file $1.
spread() {
  sort -g -k"$2","$2" "$1" | awk -v c="$2" '{ v[NR] = $c } END { printf "%.2f / %.2f / %.2f", v[1], v[int((NR + 1) / 2)], v[NR] }'
}

peak() { sort -n -k3,3 "$1" | tail -1 | awk '{ printf "%d MB", $3 / 1024 }'; }

echo "machine: $(nproc) cores, $(awk '/MemTotal/ { printf "%.0f GB", $2 / 1048576 }' /proc/meminfo); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
torus > "$work/torus54.obj"
for spec in "bunny-level4 $source_dir/assets/bunny.obj 4" "torus-level5 $work/torus54.obj 5"; do
  read -r name input level <<< "$spec"
  saved=$work/$name.obj
  rm -f "$work"/*.times
  for ((i = 0; i < runs; ++i)); do
    measure "$rgbsub" refine "$input" -o "$saved" --level "$level" >> "$work/refine.times"
    measure "$rgbsub" info "$saved" >> "$work/info.times"
    measure "$rgbsub" refine "$saved" -o "$work/coarse.obj" --level 0 >> "$work/level0.times"
  done
  triangles=$(head -1 "$saved" | sed 's/.*vertices, \([0-9]*\) triangles.*/\1/')
  body=$(grep -E '^(v|vt|vn|f) ' "$saved" | wc -c)
  state=$(grep '^#rgb' "$saved" | wc -c)
  total=$(wc -c < "$saved")
  echo
  echo "$name: $triangles triangles; file $((total / 1000000)) MB = v/f lines $((body / 1000000)) MB + state $((state / 1000000)) MB" \
       "(file / v-f lines = $(awk -v t="$total" -v b="$body" 'BEGIN { printf "%.3f", t / b }'))"
  echo "  seconds, min / median / max of $runs    wall                 CPU (user+sys)       peak memory"
  for step in refine info level0; do
    printf "  %-34s %-20s %-20s %s\n" "$step" "$(spread "$work/$step.times" 1)" "$(spread "$work/$step.times" 2)" "$(peak "$work/$step.times")"
  done
done
echo
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
