// The part of 3MF input that strata controls, without a zip: objects, components and build items
// as plain data, placed into a soup in millimetres.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "io/model_3mf_internal.hpp"
#include "support/mesh_reading.hpp"
#include "support/three_mf_package.hpp"

namespace strata::io::detail {
namespace {

using test::contains;
using test::signed_volume;

Model3mf::Object box_object(std::uint32_t id, float x, float y, float z) {
  const test::BoxMesh box = test::make_box_mesh(x, y, z);
  Model3mf::Object object;
  object.id = id;
  object.name = "box";
  object.vertices = box.vertices;
  object.triangles = box.triangles;
  return object;
}

Model3mf::Object components_object(std::uint32_t id, std::vector<Model3mf::Component> components) {
  Model3mf::Object object;
  object.id = id;
  object.is_mesh = false;
  object.components = std::move(components);
  return object;
}

Affine3 translation(double x, double y, double z) {
  Affine3 t;
  t.m[0][3] = x;
  t.m[1][3] = y;
  t.m[2][3] = z;
  return t;
}

Affine3 scaling(double s) {
  Affine3 t;
  for (int i = 0; i < 3; ++i) t.m[i][i] = s;
  return t;
}

/// A quarter turn about z: (x, y, z) -> (-y, x, z).
Affine3 quarter_turn_z() {
  Affine3 t;
  t.m[0] = {0, -1, 0, 0};
  t.m[1] = {1, 0, 0, 0};
  return t;
}

Result<TriangleSoup> assemble(const Model3mf& model, const CoordinateScale& scale = {}) {
  return assemble_3mf_mesh(model, "m.3mf", ReadLimits{}, scale);
}

Bbox3 bounds(const TriangleSoup& soup) {
  Bbox3 box;
  for (const auto& t : soup.triangles) {
    for (const Vec3& p : t) box.add(p);
  }
  return box;
}

Error assemble_error(const Model3mf& model, const ReadLimits& limits = {}) {
  const auto soup = assemble_3mf_mesh(model, "m.3mf", limits, {});
  EXPECT_FALSE(soup) << "expected an error";
  return soup ? Error{} : soup.error();
}

TEST(Assemble3mfMesh, IdentityKeepsTheFloatCoordinatesExactly) {
  Model3mf model;
  Model3mf::Object object = box_object(1, 1.1f, 2.2f, 0.3f);
  object.vertices[7] = {0.1f, 1e-7f, -123.456789f};
  model.objects.push_back(object);
  model.build.push_back({1, {}});
  const auto soup = assemble(model);
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "3mf");
  ASSERT_EQ(soup->triangles.size(), 12u);
  for (std::size_t t = 0; t < 12; ++t) {
    for (int c = 0; c < 3; ++c) {
      const auto& v = object.vertices[object.triangles[t][c]];
      EXPECT_EQ(soup->triangles[t][c], (Vec3{v[0], v[1], v[2]})) << t;
    }
  }
  EXPECT_TRUE(soup->diagnostics.empty());
}

TEST(Assemble3mfMesh, BuildItemTransformMovesRotatesAndScales) {
  Model3mf model;
  model.objects.push_back(box_object(1, 10, 20, 30));
  // Scale by 2, then a quarter turn about z, then move by (100, 0, 5).
  const Affine3 item = [] {
    Affine3 t;
    t.m[0] = {0, -2, 0, 100};
    t.m[1] = {2, 0, 0, 0};
    t.m[2] = {0, 0, 2, 5};
    return t;
  }();
  model.build.push_back({1, item});
  const auto soup = assemble(model);
  ASSERT_TRUE(soup) << soup.error().to_string();
  const Bbox3 box = bounds(*soup);
  // x' = 100 - 2y in [60, 100], y' = 2x in [0, 20], z' = 2z + 5 in [5, 65].
  EXPECT_EQ(box.min, (Vec3{60, 0, 5}));
  EXPECT_EQ(box.max, (Vec3{100, 20, 65}));
  // The corner (10, 20, 30) lands at (60, 20, 65): triangle 2 is (4, 5, 7), 7 = (10, 20, 30).
  EXPECT_EQ(soup->triangles[2][2], (Vec3{60, 20, 65}));
  EXPECT_DOUBLE_EQ(signed_volume(*soup), 8 * 10 * 20 * 30);
}

TEST(Assemble3mfMesh, NestedComponentsComposeTheirTransformsInsideOut) {
  Model3mf model;
  model.objects.push_back(box_object(1, 1, 1, 1));
  // Object 2 places the box moved by (10, 0, 0); object 3 places object 2 scaled by 2 and the
  // box as it is; the build item moves object 3 up by 5.
  model.objects.push_back(components_object(2, {{1, translation(10, 0, 0)}}));
  model.objects.push_back(components_object(3, {{2, scaling(2)}, {1, {}}}));
  model.build.push_back({3, translation(0, 0, 5)});
  const auto soup = assemble(model);
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 24u);
  TriangleSoup first;
  first.triangles.assign(soup->triangles.begin(), soup->triangles.begin() + 12);
  TriangleSoup second;
  second.triangles.assign(soup->triangles.begin() + 12, soup->triangles.end());
  // Scale after the move: the first box spans x in [20, 22], and is 2 mm on a side.
  EXPECT_EQ(bounds(first).min, (Vec3{20, 0, 5}));
  EXPECT_EQ(bounds(first).max, (Vec3{22, 2, 7}));
  EXPECT_DOUBLE_EQ(signed_volume(first), 8.0);
  EXPECT_EQ(bounds(second).min, (Vec3{0, 0, 5}));
  EXPECT_EQ(bounds(second).max, (Vec3{1, 1, 6}));
  EXPECT_DOUBLE_EQ(signed_volume(second), 1.0);
}

TEST(Assemble3mfMesh, RotationsComposeExactlyAcrossLevels) {
  // Four quarter turns, one per level, give the box back where it was.
  Model3mf model;
  model.objects.push_back(box_object(1, 3, 4, 5));
  model.objects.push_back(components_object(2, {{1, quarter_turn_z()}}));
  model.objects.push_back(components_object(3, {{2, quarter_turn_z()}}));
  model.objects.push_back(components_object(4, {{3, quarter_turn_z()}}));
  model.build.push_back({4, quarter_turn_z()});
  const auto soup = assemble(model);
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(bounds(*soup).min, (Vec3{0, 0, 0}));
  EXPECT_EQ(bounds(*soup).max, (Vec3{3, 4, 5}));
  EXPECT_DOUBLE_EQ(signed_volume(*soup), 60.0);
}

TEST(Assemble3mfMesh, AMirroringTransformKeepsTheVolumePositive) {
  Model3mf model;
  model.objects.push_back(box_object(1, 1, 2, 3));
  Affine3 mirror;
  mirror.m[0][0] = -1;
  model.build.push_back({1, mirror});
  const auto soup = assemble(model);
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(bounds(*soup).min, (Vec3{-1, 0, 0}));
  EXPECT_DOUBLE_EQ(signed_volume(*soup), 6.0);
}

TEST(Assemble3mfMesh, EveryUnitConvertsToMillimetres) {
  const Model3mf::Object box = box_object(1, 1, 2, 4);
  for (const auto& [unit, mm] : std::vector<std::pair<std::string, double>>{{"micron", 0.001},
                                                                            {"millimeter", 1.0},
                                                                            {"centimeter", 10.0},
                                                                            {"inch", 25.4},
                                                                            {"foot", 304.8},
                                                                            {"meter", 1000.0}}) {
    Model3mf model;
    model.millimetres_per_unit = mm;
    model.unit_name = unit;
    model.objects.push_back(box);
    model.build.push_back({1, translation(1, 0, 0)});
    const auto soup = assemble(model);
    ASSERT_TRUE(soup) << unit << ": " << soup.error().to_string();
    // The translation is in the file's unit too.
    EXPECT_EQ(bounds(*soup).min, (Vec3{1 * mm, 0, 0})) << unit;
    EXPECT_EQ(bounds(*soup).max, (Vec3{2 * mm, 2 * mm, 4 * mm})) << unit;
    const Diagnostic* note = test::find_diagnostic(*soup, "3mf.unit");
    if (mm == 1.0) {
      EXPECT_EQ(note, nullptr);
    } else {
      ASSERT_NE(note, nullptr) << unit;
      EXPECT_EQ(note->message, fmt::format("m.3mf: the file's unit is {}: coordinates converted "
                                           "to millimetres (x {})",
                                           unit, mm));
    }
  }
}

TEST(Assemble3mfMesh, TheScaleFactorAppliesAfterTheFileUnit) {
  Model3mf model;
  model.millimetres_per_unit = 25.4;
  model.unit_name = "inch";
  model.objects.push_back(box_object(1, 1, 1, 1));
  model.build.push_back({1, {}});
  const auto soup = assemble(model, CoordinateScale{LengthUnit::Millimetre, 0.5});
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(bounds(*soup).max, (Vec3{12.7, 12.7, 12.7}));
}

TEST(Assemble3mfMesh, AUnitAskedForBesidesTheFilesOwnIsAUsageError) {
  Model3mf model;
  model.millimetres_per_unit = 25.4;
  model.unit_name = "inch";
  model.objects.push_back(box_object(1, 1, 1, 1));
  model.build.push_back({1, {}});
  const auto soup = assemble(model, CoordinateScale{LengthUnit::Inch, 1.0});
  ASSERT_FALSE(soup);
  EXPECT_EQ(soup.error().code, ErrorCode::Usage);
  EXPECT_EQ(soup.error().location, "m.3mf");
  EXPECT_EQ(soup.error().message,
            "a 3MF file states its own unit (inch) and is converted from it; a unit (in) cannot "
            "be given for its coordinates, only a scale factor");
}

TEST(Assemble3mfMesh, EveryBuildItemPlacesItsObjectInBuildOrder) {
  Model3mf model;
  model.objects.push_back(box_object(5, 1, 1, 1));
  model.objects.push_back(box_object(9, 2, 2, 2));
  model.build.push_back({9, translation(0, 0, 10)});
  model.build.push_back({5, {}});
  model.build.push_back({5, translation(50, 0, 0)});
  const auto soup = assemble(model);
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 36u);
  EXPECT_EQ(soup->triangles[2][2], (Vec3{2, 2, 12}));
  EXPECT_EQ(soup->triangles[14][2], (Vec3{1, 1, 1}));
  EXPECT_EQ(soup->triangles[26][2], (Vec3{51, 1, 1}));
  EXPECT_DOUBLE_EQ(signed_volume(*soup), 8.0 + 1.0 + 1.0);
}

TEST(Assemble3mfMesh, AVertexIndexOutOfRangeNamesTheObjectAndTheTriangle) {
  Model3mf model;
  model.objects.push_back(box_object(4, 1, 1, 1));
  model.objects[0].triangles[7][1] = 8;
  model.build.push_back({4, {}});
  const Error e = assemble_error(model);
  EXPECT_EQ(e.code, ErrorCode::BadInput);
  EXPECT_EQ(e.location, "m.3mf: object 4 ('box'), triangle 7");
  EXPECT_EQ(e.message,
            "vertex index 8 is out of range: the object has 8 vertices (indices 0 to 7)");
}

TEST(Assemble3mfMesh, ReferencesToUndefinedObjectsAreNamed) {
  Model3mf model;
  model.objects.push_back(box_object(1, 1, 1, 1));
  model.objects.push_back(components_object(2, {{1, {}}, {6, {}}}));
  model.build.push_back({1, {}});
  model.build.push_back({7, {}});
  Error e = assemble_error(model);
  EXPECT_EQ(e.location, "m.3mf: build item 1");
  EXPECT_EQ(e.message, "refers to object 7, which the file does not define");
  model.build.back().object_id = 2;
  e = assemble_error(model);
  EXPECT_EQ(e.location, "m.3mf: object 2, component 1");
  EXPECT_EQ(e.message, "refers to object 6, which the file does not define");
}

TEST(Assemble3mfMesh, ComponentsThatContainTheirOwnObjectAreRefused) {
  Model3mf model;
  model.objects.push_back(components_object(1, {{2, {}}}));
  model.objects.push_back(components_object(2, {{1, {}}}));
  model.build.push_back({1, {}});
  const Error e = assemble_error(model);
  EXPECT_EQ(e.location, "m.3mf: object 1");
  EXPECT_EQ(e.message, "its components contain the object itself");
}

TEST(Assemble3mfMesh, AnIdDefinedTwiceIsRefused) {
  Model3mf model;
  model.objects.push_back(box_object(3, 1, 1, 1));
  model.objects.push_back(box_object(3, 2, 2, 2));
  model.build.push_back({3, {}});
  const Error e = assemble_error(model);
  EXPECT_EQ(e.location, "m.3mf: object 3 ('box')");
  EXPECT_EQ(e.message, "the id 3 is defined twice");
}

TEST(Assemble3mfMesh, RepeatedComponentsCannotExceedTheTriangleLimit) {
  // Each level places the one below twice: 12 * 2^40 triangles, counted without overflow.
  Model3mf model;
  model.objects.push_back(box_object(1, 1, 1, 1));
  for (std::uint32_t id = 2; id <= 41; ++id) {
    model.objects.push_back(components_object(id, {{id - 1, {}}, {id - 1, {}}}));
  }
  model.build.push_back({41, {}});
  const Error e = assemble_error(model);
  EXPECT_EQ(e.location, "m.3mf");
  EXPECT_EQ(e.message, "the 3MF build places more than 200000000 triangles (the limit)");
}

TEST(Assemble3mfMesh, ComponentsNestedTooDeeplyAreRefused) {
  Model3mf model;
  model.objects.push_back(box_object(1, 1, 1, 1));
  for (std::uint32_t id = 2; id <= 100; ++id) {
    model.objects.push_back(components_object(id, {{id - 1, {}}}));
  }
  model.build.push_back({100, {}});
  const Error e = assemble_error(model);
  EXPECT_EQ(e.location, "m.3mf: object 36");
  EXPECT_EQ(e.message, "components nest deeper than 64 levels");
}

TEST(Assemble3mfMesh, ABuildWithoutItemsHasNoMesh) {
  Model3mf model;
  model.objects.push_back(box_object(1, 1, 1, 1));
  const Error e = assemble_error(model);
  EXPECT_EQ(e.location, "m.3mf");
  EXPECT_EQ(e.message, "no mesh to slice: the 3MF build has no item");
}

TEST(Assemble3mfMesh, ItemsWithoutTrianglesHaveNoMesh) {
  Model3mf model;
  Model3mf::Object empty;
  empty.id = 1;
  model.objects.push_back(empty);
  model.objects.push_back(components_object(2, {}));
  model.build.push_back({1, {}});
  model.build.push_back({2, {}});
  const Error e = assemble_error(model);
  EXPECT_EQ(e.location, "m.3mf");
  EXPECT_EQ(e.message, "no mesh to slice: the objects of the 3MF build's 2 items hold no triangle");
}

TEST(Assemble3mfMesh, SupportSurfaceAndOtherObjectsAreLeftOutWithAWarning) {
  Model3mf model;
  model.objects.push_back(box_object(1, 1, 1, 1));
  model.objects.push_back(box_object(2, 5, 5, 5));
  model.objects.back().type = Object3mfType::Support;
  model.objects.push_back(box_object(3, 5, 5, 5));
  model.objects.back().type = Object3mfType::SolidSupport;
  model.build.push_back({1, {}});
  model.build.push_back({2, {}});
  model.build.push_back({3, translation(10, 0, 0)});
  const auto soup = assemble(model);
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 24u);  // the model and the solid support
  const Diagnostic* left_out = test::find_diagnostic(*soup, "3mf.object_left_out");
  ASSERT_NE(left_out, nullptr);
  EXPECT_EQ(left_out->message,
            "m.3mf: object 2 ('box') is of type support, not a solid to fill: left out");

  model.build.erase(model.build.begin());
  model.build.pop_back();
  const Error e = assemble_error(model);
  EXPECT_EQ(e.message,
            "no mesh to slice: the objects of the 3MF build's 1 item hold no triangle (1 object "
            "left out by type)");
}

TEST(Assemble3mfMesh, ACoordinateThatOverflowsOncePlacedNamesTheTriangle) {
  Model3mf model;
  model.objects.push_back(box_object(1, 3e38f, 1, 1));
  model.millimetres_per_unit = 1000.0;
  model.unit_name = "meter";
  model.build.push_back({1, scaling(1e300)});
  const Error e = assemble_error(model);
  EXPECT_EQ(e.location, "m.3mf: object 1 ('box'), triangle 0");
  EXPECT_TRUE(contains(e.message,
                       "once placed by the transforms and converted from meter: not "
                       "a finite number"))
      << e.message;
}

TEST(Assemble3mfMesh, ASingularTransformIsAWarning) {
  Model3mf model;
  model.objects.push_back(box_object(1, 1, 1, 1));
  model.build.push_back({1, scaling(0)});
  const auto soup = assemble(model);
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_NE(test::find_diagnostic(*soup, "3mf.singular_transform"), nullptr);
}

}  // namespace
}  // namespace strata::io::detail
