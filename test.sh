#!/usr/bin/env bash
# Installs what is missing, builds everything under AddressSanitizer + UBSan (build-asan/) and runs
# the suite there while everything builds in Release with warnings as errors (build/, at the lowest
# priority), then runs the whole suite again in Release, with every benchmark of tests/bench run once
# at a small size. The fuzz test runs only in the second: its target has sanitizers of its own.
# Exits non-zero if any build or test fails.
set -euo pipefail
cd "$(dirname "$0")"
source third_party/debian_packages.sh

install_missing_packages "${RGBSUB_BUILD_PACKAGES[@]}" "${RGBSUB_TEST_PACKAGES[@]}"
jobs="$(nproc)"
failed=0

# Configures and builds one configuration; prints how long it took. Usage: build DIR CMAKE ARGS...
build() {
  local dir="$1" start=$SECONDS
  shift
  echo "=== $dir: $*"
  if cmake -S . -B "$dir" "$@" >/dev/null && cmake --build "$dir" -j"$jobs"; then
    echo "=== $dir: built in $((SECONDS - start)) s"
  else
    echo "=== $dir: build failed" >&2
    return 1
  fi
}

# Runs one configuration's tests; a failure is recorded so that the other still runs.
# Usage: run_tests DIR "CTEST ARGS"
run_tests() {
  local dir="$1" ctest_args="$2" start=$SECONDS
  # shellcheck disable=SC2086 # ctest_args holds several words
  (cd "$dir" && ctest --output-on-failure --no-tests=error -j2 $ctest_args) || failed=1
  # A skipped test fails the run unless it names missing hardware or a missing privilege.
  tests/check_skips.sh "$dir" || failed=1
  echo "=== $dir: tested in $((SECONDS - start)) s"
}

# The sanitizer run goes first so that the last ctest summary printed is the whole suite's. The
# Release build runs beside the sanitizer build and tests at the lowest priority, so that it takes
# only the processor time they leave (the build's single-file tails and links, the tests' waits on
# child processes, files and the X server) and slows none of them; its output is printed when it
# ends.
release_log=$(mktemp)
trap 'rm -f "$release_log"' EXIT
nice -n 19 bash -c "$(declare -f build); jobs=$jobs; build build -DCMAKE_BUILD_TYPE=Release -DRGBSUB_WERROR=ON" \
  >"$release_log" 2>&1 &
release_build=$!
asan_built=0
build build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRGBSUB_SANITIZE=ON -DRGBSUB_WERROR=ON && asan_built=1 || failed=1
if [[ $asan_built -eq 1 ]]; then
  run_tests build-asan "--label-exclude fuzz"
fi
release_built=0
wait "$release_build" && release_built=1 || failed=1
cat "$release_log"
if [[ $release_built -eq 1 ]]; then
  run_tests build ""
fi
exit "$failed"
