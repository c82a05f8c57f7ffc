#!/usr/bin/env bash
# Installs what wardray needs to build, test and compare against POV-Ray, from Debian 12's packages.
# Safe to run any number of times: it installs only what is missing. Run as root (or with sudo available).
set -euo pipefail

packages=(
  g++ make cmake pkg-config ccache         # toolchain; ccache shares objects between checkouts (CMakeLists.txt)
  libembree-dev libtbb-dev                 # ray tracing and threads
  libopenimageio-dev openimageio-tools     # image reading (any format)
  libpng-dev libopenexr-dev                # image writing (PNG, OpenEXR)
  libjpeg-dev                              # JPEG image maps read without OpenImageIO
  libcgal-dev libboost-dev                 # mesh geometry, the Spirit X3 parser
  libgtest-dev nlohmann-json3-dev          # tests, --stats JSON
  povray povray-includes povray-examples fonts-povray  # the reference renderer, its includes and scenes
  python3-numpy python3-openimageio python3-matplotlib  # tools/compare: read HDR images, plot error against time
  libopenmpi-dev openmpi-bin              # rendering across processes (mpirun -np N wardray; -DWARDRAY_MPI)
  clang libclang-rt-14-dev                 # tools/fuzz.sh: libFuzzer and the sanitizer runtimes (CI does not fuzz)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages are installed"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: run as root to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
echo "setup: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
