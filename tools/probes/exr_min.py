"""exr_min.py: the least an offline probe needs to read and write OpenEXR without a Python EXR
package (Debian's python3 has none here): single-part scanline files, NONE or ZIP(S) compression,
HALF or FLOAT channels in; uncompressed FLOAT channels out. read() returns (width, height,
{channel: list of floats, row-major}); write() takes the same. Not for production input: `asvgf
denoise` reads EXR through the C++ reader, which checks what this does not."""
import struct
import zlib

LINES_PER_BLOCK = {0: 1, 2: 1, 3: 16}  # NONE, ZIPS, ZIP
HALF = 1


def read_header(data):
    """The attributes as {name: raw bytes}, and where the offset table starts."""
    pos, attrs = 8, {}
    while data[pos] != 0:
        name_end = data.index(0, pos)
        type_end = data.index(0, name_end + 1)
        size = struct.unpack_from("<i", data, type_end + 1)[0]
        value = type_end + 5
        attrs[data[pos:name_end].decode()] = data[value:value + size]
        pos = value + size
    return attrs, pos + 1


def channels(chlist):
    """[(name, pixel type)] from a chlist attribute: name\\0, type, 12 more bytes each."""
    out, i = [], 0
    while chlist[i] != 0:
        end = chlist.index(0, i)
        out.append((chlist[i:end].decode(), struct.unpack_from("<i", chlist, end + 1)[0]))
        i = end + 17
    return out


def unzip(raw):
    """ZIP(S) block: inflate, undo the byte predictor, then the split into even and odd bytes."""
    t = bytearray(zlib.decompress(raw))
    for k in range(1, len(t)):
        t[k] = (t[k - 1] + t[k] - 128) & 255
    half = (len(t) + 1) // 2
    u = bytearray(len(t))
    u[0::2], u[1::2] = t[:half], t[half:]
    return bytes(u)


def read(path):
    data = open(path, "rb").read()
    attrs, pos = read_header(data)
    compression = attrs["compression"][0]
    x0, y0, x1, y1 = struct.unpack("<iiii", attrs["dataWindow"])
    w, h = x1 - x0 + 1, y1 - y0 + 1
    chans = channels(attrs["channels"])
    lines_per = LINES_PER_BLOCK[compression]
    blocks = (h + lines_per - 1) // lines_per
    out = {name: [0.0] * (w * h) for name, _ in chans}
    for offset in struct.unpack_from("<%dQ" % blocks, data, pos):
        y, n = struct.unpack_from("<ii", data, offset)
        y -= y0
        raw = data[offset + 8:offset + 8 + n]
        lines = min(lines_per, h - y)
        if compression != 0 and n < lines * w * sum(2 if t == HALF else 4 for _, t in chans):
            raw = unzip(raw)  # a block that would not shrink is stored as it is
        p = 0
        for line in range(lines):
            for name, t in chans:
                size = 2 if t == HALF else 4
                values = struct.unpack_from("<%d%s" % (w, "e" if t == HALF else "f"), raw, p)
                p += w * size
                out[name][(y + line) * w:(y + line + 1) * w] = list(values)
    return w, h, out


def write(path, w, h, chans):
    names = sorted(chans)

    def attr(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value

    chlist = b"".join(n.encode() + b"\0" + struct.pack("<iBBBBii", 2, 0, 0, 0, 0, 1, 1) for n in names) + b"\0"
    window = struct.pack("<iiii", 0, 0, w - 1, h - 1)
    header = (b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + attr("channels", "chlist", chlist)
              + attr("compression", "compression", b"\0") + attr("dataWindow", "box2i", window)
              + attr("displayWindow", "box2i", window) + attr("lineOrder", "lineOrder", b"\0")
              + attr("pixelAspectRatio", "float", struct.pack("<f", 1.0))
              + attr("screenWindowCenter", "v2f", struct.pack("<ff", 0, 0))
              + attr("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    line_bytes = 8 + 4 * w * len(names)
    start = len(header) + 8 * h
    body = [struct.pack("<Q", start + y * line_bytes) for y in range(h)]
    for y in range(h):
        body.append(struct.pack("<ii", y, 4 * w * len(names)))
        body.extend(struct.pack("<%df" % w, *chans[n][y * w:(y + 1) * w]) for n in names)
    open(path, "wb").write(header + b"".join(body))
