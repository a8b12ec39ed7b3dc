#!/usr/bin/env bash
# Set everything up (Debian packages, MeshLab SDK), build, and run the test suite.
# Usage: scripts/test.sh            (as root on Debian 12; idempotent)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/setup.sh"
"$ROOT/scripts/build.sh" "$ROOT/build"
cd "$ROOT/build"
ctest --output-on-failure --timeout 900 -LE slow -j "$(nproc)"
