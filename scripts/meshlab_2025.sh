#!/usr/bin/env bash
# Fetches MeshLab 2025.07 (and 2022.02, for a compile check) from Debian's archive and builds the
# part of 2025.07 the plugin's tests need (core library, GUI, io_base, edit_pickpoints; Release,
# float scalar, Debian's Eigen and shared GLEW) into third_party/meshlab-2025/. Idempotent: every
# step is skipped when its result is there. Called by scripts/test.sh; the demo does not need it.
#
#  * the orig tarballs come from trixie (2022.02) and sid (2025.07) through an apt state of its
#    own (third_party/meshlab-2025/apt), so the system's apt lists stay bookworm's; apt checks
#    them against the signed Sources index;
#  * third_party/meshlab-2025/src/meshlab-2025.07/src is the SDK (headers, vcglib), prefix/ the
#    installed MeshLab (bin/meshlab, lib/meshlab/libmeshlab-common.so, lib/meshlab/plugins/).
# Usage: scripts/meshlab_2025.sh            (as root on Debian 12, after scripts/setup.sh)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/args.sh"; cbd_args 0 "$@"
ML="$ROOT/third_party/meshlab-2025"
V2025="2025.07~dfsg-4"   # sid
V2022="2022.02+dfsg1-1"  # trixie
SRC="$ML/src" BUILD="$ML/build" PREFIX="$ML/prefix"
log() { printf '[meshlab-2025] %s\n' "$*"; }

# The separate apt state: deb-src lines for trixie and sid only.
APTDIR="$ML/apt"
mkdir -p "$APTDIR/etc" "$APTDIR/lists/partial" "$APTDIR/cache/archives/partial" "$SRC"
cat >"$APTDIR/etc/sources.list" <<'LIST'
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian trixie main
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian sid main
LIST
APT=(-o "Dir::Etc::sourcelist=$APTDIR/etc/sources.list" -o "Dir::Etc::sourceparts=-"
     -o "Dir::State::Lists=$APTDIR/lists" -o "Dir::Cache=$APTDIR/cache"
     -o "Dir::Cache::pkgcache=" -o "Dir::Cache::srcpkgcache=")
tarball() { echo "meshlab_${1%-*}.orig.tar.xz"; }
have() { local out; out=$(apt-cache "${APT[@]}" showsrc meshlab 2>/dev/null || true); grep -qx "Version: $1" <<<"$out"; }

for v in "$V2025" "$V2022"; do
  [ -f "$SRC/$(tarball "$v")" ] && continue
  have "$v" || { log "apt-get update (trixie, sid deb-src)"; apt-get "${APT[@]}" update -qq; }
  have "$v" || { log "error: meshlab $v is no longer in Debian's trixie/sid:"; \
    apt-cache "${APT[@]}" showsrc meshlab | grep '^Version' >&2 || true; exit 1; }
  log "downloading meshlab=$v (orig tarball)"
  (cd "$SRC" && apt-get "${APT[@]}" -qq source --tar-only --download-only "meshlab=$v" 2>&1 |
    grep -v 'Download is performed unsandboxed' || true)
  [ -f "$SRC/$(tarball "$v")" ] || { log "error: the download of meshlab=$v failed"; exit 1; }
done

unpack() {  # version folder: the tarball's top folder is meshlab-<git sha>
  local dest="$SRC/$2" tb="$SRC/$(tarball "$1")"
  [ -f "$dest/.unpacked" ] && return
  log "unpacking $(basename "$tb")"
  rm -rf "$dest" "$SRC/.tmp" && mkdir -p "$SRC/.tmp"
  tar -xJf "$tb" -C "$SRC/.tmp"
  mv "$SRC/.tmp/"meshlab-* "$dest" && rmdir "$SRC/.tmp"
  touch "$dest/.unpacked"
}
unpack "$V2025" meshlab-2025.07
unpack "$V2022" meshlab-2022.02

if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  log "configuring MeshLab 2025.07"
  cmake -S "$SRC/meshlab-2025.07" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$PREFIX" -DMESHLAB_BUILD_WITH_DOUBLE_SCALAR=OFF \
    -DMESHLAB_ALLOW_OPTIONAL_EXTERNAL_LIBRARIES=OFF \
    -DMESHLAB_ALLOW_SYSTEM_GLEW=ON -DMESHLAB_ALLOW_BUNDLED_SOURCE_GLEW=OFF \
    -DVCG_ALLOW_SYSTEM_EIGEN=ON -DVCG_ALLOW_BUNDLED_EIGEN=OFF \
    -DMESHLAB_PLUGINS="meshlabplugins/io_base;meshlabplugins/edit_pickpoints" \
    >"$ML/configure.log" 2>&1 || { tail -30 "$ML/configure.log" >&2; exit 1; }
fi
if [ ! -f "$PREFIX/.installed" ] || [ "$(ninja -C "$BUILD" -n 2>/dev/null | tail -n1)" != "ninja: no work to do." ]; then
  log "building MeshLab 2025.07 (core, GUI, io_base, edit_pickpoints; a few minutes)"
  start=$(date +%s)
  cmake --build "$BUILD" --parallel "$(nproc)" >"$ML/build.log" 2>&1 || { tail -40 "$ML/build.log" >&2; exit 1; }
  cmake --install "$BUILD" >"$ML/install.log" 2>&1 || { tail -20 "$ML/install.log" >&2; exit 1; }
  touch "$PREFIX/.installed"
  log "built and installed in $(( $(date +%s) - start )) s"
fi
log "$("$PREFIX/bin/meshlab" --version 2>/dev/null | head -n1) in $PREFIX"
