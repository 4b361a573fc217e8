#!/usr/bin/env bash
# Writes the seed corpus of the fuzz targets: fuzz/corpus/<target>/seed-*. Small files only (a
# few KB at most): the sample and adversarial models of data/, and small hand-made files that
# reach the corners of each format. Files named regress-* (inputs that once made a target fail)
# are left alone. Needs python3 and gzip. Usage: fuzz/make_seeds.sh
set -euo pipefail
cd "$(dirname "$0")"
root=..
adv=$root/data/adversarial

for t in fuzz_stl_binary fuzz_stl_ascii fuzz_obj fuzz_off fuzz_ply fuzz_cells fuzz_3mf_assembly \
  fuzz_slice_kernels fuzz_serve_route fuzz_slice_options; do
  mkdir -p "corpus/$t"
  rm -f "corpus/$t"/seed-*
done

copy() {  # copy TARGET FILE...
  local t=$1
  shift
  for f in "$@"; do cp "$f" "corpus/$t/seed-$(basename "$f")"; done
}

copy fuzz_stl_binary "$root/data/tetrahedron.stl" "$adv"/{count_too_small,huge_count,nan_vertex,stray_byte,truncated}_binary.stl "$adv/tetra_binary.stl.gz"
copy fuzz_stl_ascii "$root/data/tetrahedron_ascii.stl" "$adv"/{crlf,inf_normal,missing_endsolid,overflow_vertex,quad_facet,truncated_inside_facet,two_vertex_facet}_ascii.stl "$adv"/tetra_ascii.stl.gz "$adv"/gzip_without_gz_extension.stl "$adv"/truncated.stl.gz
copy fuzz_obj "$adv"/{index_out_of_range,index_zero,nan_vertex}.obj
copy fuzz_off "$adv"/{hostile_counts,truncated}.off
copy fuzz_ply "$adv"/tetra_binary_{little,big}_endian.ply "$adv/truncated_binary.ply"

python3 - <<'PY'
import struct

def write(target, name, data):
    if isinstance(data, str):
        data = data.encode()
    with open("corpus/%s/seed-%s" % (target, name), "wb") as f:
        f.write(data)

def cube(x0=0.0, y0=0.0, z0=0.0, s=10.0, flip=False):
    """The 12 outward triangles of an axis-aligned cube."""
    v = [(x0 + s * (i & 1), y0 + s * (i >> 1 & 1), z0 + s * (i >> 2 & 1)) for i in range(8)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    tris = []
    for a, b, c, d in quads:
        for t in ((a, b, c), (a, c, d)):
            tris.append(tuple(v[i] for i in (t[::-1] if flip else t)))
    return tris

def tetra(s=1.0):
    v = [(0, 0, 0), (s, 0, 0), (0, s, 0), (0, 0, s)]
    return [tuple(v[i] for i in f) for f in ((0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3))]

def binary_stl(tris, header=b"strata fuzz seed", normal=(0.0, 0.0, 0.0)):
    out = header.ljust(80, b"\0")[:80] + struct.pack("<I", len(tris))
    for a, b, c in tris:
        out += struct.pack("<12fH", *normal, *a, *b, *c, 0)
    return out

def ascii_stl(tris, name="seed", eol="\n", fmt="%g"):
    lines = ["solid " + name]
    for t in tris:
        lines += ["  facet normal 0 0 0", "    outer loop"]
        lines += ["      vertex " + " ".join(fmt % x for x in p) for p in t]
        lines += ["    endloop", "  endfacet"]
    lines.append("endsolid " + name)
    return eol.join(lines) + eol

T = "fuzz_stl_binary"
write(T, "cube.stl", binary_stl(cube()))
write(T, "cube_solid_header.stl", binary_stl(cube(), header=b"solid cube exported in binary"))
write(T, "two_overlapping_cubes.stl", binary_stl(cube() + cube(5, 5, 5)))
write(T, "nested_cubes_hole.stl", binary_stl(cube(0, 0, 0, 30) + cube(10, 10, 10, 10, flip=True)))
write(T, "inverted_cube.stl", binary_stl(cube(flip=True)))
write(T, "open_box.stl", binary_stl(cube()[:-2]))
write(T, "degenerate_and_duplicate.stl",
      binary_stl(tetra(10) + tetra(10)[:1] + [((0, 0, 0), (5, 5, 5), (10, 10, 10)), ((1, 1, 1),) * 3]))
write(T, "flat_square.stl", binary_stl(cube()[:2]))
write(T, "nonmanifold_edge.stl",
      binary_stl(tetra(10) + [((0, 0, 0), (10, 0, 0), (5, -10, 5)), ((0, 0, 0), (5, -10, 5), (10, 0, 0))]))
write(T, "huge_coordinates.stl", binary_stl(tetra(3e37)))
write(T, "tiny_coordinates.stl", binary_stl(tetra(1e-30)))
write(T, "nan_normal.stl", binary_stl(tetra(), normal=(float("nan"), float("inf"), 0.0)))
write(T, "vertices_on_planes.stl", binary_stl(cube(0, 0, 0.05, 1.0)))

T = "fuzz_stl_ascii"
write(T, "cube.stl", ascii_stl(cube()))
write(T, "keywords_upper_case.stl", ascii_stl(tetra(), fmt="%+.6E").upper().replace("SOLID SEED", "SOLID seed"))
write(T, "two_solids.stl", ascii_stl(tetra(), "a") + ascii_stl(cube(3, 3, 3, 1), "b"))
write(T, "tabs_and_bom.stl", "\ufeff" + ascii_stl(tetra()).replace("      ", "\t\t"))
write(T, "facet_after_endsolid.stl",
      ascii_stl(tetra()) + "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
      "vertex 0 1 0\nendloop\nendfacet\n")
write(T, "junk_after_endsolid.stl", ascii_stl(tetra()) + "\x00\x00garbage trailer\n")
write(T, "missing_endfacet.stl", ascii_stl(tetra()).replace("  endfacet\n", "", 1))
write(T, "no_normal_values.stl", ascii_stl(tetra()).replace("facet normal 0 0 0", "facet", 2))

T = "fuzz_obj"
cube_v = "".join("v %d %d %d\n" % (i & 1, i >> 1 & 1, i >> 2 & 1) for i in range(8))
cube_f = "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"
write(T, "cube_quads.obj", "# cube\no cube\n" + cube_v + cube_f)
write(T, "slashes.obj", cube_v + "vt 0 0\nvn 0 0 1\n" +
      "f 1/1/1 3/1/1 4/1/1 2/1/1\nf 5//1 6//1 8//1 7//1\nf 1/1 2/1 6/1 5/1\n"
      "f 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n")
write(T, "negative_indices.obj",
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf -4 -2 -3\nf -4 -3 -1\nf -4 -1 -2\nf -3 -2 -1\n")
write(T, "continuation_and_tabs.obj",
      "v\t0 0 0\nv 1 0 \\\n 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 \\\n 4\nf 1\t4 3\nf 2 3 4\n")
write(T, "faces_before_vertices.obj",
      "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n")
write(T, "unknown_statements_crlf.obj",
      ("mtllib a.mtl\nusemtl red\ng group\ns 1\nl 1 2\ncstype bezier\n" + cube_v + cube_f)
      .replace("\n", "\r\n"))
write(T, "colours_and_w.obj",
      "v 0 0 0 1 0.5 0.5 0.5\nv 1 0 0 1.0\nv 0 1 0\nv 0 0 1 2\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
write(T, "two_vertex_face.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\nf 1 2 3\n")

T = "fuzz_off"
cube_ov = "".join("%d %d %d\n" % (i & 1, i >> 1 & 1, i >> 2 & 1) for i in range(8))
cube_of = "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n"
write(T, "cube.off", "OFF\n8 6 12\n" + cube_ov + cube_of)
write(T, "comments.off", "# a comment\nOFF # keyword\n\n8 6 0 # counts\n" + cube_ov + cube_of)
write(T, "glued_counts.off", "OFF8 6 12\n" + cube_ov + cube_of)
write(T, "coff_colours.off", "COFF\n4 4 6\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
      "0 1 0 0 0 255 255\n0 0 1 9 9 9 255\n3 0 2 1 1 0 0\n3 0 1 3\n3 0 3 2\n3 1 2 3 0.5 0.5 0.5\n")
write(T, "noff_normals.off", "NOFF\n4 4 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n0 0 1 0 0 1\n"
      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
write(T, "homogeneous.off", "4OFF\n4 4 0\n0 0 0 1\n2 0 0 2\n0 1 0 1\n0 0 3 3\n"
      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
write(T, "ndim.off", "nOFF\n4\n4 4 0\n0 0 0 7\n1 0 0 7\n0 1 0 7\n0 0 1 7\n"
      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
write(T, "no_keyword_crlf.off", ("4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n").replace("\n", "\r\n"))
write(T, "short_faces.off", "OFF\n3 3 0\n0 0 0\n1 0 0\n0 1 0\n0\n2 0 1\n3 0 1 2\n")
write(T, "binary_keyword.off", "OFF BINARY\n")

T = "fuzz_ply"
def ply_header(fmt, nv, nf, vtype="float", itype="int", ctype="uchar", extra="", index="vertex_indices"):
    return ("ply\nformat %s 1.0\ncomment strata fuzz seed\n%selement vertex %d\nproperty %s x\n"
            "property %s y\nproperty %s z\nelement face %d\nproperty list %s %s %s\nend_header\n"
            % (fmt, extra, nv, vtype, vtype, vtype, nf, ctype, itype, index))
write(T, "cube_ascii.ply", ply_header("ascii", 8, 6) + cube_ov + cube_of)
write(T, "crlf_vertex_index.ply",
      ply_header("ascii", 4, 4, index="vertex_index").replace("\n", "\r\n") +
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
write(T, "tristrips.ply",
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n8 0 2 1 3 -1 0 3 2\n")
write(T, "extra_elements.ply",
      "ply\nformat ascii 1.0\nobj_info made by hand\nelement camera 1\nproperty float view\n"
      "element vertex 4\nproperty uchar red\nproperty double x\nproperty double y\n"
      "property double z\nproperty list uchar float uv\nelement face 4\n"
      "property list uchar float texcoord\nproperty list ushort uint vertex_indices\n"
      "property int flags\nend_header\n1.5\n9 0 0 0 2 0.5 0.5\n9 1 0 0 0\n9 0 1 0 0\n9 0 0 1 0\n"
      "0 3 0 2 1 7\n2 1 1 3 0 1 3 7\n0 3 0 3 2 7\n0 3 1 2 3 7\n")
def binary_ply(endian):
    e = "<" if endian == "little" else ">"
    body = b""
    for p in [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]:
        body += struct.pack(e + "3d", *p)
    for f in ((0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)):
        body += struct.pack(e + "H3i", 3, *f)
    return ply_header("binary_%s_endian" % endian, 4, 4, vtype="double", ctype="ushort").encode() + body
write(T, "double_ushort_le.ply", binary_ply("little"))
write(T, "double_ushort_be.ply", binary_ply("big"))
write(T, "no_format.ply", "ply\nelement vertex 0\nend_header\n")
write(T, "float_indices_empty_element.ply",
      "ply\nformat ascii 1.0\nelement material 3\nelement vertex 4\nproperty float x\n"
      "property float y\nproperty float z\nelement face 4\nproperty list uchar float vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3.0\n3 0 3 2\n3 1 2 3e0\n")

T = "fuzz_cells"
def cells_binary(nx, ny, nz, codes, origin=(0.0, 0.0, 0.0), d=(1.0, 1.0, 1.0), t=0.5, pad=0):
    out = b"STRCELL1" + struct.pack("<4I", 80, nx, ny, nz) + struct.pack("<7d", *origin, *d, t)
    per_layer = nx * ny
    for k in range(nz):
        layer = codes[k * per_layer:(k + 1) * per_layer]
        byte_count = (per_layer + 3) // 4
        packed = bytearray(byte_count)
        for idx, c in enumerate(layer):
            packed[idx // 4] |= c << (6 - 2 * (idx % 4))
        if pad and per_layer % 4:
            packed[-1] |= pad
        out += bytes(packed)
    return out
def cells_ascii(nx, ny, nz, codes, eol="\n", blank=False):
    names = {0: "00", 1: "01", 3: "11", 2: "10"}
    lines = ["strata-cells 1", "grid %d %d %d" % (nx, ny, nz), "origin 0 0 0",
             "spacing 1 1 0.5", "shell 0.5"]
    for k in range(nz):
        if blank and k:
            lines.append("")
        lines.append("layer %d z=%g" % (k, 0.25 + 0.5 * k))
        for j in range(ny):
            lines.append("".join(names[codes[(k * ny + j) * nx + i]] for i in range(nx)))
    return eol.join(lines) + eol
ring = [3, 3, 3, 3, 1, 3, 3, 3, 3]
codes = ring + [3] * 9 + [0] * 9
write(T, "block.cells", cells_binary(3, 3, 3, codes))
write(T, "padded_layer.cells", cells_binary(5, 3, 2, [3, 1, 0] * 10))
write(T, "nonzero_padding.cells", cells_binary(5, 3, 1, [3, 1, 0] * 5, pad=1))
write(T, "reserved_code.cells", cells_binary(2, 2, 1, [0, 2, 1, 3]))
write(T, "bad_header_size.cells", cells_binary(1, 1, 1, [1])[:8] + struct.pack("<I", 96) + cells_binary(1, 1, 1, [1])[12:])
write(T, "nan_spacing.cells", cells_binary(1, 1, 1, [1], d=(float("nan"), 1.0, 1.0)))
write(T, "one_cell.cells", cells_binary(1, 1, 1, [3], origin=(-5.0, 1e6, 0.25), d=(0.1, 0.1, 0.05), t=0.0))
write(T, "block.cells.txt", cells_ascii(3, 3, 3, codes))
write(T, "blank_lines_crlf.cells.txt", cells_ascii(3, 3, 3, codes, eol="\r\n", blank=True))
write(T, "reserved_code.cells.txt", cells_ascii(2, 2, 1, [0, 2, 1, 3]))
write(T, "missing_shell.cells.txt", "strata-cells 1\ngrid 1 1 1\norigin 0 0 0\nspacing 1 1 1\nlayer 0 z=0.5\n11\n")
write(T, "wide_row.cells.txt", cells_ascii(40, 1, 2, ([3] + [1] * 38 + [3]) * 2))
write(T, "short_row.cells.txt", "strata-cells 1\nshell 1\nspacing 1 1 1\norigin 0 0 0\ngrid 2 1 1\nlayer 0 z=0.5\n11\n")

# The encoding of fuzz/fuzz_slice_kernels.cpp: two bytes of options and cell sizes, then nine
# bytes a triangle, each a lattice coordinate (byte & 31) / 4 - 1 in cells.
T = "fuzz_slice_kernels"
def lattice(value_in_cells):
    return int(round((value_in_cells + 1) * 4))
def kernels_seed(how, sizes, tris):
    return bytes([how, sizes]) + b"".join(bytes(lattice(c) for p in t for c in p) for t in tris)
write(T, "cube_on_cell_faces.bin", kernels_seed(0x0C, 0, cube(0, 0, 0, 4)))
write(T, "cube_through_centres.bin", kernels_seed(0x10, 0, cube(0.5, 0.5, 0.5, 3)))
write(T, "tetra_evenodd_layers.bin", kernels_seed(0x0B, 1, tetra(5)))
write(T, "cube_unequal_cells_offset.bin", kernels_seed(0x3C, 2 | 8, cube(0.25, 0.75, 0.5, 4.5)))
write(T, "inverted_cube_tenths_nudged.bin", kernels_seed(0x94, 4, cube(0, 0, 0, 5, flip=True)))
write(T, "open_box_wide_shell.bin", kernels_seed(0x1C, 0, cube(0, 0, 0, 6)[:-2]))

# Request lines of strata serve, as fuzz/fuzz_serve_route.cpp reads them: "METHOD TARGET".
T = "fuzz_serve_route"
for name, line in [("app", "GET /"), ("info", "GET /api/info"), ("jobs", "GET /api/jobs"),
                   ("upload", "POST /api/jobs?name=part%20one%281%29.stl.gz"),
                   ("upload_path", "POST /api/jobs?name=C%3A%5Cmodels%5Cpart.STL"),
                   ("status", "GET /api/jobs/0a1b2c3d4e5f6789"),
                   ("slice", "POST /api/jobs/ff/slice"), ("cancel", "POST /api/jobs/1/cancel"),
                   ("validate", "POST /api/jobs/abc/validate"), ("remove", "DELETE /api/jobs/9"),
                   ("view_data", "GET /api/jobs/12/view.json"),
                   ("file", "GET /api/jobs/12/files/cells"), ("viewer", "GET /viewer?job=3e&x=1"),
                   ("dot_dot", "GET /api/jobs/12/files/../../etc/passwd"),
                   ("encoded_dot", "GET /api/jobs/12/files/%2e%2e"),
                   ("wrong_method", "PUT /api/jobs"), ("bad_escape", "GET /api/jobs?name=%zz")]:
    write(T, name + ".txt", line)

# The options of a slice request, as the page sends them (web/src/app/options_form.js), and a
# few it never sends.
T = "fuzz_slice_options"
for name, text in [
        ("page_defaults", '{"layer":0.1,"cell":0.1,"shell":0.5,"shell_mode":"distance",'
                          '"fill_rule":"nonzero","scan_offset":0,"kernel":"fast",'
                          '"repair":false,"fill_holes":false}'),
        ("every_option", '{"layer":0.25,"dx":0.2,"dy":0.3,"shell":2,"shell_mode":"layers",'
                         '"fill_rule":"evenodd","scan_offset":-0.05,"kernel":"exact",'
                         '"origin":[-1.5,0,2e1],"repair":true,"fill_holes":true}'),
        ("empty", '{}'), ("nulls", '{"cell":null,"origin":null,"kernel":null}'),
        ("cell_and_dx", '{"cell":0.1,"dx":0.2}'), ("holes_without_repair", '{"fill_holes":true}'),
        ("unknown_key", '{"threads":4}'), ("negative_shell", '{"shell":-1}'),
        ("huge_number", '{"layer":1e400}'), ("tiny_cell", '{"cell":5e-324}'),
        ("word_for_number", '{"layer":"0.1"}'), ("short_origin", '{"origin":[1,2]}'),
        ("duplicate_key", '{"layer":0.2,"layer":-1}'), ("winding", '{"fill_rule":"winding"}'),
        ("not_an_object", '[0.1]'), ("truncated", '{"layer":0.')]:
    write(T, name + ".json", text)

# The model encoding of fuzz/fuzz_3mf_assembly.cpp (see its header comment).
T = "fuzz_3mf_assembly"
ENTRIES = [0.0, 1.0, -1.0, 2.0, 0.5, -0.5, 3.0, -2.0]
def i8(v):
    return struct.pack("b", v)
def tf(linear=None, move=(0, 0, 0)):
    """A transform: identity, or the 9 linear entries (values of ENTRIES) and an int8 move."""
    if linear is None and move == (0, 0, 0):
        return b"\x00"
    linear = linear or (1, 0, 0, 0, 1, 0, 0, 0, 1)
    return b"\x01" + bytes(ENTRIES.index(v) for v in linear) + b"".join(i8(m) for m in move)
def mesh3(oid, verts, tris, kind=0):
    """A mesh object of int8 half-millimetre coordinates; kind 0 model, 1 solidsupport, 2 support."""
    out = bytes([0, oid, kind, len(verts)]) + b"".join(i8(c) for v in verts for c in v)
    return out + bytes([len(tris)]) + b"".join(bytes(t) for t in tris)
def mesh3f(oid, verts, tris):
    out = bytes([1, oid, 0, len(verts)]) + b"".join(struct.pack("<f", c) for v in verts for c in v)
    return out + bytes([len(tris)]) + b"".join(bytes(t) for t in tris)
def comps(oid, children):
    return bytes([2, oid, len(children)]) + b"".join(bytes([c]) + t for c, t in children)
def item(oid, t=b"\x00"):
    return bytes([3, oid]) + t
MM, INCH = b"\x01", b"\x03"
box_v = [(20 * (i & 1), 20 * (i >> 1 & 1), 20 * (i >> 2 & 1)) for i in range(8)]
box_t = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4), (2, 6, 7), (2, 7, 3),
         (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]
tet_v = [(0, 0, 0), (10, 0, 0), (0, 10, 0), (0, 0, 10)]
tet_t = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
quarter_turn = (0, -1, 0, 1, 0, 0, 0, 0, 1)
write(T, "box.bin", MM + mesh3(1, box_v, box_t) + item(1))
write(T, "box_in_inches_moved.bin", INCH + mesh3(1, box_v, box_t) + item(1, tf(move=(5, -3, 7))))
write(T, "nested_components.bin",
      MM + mesh3(1, box_v, box_t) + comps(2, [(1, tf(move=(30, 0, 0))), (1, b"\x00")]) +
      comps(3, [(2, tf(quarter_turn)), (1, tf((2, 0, 0, 0, 2, 0, 0, 0, 2), (0, 0, 40)))]) +
      item(3, tf(move=(0, 0, 5))))
write(T, "mirrored_item.bin",
      MM + mesh3(1, box_v, box_t) + item(1) + item(1, tf((-1, 0, 0, 0, 1, 0, 0, 0, 1), (-5, 0, 0))))
write(T, "two_objects_overlapping.bin",
      MM + mesh3(7, box_v, box_t) + mesh3(9, tet_v, tet_t) + item(9) + item(7, tf(move=(5, 5, 5))))
write(T, "index_out_of_range.bin", MM + mesh3(1, box_v, box_t[:11] + [(1, 7, 8)]) + item(1))
write(T, "component_cycle.bin", MM + comps(1, [(2, b"\x00")]) + comps(2, [(1, b"\x00")]) + item(1))
write(T, "missing_object.bin", MM + mesh3(1, box_v, box_t) + item(4))
write(T, "duplicate_id.bin", MM + mesh3(1, box_v, box_t) + mesh3(1, tet_v, tet_t) + item(1))
write(T, "support_left_out.bin",
      MM + mesh3(1, box_v, box_t, kind=2) + mesh3(2, box_v, box_t, kind=1) + item(1) +
      item(2, tf(move=(25, 0, 0))))
write(T, "singular_transform.bin",
      MM + mesh3(1, box_v, box_t) + item(1, tf((1, 0, 0, 0, 1, 0, 0, 0, 0))))
write(T, "large_float_coordinates.bin",
      b"\x05" + mesh3f(1, [(0, 0, 0), (1e-3, 0, 0), (0, 1e38, 0), (0, 0, 3.5)], tet_t) +
      item(1, tf((3, 0, 0, 0, 3, 0, 0, 0, 3))))
write(T, "infinite_coordinate.bin",
      MM + mesh3f(1, [(0, 0, 0), (1, 0, 0), (0, float("inf"), 0), (0, 0, 1)], tet_t) + item(1))
write(T, "repeated_components.bin",
      MM + mesh3(1, tet_v, tet_t) +
      b"".join(comps(k, [(k - 1, tf(move=(1, 0, 0))), (k - 1, b"\x00")]) for k in range(2, 16)) +
      item(15))
write(T, "empty_build.bin", MM + mesh3(1, box_v, box_t))
# Zip archives, for the thumbnail patch (append_empty_zip_entry) that runs on the same bytes.
import io, zipfile
def zip_bytes(entries, comment=b""):
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as z:
        for name, data in entries:
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            z.writestr(info, data)
        z.comment = comment
    return buffer.getvalue()
write(T, "zip_two_entries.zip", zip_bytes([("_rels/.rels", "<Relationships/>"), ("3D/3dmodel.model", "<model/>")]))
write(T, "zip_with_thumbnail_and_comment.zip",
      zip_bytes([("Metadata/thumbnail.png", b""), ("a", b"x")], comment=b"PK\x05\x06 in a comment"))
PY

# Compressed variants: the gzip path in front of each mesh reader.
gzip -n -9 -c corpus/fuzz_stl_ascii/seed-cube.stl > corpus/fuzz_stl_ascii/seed-cube.stl.gz
gzip -n -9 -c corpus/fuzz_obj/seed-cube_quads.obj > corpus/fuzz_obj/seed-cube_quads.obj.gz
gzip -n -9 -c corpus/fuzz_off/seed-cube.off > corpus/fuzz_off/seed-cube.off.gz
gzip -n -9 -c corpus/fuzz_ply/seed-cube_ascii.ply > corpus/fuzz_ply/seed-cube_ascii.ply.gz

for t in corpus/*/; do echo "$(ls "$t" | wc -l) seeds in $t"; done
