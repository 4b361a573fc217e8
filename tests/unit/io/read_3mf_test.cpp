// 3MF files through read_mesh (lib3mf parses the package, assemble_3mf_mesh places the build):
// packages built here (support/three_mf_package) and one written by lib3mf's own writer; the
// errors of broken files; and the cells of corpus STLs written as 3MF.
#include <Model/COM/NMR_DLLInterfaces.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "strata/io/read_mesh.hpp"
#include "support/corpus.hpp"
#include "support/mesh_reading.hpp"
#include "support/read_file.hpp"
#include "support/result_checks.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"
#include "support/three_mf_package.hpp"

namespace strata::io {
namespace {

namespace fs = std::filesystem;
using test::build_item_xml;
using test::components_object_xml;
using test::make_3mf;
using test::mesh_object_xml;
using test::model_xml;
using test::signed_volume;

/// A package of one 10 x 20 x 30 box (object 1) in `unit`, placed by `items`.
std::string box_package(std::string_view unit, std::string_view items) {
  const test::BoxMesh box = test::make_box_mesh(10, 20, 30);
  return make_3mf(model_xml(unit, mesh_object_xml(1, box.vertices, box.triangles), items));
}

Bbox3 bounds(const TriangleSoup& soup) {
  Bbox3 box;
  for (const auto& t : soup.triangles) {
    for (const Vec3& p : t) box.add(p);
  }
  return box;
}

Error read_3mf_error(const fs::path& path) {
  return test::error_of(read_mesh(path), path.string());
}

TEST(Read3mf, BuildItemAndNestedComponentTransformsApply) {
  const test::TempDir tmp("3mf");
  const test::BoxMesh box = test::make_box_mesh(1, 1, 1);
  // Object 2: the box moved by (10, 0, 0); object 3: object 2 scaled by 2 and rotated a quarter
  // turn about z ((x, y, z) -> (-y, x, z)), and the box as it is; the item lifts object 3 by 5.
  const std::string resources =
      mesh_object_xml(1, box.vertices, box.triangles) +
      components_object_xml(2, {{1, "1 0 0 0 1 0 0 0 1 10 0 0"}}) +
      components_object_xml(3, {{2, "0 2 0 -2 0 0 0 0 2 0 0 0"}, {1, ""}});
  test::write_file(
      tmp / "nested.3mf",
      make_3mf(model_xml("millimeter", resources, build_item_xml(3, "1 0 0 0 1 0 0 0 1 0 0 5"))));
  const auto soup = read_mesh(tmp / "nested.3mf");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "3mf");
  ASSERT_EQ(soup->triangles.size(), 24u);
  TriangleSoup moved;
  moved.triangles.assign(soup->triangles.begin(), soup->triangles.begin() + 12);
  // [10, 11] x [0, 1] x [0, 1] scaled by 2 and turned: x in [-2, 0], y in [20, 22], z in [5, 7].
  EXPECT_EQ(bounds(moved).min, (Vec3{-2, 20, 5}));
  EXPECT_EQ(bounds(moved).max, (Vec3{0, 22, 7}));
  EXPECT_DOUBLE_EQ(signed_volume(moved), 8.0);
  EXPECT_DOUBLE_EQ(signed_volume(*soup), 9.0);
}

TEST(Read3mf, InchAndMetreFilesEqualTheMillimetreFileScaled) {
  const test::TempDir tmp("3mf");
  const std::string items = build_item_xml(1, "1 0 0 0 1 0 0 0 1 1 2 3");
  test::write_file(tmp / "mm.3mf", box_package("millimeter", items));
  test::write_file(tmp / "in.3mf", box_package("inch", items));
  test::write_file(tmp / "m.3mf", box_package("meter", items));
  const auto mm = read_mesh(tmp / "mm.3mf");
  ASSERT_TRUE(mm) << mm.error().to_string();
  for (const auto& [file, factor] :
       std::vector<std::pair<std::string, double>>{{"in.3mf", 25.4}, {"m.3mf", 1000.0}}) {
    const auto soup = read_mesh(tmp / file);
    ASSERT_TRUE(soup) << soup.error().to_string();
    ASSERT_EQ(soup->triangles.size(), mm->triangles.size());
    for (std::size_t t = 0; t < mm->triangles.size(); ++t) {
      for (int c = 0; c < 3; ++c) {
        const Vec3& p = mm->triangles[t][c];
        EXPECT_EQ(soup->triangles[t][c], (Vec3{p.x * factor, p.y * factor, p.z * factor}))
            << file << " triangle " << t;
      }
    }
    EXPECT_NE(test::find_diagnostic(*soup, "3mf.unit"), nullptr) << file;
  }
}

TEST(Read3mf, AUnitAskedForIsRefusedAndAScaleFactorApplies) {
  const test::TempDir tmp("3mf");
  test::write_file(tmp / "in.3mf", box_package("inch", build_item_xml(1)));
  const auto refused = read_mesh(tmp / "in.3mf", {}, CoordinateScale{LengthUnit::Centimetre, 1.0});
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().code, ErrorCode::Usage);
  EXPECT_EQ(refused.error().to_string(),
            (tmp / "in.3mf").string() +
                ": a 3MF file states its own unit (inch) and is converted from it; a unit (cm) "
                "cannot be given for its coordinates, only a scale factor");
  const auto halved = read_mesh(tmp / "in.3mf", {}, CoordinateScale{LengthUnit::Millimetre, 0.5});
  ASSERT_TRUE(halved) << halved.error().to_string();
  EXPECT_EQ(bounds(*halved).max, (Vec3{10 * 12.7, 20 * 12.7, 30 * 12.7}));
}

TEST(Read3mf, MultipleObjectsAndBuildItems) {
  const test::TempDir tmp("3mf");
  const test::BoxMesh small = test::make_box_mesh(1, 1, 1);
  const test::BoxMesh large = test::make_box_mesh(2, 3, 4);
  const std::string resources = mesh_object_xml(1, small.vertices, small.triangles) +
                                mesh_object_xml(2, large.vertices, large.triangles);
  const std::string items = build_item_xml(2) + build_item_xml(1, "1 0 0 0 1 0 0 0 1 10 0 0") +
                            build_item_xml(1, "1 0 0 0 1 0 0 0 1 20 0 0");
  test::write_file(tmp / "three.3mf", make_3mf(model_xml("millimeter", resources, items)));
  const auto soup = read_mesh(tmp / "three.3mf");
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 36u);
  EXPECT_DOUBLE_EQ(signed_volume(*soup), 24.0 + 1.0 + 1.0);
  EXPECT_EQ(bounds(*soup).min, (Vec3{0, 0, 0}));
  EXPECT_EQ(bounds(*soup).max, (Vec3{21, 3, 4}));
}

TEST(Read3mf, AFileWrittenByLib3mfsWriterReads) {
  // lib3mf's own writer: a mesh object in centimetres, a components object placing it twice,
  // and a build item of the components object.
  const test::TempDir tmp("3mf");
  const fs::path path = tmp / "written.3mf";
  const test::BoxMesh box = test::make_box_mesh(1, 2, 3);
  NMR::PLib3MFModel* model = nullptr;
  ASSERT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_model_setunit(model, NMR::MODELUNIT_CENTIMETER), LIB3MF_OK);
  NMR::PLib3MFModelMeshObject* mesh = nullptr;
  ASSERT_EQ(NMR::lib3mf_model_addmeshobject(model, &mesh), LIB3MF_OK);
  std::vector<NMR::MODELMESHVERTEX> vertices;
  for (const auto& v : box.vertices) vertices.push_back({{v[0], v[1], v[2]}});
  std::vector<NMR::MODELMESHTRIANGLE> triangles;
  for (const auto& t : box.triangles) triangles.push_back({{t[0], t[1], t[2]}});
  ASSERT_EQ(NMR::lib3mf_meshobject_setgeometry(mesh, vertices.data(), 8, triangles.data(), 12),
            LIB3MF_OK);
  NMR::PLib3MFModelComponentsObject* pair = nullptr;
  ASSERT_EQ(NMR::lib3mf_model_addcomponentsobject(model, &pair), LIB3MF_OK);
  NMR::MODELTRANSFORM moved{{{1, 0, 0, 5}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
  NMR::PLib3MFModelComponent* first = nullptr;
  NMR::PLib3MFModelComponent* second = nullptr;
  ASSERT_EQ(NMR::lib3mf_componentsobject_addcomponent(pair, mesh, nullptr, &first), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_componentsobject_addcomponent(pair, mesh, &moved, &second), LIB3MF_OK);
  NMR::PLib3MFModelBuildItem* item = nullptr;
  ASSERT_EQ(NMR::lib3mf_model_addbuilditem(model, pair, nullptr, &item), LIB3MF_OK);
  NMR::PLib3MFModelWriter* writer = nullptr;
  ASSERT_EQ(NMR::lib3mf_model_querywriter(model, "3mf", &writer), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_writer_writetofileutf8(writer, path.c_str()), LIB3MF_OK);
  for (NMR::PLib3MFBase* instance : {writer, item, second, first, pair, mesh, model}) {
    NMR::lib3mf_release(instance);
  }

  const auto soup = read_mesh(path);
  ASSERT_TRUE(soup) << soup.error().to_string();
  ASSERT_EQ(soup->triangles.size(), 24u);
  EXPECT_EQ(bounds(*soup).min, (Vec3{0, 0, 0}));
  EXPECT_EQ(bounds(*soup).max, (Vec3{60, 20, 30}));
  EXPECT_DOUBLE_EQ(signed_volume(*soup), 2 * 10 * 20 * 30);
}

TEST(Read3mf, NotAZipArchive) {
  const test::TempDir tmp("3mf");
  test::write_file(tmp / "text.3mf", "solid but not a zip\n");
  const Error e = read_3mf_error(tmp / "text.3mf");
  EXPECT_EQ(e.code, ErrorCode::BadInput);
  EXPECT_EQ(e.location, (tmp / "text.3mf").string());
  EXPECT_EQ(e.message,
            "not a 3MF file: not a zip archive, or a damaged one (lib3mf: Could not read ZIP "
            "file)");
}

TEST(Read3mf, ATruncatedArchive) {
  const test::TempDir tmp("3mf");
  const std::string whole = box_package("millimeter", build_item_xml(1));
  test::write_file(tmp / "cut.3mf", whole.substr(0, whole.size() / 2));
  EXPECT_EQ(read_3mf_error(tmp / "cut.3mf").message,
            "not a 3MF file: not a zip archive, or a damaged one (lib3mf: Could not read ZIP "
            "file)");
}

TEST(Read3mf, AZipWithoutAModelPart) {
  const test::TempDir tmp("3mf");
  auto parts = test::package_parts(model_xml("millimeter", "", ""));
  ASSERT_EQ(parts.back().first, "3D/3dmodel.model");
  parts.pop_back();
  test::write_file(tmp / "empty.3mf", test::make_zip(parts));
  const Error e = read_3mf_error(tmp / "empty.3mf");
  EXPECT_EQ(e.location, (tmp / "empty.3mf").string());
  EXPECT_EQ(e.message,
            "the 3MF package lacks a part its relationships name (the 3D model?) (lib3mf: Could "
            "not create OPC Part)");
}

TEST(Read3mf, AMissingThumbnailTheRelationshipsNameIsAWarning) {
  // As PrusaSlicer 2.5's command line writes them: the relationships name
  // /Metadata/thumbnail.png, which the package does not hold.
  const test::TempDir tmp("3mf");
  const test::BoxMesh box = test::make_box_mesh(1, 1, 1);
  auto parts = test::package_parts(
      model_xml("millimeter", mesh_object_xml(1, box.vertices, box.triangles), build_item_xml(1)));
  ASSERT_EQ(parts[1].first, "_rels/.rels");
  const std::string thumbnail =
      "<Relationship Target=\"/Metadata/thumbnail.png\" Id=\"rel1\" "
      "Type=\"http://schemas.openxmlformats.org/package/2006/relationships/metadata/"
      "thumbnail\"/>";
  parts[1].second.insert(parts[1].second.find("</Relationships>"), thumbnail);
  test::write_file(tmp / "no_thumbnail.3mf", test::make_zip(parts));
  const auto soup = read_mesh(tmp / "no_thumbnail.3mf");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->triangles.size(), 12u);
  const Diagnostic* warning = test::find_diagnostic(*soup, "3mf.missing_thumbnail");
  ASSERT_NE(warning, nullptr);
  EXPECT_EQ(warning->message, (tmp / "no_thumbnail.3mf").string() +
                                  ": the package's relationships name a thumbnail "
                                  "(Metadata/thumbnail.png) it does not hold; read without it");
}

TEST(Read3mf, BrokenXml) {
  const test::TempDir tmp("3mf");
  const test::BoxMesh box = test::make_box_mesh(1, 1, 1);
  std::string xml =
      model_xml("millimeter", mesh_object_xml(1, box.vertices, box.triangles), build_item_xml(1));
  xml.replace(xml.find("</build>"), 8, "</build");
  test::write_file(tmp / "broken.3mf", make_3mf(xml));
  const Error e = read_3mf_error(tmp / "broken.3mf");
  EXPECT_EQ(e.location, (tmp / "broken.3mf").string());
  EXPECT_EQ(e.message, "the 3MF model's XML is malformed (lib3mf: Could not end XML element)");
}

TEST(Read3mf, ATriangleIndexOutOfRange) {
  const test::TempDir tmp("3mf");
  test::BoxMesh box = test::make_box_mesh(1, 1, 1);
  box.triangles[5][2] = 8;
  test::write_file(tmp / "index.3mf",
                   make_3mf(model_xml("millimeter", mesh_object_xml(1, box.vertices, box.triangles),
                                      build_item_xml(1))));
  const Error e = read_3mf_error(tmp / "index.3mf");
  EXPECT_EQ(e.code, ErrorCode::BadInput);
  EXPECT_EQ(e.location, (tmp / "index.3mf").string());
  EXPECT_EQ(e.message,
            "a triangle of the 3MF model refers to a vertex index that is out of range or "
            "repeated within the triangle (lib3mf: Invalid model node index)");
}

TEST(Read3mf, NoMeshObjects) {
  const test::TempDir tmp("3mf");
  test::write_file(tmp / "none.3mf", make_3mf(model_xml("millimeter", "", "")));
  Error e = read_3mf_error(tmp / "none.3mf");
  EXPECT_EQ(e.location, (tmp / "none.3mf").string());
  EXPECT_EQ(e.message, "no mesh to slice: the 3MF build has no item");

  const std::string empty_mesh =
      "<object id=\"1\" type=\"model\"><mesh><vertices></vertices><triangles></triangles>"
      "</mesh></object>";
  test::write_file(tmp / "empty_mesh.3mf",
                   make_3mf(model_xml("millimeter", empty_mesh, build_item_xml(1))));
  e = read_3mf_error(tmp / "empty_mesh.3mf");
  EXPECT_EQ(e.message, "no mesh to slice: the objects of the 3MF build's 1 item hold no triangle");
}

TEST(Read3mf, AnUnknownUnitIsRefused) {
  const test::TempDir tmp("3mf");
  test::write_file(tmp / "parsec.3mf", box_package("parsec", build_item_xml(1)));
  EXPECT_EQ(read_3mf_error(tmp / "parsec.3mf").message,
            "the 3MF model's unit is not one of micron, millimeter, centimeter, inch, foot, meter "
            "(lib3mf: invalid model unit)");
}

TEST(Read3mf, AZipWithoutExtensionIsReadAs3mf) {
  const std::string bytes = box_package("millimeter", build_item_xml(1));
  const auto soup = read_mesh_bytes(bytes, "upload");
  ASSERT_TRUE(soup) << soup.error().to_string();
  EXPECT_EQ(soup->format, "3mf");
  EXPECT_EQ(soup->triangles.size(), 12u);
}

/// Slices `model` into `dir` (cells only), expecting success.
void slice(const fs::path& model, const fs::path& dir) {
  const auto run = test::run_cli({"slice", model.string(), "-o", dir.string(), "--cell", "0.5",
                                  "--layer", "0.5", "--format", "cells", "-q"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
}

TEST(Read3mf, CorpusStlsWrittenAs3mfSliceToTheSameCells) {
  const test::TempDir tmp("3mf");
  for (const std::string_view relative :
       {"prusaslicer/resources/shapes/bunny.stl", "trimesh/models/angle_block.STL",
        "admesh/test/block/remove-unconnected-bad.stl"}) {
    SCOPED_TRACE(std::string(relative));
    const fs::path stl = test::corpus_file(relative);
    const auto soup = read_mesh(stl);
    ASSERT_TRUE(soup) << soup.error().to_string();
    const fs::path three_mf = tmp / (stl.stem().string() + ".3mf");
    test::write_file(
        three_mf, make_3mf(model_xml("millimeter", mesh_object_xml(1, *soup), build_item_xml(1))));
    const auto again = read_mesh(three_mf);
    ASSERT_TRUE(again) << again.error().to_string();
    ASSERT_EQ(again->triangles, soup->triangles);

    slice(stl, tmp / "from_stl");
    slice(three_mf, tmp / "from_3mf");
    const std::string expected =
        test::read_file(tmp / "from_stl" / (stl.stem().string() + ".cells"));
    ASSERT_GT(expected.size(), 80u);
    EXPECT_EQ(test::read_file(tmp / "from_3mf" / (stl.stem().string() + ".cells")), expected);
  }
}

TEST(Read3mf, TheCommandLineChecksA3mfAndRefusesAUnitOptionOrABrokenFile) {
  const test::TempDir tmp("3mf");
  test::write_file(tmp / "in.3mf", box_package("inch", build_item_xml(1)));
  const auto check = test::run_cli({"check", (tmp / "in.3mf").string(), "--json"});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  const auto report = nlohmann::json::parse(check.out);
  EXPECT_DOUBLE_EQ(report["volume_mm3"].get<double>(), 6000 * 25.4 * 25.4 * 25.4);

  const auto refused = test::run_cli({"check", (tmp / "in.3mf").string(), "--units", "in"});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.err, "strata: " + (tmp / "in.3mf").string() +
                             ": a 3MF file states its own unit (inch) and is converted from it; "
                             "a unit (in) cannot be given for its coordinates, only a scale "
                             "factor\n");

  // A broken 3MF: exit code 1, the file named, no output.
  test::write_file(tmp / "broken.3mf", "not a zip");
  const auto bad = test::run_cli(
      {"slice", (tmp / "broken.3mf").string(), "-o", (tmp / "out").string(), "--format", "cells"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(bad.err, "strata: " + (tmp / "broken.3mf").string() +
                         ": not a 3MF file: not a zip archive, or a damaged one (lib3mf: Could "
                         "not read ZIP file)\n");
  EXPECT_FALSE(fs::exists(tmp / "out" / "broken.cells"));
}

}  // namespace
}  // namespace strata::io
