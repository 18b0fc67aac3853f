# Shared set-up for scripts/run and scripts/test (sourced, not executed).
# Installs what is missing from Debian's packages, then configures and builds
# tribodyn (Release) in build/. A second call rebuilds only what changed.

set -euo pipefail

TRIBODYN_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${TRIBODYN_BUILD_DIR:-$TRIBODYN_ROOT/build}"
BUILD_TYPE="${TRIBODYN_BUILD_TYPE:-Release}"
JOBS="${TRIBODYN_JOBS:-$(nproc)}"

# mpirun refuses to run as root unless told; oversubscription lets tests
# use 2 ranks on small machines.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none
# SIGTERM to mpirun reaches the ranks, which save a checkpoint before they
# stop; Open MPI's default of 1 s before SIGKILL is too short for a large
# scene (doc/user_guide/mca_study.md).
export OMPI_MCA_odls_base_sigkill_timeout="${OMPI_MCA_odls_base_sigkill_timeout:-30}"

TRIBODYN_PACKAGES=(libdeal.ii-dev libeigen3-dev numdiff python3
                   python3-matplotlib cmake g++ make openmpi-bin
                   nlohmann-json3-dev libfftw3-dev pkg-config
                   libtiff-dev libpng-dev
                   calculix-ccx) # the peer of a 3D homogenization test

tribodyn_install_packages() {
  local missing=()
  for package in "${TRIBODYN_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null |
        grep -q "install ok installed"; then
      missing+=("$package")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  echo "tribodyn: installing missing Debian packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null; then
      sudo="sudo"
    else
      echo "tribodyn: error: packages ${missing[*]} are missing and this is" \
           "not root (and sudo is not available). Install them as root:" \
           "apt-get install ${missing[*]}" >&2
      exit 1
    fi
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq \
    --no-install-recommends "${missing[@]}"
}

# tribodyn_build [TARGET...]: configure, then build the TARGETs (default:
# everything, the test programs included).
tribodyn_build() {
  cmake -S "$TRIBODYN_ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE="$BUILD_TYPE" \
    ${TRIBODYN_CMAKE_ARGS:-} > "$BUILD_DIR.configure.log" 2>&1 || {
      cat "$BUILD_DIR.configure.log" >&2
      echo "tribodyn: error: CMake configuration failed (log above)." >&2
      exit 1
    }
  local targets=()
  for target in "$@"; do
    targets+=(--target "$target")
  done
  cmake --build "$BUILD_DIR" -j "$JOBS" "${targets[@]}"
}

# tribodyn_setup [TARGET...]: packages, then tribodyn_build TARGET...
tribodyn_setup() {
  tribodyn_install_packages
  mkdir -p "$BUILD_DIR"
  tribodyn_build "$@"
}
