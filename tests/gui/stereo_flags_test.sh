#!/usr/bin/env bash
# --stereo and --vr through the real program (run on a display by xvfb.sh):
#  - --stereo anaglyph: status 0, no message, the screenshot shows red and cyan images apart;
#  - --stereo quad-buffer (Xvfb has no stereo visuals): status 0, the reason on stderr, a mono screenshot;
#  - --vr without an OpenXR runtime: status 0, "No VR" and the loader's result on stderr, the screenshot still written.
# Usage: stereo_flags_test.sh SCULPTLINE OUTPUT_DIR
set -uo pipefail
exe=$1
out=$2
rm -rf "$out"
mkdir -p "$out"
fail=0
check() {  # check NAME CONDITION-MESSAGE COMMAND...
  local what=$1; shift
  if ! "$@"; then echo "FAIL: $what" >&2; fail=1; fi
}

"$exe" --size 640x480 --stereo anaglyph --screenshot "$out/anaglyph.png" --quit 2>"$out/anaglyph.err"
check "anaglyph exits 0" test $? -eq 0
check "anaglyph screenshot written" test -s "$out/anaglyph.png"
check "anaglyph without a message" bash -c "! grep -q -- '--stereo' '$out/anaglyph.err'"

"$exe" --size 640x480 --stereo quad-buffer --screenshot "$out/quad.png" --quit 2>"$out/quad.err"
check "quad-buffer exits 0" test $? -eq 0
check "quad-buffer screenshot written" test -s "$out/quad.png"
check "quad-buffer says why" grep -q "Quad-buffer stereo is not available" "$out/quad.err"

"$exe" --size 640x480 --screenshot "$out/mono.png" --quit 2>"$out/mono.err"
check "mono exits 0" test $? -eq 0

XR_RUNTIME_JSON=/nonexistent/sculptline-test-runtime.json "$exe" --size 640x480 --vr --screenshot "$out/vr.png" --quit 2>"$out/vr.err"
check "--vr without runtime exits 0" test $? -eq 0
check "--vr says there is no session" grep -q "No VR" "$out/vr.err"
check "--vr screenshot written (the desktop goes on)" test -s "$out/vr.png"

# The pictures: quad-buffer refused is the mono picture, pixel for pixel; anaglyph is not.
python3 - "$out" <<'PY' || fail=1
import sys, struct, zlib
def load(path):
    # A minimal PNG reader (8-bit RGB/RGBA, no interlace): what Qt writes.
    data = open(path, 'rb').read()
    pos, idat, w = 8, b'', 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR': w, h, depth, ctype = struct.unpack('>IIBB', body[:10])
        if kind == b'IDAT': idat += body
        pos += 12 + n
    bpp = {2: 3, 6: 4}[ctype]
    raw, stride, rows, prev = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line)); prev = line
    return w, h, bpp, rows
out = sys.argv[1]
mono, quad, ana = (load(f'{out}/{n}.png') for n in ('mono', 'quad', 'anaglyph'))
if mono[3] != quad[3]:
    print('FAIL: the refused quad-buffer picture differs from the mono one'); sys.exit(1)
# In a mono picture of the grey-blue background and the default scene, red and green edges coincide;
# anaglyph shifts them: count pixels whose red and green differ by more than 60.
def split(img):
    w, h, bpp, rows = img
    return sum(1 for r in rows for x in range(0, w * bpp, bpp) if abs(r[x] - r[x + 1]) > 60)
m, a = split(mono), split(ana)
print(f'pixels with |R-G| > 60: mono {m}, anaglyph {a}')
if a <= 2 * m + 100:
    print('FAIL: the anaglyph picture shows no red/cyan fringes'); sys.exit(1)
PY
exit $fail
