"""Reading the three renderers' comparison images into one form, and comparing them: rtlab's PFM
(linear float), Tachyon's PPM48 and POV-Ray's 16-bit PPM written with File_Gamma 1 (linear, 16
bits, so that dark tones are not rounded before the comparison). Each becomes the 8-bit sRGB
codes rtlab's PNG would hold, and two images are compared code by code."""
import array
import struct
import zlib


def srgb8(linear):
    c = min(max(linear, 0.0), 1.0)
    c = 12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055
    return int(round(255 * c))


# 16-bit linear -> sRGB code, once for all 65536 values.
SRGB16 = bytes(srgb8(i / 65535) for i in range(65536))


def _header(data, count):
    """The first `count` whitespace-separated fields of a PNM/PFM header, and where the pixels start."""
    fields, i = [], 0
    while len(fields) < count:
        while data[i:i + 1].isspace():
            i += 1
        if data[i:i + 1] == b"#":  # a comment runs to the end of its line
            i = data.index(b"\n", i)
            continue
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        fields.append(data[i:j].decode())
        i = j
    return fields, i + 1


def read_pfm(path):
    data = open(path, "rb").read()
    (magic, w, h, scale), start = _header(data, 4)
    w, h = int(w), int(h)
    if magic != "PF" or float(scale) >= 0:
        raise ValueError(f"{path}: not a little-endian colour PFM")
    floats = struct.unpack_from(f"<{3 * w * h}f", data, start)
    rows = [bytes(srgb8(x) for x in floats[3 * w * y:3 * w * (y + 1)]) for y in range(h)]
    return w, h, b"".join(reversed(rows))  # PFM rows run bottom to top


def read_ppm(path):
    data = open(path, "rb").read()
    (magic, w, h, maxval), start = _header(data, 4)
    w, h, maxval = int(w), int(h), int(maxval)
    if magic != "P6":
        raise ValueError(f"{path}: not a binary PPM")
    if maxval < 256:
        raw = data[start:start + 3 * w * h]
        return w, h, bytes(srgb8(x / maxval) for x in raw)
    words = array.array("H", data[start:start + 6 * w * h])
    words.byteswap()  # PPM's 16-bit samples are big-endian
    if maxval != 65535:
        words = array.array("H", (x * 65535 // maxval for x in words))
    return w, h, bytes(SRGB16[x] for x in words)


def compare(a, b, agree=16):
    """Mean absolute difference of two images' sRGB codes (0-255, over every channel), and the
    share of pixels whose three channels are all within `agree` codes of each other."""
    if a[:2] != b[:2]:
        raise ValueError(f"images of different sizes: {a[0]}x{a[1]} and {b[0]}x{b[1]}")
    pa, pb = a[2], b[2]
    total = sum(abs(x - y) for x, y in zip(pa, pb))
    near = sum(1 for i in range(0, len(pa), 3)
               if abs(pa[i] - pb[i]) <= agree and abs(pa[i + 1] - pb[i + 1]) <= agree
               and abs(pa[i + 2] - pb[i + 2]) <= agree)
    return total / len(pa), near / (len(pa) // 3)


def write_png(path, w, h, rgb):
    """An 8-bit RGB PNG (no filter), to look at the comparison side by side."""
    raw = b"".join(b"\0" + rgb[3 * w * y:3 * w * (y + 1)] for y in range(h))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def side_by_side(images):
    """Images of one size next to each other, left to right, 4 black columns between them."""
    w, h = images[0][0], images[0][1]
    gap = b"\0" * 12
    rows = [gap.join(img[2][3 * w * y:3 * w * (y + 1)] for img in images) for y in range(h)]
    return len(images) * w + 4 * (len(images) - 1), h, b"".join(rows)
