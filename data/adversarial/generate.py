#!/usr/bin/env python3
"""Writes the small malformed meshes of this folder. Every file is made here, by hand, for
strata's tests; run `python3 generate.py` in this folder to recreate them byte for byte."""
import gzip
import io
import struct

# A tetrahedron with outward facets (right-hand rule).
V = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def write(name, data):
    with open(name, "wb") as f:
        f.write(data)


def gz(data):
    # mtime=0 and no file name keep the output reproducible.
    out = io.BytesIO()
    with gzip.GzipFile(fileobj=out, mode="wb", mtime=0, filename="") as g:
        g.write(data)
    return out.getvalue()


def binary_stl(facets, header=b"strata adversarial", count=None, trailing=b""):
    out = header.ljust(80, b"\0")[:80]
    out += struct.pack("<I", len(facets) if count is None else count)
    for normal, a, b, c in facets:
        out += struct.pack("<12fH", *normal, *a, *b, *c, 0)
    return out + trailing


def tetra_facets():
    return [((0.0, 0.0, 0.0), V[a], V[b], V[c]) for a, b, c in F]


def ascii_stl(facets, eol="\n", end=True):
    lines = ["solid tetra"]
    for normal, *corners in facets:
        lines.append("  facet normal %s %s %s" % normal)
        lines.append("    outer loop")
        for p in corners:
            lines.append("      vertex %s %s %s" % p)
        lines.append("    endloop")
        lines.append("  endfacet")
    if end:
        lines.append("endsolid tetra")
    return (eol.join(lines) + eol).encode()


tetra = tetra_facets()
write("empty.stl", b"")
write("zero_facets_binary.stl", binary_stl([]))
write("truncated_binary.stl", binary_stl(tetra, count=10)[: 84 + 3 * 50 + 20])
write("count_too_small_binary.stl", binary_stl(tetra, count=1))
write("huge_count_binary.stl", binary_stl(tetra[:2], count=0xFFFFFFFF))
write("stray_byte_binary.stl", binary_stl(tetra, header=b"solid stray byte", trailing=b"\n"))
nan = float("nan")
write("nan_vertex_binary.stl", binary_stl(tetra[:2] + [((0, 0, 1), (0, 0, 0), (1, nan, 0), (0, 1, 0))]))
write("tetra_ascii.stl", ascii_stl([(n, a, b, c) for n, a, b, c in tetra]))
txt = ascii_stl(tetra).decode()
write("nan_vertex_ascii.stl", txt.replace("vertex 0.0 0.0 1.0", "vertex 0.0 nan 1.0", 1).encode())
write("inf_normal_ascii.stl", txt.replace("normal 0.0 0.0 0.0", "normal inf -inf nan", 1).encode())
write("overflow_vertex_ascii.stl", txt.replace("vertex 1.0 0.0 0.0", "vertex 3.5e38 0.0 0.0", 1).encode())
write("bare_cr_ascii.stl", ascii_stl(tetra, eol="\r"))
write("crlf_ascii.stl", ascii_stl(tetra, eol="\r\n"))
two = txt.replace("      vertex 0.0 1.0 0.0\n", "", 1)
write("two_vertex_facet_ascii.stl", two.encode())
quad = ("solid quad\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
        "   vertex 1 1 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid quad\n")
write("quad_facet_ascii.stl", quad.encode())
write("missing_endsolid_ascii.stl", ascii_stl(tetra, end=False))
write("truncated_inside_facet_ascii.stl", ascii_stl(tetra)[:-60])
write("tetra_ascii.stl.gz", gz(ascii_stl(tetra)))
write("tetra_binary.stl.gz", gz(binary_stl(tetra)))
write("gzip_without_gz_extension.stl", gz(ascii_stl(tetra)))
write("truncated.stl.gz", gz(ascii_stl(tetra))[:-30])
obj_v = "".join("v %r %r %r\n" % p for p in V)
write("index_out_of_range.obj", (obj_v + "f 1 2 3\nf 1 2 9\n").encode())
write("index_zero.obj", (obj_v + "f 0 1 2\n").encode())
write("nan_vertex.obj", (obj_v.replace("v 1.0 0.0 0.0", "v 1.0 nan 0.0") + "f 1 2 3\n").encode())
write("hostile_counts.off", b"OFF\n4000000000 4000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
off = "OFF\n4 4 0\n" + "".join("%r %r %r\n" % p for p in V) + "".join("3 %d %d %d\n" % f for f in F)
write("truncated.off", off[:-12].encode())


def ply_binary(endian):
    fmt = "<" if endian == "little" else ">"
    head = ("ply\nformat binary_%s_endian 1.0\nelement vertex 4\nproperty float x\n"
            "property float y\nproperty float z\nelement face 4\n"
            "property list uchar int vertex_indices\nend_header\n" % endian).encode()
    body = b"".join(struct.pack(fmt + "3f", *p) for p in V)
    body += b"".join(struct.pack(fmt + "B3i", 3, *f) for f in F)
    return head + body


write("tetra_binary_little_endian.ply", ply_binary("little"))
write("tetra_binary_big_endian.ply", ply_binary("big"))
write("truncated_binary.ply", ply_binary("little")[:-7])
write("not_a_mesh.3mf", b"PK\x03\x04" + b"\0" * 26)
