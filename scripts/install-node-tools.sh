#!/usr/bin/env bash
# Installs the test tools that only the npm registry has into DIR (default build/node-tools):
# obj2gltf, the third-party converter that turns an OBJ + MTL with a map_Bump normal map into a
# .glb with normalTexture (the asset equivalence test, python/tests/test_asset_equivalence.py).
# Node.js and npm come from Debian when the machine has no npm yet.
set -euo pipefail
dir="${1:-build/node-tools}"
version="3.2.0"
bin="$dir/node_modules/.bin/obj2gltf"
if [ -x "$bin" ] && grep -q "\"version\": \"$version\"" "$dir/node_modules/obj2gltf/package.json"; then
  exit 0
fi
if ! command -v npm >/dev/null; then
  echo "Installing Debian packages: nodejs npm"
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends nodejs npm
fi
echo "Installing obj2gltf $version from the npm registry into $dir"
mkdir -p "$dir"
npm install --prefix "$dir" --no-audit --no-fund --no-save --loglevel=error "obj2gltf@$version"
"$bin" --version >/dev/null
