#!/usr/bin/env python3
"""exr_window.py IN OUT DX DY: rewrites an uncompressed single-part scanline EXR (what asvgf writes
under 16x16 pixels) with its data window moved by (DX, DY) inside an unchanged display window, as a
renderer's region render writes it (Arnold, Karma, Nuke): the same pixels, placed elsewhere. Lets
the suite test how a reader treats a data window that is not the display window without such a
renderer."""
import struct
import sys


def main():
    src, dst, dx, dy = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    data = bytearray(open(src, "rb").read())
    assert data[:4] == b"\x76\x2f\x31\x01", "not an OpenEXR file"
    pos = 8
    window = None
    compression = None
    while data[pos] != 0:  # attributes: name\0 type\0 size value
        name_end = data.index(0, pos)
        name = data[pos:name_end].decode()
        type_end = data.index(0, name_end + 1)
        size = struct.unpack_from("<i", data, type_end + 1)[0]
        value = type_end + 5
        if name == "dataWindow":
            window = value
        if name == "compression":
            compression = data[value]
        pos = value + size
    pos += 1  # the header's end
    assert window is not None and compression == 0, "needs an uncompressed file with a dataWindow"
    x0, y0, x1, y1 = struct.unpack_from("<iiii", data, window)
    struct.pack_into("<iiii", data, window, x0 + dx, y0 + dy, x1 + dx, y1 + dy)
    for line in range(y1 - y0 + 1):  # one scanline a chunk, each chunk starting with its y
        chunk = struct.unpack_from("<Q", data, pos + 8 * line)[0]
        y = struct.unpack_from("<i", data, chunk)[0]
        struct.pack_into("<i", data, chunk, y + dy)
    open(dst, "wb").write(data)


if __name__ == "__main__":
    main()
