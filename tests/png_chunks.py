"""PNG chunk reading shared by the test scripts (tests/app/report_check.py, tests/stability/fault_sweep.py)."""
import struct
import zlib


def png_chunks(data):
    """The (kind, body) chunks of PNG bytes, in order, up to IEND. Raises ValueError naming the
    problem: no signature, a truncated chunk, a bad CRC, no IEND, or bytes after IEND."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("no PNG signature")
    pos, chunks = 8, []
    while True:
        if pos + 12 > len(data):
            raise ValueError("truncated chunk at byte %d (no IEND)" % pos)
        (n,) = struct.unpack(">I", data[pos:pos + 4])
        if pos + 12 + n > len(data):
            raise ValueError("chunk at byte %d claims %d bytes, the file has %d left" % (pos, n, len(data) - pos - 12))
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        (crc,) = struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])
        if zlib.crc32(kind + body) & 0xFFFFFFFF != crc:
            raise ValueError("bad CRC in " + kind.decode("latin-1"))
        chunks.append((kind, body))
        pos += 12 + n
        if kind == b"IEND":
            if pos != len(data):
                raise ValueError("%d bytes after IEND" % (len(data) - pos))
            return chunks
