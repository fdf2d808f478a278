#!/usr/bin/env bash
# Installs what is missing, builds everything under AddressSanitizer + UBSan (build-asan/) and runs
# the suite there, then builds everything in Release with warnings as errors (build/) and runs the
# whole suite again, with every benchmark of tests/bench run once at a small size. The fuzz test runs
# only in the second: its target has sanitizers of its own.
# Exits non-zero if any build or test fails.
set -euo pipefail
cd "$(dirname "$0")"
source third_party/debian_packages.sh

install_missing_packages "${RGBSUB_BUILD_PACKAGES[@]}" "${RGBSUB_TEST_PACKAGES[@]}"
jobs="$(nproc)"
failed=0

# Builds and tests one configuration; a failure is recorded so that the other still runs.
# Usage: build_and_test DIR "CTEST ARGS" CMAKE ARGS...
build_and_test() {
  local dir="$1" ctest_args="$2"
  shift 2
  echo "=== $dir: $*"
  local start=$SECONDS
  if cmake -S . -B "$dir" "$@" >/dev/null && cmake --build "$dir" -j"$jobs"; then
    echo "=== $dir: built in $((SECONDS - start)) s"
    start=$SECONDS
    # shellcheck disable=SC2086 # ctest_args holds several words
    (cd "$dir" && ctest --output-on-failure --no-tests=error -j2 $ctest_args) || failed=1
    # A skipped test fails the run unless it names missing hardware or a missing privilege.
    tests/check_skips.sh "$dir" || failed=1
    echo "=== $dir: tested in $((SECONDS - start)) s"
  else
    echo "=== $dir: build failed" >&2
    failed=1
  fi
}

# The sanitizer run goes first so that the last ctest summary printed is the whole suite's.
build_and_test build-asan "--label-exclude fuzz" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRGBSUB_SANITIZE=ON -DRGBSUB_WERROR=ON
build_and_test build "" -DCMAKE_BUILD_TYPE=Release -DRGBSUB_WERROR=ON
exit "$failed"
