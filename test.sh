#!/usr/bin/env bash
# Installs what is missing, builds everything (Release, warnings as errors, build/) and runs the
# whole suite, then runs the core's tests under AddressSanitizer + UBSan (build-asan/).
# Exits non-zero if any build or test fails.
set -euo pipefail
cd "$(dirname "$0")"
source third_party/debian_packages.sh

install_missing_packages "${RGBSUB_BUILD_PACKAGES[@]}" "${RGBSUB_TEST_PACKAGES[@]}"
jobs="$(nproc)"
failed=0

# Builds and tests one configuration; a failure is recorded so that the other still runs.
build_and_test() {
  local dir="$1"
  shift
  echo "=== $dir: $*"
  if cmake -S . -B "$dir" "$@" >/dev/null && cmake --build "$dir" -j"$jobs"; then
    (cd "$dir" && ctest --output-on-failure --no-tests=error -j2) || failed=1
  else
    echo "=== $dir: build failed" >&2
    failed=1
  fi
}

# The sanitizer run goes first so that the last ctest summary printed is the whole suite's.
build_and_test build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRGBSUB_CORE_ONLY=ON -DRGBSUB_SANITIZE=ON -DRGBSUB_WERROR=ON
build_and_test build -DCMAKE_BUILD_TYPE=Release -DRGBSUB_WERROR=ON
exit "$failed"
