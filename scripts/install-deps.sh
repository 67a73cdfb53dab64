#!/usr/bin/env bash
# Installs hylios's build and run dependencies from Debian 12 packages (run as root).
# Skips apt-get entirely when every package is already installed.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libembree-dev libopenimageio-dev libopenexr-dev libtinyobjloader-dev libglm-dev libtbb-dev
  libcli11-dev libtomlplusplus-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  gnuplot-nox fonts-dejavu-core python3
  python3-dev python3-pybind11 python3-numpy python3-pytest python3-matplotlib
  openmpi-bin libopenmpi-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
