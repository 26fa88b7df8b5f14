// Output files are written whole or not at all.
#include "report/atomic_file.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>

#include "common/error.h"
#include "report/output_set.h"
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

// A link whose target does not exist yet stays a link too, and the file it names is made
// (it became a regular file in the link's place); a link to a link is followed to the end.
TEST(AtomicFileTest, ADanglingSymbolicLinkStaysALinkAndItsTargetIsMade) {
  const fs::path dir = FreshDir("dangling");
  fs::create_directories(dir / "sub");
  fs::create_symlink("sub/new.txt", dir / "link.txt");
  fs::create_symlink("link.txt", dir / "link_to_link.txt");
  WriteFileAtomically(dir / "link_to_link.txt", "made");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "link.txt")));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "link_to_link.txt")));
  EXPECT_EQ(Read(dir / "sub" / "new.txt"), "made");
  fs::create_symlink("loop_b", dir / "loop_a");
  fs::create_symlink("loop_a", dir / "loop_b");
  EXPECT_THROW(WriteFileAtomically(dir / "loop_a", "x"), InputError);
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "loop_a")));
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

// The bits of SIGINT and SIGTERM in a process's blocked-signal mask (/proc/PID/status, SigBlk).
bool HoldsInterrupts(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("SigBlk:", 0) != 0) continue;
    const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
    return (mask >> (SIGINT - 1) & 1) != 0 || (mask >> (SIGTERM - 1) & 1) != 0;
  }
  ADD_FAILURE() << "no SigBlk for " << pid;
  return true;
}

// Whether `pid` waits in openat(2) or open(2) (/proc/PID/syscall starts with its number).
bool WaitsInOpen(pid_t pid) {
  std::ifstream syscall("/proc/" + std::to_string(pid) + "/syscall");
  std::string number;
  syscall >> number;
#ifdef SYS_open
  if (number == std::to_string(SYS_open)) return true;
#endif
  return number == std::to_string(SYS_openat);
}

TEST(AtomicFileTest, AFifoWithoutAReaderWaitsWithInterruptsNotHeld) {
  const fs::path fifo = FreshDir("fifo_no_reader") / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // waits for a reader that never comes
    WriteFileAtomically(fifo, "nobody reads this");
    ::_exit(0);
  }
  int status = 0;
  // A deadline, not a timing assumption: a writer not yet in open() after a minute is a failure.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (!WaitsInOpen(child)) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(child, SIGKILL);
      ::waitpid(child, &status, 0);
      FAIL() << "the writer never waited in open()";
    }
    ASSERT_EQ(::waitpid(child, &status, WNOHANG), 0) << "the writer ended without waiting";
    std::this_thread::yield();
  }
  const bool held = HoldsInterrupts(child);
  EXPECT_FALSE(held) << "Ctrl-C could not end a run waiting for a reader";
  ::kill(child, held ? SIGKILL : SIGTERM);
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == (held ? SIGKILL : SIGTERM));
}

TEST(AtomicFileTest, StandardOutputByNameIsWrittenAfterWhatWasPrinted) {
  ::testing::internal::CaptureStdout();
  std::cout << "printed, ";
  WriteFileAtomically("/dev/stdout", "then written");
  // The redirected standard output (a file here) is written to, not replaced.
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "printed, then written");
}

TEST(AtomicFileTest, ALinkToStandardOutputIsWrittenAfterWhatWasPrinted) {
  const fs::path link = FreshDir("link_to_stdout") / "out.svg";
  fs::create_symlink("/dev/stdout", link);
  ::testing::internal::CaptureStdout();
  std::cout << "printed, ";
  WriteFileAtomically(link, "then written");
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "printed, then written");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
}

TEST(AtomicFileTest, AnOpenDescriptorByNameIsWrittenAsAStream) {
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  for (const std::string& name : {"/proc/self/fd/", "/dev/fd/"}) {
    WriteFileAtomically(name + std::to_string(ends[1]), "through " + name);
    char buffer[64] = {};
    const ssize_t n = ::read(ends[0], buffer, sizeof buffer);
    EXPECT_EQ(std::string(buffer, n > 0 ? static_cast<std::size_t>(n) : 0), "through " + name);
  }
  ::close(ends[0]);
  ::close(ends[1]);
}

TEST(AtomicFileTest, ADirectoryIsRefused) {
  const fs::path dir = FreshDir("dir");
  EXPECT_THROW(WriteFileAtomically(dir, "x"), InputError);
  EXPECT_TRUE(fs::is_directory(dir));
}

}  // namespace
}  // namespace foresight
