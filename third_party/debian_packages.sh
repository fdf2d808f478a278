# Sourced by run.sh and test.sh: the Debian 12 packages rgbsub needs and an idempotent installer.

# Everything the CMake configure step finds (tests and benchmarks are part of the project).
RGBSUB_BUILD_PACKAGES=(
  build-essential cmake pkg-config python3-glad
  libglfw3-dev libglm-dev libimgui-dev libstb-dev libtinyobjloader-dev libtinygltf-dev libosmesa6-dev libgl-dev
  libgtest-dev libbenchmark-dev libopenmesh-dev libeigen3-dev
  # src/io/formats reads FBX, COLLADA, 3DS, STL, OFF and the other formats Assimp has importers for.
  # Debian 12's Assimp CMake package links /usr/lib/x86_64-linux-gnu/libz.so, which only zlib1g-dev
  # installs, and libassimp-dev does not depend on it (found by tests/fresh_debian_check.sh).
  libassimp-dev zlib1g-dev
)
# Only the test suite uses these: a virtual display for the editor window (xvfb-run needs xauth),
# input injection, reference meshes, clang with its libFuzzer runtime for the loader's fuzz target,
# OpenSubdiv's Far (libosd-dev), the Loop oracle for creases, corners and face-varying UVs, and
# meshoptimizer, which the LOD quality benchmark (tests/bench/lod_quality.cpp) compares against;
# python3-meshio (with numpy), the independent reader of the PLY, STL, VTU and MSH files rgbsub writes
# (tests/cli/formats_check.py), whose numpy also checks the dense-mesh window test's saved cage
# (tests/app/dense_mesh_window.py); nodejs and npm, which install and run the Khronos glTF validator
# (npm gltf-validator, into the build tree: tests/cli/CMakeLists.txt).
# (GCC's AddressSanitizer and UBSan runtimes come with build-essential's g++.)
RGBSUB_TEST_PACKAGES=(xvfb xauth xdotool assimp-testmodels clang libclang-rt-14-dev libosd-dev libmeshoptimizer-dev
  python3-meshio nodejs)
# A node from elsewhere (NodeSource's nodejs package) brings its own npm and conflicts with Debian's.
command -v npm >/dev/null || RGBSUB_TEST_PACKAGES+=(npm)

# Installs whichever of the given packages are missing; apt-get runs only when one is.
# Without root or sudo it prints the command to run and exits 2.
install_missing_packages() {
  local missing=() package
  for package in "$@"; do
    if [[ "$(dpkg-query -W -f='${db:Status-Abbrev}' "$package" 2>/dev/null)" != ii* ]]; then
      missing+=("$package")
    fi
  done
  [[ ${#missing[@]} -eq 0 ]] && return 0

  local install="apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends ${missing[*]}"
  if [[ "$(id -u)" -eq 0 ]]; then
    bash -c "$install"
  elif command -v sudo >/dev/null; then
    sudo bash -c "$install"
  else
    echo "Missing Debian packages; as root, run: $install" >&2
    exit 2
  fi
}
