// Tests of SourceFile (line ends, UTF-8 columns, end of file) and of file reading/writing.
#include "arbiter/compiler/source.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace arbiter::compiler {
namespace {

namespace fs = std::filesystem;

void ExpectAt(const SourceFile& file, uint32_t offset, uint32_t line, uint32_t column) {
  const LineCol lc = file.Locate(offset);
  EXPECT_EQ(lc.line, line) << "offset " << offset;
  EXPECT_EQ(lc.column, column) << "offset " << offset;
}

TEST(SourceFileTest, LfLineEnds) {
  const SourceFile file("a.vp", "ab\ncd\n");
  EXPECT_EQ(file.line_count(), 2u);
  EXPECT_EQ(file.LineText(1), "ab");
  EXPECT_EQ(file.LineText(2), "cd");
  EXPECT_EQ(file.LineStart(1), 0u);
  EXPECT_EQ(file.LineStart(2), 3u);
  ExpectAt(file, 0, 1, 1);
  ExpectAt(file, 1, 1, 2);
  ExpectAt(file, 2, 1, 3);  // the '\n' itself: just after the last character
  ExpectAt(file, 3, 2, 1);
  ExpectAt(file, 4, 2, 2);
}

TEST(SourceFileTest, CrLfLineEnds) {
  const SourceFile file("a.vp", "ab\r\ncd\r\n");
  EXPECT_EQ(file.line_count(), 2u);
  EXPECT_EQ(file.LineText(1), "ab");
  EXPECT_EQ(file.LineText(2), "cd");
  EXPECT_EQ(file.LineStart(2), 4u);
  ExpectAt(file, 2, 1, 3);  // '\r'
  ExpectAt(file, 3, 1, 3);  // '\n' of the same terminator
  ExpectAt(file, 4, 2, 1);
  ExpectAt(file, 5, 2, 2);
}

TEST(SourceFileTest, CrLineEnds) {
  const SourceFile file("a.vp", "ab\rcd\r");
  EXPECT_EQ(file.line_count(), 2u);
  EXPECT_EQ(file.LineText(1), "ab");
  EXPECT_EQ(file.LineText(2), "cd");
  ExpectAt(file, 3, 2, 1);
}

TEST(SourceFileTest, MixedLineEndsEachEndOneLine) {
  // "\r\n" is one terminator; "\n\r" is two.
  const SourceFile file("a.vp", "a\r\n\rb\n\rc");
  ASSERT_EQ(file.line_count(), 5u);
  EXPECT_EQ(file.LineText(1), "a");
  EXPECT_EQ(file.LineText(2), "");
  EXPECT_EQ(file.LineText(3), "b");
  EXPECT_EQ(file.LineText(4), "");
  EXPECT_EQ(file.LineText(5), "c");
  ExpectAt(file, 3, 2, 1);
  ExpectAt(file, 4, 3, 1);
  ExpectAt(file, 7, 5, 1);
  ExpectAt(file, 8, 5, 2);
}

TEST(SourceFileTest, SameLocationsWithLfAndCrLf) {
  const SourceFile lf("a.vp", "!!ARBvp1.0\nMOV r, c;\nEND\n");
  const SourceFile crlf("a.vp", "!!ARBvp1.0\r\nMOV r, c;\r\nEND\r\n");
  // "c" on line 2 and "END" on line 3.
  EXPECT_EQ(lf.Locate(18).line, crlf.Locate(19).line);
  EXPECT_EQ(lf.Locate(18).column, crlf.Locate(19).column);
  EXPECT_EQ(lf.Locate(21).line, 3u);
  EXPECT_EQ(crlf.Locate(23).line, 3u);
  EXPECT_EQ(crlf.Locate(23).column, 1u);
}

TEST(SourceFileTest, FinalLineWithoutTerminatorCounts) {
  const SourceFile file("a.vp", "ab\ncd");
  EXPECT_EQ(file.line_count(), 2u);
  EXPECT_EQ(file.LineText(2), "cd");
  ExpectAt(file, 5, 2, 3);  // end of text
}

TEST(SourceFileTest, EndOfFileIsAfterTheLastCharacterOfTheLastLine) {
  const SourceFile file("a.vp", "ab\ncd\n");
  ExpectAt(file, 6, 2, 3);
  // Offsets past the end are clamped to it.
  ExpectAt(file, 100, 2, 3);
}

TEST(SourceFileTest, EmptyFile) {
  const SourceFile file("a.vp", "");
  EXPECT_EQ(file.line_count(), 1u);
  EXPECT_EQ(file.LineText(1), "");
  EXPECT_EQ(file.LineStart(1), 0u);
  ExpectAt(file, 0, 1, 1);
}

TEST(SourceFileTest, OnlyTerminators) {
  const SourceFile one("a.vp", "\n");
  EXPECT_EQ(one.line_count(), 1u);
  EXPECT_EQ(one.LineText(1), "");
  ExpectAt(one, 1, 1, 1);
  const SourceFile two("a.vp", "\n\n");
  EXPECT_EQ(two.line_count(), 2u);
  ExpectAt(two, 1, 2, 1);
  ExpectAt(two, 2, 2, 1);
}

TEST(SourceFileTest, Utf8CharactersAreOneColumnEach) {
  // "# é€😀 X": é is 2 bytes, € 3, 😀 4.
  const std::string text = "# \xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80 X";
  const SourceFile file("a.fp", text);
  ExpectAt(file, 2, 1, 3);   // é
  ExpectAt(file, 4, 1, 4);   // €
  ExpectAt(file, 7, 1, 5);   // 😀
  ExpectAt(file, 11, 1, 6);  // ' '
  ExpectAt(file, 12, 1, 7);  // X
  ExpectAt(file, 13, 1, 8);  // end
}

TEST(SourceFileTest, OffsetInsideACharacterIsThatCharactersColumn) {
  const SourceFile file("a.fp",
                        "a\xE2\x82\xAC"
                        "b");
  ExpectAt(file, 2, 1, 2);
  ExpectAt(file, 3, 1, 2);
  ExpectAt(file, 4, 1, 3);
}

TEST(SourceFileTest, InvalidBytesCountOneColumnEach) {
  // A stray continuation byte, an invalid lead byte, a truncated 3-byte sequence, an
  // overlong lead byte.
  const SourceFile file("a.fp", "\x80\xFF\xE2\x82X\xC0\xAFY");
  ExpectAt(file, 1, 1, 2);
  ExpectAt(file, 2, 1, 3);
  ExpectAt(file, 3, 1, 4);
  ExpectAt(file, 4, 1, 5);  // X
  ExpectAt(file, 7, 1, 8);  // Y
}

TEST(SourceFileTest, TruncatedSequenceAtEndOfText) {
  const SourceFile file("a.fp", "a\xF0\x9F");
  ExpectAt(file, 3, 1, 4);
}

TEST(SourceFileTest, LocateUsesTheRightLineAmongMany) {
  std::string text;
  for (int i = 0; i < 1000; ++i) {
    text += "line\n";
  }
  const SourceFile file("a.vp", text);
  EXPECT_EQ(file.line_count(), 1000u);
  ExpectAt(file, 5 * 637 + 2, 638, 3);
  ExpectAt(file, 5 * 999, 1000, 1);
}

// A fresh directory under the system temporary folder, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "arbiter-source-test-XXXXXX").string();
    path_ = ::mkdtemp(pattern.data());
  }
  ~TempDir() {
    std::error_code ec;
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  // The names of the entries in the folder.
  std::vector<std::string> Entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  fs::path path_;
};

void WriteRaw(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

TEST(ReadFileBytesTest, ReadsEveryByte) {
  const TempDir dir;
  const std::string bytes(
      "!!ARBvp1.0\r\n\0\xFF"
      "END",
      17);
  WriteRaw(dir.path() / "a.vp", bytes);
  std::string read;
  std::string error;
  ASSERT_TRUE(ReadFileBytes((dir.path() / "a.vp").string(), &read, &error)) << error;
  EXPECT_EQ(read, bytes);
}

TEST(ReadFileBytesTest, ReadsAnEmptyFile) {
  const TempDir dir;
  WriteRaw(dir.path() / "empty.vp", "");
  std::string read = "stale";
  std::string error;
  ASSERT_TRUE(ReadFileBytes((dir.path() / "empty.vp").string(), &read, &error)) << error;
  EXPECT_EQ(read, "");
}

TEST(ReadFileBytesTest, DashReadsStandardInput) {
  const TempDir dir;
  WriteRaw(dir.path() / "in.fp", "!!ARBfp1.0\nEND\n");
  ASSERT_NE(std::freopen((dir.path() / "in.fp").c_str(), "rb", stdin), nullptr);
  std::string read;
  std::string error;
  ASSERT_TRUE(ReadFileBytes("-", &read, &error)) << error;
  EXPECT_EQ(read, "!!ARBfp1.0\nEND\n");
}

TEST(ReadFileBytesTest, MissingFile) {
  const TempDir dir;
  std::string read;
  std::string error;
  EXPECT_FALSE(ReadFileBytes((dir.path() / "missing.vp").string(), &read, &error));
  EXPECT_EQ(error, "no such file or directory");
}

TEST(ReadFileBytesTest, Directory) {
  const TempDir dir;
  std::string read;
  std::string error;
  EXPECT_FALSE(ReadFileBytes(dir.path().string(), &read, &error));
  EXPECT_EQ(error, "is a directory");
}

// The batch reader: one open tells a directory from a file (then read) or a failure.
TEST(ReadFileOrDirectoryTest, TellsTheThreeApart) {
  const TempDir dir;
  WriteRaw(dir.path() / "a.fp", "!!ARBfp1.0\nEND\n");
  std::string read = "stale";
  std::string error;
  EXPECT_EQ(ReadFileOrDirectory(dir.path().string(), &read, &error), ReadOutcome::Directory);
  EXPECT_EQ(read, "");
  EXPECT_EQ(ReadFileOrDirectory((dir.path() / "a.fp").string(), &read, &error), ReadOutcome::Read);
  EXPECT_EQ(read, "!!ARBfp1.0\nEND\n");
  EXPECT_EQ(ReadFileOrDirectory((dir.path() / "b.fp").string(), &read, &error),
            ReadOutcome::Failed);
  EXPECT_EQ(error, "no such file or directory");
}

TEST(ReadFileBytesTest, PermissionDenied) {
  if (::geteuid() == 0) {
    GTEST_SKIP() << "root reads every file";
  }
  const TempDir dir;
  const fs::path path = dir.path() / "secret.vp";
  WriteRaw(path, "!!ARBvp1.0\nEND\n");
  fs::permissions(path, fs::perms::none);
  std::string read;
  std::string error;
  EXPECT_FALSE(ReadFileBytes(path.string(), &read, &error));
  EXPECT_EQ(error, "permission denied");
}

TEST(WriteFileAtomicallyTest, WritesAndLeavesNoTemporary) {
  const TempDir dir;
  const fs::path path = dir.path() / "out.glsl";
  std::string error;
  ASSERT_TRUE(WriteFileAtomically(path.string(), "void main() {}\n", &error)) << error;
  std::string read;
  ASSERT_TRUE(ReadFileBytes(path.string(), &read, &error)) << error;
  EXPECT_EQ(read, "void main() {}\n");
  EXPECT_EQ(dir.Entries(), std::vector<std::string>{"out.glsl"});
}

TEST(WriteFileAtomicallyTest, ReplacesAFileAndKeepsItsMode) {
  const TempDir dir;
  const fs::path path = dir.path() / "out.glsl";
  WriteRaw(path, "old contents that are longer\n");
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  std::string error;
  ASSERT_TRUE(WriteFileAtomically(path.string(), "new\n", &error)) << error;
  std::string read;
  ASSERT_TRUE(ReadFileBytes(path.string(), &read, &error)) << error;
  EXPECT_EQ(read, "new\n");
  EXPECT_EQ(fs::status(path).permissions(),
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  EXPECT_EQ(dir.Entries(), std::vector<std::string>{"out.glsl"});
}

TEST(WriteFileAtomicallyTest, WritesEmptyContents) {
  const TempDir dir;
  const fs::path path = dir.path() / "empty";
  std::string error;
  ASSERT_TRUE(WriteFileAtomically(path.string(), "", &error)) << error;
  EXPECT_EQ(fs::file_size(path), 0u);
}

TEST(WriteFileAtomicallyTest, MissingFolder) {
  const TempDir dir;
  std::string error;
  EXPECT_FALSE(
      WriteFileAtomically((dir.path() / "no-such-dir" / "out.glsl").string(), "x", &error));
  EXPECT_EQ(error, "no such file or directory");
  EXPECT_TRUE(dir.Entries().empty());
}

TEST(WriteFileAtomicallyTest, TargetIsADirectory) {
  const TempDir dir;
  fs::create_directory(dir.path() / "sub");
  std::string error;
  EXPECT_FALSE(WriteFileAtomically((dir.path() / "sub").string(), "x", &error));
  EXPECT_EQ(error, "is a directory");
  EXPECT_EQ(dir.Entries(), std::vector<std::string>{"sub"});
  EXPECT_TRUE(fs::is_empty(dir.path() / "sub"));
}

TEST(WriteFileAtomicallyTest, ReadOnlyFolder) {
  if (::geteuid() == 0) {
    GTEST_SKIP() << "root writes into every folder";
  }
  const TempDir dir;
  fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
  std::string error;
  EXPECT_FALSE(WriteFileAtomically((dir.path() / "out.glsl").string(), "x", &error));
  EXPECT_EQ(error, "permission denied");
}

}  // namespace
}  // namespace arbiter::compiler
