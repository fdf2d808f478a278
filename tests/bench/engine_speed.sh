#!/usr/bin/env bash
# Timed CLI benchmark of the selective-refinement engine on the paths users take, against OpenMesh's
# LoopT where there is a twin. Every pair runs interleaved, REPEAT times, and the medians are compared,
# so that a busy machine slows both sides alike.
#
#   tests/bench/engine_speed.sh [BUILD_DIR] [REPEAT]
#
# Prints one line per measure; docs/benchmarks.md's engine speed table is copied from it.
set -euo pipefail

build=${1:-build}
repeat=${2:-5}
rgbsub=$build/rgbsub
make_mesh=$build/tests/bench/make_bench_mesh
openmesh=$build/tests/bench/openmesh_refine
work=$(mktemp -d "${TMPDIR:-/tmp}/rgbsub_engine_speed.XXXXXX")
trap 'rm -rf "$work"' EXIT

for tool in "$rgbsub" "$make_mesh" "$openmesh"; do
    [[ -x $tool ]] || { echo "engine_speed: $tool is missing (build the project first)" >&2; exit 1; }
done

now() { date +%s.%N; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# The engine milliseconds and splits of line N of an `apply --timings` report.
engine_ms() { sed -n "${2}p" "$1" | sed -E 's/.*: ([0-9.e+-]+) ms, ([0-9]+) splits.*/\1/'; }
engine_splits() { sed -n "${2}p" "$1" | sed -E 's/.*: ([0-9.e+-]+) ms, ([0-9]+) splits.*/\2/'; }
triangles_of() { grep -c '^f ' "$1"; }
# CPU seconds (user + system) of a command, on stdout; its own output is dropped. On a shared machine
# this varies far less than wall time, which here also holds the fsync of the saved file.
cpu_seconds() {
    local TIMEFORMAT='%3U %3S'
    { time "$@" > /dev/null 2>&1; } 2>&1 | awk '{ print $1 + $2 }'
}

"$make_mesh" 64 48 "$work/torus6k.obj"      # 6,144 triangles
"$make_mesh" 204 128 "$work/torus52k.obj"   # 52,224 triangles
"$make_mesh" 640 640 "$work/torus819k.obj"  # 819,200 triangles

echo "level 4" > "$work/level4.txt"
echo "level 4 sphere 0 0 0 1000" > "$work/level4_sphere.txt"
# The path users take: a ball over part of the mesh. This one holds the torus's half with x > 0.2
# or so (the torus lies around the z axis, radii 1 and 0.4).
echo "level 4 sphere 3 0 0 3" > "$work/level4_half.txt"
echo "level 3" > "$work/level3.txt"
echo "budget 1500000" > "$work/budget.txt"
printf 'level 1 sphere 100 100 100 0.5\nlevel 1 sphere 100 100 100 0.5\n' > "$work/miss.txt"

# 1. The whole process: rgbsub refine --level 4 against OpenMesh's read, LoopT, write.
: > "$work/refine.s"; : > "$work/openmesh.s"
for _ in $(seq "$repeat"); do
    t0=$(now); "$rgbsub" refine "$work/torus6k.obj" -o "$work/out.obj" --level 4; t1=$(now)
    "$openmesh" "$work/torus6k.obj" "$work/om.obj" 4 > "$work/om.txt"; t2=$(now)
    echo "$t1 - $t0" | bc -l >> "$work/refine.s"
    echo "$t2 - $t1" | bc -l >> "$work/openmesh.s"
done
refine_s=$(median < "$work/refine.s"); openmesh_s=$(median < "$work/openmesh.s")
printf 'whole process, 6k -> %d triangles: rgbsub refine %.3f s, OpenMesh %.3f s, ratio %.2f\n' \
    "$(triangles_of "$work/out.obj")" "$refine_s" "$openmesh_s" "$(echo "$refine_s / $openmesh_s" | bc -l)"

# 2. The engine per new vertex: apply --timings against OpenMesh's in-process build + LoopT + extraction.
: > "$work/engine.ns"; : > "$work/om.ns"; : > "$work/general.ns"; : > "$work/half.ns"
for _ in $(seq "$repeat"); do
    "$rgbsub" apply "$work/torus6k.obj" "$work/level4.txt" -o "$work/out.obj" --timings > "$work/t.txt"
    echo "$(engine_ms "$work/t.txt" 1) * 1000000 / $(engine_splits "$work/t.txt" 1)" | bc -l >> "$work/engine.ns"
    "$openmesh" "$work/torus6k.obj" "$work/om.obj" 4 | sed -E 's/.* ([0-9.]+) ns per new vertex.*/\1/' >> "$work/om.ns"
    "$rgbsub" apply "$work/torus6k.obj" "$work/level4_sphere.txt" -o "$work/out.obj" --timings > "$work/t.txt"
    echo "$(engine_ms "$work/t.txt" 1) * 1000000 / $(engine_splits "$work/t.txt" 1)" | bc -l >> "$work/general.ns"
    "$rgbsub" apply "$work/torus6k.obj" "$work/level4_half.txt" -o "$work/half.obj" --timings > "$work/t.txt"
    echo "$(engine_ms "$work/t.txt" 1) * 1000000 / $(engine_splits "$work/t.txt" 1)" | bc -l >> "$work/half.ns"
done
engine=$(median < "$work/engine.ns"); om=$(median < "$work/om.ns"); general=$(median < "$work/general.ns")
half=$(median < "$work/half.ns")
printf 'engine per new vertex, level 4: rgbsub %.0f ns, OpenMesh %.0f ns, ratio %.2f\n' "$engine" "$om" "$(echo "$engine / $om" | bc -l)"
printf 'general path (level 4 in a sphere holding the mesh) per split: %.0f ns, %.2fx the whole-mesh path\n' \
    "$general" "$(echo "$general / $engine" | bc -l)"
printf 'general path (level 4 in a sphere over half the mesh, %d of %d triangles) per split: %.0f ns, %.2fx the whole-mesh path\n' \
    "$(triangles_of "$work/half.obj")" "$(triangles_of "$work/out.obj")" "$half" "$(echo "$half / $engine" | bc -l)"

# 3. A budget against a uniform level, whole process, per output triangle: wall time and CPU time.
: > "$work/budget.s"; : > "$work/level3.s"; : > "$work/budget.cpu"; : > "$work/level3.cpu"
for _ in $(seq "$repeat"); do
    t0=$(now); "$rgbsub" apply "$work/torus52k.obj" "$work/budget.txt" -o "$work/budget.obj"; t1=$(now)
    "$rgbsub" apply "$work/torus52k.obj" "$work/level3.txt" -o "$work/level3.obj"; t2=$(now)
    budget_triangles=$(triangles_of "$work/budget.obj"); level3_triangles=$(triangles_of "$work/level3.obj")
    echo "($t1 - $t0) / $budget_triangles" | bc -l >> "$work/budget.s"
    echo "($t2 - $t1) / $level3_triangles" | bc -l >> "$work/level3.s"
    echo "$(cpu_seconds "$rgbsub" apply "$work/torus52k.obj" "$work/budget.txt" -o "$work/budget.obj") / $budget_triangles" | bc -l >> "$work/budget.cpu"
    echo "$(cpu_seconds "$rgbsub" apply "$work/torus52k.obj" "$work/level3.txt" -o "$work/level3.obj") / $level3_triangles" | bc -l >> "$work/level3.cpu"
done
budget=$(median < "$work/budget.s"); level3=$(median < "$work/level3.s")
budget_cpu=$(median < "$work/budget.cpu"); level3_cpu=$(median < "$work/level3.cpu")
# Each budget run is paired with the level-3 run next to it: the median of those ratios follows the
# machine's drift from minute to minute better than the ratio of the two medians; the range shows it.
pair_ratios() { paste "$1" "$2" | awk '{ print $1 / $2 }' | sort -g; }
ratio_summary() { local r; r=$(pair_ratios "$1" "$2"); printf '%.2f (pairs %.2f-%.2f)' "$(median <<< "$r")" "$(head -1 <<< "$r")" "$(tail -1 <<< "$r")"; }
printf 'budget 1500000 on 52k triangles: %.0f ns per output triangle, level 3 %.0f ns, ratio %.2f, median of pair ratios %s\n' \
    "$(echo "$budget * 1000000000" | bc -l)" "$(echo "$level3 * 1000000000" | bc -l)" "$(echo "$budget / $level3" | bc -l)" \
    "$(ratio_summary "$work/budget.s" "$work/level3.s")"
printf 'the same in CPU time: %.0f ns per output triangle, level 3 %.0f ns, ratio %.2f, median of pair ratios %s\n' \
    "$(echo "$budget_cpu * 1000000000" | bc -l)" "$(echo "$level3_cpu * 1000000000" | bc -l)" "$(echo "$budget_cpu / $level3_cpu" | bc -l)" \
    "$(ratio_summary "$work/budget.cpu" "$work/level3.cpu")"

# 4. A region request that touches nothing, on 819k triangles: the first builds the spatial index.
"$rgbsub" apply "$work/torus819k.obj" "$work/miss.txt" -o "$work/miss.obj" --timings > "$work/t.txt"
printf 'sphere touching nothing on 819k triangles: first request %s ms (index built), next %s ms\n' \
    "$(engine_ms "$work/t.txt" 1)" "$(engine_ms "$work/t.txt" 2)"
