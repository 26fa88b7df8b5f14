// The log of files a run read: ReadDataFile records into it only while one is open, one entry
// per file however it is spelled, from any thread; an allowed file is left out.
#include "common/input_log.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <thread>
#include <vector>

#include "common/data_file.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

namespace fs = std::filesystem;

TEST(InputLogTest, RecordsWhatIsReadWhileOpenOnceEachAndLeavesOutTheAllowed) {
  const fs::path dir = testing::FreshTempDir("input_log");
  const fs::path a = testing::WriteTempFile("input_log_a.json", "{}");
  const fs::path b = testing::WriteTempFile("input_log_b.json", "{}");
  ReadDataFile(a);  // no log: nothing recorded, nothing kept for the next one
  EXPECT_TRUE(InputLog::Files().empty());
  {
    const InputLog log;
    EXPECT_TRUE(InputLog::Files().empty());
    ReadDataFile(a);
    ReadDataFile(a.parent_path() / "." / a.filename());  // the same file spelled otherwise
    std::vector<std::thread> workers;
    for (int i = 0; i < 4; ++i) workers.emplace_back([&] { ReadDataFile(b); });
    for (std::thread& w : workers) w.join();
    EXPECT_EQ(InputLog::Files(), (std::vector<fs::path>{fs::weakly_canonical(a),
                                                        fs::weakly_canonical(b)}));
    InputLog::Allow(a);
    EXPECT_EQ(InputLog::Files(), std::vector<fs::path>{fs::weakly_canonical(b)});
    EXPECT_THROW(InputLog{}, std::logic_error);  // logs do not nest
  }
  EXPECT_TRUE(InputLog::Files().empty());
  const InputLog again;  // a closed log can be opened again, empty
  EXPECT_TRUE(InputLog::Files().empty());
}

}  // namespace
}  // namespace foresight
