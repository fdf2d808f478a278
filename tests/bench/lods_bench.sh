#!/usr/bin/env bash
# Writing a set of levels of detail against writing its LOD0 alone (issue 32: a 5-level LOD set of a
# 1M-triangle mesh in at most 1.5x the time), as whole rgbsub processes, wall time: the same input,
# the same LOD0 request, the same positions (limit) and the same output format, run as interleaved
# pairs (LOD0 alone, then the set) so that a busy machine's load falls on both alike.
#
#   torus-levels-glb   a torus of 44 x 44 quads (3,872 triangles; LOD0 991,232): `lods --levels
#                      4,3,2,1,0 -o set.glb` against `refine --level 4 --positions limit -o lod0.glb`
#   bunny-levels-obj   assets/bunny.obj (3,674; LOD0 940,544): the same with OBJ files (one per level,
#                      with the adaptive state, as refine writes it)
#   bunny-budgets-glb  the bunny: `lods --budgets 940000,235000,59000,15000,3700 -o set.glb` against
#                      `apply` of the script line `budget 940000` `--positions limit -o lod0.glb`
#
# Prints per case the wall seconds of each (min / median / max), the ratio of the medians and the
# median of the pairs' ratios, and the load average before and after. Tolerance sets are not timed
# here: the tolerance criterion itself makes about 20,000 triangles a second (docs/benchmarks.md).
#
# Usage: tests/bench/lods_bench.sh BUILD_DIR [RUNS] [CASE...]   (default 3 runs, every case)
# Not a test: run it on demand; say how busy the machine was.
set -euo pipefail

build=${1:?usage: lods_bench.sh BUILD_DIR [RUNS] [CASE...]}
runs=${2:-3}
shift $(($# < 2 ? $# : 2))
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(torus-levels-glb bunny-levels-obj bunny-budgets-glb)
rgbsub=$(cd "$build" && pwd)/rgbsub
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

awk -v m=44 -v n=44 -f "$here/torus.awk" > "$work/torus.obj"
cp "$here/../../assets/bunny.obj" "$work/bunny.obj"
echo "budget 940000" > "$work/lod0.script"

seconds() {
  /usr/bin/time -o "$work/time.out" -f "%e" "$@" > /dev/null 2> /dev/null
  cat "$work/time.out"
}
spread() { sort -g "$1" | awk '{ v[NR] = $1 } END { printf "%.2f / %.2f / %.2f", v[1], v[int((NR + 1) / 2)], v[NR] }'; }
median() { sort -g "$1" | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for name in "${cases[@]}"; do
  case $name in
    torus-levels-glb)
      alone=(refine "$work/torus.obj" --level 4 --positions limit -o "$work/lod0.glb")
      set=(lods "$work/torus.obj" --levels 4,3,2,1,0 -o "$work/set.glb") ;;
    bunny-levels-obj)
      alone=(refine "$work/bunny.obj" --level 4 --positions limit -o "$work/lod0.obj")
      set=(lods "$work/bunny.obj" --levels 4,3,2,1,0 -o "$work/set.obj") ;;
    bunny-budgets-glb)
      alone=(apply "$work/bunny.obj" "$work/lod0.script" --positions limit -o "$work/lod0.glb")
      set=(lods "$work/bunny.obj" --budgets 940000,235000,59000,15000,3700 -o "$work/set.glb") ;;
    *) echo "unknown case $name" >&2; exit 1 ;;
  esac
  rm -f "$work"/*.times
  for ((k = 0; k < runs; k++)); do
    a=$(seconds "$rgbsub" "${alone[@]}")
    b=$(seconds "$rgbsub" "${set[@]}")
    echo "$a" >> "$work/alone.times"
    echo "$b" >> "$work/set.times"
    awk -v a="$a" -v b="$b" 'BEGIN { print b / a }' >> "$work/ratio.times"
  done
  echo "$name: LOD0 alone $(spread "$work/alone.times") s; the set $(spread "$work/set.times") s;" \
       "ratio of the medians $(awk -v a="$(median "$work/set.times")" -v b="$(median "$work/alone.times")" 'BEGIN { printf "%.2f", a / b }');" \
       "median pair ratio $(median "$work/ratio.times" | awk '{ printf "%.2f", $1 }')"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
