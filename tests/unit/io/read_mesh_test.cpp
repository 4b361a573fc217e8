// read_mesh and read_mesh_bytes: how a file's format is found (gzip, content, extension), the
// formats refused by name, and reading from a file that cannot be sized (a pipe).
#include "strata/io/read_mesh.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "support/result_checks.hpp"
#include "support/temp_dir.hpp"

namespace strata::io {
namespace {

constexpr std::string_view kObjTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
constexpr std::string_view kOffTriangle = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
constexpr std::string_view kSupported =
    "strata reads STL (binary or ASCII), OBJ, OFF, PLY (optionally gzip-compressed) and 3MF";

/// `bytes` as one gzip member (zlib's deflate with the gzip wrapper).
std::string gzip(std::string_view bytes) {
  z_stream stream{};
  EXPECT_EQ(deflateInit2(&stream, 6, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&stream, static_cast<uLong>(bytes.size())) + 32, '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&stream, Z_FINISH), Z_STREAM_END);
  out.resize(stream.total_out);
  deflateEnd(&stream);
  return out;
}

Error read_mesh_error(std::string_view bytes, std::string_view name) {
  return test::error_of(read_mesh_bytes(bytes, name), name);
}

std::string format_of(std::string_view bytes, std::string_view name) {
  const auto soup = read_mesh_bytes(bytes, name);
  EXPECT_TRUE(soup.has_value()) << name << ": " << (soup ? "" : soup.error().to_string());
  return soup ? soup->format : std::string();
}

TEST(ReadMeshDispatch, ForeignFormatsAreRefusedByTheirExtensionWhateverTheCase) {
  for (const std::string_view ext : {".amf", ".zip", ".ctm", ".step", ".stp", ".iges", ".igs",
                                     ".fbx", ".dae", ".gltf", ".glb", ".3ds", ".x3d", ".wrl"}) {
    std::string name = "dir.v2/Model";
    name += ext;
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const Error e = read_mesh_error("anything", name);
    EXPECT_EQ(e.location, name);
    EXPECT_EQ(e.message, fmt::format("unsupported format: '{}' files; {}", ext, kSupported));
  }
}

TEST(ReadMeshDispatch, ZipArchivesAreRefusedByTheirMagicBytes) {
  const std::string zip("PK\x03\x04rest", 8);
  EXPECT_EQ(read_mesh_error(zip, "model.stl").message,
            fmt::format("unsupported format: zip archive; {}", kSupported));
  // Named .3mf, or without an extension, a zip archive goes to the 3MF reader.
  EXPECT_EQ(read_mesh_error(zip, "model.3MF").message,
            "not a 3MF file: not a zip archive, or a damaged one (lib3mf: Could not read ZIP "
            "file)");
  EXPECT_EQ(read_mesh_error(zip, "upload").message, read_mesh_error(zip, "model.3MF").message);
}

TEST(ReadMeshDispatch, XmlContentIsRefusedAsAmf) {
  for (const std::string_view text : {"<?xml version=\"1.0\"?>\n<amf>", "<amf unit=\"mm\">"}) {
    EXPECT_EQ(read_mesh_error(text, "model").message,
              fmt::format("unsupported format: XML (AMF?); {}", kSupported));
  }
}

TEST(ReadMeshDispatch, UnknownContentNamesTheExtensionWhenThereIsOne) {
  EXPECT_EQ(read_mesh_error("hello world\n", "model").message,
            fmt::format("unsupported format: content is not STL, OBJ, OFF or PLY; {}", kSupported));
  // A leading dot starts a hidden file's name, not an extension.
  EXPECT_EQ(read_mesh_error("hello world\n", "dir\\.hidden").message,
            fmt::format("unsupported format: content is not STL, OBJ, OFF or PLY; {}", kSupported));
  EXPECT_EQ(read_mesh_error("hello world\n", "dir/model.dat").message,
            fmt::format("unsupported format: '.dat' content is not STL, OBJ, OFF or PLY; {}",
                        kSupported));
}

TEST(ReadMeshDispatch, PlyMagicNeedsItsLineEnd) {
  const std::string ply =
      "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\n"
      "property float z\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\n"
      "end_header\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
  EXPECT_EQ(format_of(ply, "model"), "ply");
  // "plyx" is not the magic line, and without an extension nothing else claims the text.
  EXPECT_EQ(read_mesh_error("plyx\n", "model").message,
            fmt::format("unsupported format: content is not STL, OBJ, OFF or PLY; {}", kSupported));
  EXPECT_EQ(read_mesh_error("ply", "model").message,
            fmt::format("unsupported format: content is not STL, OBJ, OFF or PLY; {}", kSupported));
}

TEST(ReadMeshDispatch, ThePlyExtensionSelectsThePlyReaderWithoutTheMagic) {
  const Error e = read_mesh_error("solidity\n", "model.ply");
  EXPECT_EQ(e.location, "model.ply:1");
  EXPECT_EQ(e.message, "not a PLY file: the first line is not 'ply'");
}

TEST(ReadMeshDispatch, OffIsRecognisedAfterBlankLinesAndComments) {
  EXPECT_EQ(format_of("\r\n \t\n# comment\r# another\n" + std::string(kOffTriangle), "model"),
            "off");
  EXPECT_EQ(format_of("# only a comment line, then the keyword\nCOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 "
                      "0\n3 0 1 2\n",
                      "model"),
            "off");
  // A keyword of more than 8 characters, or glued to other text, is not OFF.
  EXPECT_EQ(read_mesh_error("STCN4nOFFX\n", "model").message,
            fmt::format("unsupported format: content is not STL, OBJ, OFF or PLY; {}", kSupported));
  EXPECT_EQ(read_mesh_error("# only a comment", "model").message,
            fmt::format("unsupported format: content is not STL, OBJ, OFF or PLY; {}", kSupported));
}

TEST(ReadMeshDispatch, AnOffKeywordAtTheEndOfTheTextIsOff) {
  const Error e = read_mesh_error("OFF", "model");
  EXPECT_EQ(e.location, "model:1");
  EXPECT_EQ(e.message, "file ends where the vertex count was expected (truncated?)");
  // Eight characters ending in OFF but glued to more text are no keyword.
  EXPECT_EQ(read_mesh_error("12345OFFx 3 1 0\n", "model").message,
            fmt::format("unsupported format: content is not STL, OBJ, OFF or PLY; {}", kSupported));
}

TEST(ReadMeshDispatch, HalfAGzipMagicIsNoGzip) {
  EXPECT_EQ(read_mesh_error("\x1f\x8c not gzip", "model").message,
            fmt::format("unsupported format: content is not STL, OBJ, OFF or PLY; {}", kSupported));
}

TEST(ReadMeshDispatch, ObjIsRecognisedByAVertexStatementInItsFirstLines) {
  EXPECT_EQ(format_of("# exported\nvn 0 0 1\nv\t0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "model"),
            "obj");
  std::string late(64, '\n');
  late += kObjTriangle;
  EXPECT_EQ(read_mesh_error(late, "model").message,
            fmt::format("unsupported format: content is not STL, OBJ, OFF or PLY; {}", kSupported));
  EXPECT_EQ(read_mesh_error("# none\nv", "model").message,
            fmt::format("unsupported format: content is not STL, OBJ, OFF or PLY; {}", kSupported));
  EXPECT_EQ(read_mesh_error("vx", "model").message,
            fmt::format("unsupported format: content is not STL, OBJ, OFF or PLY; {}", kSupported));
}

TEST(ReadMeshGzip, TarArchivesAreRefused) {
  EXPECT_EQ(read_mesh_error(gzip("tar data"), "models.TGZ").message,
            fmt::format("unsupported format: tar archive; {}", kSupported));
}

TEST(ReadMeshGzip, GzipInsideGzipIsRefused) {
  EXPECT_EQ(read_mesh_error(gzip(gzip(kObjTriangle)), "model.obj.gz").message,
            fmt::format("unsupported format: gzip inside gzip; {}", kSupported));
}

TEST(ReadMeshGzip, AnEmptyMemberIsAnEmptyFile) {
  const Error e = read_mesh_error(gzip(""), "model.stl.gz");
  EXPECT_EQ(e.location, "model.stl.gz");
  EXPECT_EQ(e.message, "empty file (gzip of 0 bytes)");
}

TEST(ReadMeshGzip, TheInnerReadersErrorNamesTheCompressedFile) {
  const Error e = read_mesh_error(gzip("v 0 0\n"), "model.obj.gz");
  EXPECT_EQ(e.location, "model.obj.gz:1");
  EXPECT_EQ(e.message, "vertex has 2 coordinates, expected 3");
}

TEST(ReadMeshGzip, ConcatenatedMembersAreOneFile) {
  const std::string first = "v 0 0 0\nv 1 0 0\n";
  const std::string second = "v 0 1 0\nf 1 2 3\n";
  const auto soup = read_mesh_bytes(gzip(first) + gzip(second), "model.obj.gz");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "obj+gz");
  ASSERT_EQ(soup->triangles.size(), 1u);
  EXPECT_EQ(soup->triangles[0][2], (Vec3{0, 1, 0}));
}

TEST(ReadMeshGzip, CorruptDataIsAnErrorSayingWhere) {
  // A gzip header, then a deflate block of the reserved type 3.
  const std::string bytes("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03\xff\xff\xff\xff", 14);
  const Error e = read_mesh_error(bytes, "model.stl.gz");
  EXPECT_EQ(e.code, ErrorCode::BadInput);
  EXPECT_EQ(e.location, "model.stl.gz");
  EXPECT_EQ(e.message, "corrupt gzip data after 11 compressed bytes: invalid block type");
}

TEST(ReadMeshFile, ReadsAMeshFromAPipe) {
  // A pipe has no size to seek to: the reader takes it as a stream.
  const test::TempDir dir("read-mesh");
  const auto fifo = dir / "model.obj";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] {
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    if (fd < 0) return;
    const std::size_t written =
        static_cast<std::size_t>(::write(fd, kObjTriangle.data(), kObjTriangle.size()));
    EXPECT_EQ(written, kObjTriangle.size());
    ::close(fd);
  });
  const auto soup = read_mesh(fifo);
  writer.join();
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "obj");
  EXPECT_EQ(soup->triangles.size(), 1u);
}

TEST(ReadMeshFile, ADeviceWithoutEndIsAnEmptyFileNotReadForever) {
  // Seeking to the end of /dev/zero goes nowhere: it is an empty file, as for /dev/null.
  for (const char* device : {"/dev/zero", "/dev/null"}) {
    const auto soup = read_mesh(device);
    ASSERT_FALSE(soup) << device;
    EXPECT_EQ(soup.error().message, "empty file (0 bytes)") << device;
  }
}

TEST(ReadMeshFile, AnEmptyPipeIsAnEmptyFile) {
  const test::TempDir dir("read-mesh");
  const auto fifo = dir / "model.stl";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] {
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    if (fd >= 0) ::close(fd);
  });
  const auto soup = read_mesh(fifo);
  writer.join();
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().message, "empty file (0 bytes)");
}

}  // namespace
}  // namespace strata::io
