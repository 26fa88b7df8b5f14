// Output files are written whole or not at all.
#include "report/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "common/error.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

namespace fs = std::filesystem;

fs::path FreshDir(const std::string& name) {
  return testing::FreshTempDir(name);
}

std::string Read(const fs::path& file) {
  return testing::ReadText(file);
}

TEST(AtomicFileTest, WritesTheWholeContentAndNoTemporaryRemains) {
  const fs::path dir = FreshDir("whole");
  WriteFileAtomically(dir / "out.txt", "first");
  WriteFileAtomically(dir / "out.txt", "second, longer");  // replaces
  EXPECT_EQ(Read(dir / "out.txt"), "second, longer");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicFileTest, MissingDirectoryIsAnInputErrorNamingTheFile) {
  const fs::path dir = FreshDir("missing");
  try {
    WriteFileAtomically(dir / "nope" / "out.txt", "x");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nope/out.txt"), std::string::npos) << e.what();
  }
}

TEST(AtomicFileTest, TargetThatIsADirectoryFailsAndLeavesItAlone) {
  const fs::path dir = FreshDir("is_dir");
  fs::create_directories(dir / "taken");
  EXPECT_THROW(WriteFileAtomically(dir / "taken", "x"), InputError);
  EXPECT_TRUE(fs::is_directory(dir / "taken"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// Issue 16: what is not a regular file is never replaced by one.
TEST(AtomicFileTest, ASymbolicLinkStaysALinkAndItsTargetIsReplaced) {
  const fs::path dir = FreshDir("link");
  WriteFileAtomically(dir / "target.txt", "old");
  fs::create_symlink(dir / "target.txt", dir / "link.txt");
  WriteFileAtomically(dir / "link.txt", "new");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "link.txt")));
  EXPECT_EQ(Read(dir / "target.txt"), "new");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
}

TEST(AtomicFileTest, ADeviceStaysADevice) {
  WriteFileAtomically("/dev/null", "discarded");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(AtomicFileTest, AFifoIsWrittenAsAStream) {
  const fs::path dir = FreshDir("fifo");
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = Read(fifo); });
  WriteFileAtomically(fifo, "through the pipe");
  reader.join();
  EXPECT_EQ(received, "through the pipe");
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(AtomicFileTest, DashIsStandardOutput) {
  ::testing::internal::CaptureStdout();
  WriteFileAtomically("-", "to stdout");
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "to stdout");
}

TEST(AtomicFileTest, ADirectoryIsRefused) {
  const fs::path dir = FreshDir("dir");
  EXPECT_THROW(WriteFileAtomically(dir, "x"), InputError);
  EXPECT_TRUE(fs::is_directory(dir));
}

}  // namespace
}  // namespace foresight
