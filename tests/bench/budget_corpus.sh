#!/usr/bin/env bash
# budget_corpus.sh: fingerprints what the LOD driver makes (`budget`, `max-edge`, `tolerance` over the
# whole mesh, through `apply` and `refine`) on regular and irregular meshes, so that a change to the
# driver's speed machinery is checked byte for byte against the binary before it.
#
#   tests/bench/budget_corpus.sh RGBSUB OUT_DIR     runs the corpus, writes OUT_DIR/SHA256SUMS and CANONICAL
#   diff OLD/SHA256SUMS NEW/SHA256SUMS               identical sums: identical outputs and messages
#   diff OLD/CANONICAL NEW/CANONICAL                 identical: the same meshes (canonical_obj.py)
#
# The meshes: the bunny, the cat's head, the machined part (sharp features: the driver's general
# way), a 52k torus (make_bench_mesh, next to RGBSUB in tests/bench/), and make_irregular_mesh.py's
# scan-like 59k mesh and torus of mixed triangle sizes. Each output is checked canonical too: the
# same budget from the base and from a mesh that already holds detail (the run removes it first) give
# the same mesh (canonical_obj.py: the files list the vertices in slot order, which the removals'
# freed slots change). About 20 minutes on two busy cores.
set -euo pipefail

[[ $# -eq 2 ]] || { echo "usage: $0 RGBSUB OUT_DIR" >&2; exit 2; }
BIN="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
make_mesh="$(dirname "$BIN")/tests/bench/make_bench_mesh"
here="$(cd "$(dirname "$0")" && pwd)"
assets="$here/../../assets"
mkdir -p "$2"
[[ -z "$(ls -A "$2")" ]] || { echo "budget_corpus: $2 is not empty" >&2; exit 2; }
cd "$2"
mkdir in out log
export LC_ALL=C

cp "$assets/bunny.obj" "$assets/default.obj" "$assets/machined_part.obj" in/
"$make_mesh" 204 128 in/torus52k.obj
/usr/bin/python3 "$here/make_irregular_mesh.py" scan "$assets/bunny.obj" in/scan.obj
/usr/bin/python3 "$here/make_irregular_mesh.py" mixed 160 80 in/mixed.obj

failed=0
# run NAME ARGS...: rgbsub ARGS..., its stdout, stderr and exit code kept in log/NAME.
run() {
    local name=$1 rc=0
    shift
    "$BIN" "$@" >"log/$name.out" 2>"log/$name.err" </dev/null || rc=$?
    echo "$rc" >"log/$name.rc"
    [[ $rc -eq 0 ]] || { echo "budget_corpus: $name exited $rc" >&2; failed=1; }
}
script() { printf '%s\n' "$@" >"in/$1.txt"; }

for line in "budget 2000" "budget 20000" "budget 150000" "budget 700000" "max-edge 0.5%" "max-edge 0.2%" \
    "tolerance 0.1%" "level 2"; do
    name=${line// /_}
    name=${name//%/pc}
    printf '%s\n' "$line" >"in/$name.txt"
done
printf '%s\n' "level 3 sphere 0 0 0 1" "budget 20000" >in/detail_then_budget.txt

for mesh in bunny default machined_part torus52k scan mixed; do
    for s in budget_2000 budget_20000 budget_150000 max-edge_0.5pc; do
        run "$mesh-$s" apply "in/$mesh.obj" "in/$s.txt" -o "out/$mesh-$s.obj"
    done
    run "$mesh-detail_then_budget" apply "in/$mesh.obj" in/detail_then_budget.txt -o "out/$mesh-detail_then_budget.obj"
done
for mesh in bunny scan mixed; do
    run "$mesh-budget_700000" apply "in/$mesh.obj" in/budget_700000.txt -o "out/$mesh-budget_700000.obj"
    run "$mesh-max-edge_0.2pc" apply "in/$mesh.obj" in/max-edge_0.2pc.txt -o "out/$mesh-max-edge_0.2pc.obj"
    run "$mesh-refine-max-edge" refine "in/$mesh.obj" -o "out/$mesh-refine-max-edge.obj" --max-edge 0.3%
done
# Tolerances cost most (15 limit evaluations per triangle of the hierarchy looked at): smaller meshes.
for mesh in bunny default machined_part mixed; do
    run "$mesh-tolerance_0.1pc" apply "in/$mesh.obj" in/tolerance_0.1pc.txt -o "out/$mesh-tolerance_0.1pc.obj"
    run "$mesh-refine-tolerance" refine "in/$mesh.obj" -o "out/$mesh-refine-tolerance.obj" --tolerance 0.3%
done
# Canonical: a budget over a mesh with detail (removed first) ends where it ends from the base.
for mesh in bunny scan mixed; do
    run "$mesh-level2" apply "in/$mesh.obj" in/level_2.txt -o "out/$mesh-level2.obj"
    run "$mesh-level2-budget" apply "out/$mesh-level2.obj" in/budget_150000.txt -o "out/$mesh-level2-budget.obj"
    [[ $(/usr/bin/python3 "$here/canonical_obj.py" "out/$mesh-level2-budget.obj" | cut -d' ' -f1) == \
        $(/usr/bin/python3 "$here/canonical_obj.py" "out/$mesh-budget_150000.obj" | cut -d' ' -f1) ]] ||
        { echo "budget_corpus: $mesh: budget 150000 over level 2 differs from the budget from the base" >&2; failed=1; }
done
find in out log -type f | sort | xargs sha256sum >SHA256SUMS
/usr/bin/python3 "$here/canonical_obj.py" out/*.obj >CANONICAL
echo "budget_corpus: $(wc -l <SHA256SUMS) files fingerprinted in $PWD/SHA256SUMS"
exit $failed
