#!/usr/bin/env bash
# Sets up a Debian 12 machine for building, testing and running cbd. Idempotent.
#
#  * installs the Debian packages the project needs (needs root, as apt-get does);
#  * adds a bookworm deb-src entry when none is there;
#  * fetches MeshLab 2020.09's source package (SDK headers + the matching vcglib)
#    into third_party/ with `apt-get source meshlab` (Debian's archive only; ignored by git).
#
# Usage: scripts/setup.sh            (from anywhere)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/args.sh"; cbd_args 0 "$@"
THIRD="$ROOT/third_party"

log() { printf '[setup] %s\n' "$*"; }

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "[setup] error: installing packages needs root (run as root or install sudo)" >&2; exit 1
  fi
fi

PACKAGES=(
  build-essential cmake ninja-build pkg-config git dpkg-dev
  libgtest-dev googletest libeigen3-dev
  libpugixml-dev nlohmann-json3-dev libcli11-dev
  qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev libglu1-mesa-dev
  meshlab xvfb xauth x11-apps x11-utils imagemagick
  libcgal-demo gnuplot-nox
  clang libclang-rt-14-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

# A deb-src entry for bookworm, so that `apt-get source meshlab` works.
need_src_update=0
if ! grep -rqsE '^(deb-src|Types:.*deb-src)' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  log "adding a bookworm deb-src entry"
  $SUDO tee /etc/apt/sources.list.d/cbd-deb-src.sources >/dev/null <<'SRC'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  need_src_update=1
fi

if [ "${#missing[@]}" -gt 0 ] || [ "$need_src_update" -eq 1 ] || [ ! -d "$THIRD/meshlab" ]; then
  log "apt-get update"
  $SUDO apt-get update -qq
fi
if [ "${#missing[@]}" -gt 0 ]; then
  log "installing: ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  log "all Debian packages present"
fi

# MeshLab 2020.09 source: SDK headers (src/common) and the vcglib the binary was built with.
if [ ! -f "$THIRD/meshlab/vcglib/vcg/complex/complex.h" ] || [ ! -f "$THIRD/meshlab/src/common/interfaces.h" ]; then
  log "fetching MeshLab's source package into third_party/"
  rm -rf "$THIRD/meshlab" "$THIRD/src"
  mkdir -p "$THIRD/src"
  (cd "$THIRD/src" && apt-get source -qq --download-only meshlab >/dev/null && dpkg-source -x meshlab_*.dsc meshlab >/dev/null)
  mv "$THIRD/src/meshlab" "$THIRD/meshlab"
  rm -rf "$THIRD/src"
  # Debian's tree keeps vcglib next to src/; some versions nest it under src/.
  if [ ! -d "$THIRD/meshlab/vcglib" ] && [ -d "$THIRD/meshlab/src/vcglib" ]; then
    ln -s src/vcglib "$THIRD/meshlab/vcglib"
  fi
fi
test -f "$THIRD/meshlab/vcglib/vcg/complex/complex.h" || { echo "[setup] error: vcglib not found in $THIRD/meshlab" >&2; exit 1; }
log "MeshLab SDK + vcglib: $THIRD/meshlab"

# Real meshes from libcgal-demo, unpacked once for examples, tests and benchmarks.
CGAL_TGZ=/usr/share/doc/libcgal-demo/examples/data.tar.gz
if [ ! -f "$THIRD/cgal-data/meshes/cow.off" ]; then
  tgz=$(dpkg -L libcgal-demo | grep -E '/data\.tar\.gz$' | head -n1 || true)
  [ -n "$tgz" ] || tgz="$CGAL_TGZ"
  log "unpacking CGAL demo meshes from $tgz"
  rm -rf "$THIRD/cgal-data" && mkdir -p "$THIRD/cgal-data"
  tar -xzf "$tgz" -C "$THIRD/cgal-data" --strip-components=1 --wildcards '*/meshes/*.off'
fi
log "done"
