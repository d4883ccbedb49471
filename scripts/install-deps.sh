#!/usr/bin/env bash
# Installs the Debian packages vantage needs: scripts/install-deps.sh [demo|all]
#   demo  what `make demo` builds and runs: the compiler, CMake and the libraries the `vantage`
#         command links without figures (Eigen, CSDP with LAPACK/BLAS, NLopt, nlohmann-json,
#         CLI11, yaml-cpp);
#   all   (the default) everything `make test` builds: the above plus PLplot, the viewer,
#         Python, the test and benchmark frameworks, clang (fuzzing), clang-format and help2man
#         (the man pages).
# Idempotent: packages already installed are skipped, so a second run does nothing and needs no
# network. Installs the missing packages in one apt-get call; when that fails, retries them one
# by one and fails loudly, naming the package apt cannot install.
set -euo pipefail

demo_packages=(
  build-essential cmake make
  libeigen3-dev
  libsdp-dev liblapack-dev libblas-dev
  libnlopt-cxx-dev
  nlohmann-json3-dev
  libcli11-dev
  libyaml-cpp-dev
  libassimp-dev libembree-dev
)
all_packages=(
  "${demo_packages[@]}"
  pkg-config git
  clang libclang-rt-14-dev clang-format
  libplplot-dev plplot-driver-cairo
  libcairo2-dev libpng-dev
  libglfw3-dev libimgui-dev libstb-dev
  libgtest-dev libgmock-dev googletest
  libbenchmark-dev
  xvfb xauth libgl1-mesa-dri libglx-mesa0 fonts-dejavu-core
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest
  python3-mpmath
  python3-setuptools python3-wheel python3-venv python3-pip python3-build mypy binutils
  help2man
)

set_name=${1:-all}
case "$set_name" in
  demo) packages=("${demo_packages[@]}") ;;
  all) packages=("${all_packages[@]}") ;;
  *)
    echo "install-deps: unknown package set '$set_name' (use demo or all)" >&2
    exit 2
    ;;
esac

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages of '$set_name' present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo_cmd=(sudo)
  else
    echo "install-deps: need root or sudo to install: ${missing[*]}" >&2
    exit 1
  fi
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
if ! "${sudo_cmd[@]}" apt-get update -qq; then
  echo "install-deps: apt-get update failed" >&2
  exit 1
fi
apt_install=("${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends)
if ! "${apt_install[@]}" "${missing[@]}" >/dev/null; then
  for p in "${missing[@]}"; do
    if ! "${apt_install[@]}" "$p" >/dev/null; then
      echo "install-deps: apt-get could not install package '$p'" >&2
      exit 1
    fi
  done
fi
echo "install-deps: done"
