#!/usr/bin/env bash
# The panel on a real X server (Xvfb, xcb platform): it starts, renders and
# the screenshot shows more than a blank window.
set -u
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export XDG_CONFIG_HOME="$out/config"
fail=0
"$MTC_PANEL" --screen programs --program 1 --screenshot "$out/x11.png"
rc=$?
[ $rc -eq 0 ] || { echo "FAIL: panel under Xvfb exited $rc"; fail=1; }
size=$(stat -c %s "$out/x11.png" 2>/dev/null || echo 0)
[ "$size" -gt 10000 ] || { echo "FAIL: screenshot too small ($size bytes)"; fail=1; }
python3 - "$out/x11.png" <<'PY' || fail=1
import sys, zlib, struct
data = open(sys.argv[1], 'rb').read()
assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
pos, idat, width, height = 8, b'', 0, 0
while pos < len(data):
    length, kind = struct.unpack('>I4s', data[pos:pos + 8])
    chunk = data[pos + 8:pos + 8 + length]
    if kind == b'IHDR':
        width, height = struct.unpack('>II', chunk[:8])
    if kind == b'IDAT':
        idat += chunk
    pos += 12 + length
raw = zlib.decompress(idat)
distinct = len(set(raw[i:i + 3] for i in range(0, min(len(raw), 400000), 3)))
print(f'{width}x{height}, {distinct} distinct byte triples')
assert width >= 800 and height >= 600, 'window too small'
assert distinct > 20, 'picture looks blank'
PY
[ $fail -eq 0 ] && echo "ok: panel renders under Xvfb"
exit $fail
