#!/usr/bin/env bash
# output_corpus.sh: runs a fixed corpus of rgbsub commands and fingerprints every byte they produce.
#
# Why: a refactor (moving files, renaming, splitting units) must not change any output byte. Run
# this corpus with the binary built before the refactor and with the one built after it, into two
# folders, and compare the two SHA256SUMS files: identical sums mean identical OBJ, glTF and PNG
# outputs, identical messages (stdout and stderr kept apart) and identical exit codes.
#
# Usage:
#   tests/output_corpus.sh RGBSUB_BINARY OUT_DIR     run the corpus into OUT_DIR (new or empty)
#   tests/output_corpus.sh --compare OUT1 OUT2       diff OUT1/SHA256SUMS OUT2/SHA256SUMS (exit 0 if equal)
# For example:
#   tests/output_corpus.sh /tmp/base/build/rgbsub /tmp/corpus-base
#   tests/output_corpus.sh build/rgbsub /tmp/corpus-new
#   diff /tmp/corpus-base/SHA256SUMS /tmp/corpus-new/SHA256SUMS   # or: --compare, same thing
#
# OUT_DIR gets in/ (the inputs: assets/*.obj copied, small meshes, materials and scripts written
# here with printf), out/ (every file the commands write), log/NNN-NAME.txt (per command: the
# command line, its stdout, its stderr, its exit code) and SHA256SUMS (every file but itself).
# Commands run with OUT_DIR as the working directory and relative paths, under a fixed name
# (argv[0] = rgbsub), locale (C), time zone and empty HOME/XDG folders, so that two runs into
# different folders, or with binaries in different places, give the same sums. --timings is never
# used (the only time-dependent output); any absolute OUT_DIR path in a message would be replaced by
# <OUT> (none is printed today). Compare runs made on one machine: the default --max-triangles and
# the editor panel's history bound (in the edit screenshots) follow the machine's physical memory.
# The corpus takes about half a minute on two cores.
#
# The script exits 1 (after writing SHA256SUMS) when a command's exit code is not the one the
# corpus expects (0, or a failure for the error cases), so a broken binary is noticed even before
# comparing.
set -euo pipefail

usage() {
    echo "usage: $0 RGBSUB_BINARY OUT_DIR     (run the corpus into OUT_DIR, new or empty)" >&2
    echo "       $0 --compare OUT1 OUT2       (diff OUT1/SHA256SUMS OUT2/SHA256SUMS)" >&2
    exit 2
}

if [[ $# -eq 3 && $1 == --compare ]]; then
    if diff -u "$2/SHA256SUMS" "$3/SHA256SUMS"; then
        echo "output_corpus: identical ($(wc -l <"$2/SHA256SUMS") files)"
        exit 0
    fi
    echo "output_corpus: the outputs differ (lines above)" >&2
    exit 1
fi
[[ $# -eq 2 ]] || usage

bin_arg=$1
out_arg=$2
[[ -f $bin_arg && -x $bin_arg ]] || { echo "output_corpus: $bin_arg is not an executable" >&2; exit 2; }
BIN="$(cd "$(dirname "$bin_arg")" && pwd)/$(basename "$bin_arg")"
mkdir -p "$out_arg"
if [[ -n "$(ls -A "$out_arg")" ]]; then
    echo "output_corpus: $out_arg is not empty" >&2
    exit 2
fi
OUT="$(cd "$out_arg" && pwd)"
ASSETS="$(cd "$(dirname "$0")/../assets" && pwd)"

scratch_home="$(mktemp -d)"
trap 'rm -rf "$scratch_home"' EXIT
export HOME="$scratch_home" XDG_STATE_HOME="$scratch_home/state" XDG_CONFIG_HOME="$scratch_home/config"
export XDG_CACHE_HOME="$scratch_home/cache" XDG_DATA_HOME="$scratch_home/data"
export LC_ALL=C TZ=UTC
unset DISPLAY WAYLAND_DISPLAY LANG LANGUAGE

cd "$OUT"
mkdir in out log

# ---------------------------------------------------------------------------------------------
# Running commands
# ---------------------------------------------------------------------------------------------

count=0
unexpected=0

# Replaces every occurrence of the absolute OUT_DIR in FILE by <OUT> (a safety net: none today).
scrub() {
    if grep -qF -- "$OUT" "$1"; then
        awk -v s="$OUT" '{ out = ""; while ((i = index($0, s)) > 0) { out = out substr($0, 1, i - 1) "<OUT>"; $0 = substr($0, i + length(s)) } print out $0 }' \
            "$1" >"$1.scrubbed"
        mv "$1.scrubbed" "$1"
    fi
}

# run EXPECT NAME ARGS...: runs 'rgbsub ARGS...' and logs it as log/NNN-NAME.txt. EXPECT is 0 (must
# succeed), 'fail' (must fail) or a particular exit code.
run() {
    local expect=$1 name=$2
    shift 2
    count=$((count + 1))
    local log
    log="log/$(printf '%03d' "$count")-$name.txt"
    local rc=0
    (exec -a rgbsub "$BIN" "$@") >"$log.stdout" 2>"$log.stderr" </dev/null || rc=$?
    scrub "$log.stdout"
    scrub "$log.stderr"
    {
        printf '$ rgbsub'
        printf ' %q' "$@"
        printf '\n--- stdout\n'
        cat "$log.stdout"
        printf -- '--- stderr\n'
        cat "$log.stderr"
        printf -- '--- exit %d\n' "$rc"
    } >"$log"
    rm "$log.stdout" "$log.stderr"
    if [[ $expect == fail && $rc -eq 0 ]] || [[ $expect != fail && $rc -ne $expect ]]; then
        echo "output_corpus: $log: exit $rc, expected $expect" >&2
        unexpected=$((unexpected + 1))
    fi
}

# ---------------------------------------------------------------------------------------------
# Inputs
# ---------------------------------------------------------------------------------------------

cp "$ASSETS/default.obj" "$ASSETS/bunny.obj" "$ASSETS/machined_part.obj" in/

# A closed tetrahedron with vertex colours.
printf '%s\n' '# tetrahedron with vertex colours' \
    'v 1 1 1 1 0 0' 'v -1 -1 1 0 1 0' 'v -1 1 -1 0 0 1' 'v 1 -1 -1 0.5 0.5 0.5' \
    'f 1 2 4' 'f 1 3 2' 'f 1 4 3' 'f 2 3 4' >in/tetra.obj

# An open 4 x 4 grid of quads with bumps (one boundary loop), plain.
{
    echo '# open grid, 4 x 4 quads, bumps'
    for y in 0 1 2 3 4; do
        for x in 0 1 2 3 4; do printf 'v %d %d %d\n' "$x" "$y" $(((x * y) % 3)); done
    done
    for y in 0 1 2 3; do
        for x in 0 1 2 3; do
            a=$((y * 5 + x + 1))
            printf 'f %d %d %d %d\n' "$a" $((a + 1)) $((a + 6)) $((a + 5))
        done
    done
} >in/grid.obj

# The same grid with a crease across the middle row, semi-sharp at its ends, and OpenSubdiv's
# edge-and-corner boundary rule in the file.
{
    cat in/grid.obj
    echo 't interpolateboundary 1/0/0 1'
    printf 't crease 2/1/0 %d %d %d\n' 10 11 3 11 12 10 12 13 10 13 14 3
    echo 't corner 1/1/0 12 2'
} >in/grid_creased.obj

# A cube of quads: the top rim infinitely sharp, one semi-sharp bottom edge, one corner.
printf '%s\n' '# cube of quads with crease tags' \
    'v -1 -1 -1' 'v 1 -1 -1' 'v 1 1 -1' 'v -1 1 -1' 'v -1 -1 1' 'v 1 -1 1' 'v 1 1 1' 'v -1 1 1' \
    'f 1 4 3 2' 'f 5 6 7 8' 'f 1 2 6 5' 'f 3 4 8 7' 'f 2 3 7 6' 'f 4 1 5 8' \
    't crease 2/1/0 4 5 10' 't crease 2/1/0 5 6 10' 't crease 2/1/0 6 7 10' 't crease 2/1/0 7 4 10' \
    't crease 2/1/0 0 1 2' 't corner 1/1/0 2 10' >in/cube_creased.obj

# A 4 x 3 grid with bumps and vertex colours, cut by a UV seam along x = 2, with a one-triangle UV
# island at (1,1) (2,1) (2,2) (as tests/io/textured_grid.h, with short decimals).
{
    echo '# textured grid: UV seam at x = 2, a one-triangle island, vertex colours'
    for y in 0 1 2 3; do
        for x in 0 1 2 3 4; do
            i=$((y * 5 + x))
            printf 'v %d %d %d 0.%02d 0.%02d 0.%02d\n' "$x" "$y" $(((x * y) % 3)) $((10 + i * 4)) $((90 - i * 3)) $((20 + i * 2))
        done
    done
    for island in 0 1 2; do
        for y in 0 1 2 3; do
            for x in 0 1 2 3 4; do
                u=$((x * 125 + island * 500))
                printf 'vt %d.%03d 0.%03d\n' $((u / 1000)) $((u % 1000)) $((y * 250 + 50))
            done
        done
    done
    corner() { local v=$(($2 * 5 + $1 + 1)); printf '%d/%d' "$v" $(($3 * 20 + v)); }
    for y in 0 1 2; do
        for x in 0 1 2 3; do
            i=$((x < 2 ? 0 : 1))
            upper=$i
            if [[ $x -eq 1 && $y -eq 1 ]]; then upper=2; fi
            printf 'f %s %s %s\n' "$(corner "$x" "$y" "$i")" "$(corner $((x + 1)) "$y" "$i")" "$(corner $((x + 1)) $((y + 1)) "$i")"
            printf 'f %s %s %s\n' "$(corner "$x" "$y" "$upper")" "$(corner $((x + 1)) $((y + 1)) "$upper")" "$(corner "$x" $((y + 1)) "$upper")"
        done
    done
} >in/uvgrid.obj

# Materials: a 4 x 4 RGB checker PNG, a library with a plain and a textured material, a mesh with
# objects, groups and smoothing groups using both, and one whose library and texture are missing.
printf '\211\120\116\107\015\012\032\012\000\000\000\015\111\110\104\122\000\000\000\004\000\000\000\004\010\002\000\000\000\046\223\011\051\000\000\000\030\111\104\101\124\170\332\143\140\150\370\377\277\201\001\112\042\130\015\377\031\160\312\000\000\156\262\027\361\026\133\220\344\000\000\000\000\111\105\116\104\256\102\140\202' >in/checker.png
printf '%s\n' 'newmtl Red' 'Kd 0.8 0.1 0.1' '' 'newmtl Checker' 'Kd 1 1 1' 'map_Kd checker.png' >in/mat.mtl
{
    echo 'mtllib mat.mtl'
    echo 'o bracket'
    for y in 0 1 2 3; do
        for x in 0 1 2 3; do printf 'v %d %d %d\n' "$x" "$y" $(((x + y) % 2)); done
    done
    for y in 0 1 2 3; do
        for x in 0 1 2 3; do printf 'vt 0.%03d 0.%03d\n' $((x * 250 + 100)) $((y * 250 + 100)); done
    done
    echo 'g left'
    echo 'usemtl Red'
    echo 's off'
    for y in 0 1 2; do
        a=$((y * 4 + 1))
        printf 'f %d/%d %d/%d %d/%d %d/%d\n' "$a" "$a" $((a + 1)) $((a + 1)) $((a + 5)) $((a + 5)) $((a + 4)) $((a + 4))
    done
    echo 'g right'
    echo 'usemtl Checker'
    echo 's 1'
    for y in 0 1 2; do
        for x in 1 2; do
            a=$((y * 4 + x + 1))
            printf 'f %d/%d %d/%d %d/%d\n' "$a" "$a" $((a + 1)) $((a + 1)) $((a + 5)) $((a + 5))
            printf 'f %d/%d %d/%d %d/%d\n' "$a" "$a" $((a + 5)) $((a + 5)) $((a + 4)) $((a + 4))
        done
    done
} >in/mat.obj
printf '%s\n' 'newmtl Gone' 'Kd 0 1 0' 'map_Kd gone.jpg' >in/gone.mtl
printf '%s\n' 'mtllib gone.mtl missing.mtl' 'v 0 0 0' 'v 1 0 0' 'v 0 1 0' 'v 0 0 1' \
    'usemtl Gone' 'f 1 3 2' 'f 1 2 4' 'usemtl Nowhere' 'f 1 4 3' 'f 2 3 4' >in/missing_material.obj

# Bad inputs.
printf '%s\n' 'v 0 0 0' 'v 1 0 0' 'v 0 1 0' 'f 1 2 7' >in/bad_index.obj
printf '%s\n' 'v 0 0 0' 'v 1 zero 0' 'v 0 1 0' 'f 1 2 3' >in/bad_number.obj
{ cat in/tetra.obj; echo 't crease 2/1/0 0 1 2.5'; } >in/bad_crease.obj
printf '%s\n' '# three triangles on one edge' 'v 0 0 0' 'v 1 0 0' 'v 0 1 0' 'v 0 -1 0' 'v 0 0 1' \
    'f 1 2 3' 'f 2 1 4' 'f 1 2 5' >in/nonmanifold.obj
: >in/empty.obj

# Scripts.
printf '%s\n' '# mixed levels and spheres' 'level 1' 'level 3 sphere 0.8 0 0.4 0.5' 'level 0 sphere -0.8 0 0 0.4' \
    '' 'refine 2 sphere 0 1 0 0.3' 'coarsen 2 sphere 0.8 0 0.4 0.2' >in/mixed.txt
printf '%s\n' 'level 2 sphere 0 5 0 2' 'level 1' 'level 3 sphere 0 8 0 1' 'level 0 sphere 3 2 0 1.5' >in/bunny_mixed.txt
printf '%s\n' 'budget 500' >in/budget500.txt
printf '%s\n' 'budget 5000' >in/budget5000.txt
printf '%s\n' 'budget 40000' >in/budget40000.txt
printf '%s\n' 'level 2' 'budget 3000' 'budget 300' 'budget 12000' >in/budgets.txt
printf '%s\n' 'max-edge 0.2' 'max-edge 0.05 sphere 0.8 0 0.4 0.4 refine' 'max-edge 0.3 sphere -0.8 0 0 0.5 coarsen' \
    'max-edge 0.1 sphere 0 1 0 0.3' >in/max_edge.txt
printf '%s\n' 'max-edge 3%' >in/max_edge_pct.txt
printf '%s\n' 'tolerance 0.01' 'tolerance 0.001 sphere 0.8 0 0.4 0.4 refine' 'tolerance 0.05 sphere -0.8 0 0 0.5 coarsen' \
    'tolerance 0.002 sphere 0 1 0 0.3' >in/tolerance.txt
printf '%s\n' 'tolerance 0.5%' 'tolerance 0.1% sphere 0 5 0 1.5 refine' >in/tolerance_pct.txt
printf '%s\n' 'brush refine 3 0.4' 'dab 0.8 0 0.4' 'dab 0.7 0.2 0.5 1 0 0.5' 'brush coarsen 0 0.3 0.5' 'dab 0.8 0 0.4' \
    'brush set 2 0.5 0.3' 'dab -0.8 0 0 -1 0 0' >in/dabs.txt
printf '%s\n' 'level 2 sphere 4 0.5 1 1.5' 'tolerance 0.01 sphere 0 3 1 1' 'max-edge 0.25 sphere 1 1 2 1' >in/machined.txt
printf '%s\n' 'level 1' 'level 3 sphere 2 1.5 0 1' 'level 0 sphere 4 3 0 0.5' >in/uvgrid.txt
printf '%s\n' 'level 1' 'level banana' >in/bad_script.txt
printf '%s\n' 'level 1' 'frobnicate 3' >in/bad_command_script.txt

# ---------------------------------------------------------------------------------------------
# The corpus
# ---------------------------------------------------------------------------------------------

# info on every input, with sharp-angle and boundary options.
for m in default bunny machined_part tetra grid grid_creased cube_creased uvgrid mat missing_material nonmanifold; do
    run 0 "info-$m" info "in/$m.obj"
done
run 0 info-machined-sharp30 info in/machined_part.obj --sharp-angle 30
run 0 info-machined-sharp60 info in/machined_part.obj --sharp-angle 60
run 0 info-machined-sharp90 info in/machined_part.obj --sharp-angle 90
run 0 info-grid-edge-corner info in/grid.obj --boundary edge-and-corner
run 0 info-cube-sharp30 info in/cube_creased.obj --sharp-angle 30

# Uniform levels.
for m in default machined_part tetra grid cube_creased uvgrid; do
    for level in 0 1 2 3; do
        run 0 "refine-$m-$level" refine "in/$m.obj" -o "out/$m-$level.obj" --level "$level"
    done
done
for level in 0 1 2 3; do
    run 0 "refine-bunny-$level" refine in/bunny.obj -o "out/bunny-$level.obj" --level "$level"
done
run 0 refine-default-5 refine in/default.obj -o out/default-5.obj --level 5
run 0 info-default-3 info out/default-3.obj
run 0 info-bunny-3 info out/bunny-3.obj

# Positions, normals, plain.
run 0 refine-default-2-limit refine in/default.obj -o out/default-2-limit.obj --level 2 --positions limit
run 0 refine-default-2-display refine in/default.obj -o out/default-2-display.obj --level 2 --positions display
run 0 refine-bunny-1-limit refine in/bunny.obj -o out/bunny-1-limit.obj --level 1 --positions limit
run 0 refine-default-2-plain refine in/default.obj -o out/default-2-plain.obj --level 2 --plain
run 0 refine-default-1-normals refine in/default.obj -o out/default-1-normals.obj --level 1 --normals
run 0 refine-default-2-limit-normals-plain refine in/default.obj -o out/default-2-lnp.obj --level 2 --positions limit --normals --plain

# Spheres.
run 0 refine-default-sphere refine in/default.obj -o out/default-sphere.obj --level 3 --sphere 0.8,0,0.4,0.5
run 0 refine-default-sphere-small refine in/default.obj -o out/default-sphere-small.obj --level 4 --sphere 0.9,0.1,0.4,0.05
run 0 refine-bunny-sphere refine in/bunny.obj -o out/bunny-sphere.obj --level 3 --sphere 0,5,0,1.5
run 0 refine-machined-sphere refine in/machined_part.obj -o out/machined-sphere.obj --level 3 --sphere 0,0,0,1
run 0 refine-grid-sphere refine in/grid.obj -o out/grid-sphere.obj --level 3 --sphere 4,4,1,1
run 0 refine-default-sphere-limit refine in/default.obj -o out/default-sphere-limit.obj --level 3 --sphere 0.8,0,0.4,0.5 --positions limit
run 0 info-default-sphere info out/default-sphere.obj

# Saved files reloaded: refined further, coarsened, back to level 0.
run 0 reload-sphere-0 refine out/default-sphere.obj -o out/reload-sphere-0.obj --level 0
run 0 reload-sphere-0-plain refine out/default-sphere.obj -o out/reload-sphere-0-plain.obj --level 0 --plain
run 0 reload-sphere-more refine out/default-sphere.obj -o out/reload-sphere-more.obj --level 2 --sphere -0.8,0,0,0.6
run 0 reload-3-to-1 refine out/default-3.obj -o out/reload-3-to-1.obj --level 1
run 0 reload-3-coarsen-sphere refine out/default-3.obj -o out/reload-3-coarsen.obj --level 0 --sphere 0.8,0,0.4,0.5
run 0 reload-bunny-sphere-0 refine out/bunny-sphere.obj -o out/reload-bunny-sphere-0.obj --level 0
run 0 reload-reload refine out/reload-sphere-more.obj -o out/reload-reload.obj --level 4 --sphere 0,1,0,0.2
run 0 reload-limit refine out/default-sphere-limit.obj -o out/reload-limit.obj --level 1
run 0 info-reload-sphere-0 info out/reload-sphere-0.obj

# Detail by size.
run 0 max-edge-default refine in/default.obj -o out/max-edge-default.obj --max-edge 0.1
run 0 max-edge-default-pct refine in/default.obj -o out/max-edge-default-pct.obj --max-edge 5%
run 0 max-edge-bunny-pct refine in/bunny.obj -o out/max-edge-bunny-pct.obj --max-edge 2%
run 0 max-edge-default-sphere refine in/default.obj -o out/max-edge-default-sphere.obj --max-edge 0.05 --sphere 0.8,0,0.4,0.5
run 0 max-edge-reload refine out/default-3.obj -o out/max-edge-reload.obj --max-edge 0.2
run 0 max-edge-machined refine in/machined_part.obj -o out/max-edge-machined.obj --max-edge 0.3 --sharp-angle 30

# Detail by accuracy.
run 0 tolerance-default refine in/default.obj -o out/tolerance-default.obj --tolerance 0.01
run 0 tolerance-default-pct refine in/default.obj -o out/tolerance-default-pct.obj --tolerance 0.5%
run 0 tolerance-bunny-pct refine in/bunny.obj -o out/tolerance-bunny-pct.obj --tolerance 0.2%
run 0 tolerance-default-sphere refine in/default.obj -o out/tolerance-default-sphere.obj --tolerance 0.001 --sphere 0.8,0,0.4,0.5
run 0 tolerance-machined-sharp refine in/machined_part.obj -o out/tolerance-machined.obj --tolerance 0.01 --sharp-angle 30
run 0 tolerance-cube refine in/cube_creased.obj -o out/tolerance-cube.obj --tolerance 0.005
run 0 tolerance-grid-creased refine in/grid_creased.obj -o out/tolerance-grid-creased.obj --tolerance 1%
run 0 tolerance-reload refine out/default-sphere.obj -o out/tolerance-reload.obj --tolerance 0.02

# Creases: by angle, by the file's tags, boundary rules.
run 0 sharp30-machined-2 refine in/machined_part.obj -o out/sharp30-machined-2.obj --level 2 --sharp-angle 30
run 0 sharp60-machined-3-limit refine in/machined_part.obj -o out/sharp60-machined-3-limit.obj --level 3 --sharp-angle 60 --positions limit
run 0 sharp30-machined-sphere refine in/machined_part.obj -o out/sharp30-machined-sphere.obj --level 3 --sphere 4,0.5,1,1 --sharp-angle 30
run 0 sharp30-default refine in/default.obj -o out/sharp30-default.obj --level 2 --sharp-angle 30
run 0 sharp30-cube refine in/cube_creased.obj -o out/sharp30-cube.obj --level 2 --sharp-angle 30
run 0 tags-cube-limit refine in/cube_creased.obj -o out/tags-cube-limit.obj --level 3 --positions limit
run 0 tags-cube-sphere refine in/cube_creased.obj -o out/tags-cube-sphere.obj --level 3 --sphere 1,1,1,0.8
run 0 tags-cube-reload-0 refine out/tags-cube-sphere.obj -o out/tags-cube-reload-0.obj --level 0
run 0 tags-cube-reload-more refine out/tags-cube-sphere.obj -o out/tags-cube-reload-more.obj --level 2 --sphere -1,-1,-1,1
for level in 1 2 3; do
    run 0 "tags-grid-creased-$level" refine in/grid_creased.obj -o "out/tags-grid-creased-$level.obj" --level "$level"
done
run 0 tags-grid-creased-edge-only refine in/grid_creased.obj -o out/tags-grid-creased-edge-only.obj --level 2 --boundary edge-only
run 0 boundary-grid-edge-corner refine in/grid.obj -o out/boundary-grid-edge-corner.obj --level 2 --boundary edge-and-corner
run 0 boundary-grid-edge-only refine in/grid.obj -o out/boundary-grid-edge-only.obj --level 2 --boundary edge-only
run 0 boundary-grid-edge-corner-limit refine in/grid.obj -o out/boundary-grid-ec-limit.obj --level 2 --boundary edge-and-corner --positions limit
run 0 info-tags-cube-sphere info out/tags-cube-sphere.obj
run 0 info-sharp30-machined-2 info out/sharp30-machined-2.obj

# Texture coordinates and vertex colours.
for option in none corners boundaries all; do
    run 0 "uv-$option-2" refine in/uvgrid.obj -o "out/uv-$option-2.obj" --level 2 --uv-interpolation "$option"
    run 0 "uv-$option-limit" refine in/uvgrid.obj -o "out/uv-$option-limit.obj" --level 3 --positions limit --uv-interpolation "$option"
done
run 0 uv-sphere refine in/uvgrid.obj -o out/uv-sphere.obj --level 3 --sphere 2,1.5,0,0.8 --uv-interpolation boundaries
run 0 uv-reload-0 refine out/uv-sphere.obj -o out/uv-reload-0.obj --level 0
run 0 uv-reload-more refine out/uv-sphere.obj -o out/uv-reload-more.obj --level 2
run 0 uv-edge-corner refine in/uvgrid.obj -o out/uv-edge-corner.obj --level 2 --boundary edge-and-corner --uv-interpolation none
run 0 uv-plain refine in/uvgrid.obj -o out/uv-plain.obj --level 1 --plain
run 0 colours-tetra-limit refine in/tetra.obj -o out/colours-tetra-limit.obj --level 2 --positions limit
run 0 info-uv-sphere info out/uv-sphere.obj

# Materials, groups, objects.
run 0 mat-0 refine in/mat.obj -o out/mat-0.obj --level 0
run 0 mat-2 refine in/mat.obj -o out/mat-2.obj --level 2
run 0 mat-missing-1 refine in/missing_material.obj -o out/mat-missing-1.obj --level 1

# glTF.
run 0 glb-default-2 refine in/default.obj -o out/default-2.glb --level 2
run 0 gltf-default-1 refine in/default.obj -o out/default-1.gltf --level 1
run 0 glb-bunny-sphere refine in/bunny.obj -o out/bunny-sphere.glb --level 3 --sphere 0,5,0,1.5
run 0 glb-default-limit refine in/default.obj -o out/default-2-limit.glb --level 2 --positions limit
run 0 gltf-uvgrid-0 refine in/uvgrid.obj -o out/uvgrid-0.gltf --level 0
run 0 glb-uvgrid-2 refine in/uvgrid.obj -o out/uvgrid-2.glb --level 2
run 0 glb-mat-0 refine in/mat.obj -o out/mat-0.glb --level 0
run 0 gltf-mat-2 refine in/mat.obj -o out/mat-2.gltf --level 2
run 0 gltf-cube-tags refine in/cube_creased.obj -o out/cube-tags-2.gltf --level 2
run 0 glb-tolerance refine in/default.obj -o out/tolerance-default.glb --tolerance 0.5%
run 0 glb-reload refine out/default-sphere.obj -o out/reload-sphere.glb --level 1 --sphere -0.8,0,0,0.6

# apply scripts.
run 0 apply-mixed apply in/default.obj in/mixed.txt -o out/apply-mixed.obj
run 0 apply-mixed-plain apply in/default.obj in/mixed.txt -o out/apply-mixed-plain.obj --plain
run 0 apply-mixed-limit apply in/default.obj in/mixed.txt -o out/apply-mixed-limit.obj --positions limit --normals
run 0 apply-mixed-glb apply in/default.obj in/mixed.txt -o out/apply-mixed.glb
run 0 apply-mixed-gltf apply in/default.obj in/mixed.txt -o out/apply-mixed.gltf
run 0 apply-mixed-reload apply out/apply-mixed.obj in/mixed.txt -o out/apply-mixed-reload.obj
run 0 apply-bunny-mixed apply in/bunny.obj in/bunny_mixed.txt -o out/apply-bunny-mixed.obj
for n in 500 5000 40000; do
    run 0 "apply-budget-$n" apply in/bunny.obj "in/budget$n.txt" -o "out/apply-budget-$n.obj"
done
run 0 apply-budget-default apply in/default.obj in/budget5000.txt -o out/apply-budget-default.obj
run 0 apply-budgets apply in/default.obj in/budgets.txt -o out/apply-budgets.obj
run 0 apply-budget-reload apply out/bunny-2.obj in/budget5000.txt -o out/apply-budget-reload.obj
run 0 apply-max-edge apply in/default.obj in/max_edge.txt -o out/apply-max-edge.obj
run 0 apply-max-edge-pct apply in/bunny.obj in/max_edge_pct.txt -o out/apply-max-edge-pct.obj
run 0 apply-tolerance apply in/default.obj in/tolerance.txt -o out/apply-tolerance.obj
run 0 apply-tolerance-pct apply in/bunny.obj in/tolerance_pct.txt -o out/apply-tolerance-pct.obj
run 0 apply-dabs apply in/default.obj in/dabs.txt -o out/apply-dabs.obj
run 0 apply-machined-sharp apply in/machined_part.obj in/machined.txt -o out/apply-machined.obj --sharp-angle 30
run 0 apply-machined-glb apply in/machined_part.obj in/machined.txt -o out/apply-machined.glb --sharp-angle 60
run 0 apply-cube-tags apply in/cube_creased.obj in/mixed.txt -o out/apply-cube-tags.obj
run 0 apply-grid-creased apply in/grid_creased.obj in/uvgrid.txt -o out/apply-grid-creased.obj --boundary edge-only
for option in none corners boundaries all; do
    run 0 "apply-uv-$option" apply in/uvgrid.obj in/uvgrid.txt -o "out/apply-uv-$option.obj" --uv-interpolation "$option"
done
run 0 apply-mat-gltf apply in/mat.obj in/uvgrid.txt -o out/apply-mat.gltf

# Renders (small, except one at the default size).
for mode in shaded flat rgb level; do
    run 0 "render-$mode" render out/default-sphere.obj -o "out/render-$mode.png" --size 320x240 --mode "$mode"
    run 0 "render-$mode-wire" render out/default-sphere.obj -o "out/render-$mode-wire.png" --size 320x240 --mode "$mode" --wire
done
run 0 render-default-size render out/apply-mixed.obj -o out/render-default-size.png
run 0 render-view render out/apply-dabs.obj -o out/render-view.png --size 320x240 --view 120,-15 --mode level --wire
run 0 render-limit render out/default-sphere.obj -o out/render-limit.png --size 320x240 --limit
run 0 render-limit-wire render out/default-sphere.obj -o out/render-limit-wire.png --size 320x240 --limit --wire --mode rgb
run 0 render-base render out/default-sphere.obj -o out/render-base.png --size 320x240 --base
run 0 render-base-limit render out/apply-budgets.obj -o out/render-base-limit.png --size 320x240 --base --limit --mode flat
run 0 render-screen-lod render in/bunny.obj -o out/render-screen-lod.png --size 320x240 --screen-lod 8 --mode level --wire
run 0 render-screen-lod-aside render in/bunny.obj -o out/render-screen-lod-aside.png --size 320x240 --screen-lod 6 --lod-view 200,10 --mode level
run 0 render-screen-lod-reload render out/default-sphere.obj -o out/render-screen-lod-reload.png --size 320x240 --screen-lod 10 --view 60,30 --wire
run 0 render-machined-sharp render in/machined_part.obj -o out/render-machined-sharp.png --size 320x240 --sharp-angle 30 --wire
run 0 render-machined-sharp-2 render out/sharp30-machined-2.obj -o out/render-machined-sharp-2.png --size 320x240 --mode flat
run 0 render-cube-tags render out/tags-cube-sphere.obj -o out/render-cube-tags.png --size 320x240 --mode rgb --wire --limit
run 0 render-grid-edge-corner render in/grid_creased.obj -o out/render-grid-edge-corner.png --size 320x240 --boundary edge-and-corner --base
run 0 render-uvgrid render out/uv-sphere.obj -o out/render-uvgrid.png --size 320x240 --mode level --wire
run 0 render-mat render out/mat-2.obj -o out/render-mat.png --size 320x240
run 0 render-tetra render out/colours-tetra-limit.obj -o out/render-tetra.png --size 320x240 --view 45,45
run 0 render-bunny-3 render out/bunny-3.obj -o out/render-bunny-3.png --size 320x240 --mode flat

# The editor's headless screenshot.
for mode in shaded rgb level texture colours; do
    run 0 "edit-screenshot-$mode" edit out/uv-sphere.obj --screenshot "out/edit-$mode.png" --mode "$mode"
done
run 0 edit-screenshot-mat-texture edit out/mat-2.obj --screenshot out/edit-mat-texture.png --mode texture
run 0 edit-screenshot-mat-material edit out/mat-2.obj --screenshot out/edit-mat-material.png --mode material

# Help texts.
run 0 help --help
for command in info refine apply render edit; do
    run 0 "help-$command" "$command" --help
done

# Errors: bad input, usage errors, I/O and resource failures (message and exit code).
run fail err-bad-index info in/bad_index.obj
run fail err-bad-index-refine refine in/bad_index.obj -o out/err.obj --level 1
run fail err-bad-number info in/bad_number.obj
run fail err-bad-crease info in/bad_crease.obj
run fail err-empty refine in/empty.obj -o out/err.obj --level 1
run 0 nonmanifold-repair refine in/nonmanifold.obj -o out/nonmanifold-repair.obj --level 1
run fail err-nonmanifold-strict refine in/nonmanifold.obj -o out/err.obj --level 1 --strict
run fail err-nonmanifold-strict-info info in/nonmanifold.obj --strict
run fail err-missing-file refine in/no_such_file.obj -o out/err.obj --level 1
run fail err-missing-script apply in/default.obj in/no_such_script.txt -o out/err.obj
run fail err-bad-script apply in/default.obj in/bad_script.txt -o out/err.obj
run fail err-bad-command-script apply in/default.obj in/bad_command_script.txt -o out/err.obj
run fail err-unknown-option refine in/default.obj -o out/err.obj --level 1 --nope
run fail err-unknown-short refine in/default.obj -o out/err.obj --level 1 -x
run fail err-unknown-command frobnicate in/default.obj
run fail err-repeated-o refine in/default.obj -o -o out/err.obj --level 1
run fail err-missing-o refine in/default.obj --level 1
run fail err-no-criterion refine in/default.obj -o out/err.obj
run fail err-two-criteria refine in/default.obj -o out/err.obj --level 1 --max-edge 0.1
run fail err-level-21 refine in/default.obj -o out/err.obj --level 21
run fail err-level-negative refine in/default.obj -o out/err.obj --level -1
run fail err-bad-sphere refine in/default.obj -o out/err.obj --level 1 --sphere 1,2,3
run fail err-bad-tolerance refine in/default.obj -o out/err.obj --tolerance -1
run fail err-bad-max-edge refine in/default.obj -o out/err.obj --max-edge abc%
run fail err-bad-uv-option refine in/uvgrid.obj -o out/err.obj --level 1 --uv-interpolation bogus
run fail err-bad-boundary refine in/grid.obj -o out/err.obj --level 1 --boundary nope
run fail err-bad-sharp-angle info in/default.obj --sharp-angle 200
run fail err-bad-positions refine in/default.obj -o out/err.obj --level 1 --positions nope
run 0 other-extension refine in/default.obj -o out/other-extension.stl --level 1
run fail err-max-triangles refine in/default.obj -o out/err.obj --level 4 --max-triangles 1000
run fail err-max-triangles-tolerance refine in/default.obj -o out/err.obj --tolerance 0.0001 --max-triangles 1000
run fail err-render-view-nan render in/default.obj -o out/err.png --view nan,0
run fail err-render-mode render in/default.obj -o out/err.png --mode nope
run fail err-render-size render in/default.obj -o out/err.png --size 0x10
run fail err-render-lod-view-alone render in/default.obj -o out/err.png --lod-view 10,10
run fail err-save-dir refine in/default.obj -o out/no_such_dir/err.obj --level 1
run 0 end-of-options refine -o out/end-of-options.obj --level 1 -- in/default.obj
run fail err-end-of-options refine -- in/default.obj -o out/err.obj --level 1

# ---------------------------------------------------------------------------------------------
# Fingerprints
# ---------------------------------------------------------------------------------------------

sums="$(find . -type f ! -name SHA256SUMS -printf '%P\0' | LC_ALL=C sort -z | xargs -0 sha256sum)"
printf '%s\n' "$sums" >SHA256SUMS
echo "output_corpus: $count commands, $(wc -l <SHA256SUMS) files, sums in $OUT/SHA256SUMS"
if [[ $unexpected -ne 0 ]]; then
    echo "output_corpus: $unexpected commands exited otherwise than expected (see above)" >&2
    exit 1
fi
