#!/usr/bin/env bash
# Set everything up (Debian packages, MeshLab 2020.09's SDK, MeshLab 2025.07 built from Debian's
# source tarball by scripts/meshlab_2025.sh), build, and pass the test suite:
#   1. the release build: every unit, CLI and plugin test (ctest), the plugin against both
#      MeshLab 2020.09 and 2025.07 (and compiled against 2022.02's headers);
#   2. the same suite built with AddressSanitizer + UndefinedBehaviorSanitizer (no plugin:
#      MeshLab itself is not built with them);
#   3. a short libFuzzer run of the anchor parsers and the mesh loaders: inputs that once
#      crashed are replayed, then FUZZ_RUNS executions (default 600000, about 30 s) from a
#      fixed seed, so the run is the same on every machine; 0 skips it.
# Usage: scripts/test.sh            (as root on Debian 12; idempotent)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/args.sh"; cbd_args 0 "$@"
FUZZ_RUNS="${FUZZ_RUNS:-600000}"
"$ROOT/scripts/setup.sh"
"$ROOT/scripts/meshlab_2025.sh"

echo "== release build and tests"
"$ROOT/scripts/build.sh" "$ROOT/build"
(cd "$ROOT/build" && ctest --output-on-failure --timeout 900 -j "$(nproc)")

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
"$ROOT/scripts/build.sh" "$ROOT/build-asan" -DCBD_SANITIZE=ON -DCBD_BUILD_PLUGIN=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
(cd "$ROOT/build-asan" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
   ctest --output-on-failure --timeout 900 -j "$(nproc)")

if [ "$FUZZ_RUNS" -gt 0 ]; then
  echo "== libFuzzer: ${FUZZ_RUNS} runs per target"
  if [ ! -f "$ROOT/build-fuzz/CMakeCache.txt" ]; then
    cmake -S "$ROOT" -B "$ROOT/build-fuzz" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCBD_FUZZ=ON \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  fi
  cmake --build "$ROOT/build-fuzz" --parallel "$(nproc)"
  for t in anchors mesh; do
    work="$(mktemp -d)"
    cp -r "$ROOT/tests/fuzz/corpus/$t/." "$work/"
    # Regressions (inputs that once crashed) first, then a seeded run from the corpus.
    if ls "$ROOT/tests/fuzz/regressions/$t"-* >/dev/null 2>&1; then
      "$ROOT/build-fuzz/tests/fuzz/fuzz_$t" "$ROOT/tests/fuzz/regressions/$t"-* 2>&1 | tail -n 1
    fi
    "$ROOT/build-fuzz/tests/fuzz/fuzz_$t" -seed=1 -timeout=20 -runs="$FUZZ_RUNS" -print_final_stats=1 \
      -artifact_prefix="$ROOT/build-fuzz/crash-$t-" "$work" 2>&1 | tail -n 3
    rm -rf "$work"
  done
  echo "fuzz: 2 passed, 0 failed"
fi
