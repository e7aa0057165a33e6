#!/bin/sh
# Installs the built libraries and headers into a temporary prefix, builds examples/cpp/ against
# them with find_package(asperity) as an outside project would, and runs the programs.
#   install_and_build_examples.sh BUILD_DIR CXX_COMPILER HAVE_GL
set -eu
build_dir=$1
cxx=$2
have_gl=$3
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build_dir" --prefix "$work/prefix" --component cpp > "$work/install.log"
# Nothing of the source or build tree may leak into the outside project.
cmake -S "$source_dir/examples/cpp" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
cmake --build "$work/build" -j2 > "$work/build.log" || { cat "$work/build.log"; exit 1; }

"$work/build/sawtooth_box"
"$work/build/scene_contacts" "$source_dir/scenes/stacking.json" 50 | head -5
"$work/build/bullet_sawtooth"
if [ "$have_gl" = ON ]; then
  "$work/build/gl_sampler"
fi
