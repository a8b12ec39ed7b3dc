#!/usr/bin/env bash
# Configure and build cbd (core, CLI, tests, and the MeshLab plugin when the SDK is present).
# Usage: scripts/build.sh [BUILD_DIR] [extra cmake args...]   (default BUILD_DIR: build)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
case "${1:-}" in -h | --help) sed -n 's/^# Usage: //p' "$0"; exit 0 ;; esac
# The first argument is the build directory unless it is already one of cmake's (-D...).
if [ "$#" -gt 0 ] && [[ "$1" != -* ]]; then BUILD="$1"; shift; else BUILD="$ROOT/build"; fi
GEN=()
command -v ninja >/dev/null 2>&1 && GEN=(-G Ninja)
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  cmake -S "$ROOT" -B "$BUILD" "${GEN[@]}" -DCMAKE_BUILD_TYPE=Release "$@"
elif [ "$#" -gt 0 ]; then
  cmake "$BUILD" "$@"
fi
cmake --build "$BUILD" --parallel "$(nproc)"
