// The physics calibration loop shared by `foresight calibrate` and `foresight check`: which
// kicks it plays, that every trial is an observation or a miss, that a kick alone gives the
// numbers it gives among all, and its errors.
#include "validation/physics_calibration.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "common/error.h"
#include "validation/calibration_report.h"
#include "tests/support/temp_files.h"

namespace foresight {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

PhysicsCalibrationSettings Nao(const std::string& kick) {
  PhysicsCalibrationSettings settings;
  settings.robot = "nao";
  settings.kick = kick;
  settings.trials = 8;
  settings.seed = 3;
  settings.threads = 1;
  // The fixed base, the cheap approximation (a tenth of a floating trial's cost): what is
  // tested here does not depend on the base.
  settings.base = RobotBase::kFixed;
  return settings;
}

std::string ErrorOf(const PhysicsCalibrationSettings& settings) {
  try {
    RunPhysicsCalibration(settings, testing::ModelsDir());
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PhysicsCalibrationTest, ChooseKicksTakesOneOrAllAndNamesTheChoices) {
  const std::vector<std::string> available = {"forward", "side"};
  EXPECT_EQ(ChooseKicks("", available, "--kick", "here"), available);
  EXPECT_THAT(ChooseKicks("side", available, "--kick", "here"), ElementsAre("side"));
  try {
    ChooseKicks("back", available, "--kick", "here");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--kick: no kick 'back' in here (one of: forward, side)");
  }
}

TEST(PhysicsCalibrationTest, EveryKickWithAMotionEveryTrialCounted) {
  int progress_calls = 0;
  PhysicsCalibrationSettings settings = Nao("");
  settings.progress = [&](const std::string&) {
    ++progress_calls;
    return std::function<void(int, int)>();
  };
  const PhysicsCalibration r = RunPhysicsCalibration(settings, testing::ModelsDir());
  ASSERT_EQ(r.kicks.size(), 3u);
  EXPECT_EQ(progress_calls, 3);
  EXPECT_GT(r.carpet_deceleration_mps2, 0.0);
  EXPECT_EQ(r.situation_file, testing::ModelsDir() / "calibration" / "nao.json");
  for (const PhysicsKickTrials& k : r.kicks) {
    EXPECT_EQ(r.model.kicks[k.kick_index].name, k.kick);
    EXPECT_EQ(static_cast<int>(k.observations.size()) + k.missed, settings.trials) << k.kick;
    EXPECT_EQ(k.draws.size(), k.observations.size()) << k.kick;
  }
}

TEST(PhysicsCalibrationTest, OneKickAloneGivesTheSameObservationsAsAmongAll) {
  const PhysicsCalibration all = RunPhysicsCalibration(Nao(""), testing::ModelsDir());
  const PhysicsCalibration one = RunPhysicsCalibration(Nao("side_kick_left"), testing::ModelsDir());
  ASSERT_EQ(one.kicks.size(), 1u);
  const PhysicsKickTrials& alone = one.kicks[0];
  ASSERT_EQ(all.kicks[1].kick, "side_kick_left");
  ASSERT_EQ(alone.observations.size(), all.kicks[1].observations.size());
  for (std::size_t i = 0; i < alone.observations.size(); ++i) {
    EXPECT_EQ(alone.observations[i].launch_speed_mps,
              all.kicks[1].observations[i].launch_speed_mps);
  }
}

// Each kick carries its motion's clearance. The shipped kicks stay above the carpet (issue 12,
// sixth pass) and get no warning; a motion that runs through it is warned about with the link,
// the depth and the time (the NAO's forward kick before the sixth pass: 34 mm at 1.04 s; here the
// same kick with its stance sunk 2 cm, so both soles start 20 mm below the carpet).
TEST(PhysicsCalibrationTest, AKickWhoseMotionRunsThroughTheCarpetIsWarnedAbout) {
  const PhysicsCalibration physics = RunPhysicsCalibration(Nao(""), testing::ModelsDir());
  CalibrationRun run;
  for (const PhysicsKickTrials& trials : physics.kicks) {
    CalibratedKick kick;
    kick.fit.kick = trials.kick;
    kick.clearance = trials.clearance;
    run.kicks.push_back(kick);
  }
  ASSERT_EQ(run.kicks.size(), 3u);
  const auto below_carpet = [&run]() {
    std::vector<std::string> below;
    for (const std::string& w : CalibrationWarnings(run)) {
      if (w.find("below the carpet") != std::string::npos) below.push_back(w);
    }
    return below;
  };
  for (const CalibratedKick& kick : run.kicks) {
    EXPECT_GT(kick.clearance->lowest_m, -0.001) << kick.fit.kick;
  }
  EXPECT_TRUE(below_carpet().empty());

  const Robot robot = LoadRobot("nao", testing::ModelsDir());
  KickMotion sunk = robot.motions[*robot.FindMotion("forward")];
  sunk.stance.base_height_m -= 0.02;
  run.kicks[0].clearance = FindMotionClearance(robot, sunk);
  EXPECT_NEAR(run.kicks[0].clearance->lowest_m, -0.02, 0.001);
  const std::vector<std::string> below = below_carpet();
  ASSERT_EQ(below.size(), 1u);
  EXPECT_THAT(below[0], HasSubstr("forward: its motion takes "));
  EXPECT_THAT(below[0], HasSubstr("_foot 20 mm below the carpet at "));
}

TEST(PhysicsCalibrationTest, UnknownKickAndOtherRobotsModelAreInputErrors) {
  EXPECT_THAT(ErrorOf(Nao("bicycle")),
              HasSubstr("--kick: no kick 'bicycle' in the motions of robot 'nao'"));
  PhysicsCalibrationSettings other = Nao("");
  other.kicks_file = testing::ModelsDir() / "kicks" / "aibo_ers7.json";
  EXPECT_THAT(ErrorOf(other), HasSubstr("the kick model is for robot 'aibo_ers7', not 'nao'"));
}

}  // namespace
}  // namespace foresight

namespace foresight {
namespace {

// The shipped physics of `field` with a uniform carpet (no per-trial or per-patch factor).
std::filesystem::path UniformCarpet(const std::string& field) {
  nlohmann::json physics = nlohmann::json::parse(
      testing::ReadText(testing::ModelsDir() / "physics" / (field + ".json")));
  physics["carpet"]["deceleration_sigma_rel"] = 0.0;
  physics["carpet"]["patch_sigma_rel"] = 0.0;
  return testing::WriteTempFile("uniform_" + field + ".json", physics.dump());
}

// The deceleration calibration reads from kicked balls is the carpet's: rolling resistance acts
// on every rolling step (issue 12: when it was switched off whenever the solver's slip flickered
// above 1 %, the AIBO's head-kicked balls decelerated at 0.217 instead of 0.270 m/s^2). The
// carpet is uniform here: the AIBO's forward kick rolls about 1.8 m from the calibration spot
// across three 1 m patches of the shipped carpet, whose fixed factors make it read 3-4 % low.
TEST(PhysicsCalibrationTest, KickedBallsDecelerateAtTheCarpetsRate) {
  for (const auto& [robot, field] :
       {std::pair{"nao", "spl"}, std::pair{"aibo_ers7", "four_legged"}}) {
    PhysicsCalibrationSettings settings;
    settings.robot = robot;
    settings.trials = 40;
    settings.threads = 2;
    settings.physics_file = UniformCarpet(field);
    // The fixed base, the cheap approximation: the carpet brakes the ball alike on both.
    settings.base = RobotBase::kFixed;
    const PhysicsCalibration r = RunPhysicsCalibration(settings, testing::ModelsDir());
    std::vector<KickObservation> all;
    for (const PhysicsKickTrials& k : r.kicks) {
      all.insert(all.end(), k.observations.begin(), k.observations.end());
    }
    CalibrationSettings fit;
    fit.resamples = 200;
    const std::optional<DecelerationFit> d = FitPooledDeceleration(all, fit);
    ASSERT_TRUE(d.has_value()) << robot;
    // On a uniform carpet the fit reads the carpet's deceleration to within 1 %.
    EXPECT_NEAR(d->deceleration_mps2, r.carpet_deceleration_mps2,
                0.01 * r.carpet_deceleration_mps2)
        << robot;
  }
}

}  // namespace
}  // namespace foresight
