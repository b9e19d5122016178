#!/usr/bin/env bash
# mtc200-panel --screen toolpath --program P --screenshot F renders the 3D
# toolpath view under Xvfb: the PNG shows the path colours (feed green,
# rapid orange) and is more than a blank window; the G32 lathe program too.
set -u
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export XDG_CONFIG_HOME="$out/config"
fail=0
"$MTC_PANEL" --screen toolpath --program 1 --screenshot "$out/mill.png" || { echo "FAIL: mill exit $?"; fail=1; }
"$MTC_PANEL" --process 1 --screen toolpath --program 1 --screenshot "$out/lathe.png" || { echo "FAIL: lathe exit $?"; fail=1; }
python3 - "$out/mill.png" "$out/lathe.png" <<'PY' || fail=1
import sys, zlib, struct
def pixels(path):
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
    pos, idat = 8, b''
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR':
            width, height, depth, ctype = struct.unpack('>IIBB', chunk[:10])
        if kind == b'IDAT':
            idat += chunk
        pos += 12 + length
    raw = zlib.decompress(idat)
    bpp = {2: 3, 6: 4}[ctype]
    stride = width * bpp
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line)); prev = line
    return width, height, bpp, rows
def near(rows, bpp, colour):
    n = 0
    for row in rows:
        for i in range(0, len(row), bpp):
            if sum(abs(row[i + k] - colour[k]) for k in range(3)) < 40:
                n += 1
    return n
for path in sys.argv[1:]:
    w, h, bpp, rows = pixels(path)
    feed, rapid, arc = near(rows, bpp, (0, 200, 0)), near(rows, bpp, (255, 170, 0)), near(rows, bpp, (0, 160, 255))
    print(f'{path}: {w}x{h} feed {feed} rapid {rapid} arc {arc}')
    assert w >= 800 and h >= 600, 'window too small'
    assert feed + arc > 50, 'no feed/arc path pixels'
    assert rapid > 10, 'no rapid path pixels'
PY
[ $fail -eq 0 ] && echo "ok: toolpath screenshots render under Xvfb"
exit $fail
