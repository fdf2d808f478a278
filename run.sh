#!/usr/bin/env bash
# Installs what is missing, builds rgbsub (Release, build/) and opens the editor on FILE.obj
# or on the default mesh.
set -euo pipefail
cd "$(dirname "$0")"
source third_party/debian_packages.sh

if [[ $# -gt 1 ]]; then
  echo "usage: ./run.sh [FILE.obj]" >&2
  exit 1
fi

install_missing_packages "${RGBSUB_BUILD_PACKAGES[@]}"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target rgbsub -j"$(nproc)"

if [[ -z "${DISPLAY:-}" ]]; then
  echo "run.sh: no display (DISPLAY is not set); headless alternative: build/rgbsub render (see build/rgbsub --help)" >&2
  exit 2
fi

mesh=("$@")
if [[ $# -eq 0 && -f assets/default.obj ]]; then
  mesh=(assets/default.obj)
fi
exec build/rgbsub edit "${mesh[@]}"
