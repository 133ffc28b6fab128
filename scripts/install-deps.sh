#!/usr/bin/env bash
# Installs what TimeCritical needs from Debian 12 (idempotent: skips when all
# packages are present). Never installs libvtk9-dev or python3-vtk9, which
# conflict with ParaView's bundled VTK.
set -euo pipefail

packages=(
  # toolchain and test tools
  cmake g++ make googletest libgtest-dev xvfb xauth
  # ParaView 5.11 with its bundled VTK 9.2, and its Python modules
  paraview paraview-dev python3-paraview python3-numpy python3-matplotlib
  # libraries of the project
  libopenmesh-dev libopenimageio-dev libmeshoptimizer-dev
  # development files ParaView's CMake package looks for but does not depend on
  libopenmpi-dev libdouble-conversion-dev liblz4-dev liblzma-dev zlib1g-dev libexpat1-dev
  libpng-dev libjpeg-dev libtiff-dev libfreetype-dev libglew-dev libgl-dev libx11-dev
  libxt-dev libpugixml-dev libjsoncpp-dev libeigen3-dev libfmt-dev libutfcpp-dev libgl2ps-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
