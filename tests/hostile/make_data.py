#!/usr/bin/env python3
"""Writes the crafted hostile inputs of tests/hostile/data/ (committed; rerun to regenerate).

Each file is named after what is wrong with it; tests/hostile/foreign_files_test.cpp lists the
message each must produce."""
import os
import struct
import zlib

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")
XML = ('<?xml version="1.0" encoding="UTF-8"?>\n'
       '<vibroimage version="1.0" width="20" height="10">\n'
       '  <dot id="d" x="5" y="5" radius="2" gain="1"/>\n'
       '</vibroimage>\n')


def chunk(kind, data, crc=None):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", crc if crc is not None else zlib.crc32(body))


def ihdr(w, h, depth, colour, interlace=0):
    return chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, colour, 0, 0, interlace))


def row_bytes(w, depth, colour):
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[colour]
    return (w * channels * depth + 7) // 8


def idat(w, h, depth, colour, interlace=0):
    raw = b""
    if interlace:
        passes = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]
        for x0, y0, dx, dy in passes:
            pw = (w - x0 + dx - 1) // dx if w > x0 else 0
            ph = (h - y0 + dy - 1) // dy if h > y0 else 0
            if pw and ph:
                raw += (b"\0" + b"\x80" * row_bytes(pw, depth, colour)) * ph
    else:
        raw = (b"\0" + b"\x80" * row_bytes(w, depth, colour)) * h
    return chunk(b"IDAT", zlib.compress(raw))


def itxt(text, compressed=True):
    payload = zlib.compress(text) if compressed else text
    return chunk(b"iTXt", b"vibroimage\0" + (b"\1" if compressed else b"\0") + b"\0" + b"\0\0" + payload)


def ztxt(text):
    return chunk(b"zTXt", b"vibroimage\0\0" + zlib.compress(text, 9))


SIG = b"\x89PNG\r\n\x1a\n"
IEND = chunk(b"IEND", b"")


def png(w, h, depth, colour, extra=b"", interlace=0, palette=False):
    plte = chunk(b"PLTE", bytes(range(48))) if palette else b""
    return SIG + ihdr(w, h, depth, colour, interlace) + plte + extra + idat(w, h, depth, colour, interlace) + IEND


def write(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


def main():
    os.makedirs(HERE, exist_ok=True)
    text = XML.encode()
    vib = itxt(text)
    # Pictures of every kind, with and without the vibroimage chunk: all decode.
    write("interlaced-with-chunk.png", png(200, 100, 8, 2, vib, interlace=1))
    write("sixteen-bit-with-chunk.png", png(200, 100, 16, 2, vib))
    write("palette-with-chunk.png", png(200, 100, 4, 3, vib, palette=True))
    write("grey-alpha-with-chunk.png", png(200, 100, 8, 4, vib))
    write("grey-alpha-without-chunk.png", png(200, 100, 8, 4))
    write("palette-without-chunk.png", png(50, 50, 2, 3, palette=True))
    write("uncompressed-itxt-with-chunk.png", png(20, 10, 8, 2, itxt(text, compressed=False)))
    write("ztxt-with-chunk.png", png(20, 10, 8, 2, ztxt(text)))
    good = png(200, 100, 8, 2, vib)
    # Damage.
    write("truncated-in-idat.png", good[: len(good) - 40])
    write("truncated-after-signature.png", SIG + b"\0\0")
    bad_ihdr = bytearray(good)
    bad_ihdr[29] ^= 0xFF  # the IHDR CRC
    write("bad-crc-ihdr.png", bytes(bad_ihdr))
    itxt_at = good.index(b"iTXt")
    bad_text = bytearray(good)
    bad_text[itxt_at + 20] ^= 0x55  # inside the compressed text: its CRC no longer matches
    write("bad-crc-vibroimage-chunk.png", bytes(bad_text))
    write("huge-dimensions.png", SIG + ihdr(1000000, 1000000, 8, 2) + IEND)
    write("huge-but-legal-dimensions.png", SIG + ihdr(100000, 100000, 8, 2) + chunk(b"IDAT", zlib.compress(b"\0" * 100)) + IEND)
    bomb = zlib.compress(b" " * (80 << 20), 9)  # 80 MiB of spaces in about 80 kB
    write("ztxt-bomb.png", png(20, 10, 8, 2, chunk(b"zTXt", b"vibroimage\0\0" + bomb)))
    write("itxt-bomb.png", png(20, 10, 8, 2, chunk(b"iTXt", b"vibroimage\0\1\0\0\0" + bomb)))
    write("two-vibroimage-chunks.png", png(20, 10, 8, 2, vib + vib))
    write("chunk-longer-than-file.png", SIG + ihdr(20, 10, 8, 2) + struct.pack(">I", 0x7FFFFFF0) + b"iTXt" + b"x" * 10)
    write("not-xml-in-chunk.png", png(20, 10, 8, 2, itxt(b"\0\1\2 this is not XML")))
    # XML.
    write("doctype-billion-laughs.vimg",
          b'<?xml version="1.0"?>\n<!DOCTYPE lolz [\n <!ENTITY lol "lol">\n'
          b' <!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">\n'
          b' <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">\n]>\n'
          b'<vibroimage version="1.0" width="10" height="10"><dot x="1" y="1" radius="&lol3;"/></vibroimage>\n')
    write("external-entity.vimg",
          b'<?xml version="1.0"?>\n<!DOCTYPE v [<!ENTITY xxe SYSTEM "file:///etc/passwd">]>\n'
          b'<vibroimage version="1.0" width="10" height="10"><dot x="1" y="1" radius="1" id="&xxe;"/></vibroimage>\n')
    write("deep-nesting.vimg",
          b'<vibroimage version="1.0" width="10" height="10">\n' + b"<group>" * 2000 + b"</group>" * 2000 + b"\n</vibroimage>\n")
    write("utf8-bom.vimg", b"\xef\xbb\xbf" + text)
    write("utf16-bom.vimg", b"\xff\xfe" + XML.replace("UTF-8", "UTF-16").encode("utf-16-le"))
    write("latin1-bytes-declared-utf8.vimg", text.replace(b'id="d"', b'id="caf\xe9"'))
    write("nul-in-the-middle.vimg", text.replace(b"<dot", b"<dot\0", 1))
    write("nul-only.vimg", b"\0" * 4096)
    write("empty.vimg", b"")
    write("unclosed-root.vimg", text.replace(b"</vibroimage>\n", b""))
    # Not well-formed although tinyxml2 accepts it (XML conformance "not-wf" cases).
    root = b'<vibroimage version="1.0" width="10" height="10">\n'
    write("undefined-entity.vimg", root + b'<dot x="1" y="1" id="caf&eacute;"/>\n</vibroimage>\n')
    write("bare-ampersand.vimg", root + b'<meta><title>Salt & pepper</title></meta>\n</vibroimage>\n')
    write("escape-sequence.vimg", root + b'<dot x="1" y="1" id="\x1b[2Jgone"/>\n</vibroimage>\n')
    write("reference-to-nul.vimg", root + b'<dot x="1" y="1" id="a&#0;b"/>\n</vibroimage>\n')
    write("lt-in-attribute.vimg", root + b'<dot x="1" y="1" id="a<b"/>\n</vibroimage>\n')
    write("dashes-in-comment.vimg", root + b'<!-- draft -- do not ship -->\n</vibroimage>\n')
    write("declaration-not-first.vimg", b'\n<?xml version="1.0"?>\n' + root + b'</vibroimage>\n')
    write("mismatched-tag.vimg", root + b'<group>\n<dot x="1" y="1"/>\n</grop>\n</vibroimage>\n')
    # Other kinds of file handed to the image tools by mistake.
    write("nrrd-volume.nrrd",
          b"NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n" + bytes(range(8)))
    write("gesture-table.vimg", b"time_s,finger,x_mm,y_mm,pressure,phase\n0,0,1,1,,down\n")
    write("json-after-blank-lines.vimg", b"\n\n  {\"version\": 1}\n")
    write("svg-not-a-vibroimage.svg",
          b'<?xml version="1.0"?>\n<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"><rect width="5" height="5"/></svg>\n')


main()
