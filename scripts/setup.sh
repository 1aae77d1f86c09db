#!/usr/bin/env bash
# Installs the Debian packages rayo needs, only those that are missing (idempotent, quick when
# everything is present). Used by both README commands and by .ci/run.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libembree-dev libtbb-dev
  libopenimageio-dev openimageio-tools libopencolorio-dev libopenexr-dev libpng-dev
  libglm-dev libgtest-dev libbenchmark-dev nlohmann-json3-dev
  libtinyobjloader-dev libtinygltf-dev libdraco-dev
  libopenmpi-dev openmpi-bin
  gnuplot-nox
  pybind11-dev python3-dev python3-numpy python3-pytest
)
if [[ "${RAYO_SETUP_EXTRAS:-}" == *povray* ]]; then packages+=(povray); fi
if [[ "${RAYO_SETUP_EXTRAS:-}" == *clang* ]]; then packages+=(clang libclang-rt-14-dev); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
