#include "common/progress_log.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace foresight {
namespace {

using ::testing::ElementsAre;

// What a ProgressLog wrote into a temporary file.
std::string Written(std::FILE* file) {
  std::fflush(file);
  std::rewind(file);
  std::string text;
  for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file)) text += static_cast<char>(c);
  return text;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t end = text.find('\n'); end != std::string::npos; end = text.find('\n', start)) {
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

TEST(ProgressLogTest, ALogGetsAtMostOneLinePerIntervalWithRateAndTimeLeft) {
  std::FILE* file = std::tmpfile();
  double now_s = 100.0;
  ProgressLogSettings settings;
  settings.interval_s = 5.0;
  settings.clock_s = [&] { return now_s; };
  settings.out = file;
  ProgressLog log("calibrate forward", "trials", settings);
  for (int done = 1; done <= 40; ++done) {  // one trial every half second
    now_s += 0.5;
    log.Report(done, 40);
  }
  EXPECT_THAT(Lines(Written(file)),
              ElementsAre("calibrate forward: 10 / 40 trials (25 %), 2 trials/s, about 15 s left",
                          "calibrate forward: 20 / 40 trials (50 %), 2 trials/s, about 10 s left",
                          "calibrate forward: 30 / 40 trials (75 %), 2 trials/s, about 5 s left",
                          "calibrate forward: 40 / 40 trials (100 %), done in 20 s"));
  std::fclose(file);
}

TEST(ProgressLogTest, ALoopShorterThanOneIntervalWritesNothingIntoALog) {
  std::FILE* file = std::tmpfile();
  double now_s = 0.0;
  ProgressLogSettings settings;
  settings.clock_s = [&] { return now_s; };
  settings.out = file;
  ProgressLog log("simulate", "trials", settings);
  for (int done = 1; done <= 10; ++done) {
    now_s += 0.1;
    log.Report(done, 10);
  }
  EXPECT_EQ(Written(file), "");
  std::fclose(file);
}

TEST(ProgressLogTest, ATerminalLineIsRewrittenInPlace) {
  std::FILE* file = std::tmpfile();
  double now_s = 0.0;
  ProgressLogSettings settings;
  settings.terminal = true;
  settings.clock_s = [&] { return now_s; };
  settings.out = file;
  ProgressLog log("fidelity", "situations", settings);
  now_s = 2.0;
  log.Report(1, 2);
  now_s = 4.0;
  log.Report(2, 2);
  EXPECT_EQ(Written(file),
            "\rfidelity: 1 / 2 situations (50 %), 0.5 situations/s, about 2 s left"
            "\rfidelity: 2 / 2 situations (100 %), done in 4 s\n");
  std::fclose(file);
}

TEST(ProgressLogTest, LongTimesReadInMinutesAndHours) {
  EXPECT_EQ(ProgressLog::Line("stability", "poses", 2, 1000, 60.0),
            "stability: 2 / 1000 poses (0 %), 0.0333 poses/s, about 8.3 h left");
  EXPECT_EQ(ProgressLog::Line("stability", "poses", 100, 1000, 60.0),
            "stability: 100 / 1000 poses (10 %), 1.67 poses/s, about 9 min left");
}

TEST(ProgressLogTest, TheEnvironmentSetsTheInterval) {
  ::setenv("FORESIGHT_PROGRESS_INTERVAL_S", "0.5", 1);
  EXPECT_EQ(StderrProgressSettings().interval_s, 0.5);
  ::setenv("FORESIGHT_PROGRESS_INTERVAL_S", "soon", 1);  // unreadable: the default
  EXPECT_EQ(StderrProgressSettings().interval_s, kDefaultProgressIntervalS);
  ::unsetenv("FORESIGHT_PROGRESS_INTERVAL_S");
  EXPECT_EQ(StderrProgressSettings().interval_s, kDefaultProgressIntervalS);
}

}  // namespace
}  // namespace foresight
