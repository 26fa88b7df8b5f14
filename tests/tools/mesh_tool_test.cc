// foresight_mesh_tool against the shipped meshes: it writes them byte for byte, all as one set,
// and a folder it cannot write into ends it with one line, exit 1 and nothing written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/support/temp_files.h"

namespace foresight {
namespace {

namespace fs = std::filesystem;

std::string Read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

int RunMeshTool(const fs::path& out_dir, const fs::path& log) {
  const std::string command = std::string(FORESIGHT_MESH_TOOL) + " " + out_dir.string() + " >" +
                              log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(MeshToolTest, WritesTheShippedMeshesByteForByte) {
  const fs::path dir = testing::FreshTempDir("mesh_tool");
  ASSERT_EQ(RunMeshTool(dir / "robots", dir / "log.txt"), 0) << Read(dir / "log.txt");
  int meshes = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir / "robots")) {
    if (entry.path().extension() != ".obj") continue;
    const fs::path shipped = testing::ModelsDir() / "robots" /
                             entry.path().lexically_relative(dir / "robots");
    EXPECT_EQ(Read(entry.path()), Read(shipped)) << shipped;
    ++meshes;
  }
  EXPECT_EQ(meshes, 5);
}

TEST(MeshToolTest, AFolderItCannotWriteEndsItWithNothingWritten) {
  const fs::path dir = testing::FreshTempDir("mesh_tool_refused");
  { std::ofstream(dir / "a_file") << "x"; }
  EXPECT_EQ(RunMeshTool(dir / "a_file" / "robots", dir / "log.txt"), 1);
  const std::string log = Read(dir / "log.txt");
  EXPECT_EQ(log.find("foresight_mesh_tool: "), 0u) << log;
  EXPECT_EQ(log.find('\n'), log.size() - 1) << log;  // one line
  EXPECT_EQ(Read(dir / "a_file"), "x");
}

}  // namespace
}  // namespace foresight
