#include "strata/io/output_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/file_size_limit.hpp"
#include "support/sink_runs.hpp"
#include "support/text_meshes.hpp"

namespace strata::io {
namespace {

using test::read_file;
using testing::list_tree;
using testing::ScratchDir;

TEST(OutputFile, CommitRenamesTemporaryOntoFinalPath) {
  ScratchDir dir;
  auto out = OutputFile::create(dir / "a.bin");
  ASSERT_TRUE(out) << out.error().to_string();
  out->write("hello ");
  out->write("world");
  ASSERT_TRUE(out->commit());
  EXPECT_EQ(read_file(dir / "a.bin"), "hello world");
  EXPECT_EQ(list_tree(dir.path()), std::vector<std::string>{"a.bin"});
}

TEST(OutputFile, TemporaryLivesBesideTheTargetUnderAnotherName) {
  ScratchDir dir;
  auto out = OutputFile::create(dir / "a.bin");
  ASSERT_TRUE(out);
  EXPECT_EQ(out->temp_path().parent_path(), dir.path());
  EXPECT_NE(out->temp_path(), dir / "a.bin");
  EXPECT_TRUE(std::filesystem::exists(out->temp_path()));
  EXPECT_EQ(out->path(), dir / "a.bin");
}

TEST(OutputFile, UncommittedFileNeverAppearsUnderFinalName) {
  ScratchDir dir;
  {
    auto out = OutputFile::create(dir / "a.bin");
    ASSERT_TRUE(out);
    out->write("partial");
    EXPECT_FALSE(std::filesystem::exists(dir / "a.bin"));
  }
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(OutputFile, DiscardRemovesTemporaryAndIsIdempotent) {
  ScratchDir dir;
  auto out = OutputFile::create(dir / "a.bin");
  ASSERT_TRUE(out);
  out->write("x");
  out->discard();
  out->discard();
  EXPECT_TRUE(list_tree(dir.path()).empty());
  EXPECT_EQ(out->stream(), nullptr);
}

TEST(OutputFile, DiscardedFileCannotBeCommitted) {
  ScratchDir dir;
  auto out = OutputFile::create(dir / "a.bin");
  ASSERT_TRUE(out);
  out->discard();
  auto committed = out->commit();
  ASSERT_FALSE(committed);
  EXPECT_FALSE(std::filesystem::exists(dir / "a.bin"));
}

TEST(OutputFile, CommitReplacesExistingFile) {
  ScratchDir dir;
  test::write_text_file(dir / "a.bin", "old content");
  auto out = OutputFile::create(dir / "a.bin");
  ASSERT_TRUE(out);
  out->write("new");
  EXPECT_EQ(read_file(dir / "a.bin"), "old content");
  ASSERT_TRUE(out->commit());
  EXPECT_EQ(read_file(dir / "a.bin"), "new");
}

TEST(OutputFile, DiscardKeepsExistingFile) {
  ScratchDir dir;
  test::write_text_file(dir / "a.bin", "old content");
  auto out = OutputFile::create(dir / "a.bin");
  ASSERT_TRUE(out);
  out->write("new");
  out->discard();
  EXPECT_EQ(read_file(dir / "a.bin"), "old content");
  EXPECT_EQ(list_tree(dir.path()), std::vector<std::string>{"a.bin"});
}

TEST(OutputFile, CreateInMissingFolderFailsNamingThePath) {
  ScratchDir dir;
  auto out = OutputFile::create(dir / "missing" / "a.bin");
  ASSERT_FALSE(out);
  EXPECT_EQ(out.error().code, ErrorCode::BadInput);
  EXPECT_EQ(out.error().location, (dir / "missing" / "a.bin").string());
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(OutputFile, CreateOverFolderFails) {
  ScratchDir dir;
  std::filesystem::create_directory(dir / "sub");
  auto out = OutputFile::create(dir / "sub");
  ASSERT_FALSE(out);
  EXPECT_EQ(out.error().code, ErrorCode::BadInput);
}

TEST(OutputFile, APathWithoutAFileNameIsAUsageError) {
  ScratchDir dir;
  for (const std::filesystem::path& path : {std::filesystem::path(), dir / ""}) {
    auto out = OutputFile::create(path);
    ASSERT_FALSE(out) << path;
    EXPECT_EQ(out.error().code, ErrorCode::Usage);
    EXPECT_EQ(out.error().message, "an output file needs a file name");
    EXPECT_EQ(out.error().location, path.string());
  }
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(OutputFile, AWriteTheDiskRefusesFailsTheCommitAndLeavesNothing) {
  // 3 MiB pass the 1 MiB buffer at once, so the refusal comes from fwrite itself.
  ScratchDir dir;
  auto out = OutputFile::create(dir / "a.bin");
  ASSERT_TRUE(out) << out.error().to_string();
  Result<void> committed;
  {
    const test::FileSizeLimit limit(4096);
    out->write(std::string(3 << 20, 'x'));
    out->write("more");  // ignored after the failure
    committed = out->commit();
  }
  ASSERT_FALSE(committed);
  EXPECT_EQ(committed.error().code, ErrorCode::BadInput);
  EXPECT_EQ(committed.error().location, (dir / "a.bin").string());
  EXPECT_EQ(committed.error().message, "cannot write the file: File too large");
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(OutputFile, AFlushTheDiskRefusesFailsTheCommitAndLeavesNothing) {
  // 64 KiB stay in the buffer until the commit flushes them.
  ScratchDir dir;
  auto out = OutputFile::create(dir / "a.bin");
  ASSERT_TRUE(out) << out.error().to_string();
  Result<void> committed;
  {
    const test::FileSizeLimit limit(4096);
    out->write(std::string(64 << 10, 'x'));
    committed = out->commit();
  }
  ASSERT_FALSE(committed);
  EXPECT_EQ(committed.error().message, "cannot write the file: File too large");
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

TEST(OutputFile, MoveTransfersTheOpenFile) {
  ScratchDir dir;
  auto created = OutputFile::create(dir / "a.bin");
  ASSERT_TRUE(created);
  OutputFile first = std::move(created.value());
  first.write("ab");
  OutputFile second;
  second = std::move(first);
  EXPECT_EQ(first.stream(), nullptr);  // NOLINT(bugprone-use-after-move): moved-from state
  second.write("cd");
  ASSERT_TRUE(second.commit());
  EXPECT_EQ(read_file(dir / "a.bin"), "abcd");
}

TEST(OutputFile, TwoFilesForOnePathGetDistinctTemporaries) {
  ScratchDir dir;
  auto a = OutputFile::create(dir / "a.bin");
  auto b = OutputFile::create(dir / "a.bin");
  ASSERT_TRUE(a);
  ASSERT_TRUE(b);
  EXPECT_NE(a->temp_path(), b->temp_path());
}

TEST(OutputFile, WriteTextFileWritesContentAtomically) {
  ScratchDir dir;
  ASSERT_TRUE(write_text_file(dir / "report.json", "{\"ok\": true}\n"));
  EXPECT_EQ(read_file(dir / "report.json"), "{\"ok\": true}\n");
  EXPECT_EQ(list_tree(dir.path()), std::vector<std::string>{"report.json"});
}

TEST(OutputFile, WriteTextFileInMissingFolderFailsAndLeavesNothing) {
  ScratchDir dir;
  auto written = write_text_file(dir / "no" / "report.json", "{}");
  ASSERT_FALSE(written);
  EXPECT_EQ(written.error().code, ErrorCode::BadInput);
  EXPECT_TRUE(list_tree(dir.path()).empty());
}

}  // namespace
}  // namespace strata::io
