#!/usr/bin/env bash
# Installs every Debian package vantage needs. Idempotent: packages already installed are
# skipped, so a second run does nothing and needs no network. Fails loudly, naming the package,
# when apt cannot install one.
set -euo pipefail

packages=(
  build-essential cmake make pkg-config git
  clang libclang-rt-14-dev clang-format
  libeigen3-dev
  libsdp-dev liblapack-dev libblas-dev
  libnlopt-cxx-dev
  nlohmann-json3-dev
  libcli11-dev
  libplplot-dev plplot-driver-cairo
  libcairo2-dev libpng-dev
  libglfw3-dev libimgui-dev libstb-dev
  libgtest-dev libgmock-dev googletest
  libbenchmark-dev
  xvfb xauth libgl1-mesa-dri libglx-mesa0 fonts-dejavu-core
  libyaml-cpp-dev
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest
  python3-mpmath
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
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
for p in "${missing[@]}"; do
  if ! "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "$p" >/dev/null; then
    echo "install-deps: apt-get could not install package '$p'" >&2
    exit 1
  fi
done
echo "install-deps: done"
