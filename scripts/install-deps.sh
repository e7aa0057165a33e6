#!/usr/bin/env bash
# Installs the Debian packages Asperity needs that are not installed yet (apt-get only).
# Usage: scripts/install-deps.sh   (as root, or with sudo available)
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake pkg-config
  # core library
  libeigen3-dev libstb-dev nlohmann-json3-dev libcli11-dev libbullet-dev
  libmeshoptimizer-dev libtinyobjloader-dev zlib1g-dev
  # meshes and their materials from glTF, FBX, COLLADA and 3DS files
  libassimp-dev
  # ensembles of runs on a pool of threads
  libtbb-dev
  # the Python module, its tests, examples and cluster runs (Debian's /usr/bin/python3)
  pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed python3-matplotlib
  # command-line tool plots (SVG and PNG) and their font
  libcairo2-dev fonts-dejavu-core
  # the engine adapters (docs/engines.md): Asperity's friction inside MuJoCo 2.2 and ODE 0.16
  libmujoco-dev libode-dev
  # float height maps (OpenEXR)
  libopenexr-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # the assimp command, which writes the FBX and COLLADA files the asset tests read back
  assimp-utils
  # OpenGL through EGL (Mesa's llvmpipe when there is no GPU), viewer, videos
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libglfw3-dev libimgui-dev
  xvfb xauth ffmpeg
  # meshes used by scenes (the Stanford bunny)
  glmark2-data
  # reliability: libFuzzer targets and sanitizer builds (make fuzz, make sanitize)
  clang libfuzzer-14-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing missing Debian packages: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "error: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
