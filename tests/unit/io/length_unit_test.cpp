// Units of a model file's coordinates (include/strata/io/length_unit.hpp) and their conversion
// to millimetres as read_mesh reads.
#include "strata/io/length_unit.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "strata/io/read_mesh.hpp"

namespace strata::io {
namespace {

TEST(LengthUnit, NamesParseBackAndGiveTheirMillimetres) {
  const struct {
    const char* name;
    LengthUnit unit;
    double mm;
  } units[] = {{"mm", LengthUnit::Millimetre, 1.0},
               {"cm", LengthUnit::Centimetre, 10.0},
               {"m", LengthUnit::Metre, 1000.0},
               {"in", LengthUnit::Inch, 25.4},
               {"um", LengthUnit::Micrometre, 0.001}};
  for (const auto& u : units) {
    EXPECT_EQ(parse_length_unit(u.name), u.unit);
    EXPECT_EQ(length_unit_name(u.unit), u.name);
    EXPECT_EQ(millimetres_per(u.unit), u.mm);
  }
  EXPECT_EQ(parse_length_unit("ft"), std::nullopt);
  EXPECT_EQ(parse_length_unit("MM"), std::nullopt);
  EXPECT_EQ(parse_length_unit(""), std::nullopt);
}

constexpr const char* kObjTriangleOneAndAHalfHigh = "v 0 0 0\nv 1 0 0\nv 0 1.5 0\nf 1 2 3\n";

TEST(ReadMeshScale, DoubleFormatsAreMultipliedOnceInDouble) {
  const auto inches =
      read_mesh_bytes(kObjTriangleOneAndAHalfHigh, "t.obj", {}, {LengthUnit::Inch, 1.0});
  ASSERT_TRUE(inches) << inches.error().to_string();
  EXPECT_EQ(inches->triangles[0][1], (Vec3{25.4, 0, 0}));
  EXPECT_EQ(inches->triangles[0][2], (Vec3{0, 1.5 * 25.4, 0}));
  const auto scaled =
      read_mesh_bytes(kObjTriangleOneAndAHalfHigh, "t.obj", {}, {LengthUnit::Centimetre, 3.0});
  ASSERT_TRUE(scaled);
  EXPECT_EQ(scaled->triangles[0][2], (Vec3{0, 1.5 * 30.0, 0}));
  const auto micro =
      read_mesh_bytes(kObjTriangleOneAndAHalfHigh, "t.obj", {}, {LengthUnit::Micrometre, 1.0});
  ASSERT_TRUE(micro);
  EXPECT_EQ(micro->triangles[0][1], (Vec3{0.001, 0, 0}));
}

TEST(ReadMeshScale, StlCoordinatesAreRoundedToFloat32AgainAfterScaling) {
  // 0.1 m is float32 0.100000001490116...; times 1000 that is 100.0000014901..., whose nearest
  // float32 is 100: the millimetre export's coordinate.
  const std::string stl =
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0.1 0 0\nvertex 0 0.1 0\n"
      "endloop\nendfacet\nendsolid t\n";
  const auto soup = read_mesh_bytes(stl, "t.stl", {}, {LengthUnit::Metre, 1.0});
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles[0][1], (Vec3{100, 0, 0}));
  EXPECT_EQ(soup->triangles[0][2], (Vec3{0, 100, 0}));
  // The same in OBJ (double) keeps the product's rounding in double.
  const auto obj = read_mesh_bytes("v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nf 1 2 3\n", "t.obj", {},
                                   {LengthUnit::Metre, 1.0});
  ASSERT_TRUE(obj);
  EXPECT_EQ(obj->triangles[0][1].x, 0.1 * 1000.0);
}

TEST(ReadMeshScale, MillimetresAtScaleOneLeaveEveryBitAlone) {
  const auto plain = read_mesh_bytes(kObjTriangleOneAndAHalfHigh, "t.obj");
  const auto same =
      read_mesh_bytes(kObjTriangleOneAndAHalfHigh, "t.obj", {}, {LengthUnit::Millimetre, 1.0});
  ASSERT_TRUE(plain);
  ASSERT_TRUE(same);
  EXPECT_EQ(plain->triangles, same->triangles);
}

TEST(ReadMeshScale, CoordinateBeyondFloat32OnceScaledIsAnErrorNamingTheFacet) {
  const std::string stl =
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 3e38 0 0\n"
      "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
  const auto soup = read_mesh_bytes(stl, "big.stl", {}, {LengthUnit::Centimetre, 1.0});
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().code, ErrorCode::BadInput);
  EXPECT_EQ(soup.error().location, "big.stl: facet 1");
  EXPECT_EQ(soup.error().message.rfind("coordinate 3", 0), 0u) << soup.error().message;
  EXPECT_NE(soup.error().message.find("beyond the largest STL coordinate (float32)"),
            std::string::npos)
      << soup.error().message;
}

TEST(ReadMeshScale, ScaleMustBeFiniteAndPositive) {
  for (const double scale : {0.0, -1.0, std::numeric_limits<double>::infinity()}) {
    const auto soup =
        read_mesh_bytes(kObjTriangleOneAndAHalfHigh, "t.obj", {}, {LengthUnit::Millimetre, scale});
    ASSERT_FALSE(soup);
    EXPECT_EQ(soup.error().code, ErrorCode::Usage);
    EXPECT_EQ(soup.error().message.rfind("the scale factor must be a finite number > 0, got ", 0),
              0u)
        << soup.error().message;
  }
}

}  // namespace
}  // namespace strata::io
