#include "app/cbr_atlas.h"

#include <string>
#include <utility>
#include <vector>

#include "app/cbr_drawing.h"
#include "cbr/own_situation.h"
#include "models/model_paths.h"
#include "report/html_report.h"
#include "report/report_format.h"

namespace foresight {

namespace {

constexpr double kPixelsPerM = 52.0;  // 352 px a case: three columns on the page

std::string ActionsText(const Case& c) {
  std::string s;
  for (const CaseTeammate& t : c.teammates) {
    if (!s.empty()) s += "; ";
    s += std::to_string(t.id);
    s += ":";
    for (const CaseAction& a : t.actions) {
      s += ' ';
      s += ActionTypeName(a.type);
      if (a.type == ActionType::kPass || a.type == ActionType::kReceive) {
        s += ' ';
        s += std::to_string(a.teammate);
      } else if (a.type == ActionType::kKick && a.at_goal) {
        s += " goal";
      }
    }
  }
  return s;
}

}  // namespace

std::string CbrAtlasHtml(const CbrAtlasInput& input) {
  const CaseBase& base = input.base->cases;
  HtmlReport report("Case atlas");
  std::vector<const Case*> originals;
  for (const DefendingGoal goal : {DefendingGoal::kCyan, DefendingGoal::kYellow}) {
    for (const Case& c : base.Defending(goal)) {
      if (c.transform == CaseTransform::kOriginal) originals.push_back(&c);
    }
  }
  report.KeyValues({{"case base", DisplayPath(input.case_base_path, input.models_dir)},
                    {"retrieval parameters", DisplayPath(input.params_file, input.models_dir)},
                    {"hand-written cases", std::to_string(base.HandWrittenCount())},
                    {"stored cases", std::to_string(base.size())},
                    {"foresight", FORESIGHT_VERSION}});
  report.Paragraph(
      "Every hand-written case of the case base (Ros et al. 2009, sec. 2), as written. Blue: the "
      "case's teammates (with their id, facing the goal they attack); red: opponents; orange: the "
      "ball. Dashed ellipses: the scopes (the exp(-1) edge of the ball's and each opponent's "
      "Gaussian). Yellow trapezoids: the fuzzy ball path where mu > exp(-1), built by retrieval's "
      "ball-path builder with the case played from its own problem; black arrows are passes, dark "
      "red arrows kicks, dashed blue arrows go_to moves, orange arrows dribbles. Each case is also "
      "stored as the copies listed under it.");
  std::vector<std::pair<std::string, std::string>> figures;
  int blocked = 0;
  for (const Case* c : originals) {
    // "/mirror_y (cyan), /mirror_x, /mirror_xy (yellow)": the copies are named <name>/<transform>.
    std::string copies;
    for (const DefendingGoal goal : {DefendingGoal::kCyan, DefendingGoal::kYellow}) {
      std::string names;
      for (const Case& s : base.Defending(goal)) {
        if (s.source == c->source && s.transform != CaseTransform::kOriginal) {
          if (!names.empty()) names += ", ";
          names += s.name.substr(s.name.find('/') == std::string::npos ? 0 : s.name.find('/'));
        }
      }
      if (names.empty()) continue;
      if (!copies.empty()) copies += ", ";
      copies += names + " (" + std::string(DefendingGoalName(goal)) + ")";
    }
    std::string caption = c->notes + " Gameplay: " + ActionsText(*c) + ". Copies: " +
                          (copies.empty() ? std::string("none") : copies) + ".";
    // Whether the case passes its own free-path test (sec. 3.3.1) with the opponents where it
    // puts them: if not, a problem that looks exactly like the case does not retrieve it.
    const PathCheck own = OwnPathCheck(*c, input.params);
    std::string warning;
    if (!own.free) {
      warning = "blocked";
      ++blocked;
      caption += Format(" NOT RETRIEVABLE AS WRITTEN: its own opponent %d lies on its ball path "
                        "(trajectory %d, mu %.2f).",
                        c->opponents[static_cast<std::size_t>(own.opponent)].id, own.trajectory,
                        own.membership);
    }
    figures.emplace_back(CaseSvg(*c, input.base->rules.field, input.params, kPixelsPerM, warning), caption);
  }
  if (blocked > 0) {
    report.Warning(Format("%d of %zu cases are not retrieved by a problem that looks exactly like "
                          "them: one of their own opponents stands on their ball path (marked in "
                          "the captions).",
                          blocked, originals.size()));
  }
  report.FigureGrid(figures, 330);
  return report.Finish();
}

}  // namespace foresight
