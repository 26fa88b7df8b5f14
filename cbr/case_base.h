// The case base (Ros et al. 2009, sec. 2.4 and 5.1.1): the hand-written cases and all their
// symmetric copies held explicitly, indexed by the defending goal (sec. 3.4).
//
// LoadCaseBase(PATH) reads either
//   a folder: its settings file case_base.json and every other *.json in it, in sorted name
//             order, each one case (cbr/case_file.h); or
//   a settings file that lists the case files in "cases" (paths relative to it).
// Settings file (strict):
//   {"notes": "...",                                   optional
//    "field": "four_legged", "kicks": "aibo_ers7",     bare names in MODELS_DIR or *.json paths
//    "kick_mirrors": {"head_kick_left": "head_kick_right"},   left/right pairs, both kicks known
//    "configurations": ["dg", "2d"],                   optional: the opponent configurations
//                                                      (models/match) the cases are written for
//    "cases": ["a.json", ...]}                         required for a file, optional for a folder
// Every hand-written case yields four stored cases: itself and its mirror_y, mirror_x and
// mirror_xy copies ("<name>/mirror_y", ...). Hand-written names must be unique.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "cbr/case.h"
#include "cbr/case_file.h"
#include "cbr/symmetry.h"
#include "models/model_paths.h"

namespace foresight {

class CaseBase {
 public:
  CaseBase() = default;
  // Stores `hand_written` and their three mirror images each.
  CaseBase(const std::vector<Case>& hand_written, const KickMirrors& mirrors);

  // The stored cases of a team defending `goal`: hand-written order, each followed by its copies.
  std::span<const Case> Defending(DefendingGoal goal) const;
  std::size_t size() const { return cyan_.size() + yellow_.size(); }
  std::size_t HandWrittenCount() const { return hand_written_; }
  // The stored case called `name`, or nullptr.
  const Case* Find(const std::string& name) const;
  // The base without the symmetric augmentation of the field's y axis (the mirror_y copies and
  // their x mirrors): each goal keeps one copy of every hand-written case (the paper's 34 cases
  // were stored as 136, sec. 5.1.1). An ablation.
  CaseBase WithoutMirrorY() const;

 private:
  std::vector<Case> cyan_, yellow_;
  std::size_t hand_written_ = 0;
};

struct LoadedCaseBase {
  CaseBase cases;
  CaseRules rules;  // the field and kick model the cases were checked against
  KickMirrors kick_mirrors;
  std::vector<std::string> configurations;  // "configurations", as written (cbr check uses them)
};

// Every kick a case of `base` plays must be a kick of `kicks` (the model of the robots that play
// the cases, read from `kicks_file`); InputError "KICKS_FILE: kicks: no kick 'K', which case C
// plays (the model has: ...)" otherwise.
void RequireCaseKicks(const CaseBase& base, const KickModel& kicks,
                      const std::filesystem::path& kicks_file);

// The shipped case base: MODELS_DIR/cases (models/model_paths.h).
std::filesystem::path DefaultCaseBasePath(const std::filesystem::path& models_dir);

LoadedCaseBase LoadCaseBase(const std::filesystem::path& path,
                            const std::filesystem::path& models_dir = DefaultModelsDir());

// The share of the points of a grid over [x_min, x_max] x [-half width, half width] of the field
// (steps of step_m) that lie inside the ball scope of at least one case for `goal`: a rough
// coverage figure for the case author (retrieval also needs the rest of the case to fit).
double BallScopeCoverage(const LoadedCaseBase& base, DefendingGoal goal, double x_min_m,
                         double x_max_m, double step_m);

// Two stored cases for the same defending goal that are the same after a transform, e.g. a
// hand-written case symmetric in y and its mirror_y copy. Not an error: such a case is legal and
// its copy only costs retrieval time; CheckCaseBase reports them as warnings, one per group of
// identical cases ("A and B are identical", "A, B, C, D, E and 7 more are identical (12 cases)"),
// so the author can see them.
inline constexpr std::size_t kMaxNamesPerOverlap = 5;
std::vector<std::string> CheckCaseBase(const CaseBase& base);

}  // namespace foresight
