"""exr_min.py: the least an offline probe needs to read and write OpenEXR without a Python EXR
package (Debian's python3 has none here): single-part scanline files, NONE or ZIP(S) compression,
HALF or FLOAT channels in; uncompressed FLOAT channels out. read() returns (width, height,
{channel: list of floats, row-major}); write() takes the same. Not for production input: `asvgf
denoise` reads EXR through the C++ reader, which checks what this does not."""
import struct, zlib, array
def read(path):
    d = open(path, 'rb').read(); pos = 8; attrs = {}
    while d[pos] != 0:
        ne = d.index(0, pos); name = d[pos:ne].decode(); te = d.index(0, ne + 1)
        size = struct.unpack_from('<i', d, te + 1)[0]; v = te + 5
        attrs[name] = d[v:v + size]; pos = v + size
    pos += 1
    comp = attrs['compression'][0]
    x0, y0, x1, y1 = struct.unpack('<iiii', attrs['dataWindow'])
    w, h = x1 - x0 + 1, y1 - y0 + 1
    chans = []; c = attrs['channels']; i = 0
    while c[i] != 0:
        e = c.index(0, i); nm = c[i:e].decode(); pt = struct.unpack_from('<i', c, e + 1)[0]; chans.append((nm, pt)); i = e + 17
    lines_per = {0: 1, 2: 1, 3: 16}[comp]
    nblocks = (h + lines_per - 1) // lines_per
    offs = struct.unpack_from('<%dQ' % nblocks, d, pos)
    out = {nm: [0.0] * (w * h) for nm, _ in chans}
    for b in range(nblocks):
        o = offs[b]; y = struct.unpack_from('<i', d, o)[0] - y0; n = struct.unpack_from('<i', d, o + 4)[0]
        raw = d[o + 8:o + 8 + n]
        nl = min(lines_per, h - y)
        expect = nl * w * sum(2 if pt == 1 else 4 for _, pt in chans)
        if comp in (2, 3) and n < expect:
            t = bytearray(zlib.decompress(raw))
            for k in range(1, len(t)): t[k] = (t[k - 1] + t[k] - 128) & 255
            half = (len(t) + 1) // 2; u = bytearray(len(t)); u[0::2] = t[:half]; u[1::2] = t[half:]; raw = bytes(u)
        p = 0
        for line in range(nl):
            for nm, pt in chans:
                fmt = 'e' if pt == 1 else 'f'; sz = 2 if pt == 1 else 4
                vals = struct.unpack_from('<%d%s' % (w, fmt), raw, p); p += w * sz
                out[nm][(y + line) * w:(y + line + 1) * w] = list(vals)
    return w, h, out
def write(path, w, h, chans):
    names = sorted(chans)
    def attr(n, t, v): return n.encode() + b'\0' + t.encode() + b'\0' + struct.pack('<i', len(v)) + v
    ch = b''.join(nm.encode() + b'\0' + struct.pack('<iBBBBii', 2, 0, 0, 0, 0, 1, 1) for nm in names) + b'\0'
    hdr = b'\x76\x2f\x31\x01' + struct.pack('<i', 2)
    hdr += attr('channels', 'chlist', ch) + attr('compression', 'compression', b'\0')
    win = struct.pack('<iiii', 0, 0, w - 1, h - 1)
    hdr += attr('dataWindow', 'box2i', win) + attr('displayWindow', 'box2i', win) + attr('lineOrder', 'lineOrder', b'\0')
    hdr += attr('pixelAspectRatio', 'float', struct.pack('<f', 1.0)) + attr('screenWindowCenter', 'v2f', struct.pack('<ff', 0, 0))
    hdr += attr('screenWindowWidth', 'float', struct.pack('<f', 1.0)) + b'\0'
    linesz = 8 + 4 * w * len(names); start = len(hdr) + 8 * h
    body = b''.join(struct.pack('<Q', start + y * linesz) for y in range(h))
    for y in range(h):
        body += struct.pack('<ii', y, 4 * w * len(names))
        for nm in names: body += struct.pack('<%df' % w, *chans[nm][y * w:(y + 1) * w])
    open(path, 'wb').write(hdr + body)
