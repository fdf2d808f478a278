#!/usr/bin/env bash
# Writing a set of levels of detail (issue 32: a 5-level LOD set of a 1M-triangle mesh written in at
# most 1.5x the time of writing its LOD0 alone), as whole rgbsub processes: a torus of 44 x 44 quads
# (3,872 triangles; level 4: 991,232), `rgbsub lods --levels 4,3,2,1,0` against `rgbsub refine
# --level 4` of the same input with the same positions (limit), for .glb and .ply; and `lods --levels 4`
# (the set's own work for LOD0 alone: its error and coverage). RUNS runs each, interleaved; wall seconds
# min / median / max and the ratio of the medians.
#
# Usage: tests/bench/lods_bench.sh BUILD_DIR [RUNS]
# Not a test: run it on demand, on a quiet machine (it prints the load average before and after).
set -euo pipefail

build=${1:?usage: lods_bench.sh BUILD_DIR [RUNS]}
runs=${2:-3}
rgbsub=$(cd "$build" && pwd)/rgbsub
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

awk -v m=44 -v n=44 -f "$(dirname "$0")/torus.awk" > "$work/torus.obj"

seconds() {
  /usr/bin/time -o "$work/time.out" -f "%e" "$@" > /dev/null 2> /dev/null
  cat "$work/time.out"
}

spread() { sort -g "$1" | awk '{ v[NR] = $1 } END { printf "%.2f / %.2f / %.2f", v[1], v[int((NR + 1) / 2)], v[NR] }'; }
median() { sort -g "$1" | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for ext in glb ply; do
  rm -f "$work"/*.times
  for ((k = 0; k < runs; k++)); do
    seconds "$rgbsub" refine "$work/torus.obj" --level 4 --positions limit -o "$work/lod0.$ext" >> "$work/lod0.times"
    seconds "$rgbsub" lods "$work/torus.obj" --levels 4 -o "$work/one.$ext" >> "$work/one.times"
    seconds "$rgbsub" lods "$work/torus.obj" --levels 4,3,2,1,0 -o "$work/set.$ext" >> "$work/set.times"
  done
  echo ".$ext: refine --level 4 (LOD0 alone) $(spread "$work/lod0.times") s; lods --levels 4 $(spread "$work/one.times") s;" \
       "lods --levels 4,3,2,1,0 $(spread "$work/set.times") s; set / LOD0 alone: $(awk -v a="$(median "$work/set.times")" -v b="$(median "$work/lod0.times")" 'BEGIN { printf "%.2f", a / b }')"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
