#include <gtest/gtest.h>

#include "serve/route_internal.hpp"

namespace strata::serve::detail {
namespace {

TEST(MatchRoute, ServesThePageAndItsApi) {
  EXPECT_EQ(match_route("GET", "/").kind, RouteKind::AppPage);
  EXPECT_EQ(match_route("GET", "/api/info").kind, RouteKind::Info);
  EXPECT_EQ(match_route("GET", "/api/jobs").kind, RouteKind::ListJobs);
  EXPECT_EQ(match_route("GET", "/api/jobs/00a1").kind, RouteKind::JobStatus);
  EXPECT_EQ(match_route("DELETE", "/api/jobs/00a1").kind, RouteKind::Remove);
  EXPECT_EQ(match_route("POST", "/api/jobs/00a1/slice").kind, RouteKind::Slice);
  EXPECT_EQ(match_route("POST", "/api/jobs/00a1/cancel").kind, RouteKind::Cancel);
  EXPECT_EQ(match_route("POST", "/api/jobs/00a1/validate").kind, RouteKind::Validate);
  EXPECT_EQ(match_route("GET", "/api/jobs/00a1/view.json").kind, RouteKind::ViewData);
  const Route viewer = match_route("GET", "/viewer?job=00a1");
  EXPECT_EQ(viewer.kind, RouteKind::ViewerPage);
  EXPECT_EQ(viewer.job, "00a1");
  const Route file = match_route("GET", "/api/jobs/00a1/files/png");
  EXPECT_EQ(file.kind, RouteKind::File);
  EXPECT_EQ(file.job, "00a1");
  EXPECT_EQ(file.file, "png");
}

TEST(MatchRoute, UploadTakesACheckedName) {
  const Route r = match_route("POST", "/api/jobs?name=my%20part.stl.gz");
  ASSERT_EQ(r.kind, RouteKind::Upload);
  EXPECT_EQ(r.name, "my part.stl.gz");
  EXPECT_EQ(match_route("POST", "/api/jobs").kind, RouteKind::BadRequest);
  EXPECT_EQ(match_route("POST", "/api/jobs?name=run.sh").kind, RouteKind::BadRequest);
  EXPECT_EQ(match_route("POST", "/api/jobs?name=%ZZ.stl").kind, RouteKind::BadRequest);
  // A path in the name keeps its last component only.
  EXPECT_EQ(match_route("POST", "/api/jobs?name=..%2F..%2Fpart.stl").name, "part.stl");
}

TEST(MatchRoute, RefusesTraversalAndEncodedPaths) {
  for (const char* target :
       {"/api/jobs/../../etc/passwd", "/api/jobs/0001/files/../../job.json", "/..",
        "/api/jobs/%2e%2e/x", "/api%2fjobs", "/api/jobs/0001\\x", "//etc/passwd", "relative"}) {
    EXPECT_EQ(match_route("GET", target).kind, RouteKind::BadRequest) << target;
  }
}

TEST(MatchRoute, AnswersNothingElse) {
  for (const char* target :
       {"/index.html", "/etc/passwd", "/api", "/api/jobs/0001/job.json", "/api/jobs/0001/model",
        "/api/jobs/0001/files/options", "/api/jobs/0001/files/", "/api/jobs/XYZ",
        "/api/jobs/0123456789abcdef0", "/api/jobs/0001/files/cells/x", "/favicon.ico"}) {
    EXPECT_EQ(match_route("GET", target).kind, RouteKind::NotFound) << target;
  }
  EXPECT_EQ(match_route("PUT", "/api/jobs/0001").kind, RouteKind::WrongMethod);
  EXPECT_EQ(match_route("GET", "/api/jobs/0001/slice").kind, RouteKind::WrongMethod);
  EXPECT_EQ(match_route("POST", "/").kind, RouteKind::WrongMethod);
  EXPECT_EQ(match_route("GET", "/viewer?job=../x").kind, RouteKind::BadRequest);
  EXPECT_EQ(match_route("GET", "/viewer?job").kind, RouteKind::BadRequest);
  EXPECT_EQ(match_route("GET", "/viewer?other=1&job=00a1").job, "00a1");
  EXPECT_EQ(match_route("GET", "/api/files/0001").kind, RouteKind::NotFound);
  EXPECT_EQ(match_route("GET", "/api/jobs/0001/downloads/cells").kind, RouteKind::NotFound);
}

TEST(MatchRoute, RefusesAnEmptyTargetAndANulInThePath) {
  EXPECT_EQ(match_route("GET", "").reason, "the request target is not a path");
  EXPECT_EQ(match_route("GET", std::string_view("/api\0/info", 10)).reason, "the path is refused");
}

TEST(IsJobId, OneToSixteenLowercaseHexDigits) {
  EXPECT_TRUE(is_job_id("0"));
  EXPECT_TRUE(is_job_id("0123456789abcdef"));
  EXPECT_FALSE(is_job_id(""));
  EXPECT_FALSE(is_job_id("0123456789abcdef0"));
  EXPECT_FALSE(is_job_id("00A1"));
  EXPECT_FALSE(is_job_id(".."));
}

TEST(PercentDecode, DecodesEscapesAndPlus) {
  EXPECT_EQ(*percent_decode("a%20b+c%2F"), "a b c/");
  EXPECT_EQ(*percent_decode("%7e%7E%41%5a"), "~~AZ");
  EXPECT_FALSE(percent_decode("a%2"));
  // A digit beside each end of the ranges 0-9, a-f and A-F, in either place.
  for (const char* bad : {"%g0", "%0g", "%/0", "%:0", "%`0", "%G0", "%@0"}) {
    const auto decoded = percent_decode(bad);
    ASSERT_FALSE(decoded) << bad;
    EXPECT_EQ(decoded.error().message, "a malformed %-escape") << bad;
  }
}

TEST(CheckUploadName, KeepsModelNamesOnly) {
  EXPECT_EQ(*check_upload_name("part.STL"), "part.STL");
  EXPECT_EQ(*check_upload_name("C:\\models\\part (2).ply.gz"), "part (2).ply.gz");
  for (const char* name : {"my_part-2.obj", "a.off", "B.PLY", "c.Stl.GZ", "plate.3mf", "Cup.3MF"}) {
    EXPECT_EQ(*check_upload_name(name), name);
  }
  EXPECT_FALSE(check_upload_name("ab"));
  EXPECT_FALSE(check_upload_name("part.gz"));
  EXPECT_FALSE(check_upload_name(""));
  EXPECT_FALSE(check_upload_name(".stl"));
  EXPECT_FALSE(check_upload_name(".hidden.stl"));
  EXPECT_FALSE(check_upload_name("part.stl.exe"));
  EXPECT_FALSE(check_upload_name("plate.3mf.gz"));  // a 3MF is a zip archive already
  EXPECT_FALSE(check_upload_name("a;b.stl"));
  EXPECT_FALSE(check_upload_name(std::string(197, 'a') + ".stl"));
  EXPECT_FALSE(check_upload_name("dir/"));
}

TEST(StemOf, DropsTheModelExtensions) {
  EXPECT_EQ(stem_of("part.stl.gz"), "part");
  EXPECT_EQ(stem_of("a.b.obj"), "a.b");
  EXPECT_EQ(stem_of("plate.3mf"), "plate");
  EXPECT_EQ(stem_of("part"), "part");
  EXPECT_EQ(stem_of(".stl"), ".stl");  // a leading dot is not an extension
  EXPECT_EQ(stem_of(".gz"), "model");  // nothing left: a name all the same
}

}  // namespace
}  // namespace strata::serve::detail
