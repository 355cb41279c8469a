#!/usr/bin/env bash
# Installs the built litkit into a scratch prefix and builds and runs a small
# project that finds it with find_package(litkit). Usage: check_install.sh BUILD_DIR
set -euo pipefail
build=$1
here=$(cd "$(dirname "$0")" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build" --prefix "$scratch/prefix" > /dev/null
cmake -S "$here/install_consumer" -B "$scratch/consumer" -G Ninja \
      -DCMAKE_PREFIX_PATH="$scratch/prefix" > /dev/null
cmake --build "$scratch/consumer" > /dev/null
"$scratch/consumer/consumer"
test -x "$scratch/prefix/bin/litkit"
"$scratch/prefix/bin/litkit" --version
