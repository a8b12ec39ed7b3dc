#!/usr/bin/env bash
# Regenerate docs/meshlab_cbd.png: MeshLab's own window (the real `meshlab` GUI, from the no-root
# prefix with the cbd plugin) on a virtual X server, showing the cow and the bull side by side,
# each coloured per face by patch of their common base domain (corresponding patches share a
# colour), as written by meshlab_scripts/cross_parameterize.sh.
#
# Usage: scripts/screenshot.sh [OUTPUT.png]        (default: docs/meshlab_cbd.png)
# Environment: CBD_PLUGIN_SO, CBD_MESHLAB_PREFIX (as for cross_parameterize.sh);
#              SCREENSHOT_WAIT seconds to let MeshLab draw (default 12); KEEP_TMP=1.
# Needs: Xvfb, ImageMagick (import, convert), python3, xwininfo (x11-utils).
set -uo pipefail

NAME="screenshot"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$ROOT/scripts/args.sh"; cbd_args 1 "$@"
OUT="${1:-$ROOT/docs/meshlab_cbd.png}"
die() { printf '[%s] error: %s\n' "$NAME" "$*" >&2; exit 1; }
info() { printf '[%s] %s\n' "$NAME" "$*"; }
for tool in Xvfb import convert python3 xwininfo; do
  command -v "$tool" >/dev/null || die "$tool not found (apt-get install xvfb imagemagick python3 x11-utils)"
done

TMP="$(mktemp -d "${TMPDIR:-/tmp}/cbd_screenshot.XXXXXX")" || die "cannot create a temporary folder"
XPID="" MPID=""
cleanup() {
  [ -n "$MPID" ] && kill "$MPID" 2>/dev/null
  [ -n "$XPID" ] && kill "$XPID" 2>/dev/null
  wait 2>/dev/null
  if [ "${KEEP_TMP:-0}" = 1 ]; then info "kept $TMP"; else rm -rf "$TMP"; fi
}
trap cleanup EXIT

# 1. The coloured layers (and the prefix) from the wrapper.
export CBD_MESHLAB_PREFIX="${CBD_MESHLAB_PREFIX:-${XDG_CACHE_HOME:-$HOME/.cache}/cbd/meshlab-prefix}"
M="$ROOT/third_party/cgal-data/meshes"
KEEP_TMP=0 "$ROOT/meshlab_scripts/cross_parameterize.sh" "$M/cow.off" "$ROOT/examples/cow_picked_points.pp" \
  "$M/bull.off" "$ROOT/examples/bull_picked_points.pp" "$TMP/run" >"$TMP/run.log" 2>&1 ||
  { cat "$TMP/run.log" >&2; die "meshlab_scripts/cross_parameterize.sh failed"; }

# 2. Side by side: MeshLab shows every layer where it is, so move the bull to the right of the cow
#    (a copy of the PLY with x shifted; binary little-endian or ASCII, any vertex properties).
python3 - "$TMP/run/source_patches.ply" "$TMP/run/target_patches.ply" "$TMP/cow.ply" "$TMP/bull.ply" <<'PY' ||
import struct, sys, shutil
SIZES = {"char": "b", "uchar": "B", "int8": "b", "uint8": "B", "short": "h", "ushort": "H", "int16": "h",
         "uint16": "H", "int": "i", "uint": "I", "int32": "i", "uint32": "I", "float": "f", "float32": "f",
         "double": "d", "float64": "d"}
def read(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    fmt = next(l.split()[1] for l in header if l.startswith("format"))
    props, nv, inv = [], 0, False
    for l in header:
        w = l.split()
        if w[:2] == ["element", "vertex"]: nv, inv = int(w[2]), True
        elif w and w[0] == "element": inv = False
        elif inv and w[0] == "property": props.append((w[-1], SIZES[w[1]]))
    return data, end, fmt, props, nv
def xrange_of(path):
    data, end, fmt, props, nv = read(path)
    xs = []
    if fmt == "ascii":
        lines = data[end:].decode("ascii").splitlines()
        xs = [float(lines[i].split()[[p[0] for p in props].index("x")]) for i in range(nv)]
    else:
        rec = struct.Struct("<" + "".join(p[1] for p in props)); ix = [p[0] for p in props].index("x")
        xs = [rec.unpack_from(data, end + i * rec.size)[ix] for i in range(nv)]
    return min(xs), max(xs)
def shifted(src, dst, dx):
    data, end, fmt, props, nv = read(src)
    names = [p[0] for p in props]; ix = names.index("x")
    if fmt == "ascii":
        lines = data[end:].decode("ascii").split("\n")
        for i in range(nv):
            w = lines[i].split(); w[ix] = repr(float(w[ix]) + dx); lines[i] = " ".join(w)
        open(dst, "wb").write(data[:end] + "\n".join(lines).encode("ascii"))
        return
    assert fmt == "binary_little_endian", fmt
    rec = struct.Struct("<" + "".join(p[1] for p in props)); body = bytearray(data)
    for i in range(nv):
        v = list(rec.unpack_from(body, end + i * rec.size)); v[ix] += dx; rec.pack_into(body, end + i * rec.size, *v)
    open(dst, "wb").write(bytes(body))
cow, bull, cow_out, bull_out = sys.argv[1:5]
c0, c1 = xrange_of(cow); b0, b1 = xrange_of(bull)
gap = 0.15 * max(c1 - c0, b1 - b0)
shutil.copyfile(cow, cow_out)
shifted(bull, bull_out, c1 + gap - b0)
PY
  die "could not place the bull next to the cow"

# 3. MeshLab's GUI on a virtual screen, then a capture of the whole screen.
N=""
for n in $(seq 91 140); do
  if [ ! -e "/tmp/.X$n-lock" ] && [ ! -e "/tmp/.X11-unix/X$n" ]; then N=$n; break; fi
done
[ -n "$N" ] || die "no free X display number"
Xvfb ":$N" -screen 0 1600x1000x24 -nolisten tcp >"$TMP/xvfb.log" 2>&1 &
XPID=$!
for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X$N" ] && break; sleep 0.1; done
[ -e "/tmp/.X11-unix/X$N" ] || { cat "$TMP/xvfb.log" >&2; die "Xvfb :$N did not start"; }
export DISPLAY=":$N"
# A fresh MeshLab settings folder: no window geometry or dialogs from earlier sessions.
mkdir -p "$TMP/home/.config"
(cd "$TMP" && HOME="$TMP/home" XDG_CONFIG_HOME="$TMP/home/.config" \
   exec "$CBD_MESHLAB_PREFIX/bin/meshlab" -geometry 1600x1000+0+0 "$TMP/cow.ply" "$TMP/bull.ply") \
   >"$TMP/meshlab.log" 2>&1 &
MPID=$!
for _ in $(seq 100); do
  xwininfo -root -tree 2>/dev/null | grep -qi '"MeshLab' && break
  kill -0 "$MPID" 2>/dev/null || { cat "$TMP/meshlab.log" >&2; die "meshlab exited early"; }
  sleep 0.2
done
sleep 2
# Without a window manager showMaximized() does nothing: resize MeshLab's window to the screen
# through Xlib, and hide the trackball overlay (View > Show Trackball, Shift+H) through XTest.
python3 - 1600 1000 >"$TMP/xlib.log" 2>&1 <<'PY' || info "warning: could not resize the window or hide the trackball (see $TMP/xlib.log)"
import ctypes, ctypes.util, sys, time
W, H = int(sys.argv[1]), int(sys.argv[2])
x11 = ctypes.cdll.LoadLibrary("libX11.so.6")
xtst = ctypes.cdll.LoadLibrary("libXtst.so.6")
x11.XOpenDisplay.restype = ctypes.c_void_p
x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
dpy = x11.XOpenDisplay(None)
assert dpy, "cannot open the display"
for f in ("XDefaultRootWindow",):
    getattr(x11, f).restype = ctypes.c_ulong; getattr(x11, f).argtypes = [ctypes.c_void_p]
root = x11.XDefaultRootWindow(dpy)
x11.XQueryTree.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_ulong), ctypes.POINTER(ctypes.c_ulong),
                           ctypes.POINTER(ctypes.POINTER(ctypes.c_ulong)), ctypes.POINTER(ctypes.c_uint)]
x11.XFetchName.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_char_p)]
x11.XMoveResizeWindow.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_int, ctypes.c_uint, ctypes.c_uint]
x11.XSetInputFocus.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_ulong]
x11.XKeysymToKeycode.argtypes = [ctypes.c_void_p, ctypes.c_ulong]
x11.XKeysymToKeycode.restype = ctypes.c_ubyte
x11.XFlush.argtypes = x11.XSync.argtypes = [ctypes.c_void_p]
x11.XSync.argtypes = [ctypes.c_void_p, ctypes.c_int]
xtst.XTestFakeKeyEvent.argtypes = [ctypes.c_void_p, ctypes.c_uint, ctypes.c_int, ctypes.c_ulong]
xtst.XTestFakeMotionEvent.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_ulong]
r, p, n = ctypes.c_ulong(), ctypes.c_ulong(), ctypes.c_uint()
kids = ctypes.POINTER(ctypes.c_ulong)()
x11.XQueryTree(dpy, root, ctypes.byref(r), ctypes.byref(p), ctypes.byref(kids), ctypes.byref(n))
win = None
for i in range(n.value):
    name = ctypes.c_char_p()
    # The main window is "MeshLab 2020.09 - [Project_1]" (Qt also makes a hidden "MeshLab_64bit_fp").
    if x11.XFetchName(dpy, kids[i], ctypes.byref(name)) and name.value and name.value.startswith(b"MeshLab "):
        win = kids[i]; print("window", hex(win), name.value.decode())
assert win, "no MeshLab window"
x11.XMoveResizeWindow(dpy, win, 0, 0, W, H)
x11.XSync(dpy, 0)
time.sleep(2)
x11.XSetInputFocus(dpy, win, 2, 0)               # RevertToParent, CurrentTime
xtst.XTestFakeMotionEvent(dpy, -1, W // 3, H // 2, 0)
x11.XSync(dpy, 0)
time.sleep(0.5)
shift, h = x11.XKeysymToKeycode(dpy, 0xffe1), x11.XKeysymToKeycode(dpy, ord("h"))
for code, down in ((shift, 1), (h, 1), (h, 0), (shift, 0)):
    xtst.XTestFakeKeyEvent(dpy, code, down, 0); x11.XSync(dpy, 0); time.sleep(0.05)
print("resized to %dx%d, sent Shift+H" % (W, H))
PY
sleep "${SCREENSHOT_WAIT:-12}"   # loading, first frames (software OpenGL)
kill -0 "$MPID" 2>/dev/null || { cat "$TMP/meshlab.log" >&2; die "meshlab exited early"; }
mkdir -p "$(dirname "$OUT")"
import -window root "$TMP/shot.png" 2>"$TMP/import.log" || { cat "$TMP/import.log" >&2; die "screen capture failed"; }
convert "$TMP/shot.png" -strip "$OUT" || die "cannot write $OUT"
info "wrote $OUT ($(identify -format '%wx%h' "$OUT" 2>/dev/null))"
