#!/usr/bin/env bash
# Timed CLI benchmark of the LOD driver (issue 29): on every mesh of the benchmark set, `apply budget B`
# and the whole-surface `max-edge` and `tolerance` lines against `apply level k`, k the first uniform
# level with more triangles than the line's result, per output triangle as whole processes; and the
# engine's time per split (`apply --timings`) of the budget against the region path (`level k` in a
# sphere holding the mesh) and whole-mesh `level k`. Every measure of a mesh runs interleaved, REPEAT
# times, and the medians are compared, so that a busy machine slows every side alike.
#
#   tests/bench/budget_speed.sh [BUILD_DIR] [REPEAT] [MESHES...]
#
# MESHES are names of the set (default: all): bunny (3,674 triangles, assets/), torus52k (make_bench_mesh),
# scan (59k, scan-like) and mixed (26k, triangles of very different sizes), both by make_irregular_mesh.py.
# LINES (environment, default "budget max_edge tolerance") picks the lines timed: the whole-surface
# tolerance is far slower (its criterion), so `LINES="budget max_edge"` leaves it out; budget must stay.
# Prints one line per mesh and measure; docs/benchmarks.md's budget table is copied from it.
set -euo pipefail

build=${1:-build}
repeat=${2:-5}
shift $(($# > 2 ? 2 : $#))
meshes=("$@")
[[ ${#meshes[@]} -gt 0 ]] || meshes=(bunny torus52k scan mixed)
read -r -a lines <<< "${LINES:-budget max_edge tolerance}"
[[ " ${lines[*]} " == *" budget "* ]] || { echo "budget_speed: LINES must include budget (the region path is timed at its level)" >&2; exit 1; }
rgbsub=$build/rgbsub
here="$(cd "$(dirname "$0")" && pwd)"
work=$(mktemp -d "${TMPDIR:-/tmp}/rgbsub_budget_speed.XXXXXX")
trap 'rm -rf "$work"' EXIT
[[ -x $rgbsub && -x $build/tests/bench/make_bench_mesh ]] || { echo "budget_speed: build rgbsub and make_bench_mesh first" >&2; exit 1; }

cp "$here/../../assets/bunny.obj" "$work/bunny.obj"
"$build/tests/bench/make_bench_mesh" 204 128 "$work/torus52k.obj"
/usr/bin/python3 "$here/make_irregular_mesh.py" scan "$here/../../assets/bunny.obj" "$work/scan.obj"
/usr/bin/python3 "$here/make_irregular_mesh.py" mixed 160 80 "$work/mixed.obj"

now() { date +%s.%N; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
triangles_of() { grep -c '^f ' "$1"; }
# The engine milliseconds and splits of the first line of an `apply --timings` report.
engine_ms() { sed -n 1p "$1" | sed -E 's/.*: ([0-9.e+-]+) ms, ([0-9]+) splits.*/\1/'; }
engine_splits() { sed -n 1p "$1" | sed -E 's/.*: ([0-9.e+-]+) ms, ([0-9]+) splits.*/\2/'; }
# The first uniform level of MESH with more than N triangles.
level_above() {
    local faces k=0
    faces=$(triangles_of "$1")
    while ((faces <= $2)); do faces=$((faces * 4)); k=$((k + 1)); done
    echo "$k"
}
# time_run NAME SCRIPT MESH: one whole `apply` process; appends its seconds per output triangle to
# NAME.s and its engine ns per split (a second run, with --timings) to NAME.ns.
time_run() {
    local t0 t1
    t0=$(now); "$rgbsub" apply "$work/$3.obj" "$2" -o "$work/out.obj" > /dev/null; t1=$(now)
    echo "($t1 - $t0) / $(triangles_of "$work/out.obj")" | bc -l >> "$work/$1.s"
    "$rgbsub" apply "$work/$3.obj" "$2" -o "$work/out.obj" --timings > "$work/t.txt"
    echo "$(engine_ms "$work/t.txt") * 1000000 / $(engine_splits "$work/t.txt")" | bc -l >> "$work/$1.ns"
}

budget_of() { case $1 in bunny) echo 700000 ;; *) echo 1500000 ;; esac; }
for mesh in "${meshes[@]}"; do
    budget=$(budget_of "$mesh")
    echo "budget $budget" > "$work/budget.txt"
    echo "max-edge 0.15%" > "$work/max_edge.txt"
    echo "tolerance 0.01%" > "$work/tolerance.txt"
    # The uniform levels above each line's result.
    declare -A level=()
    for line in "${lines[@]}"; do
        "$rgbsub" apply "$work/$mesh.obj" "$work/$line.txt" -o "$work/out.obj" > /dev/null
        level[$line]=$(level_above "$work/$mesh.obj" "$(triangles_of "$work/out.obj")")
        echo "level ${level[$line]}" > "$work/level_$line.txt"
    done
    echo "level ${level[budget]} sphere 0 0 0 1e6" > "$work/region.txt"
    rm -f "$work"/*.s "$work"/*.ns
    for _ in $(seq "$repeat"); do
        for line in "${lines[@]}"; do
            time_run "$line" "$work/$line.txt" "$mesh"
            time_run "level_$line" "$work/level_$line.txt" "$mesh"
        done
        time_run region "$work/region.txt" "$mesh"
    done
    ns() { echo "$(median < "$work/$1.s") * 1000000000" | bc -l; }
    for line in "${lines[@]}"; do
        printf '%s: %s per output triangle %.0f ns, level %d %.0f ns, ratio %.2f; engine per split %.0f ns, level %d %.0f ns, ratio %.2f\n' \
            "$mesh" "$(cat "$work/$line.txt")" "$(ns "$line")" "${level[$line]}" "$(ns "level_$line")" \
            "$(echo "$(ns "$line") / $(ns "level_$line")" | bc -l)" "$(median < "$work/$line.ns")" "${level[$line]}" \
            "$(median < "$work/level_$line.ns")" "$(echo "$(median < "$work/$line.ns") / $(median < "$work/level_$line.ns")" | bc -l)"
    done
    printf '%s: region path (level %d in a sphere holding the mesh) per split %.0f ns, %.2fx whole-mesh level; budget per split %.2fx the region path\n' \
        "$mesh" "${level[budget]}" "$(median < "$work/region.ns")" \
        "$(echo "$(median < "$work/region.ns") / $(median < "$work/level_budget.ns")" | bc -l)" \
        "$(echo "$(median < "$work/budget.ns") / $(median < "$work/region.ns")" | bc -l)"
done
