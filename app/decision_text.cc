#include "app/decision_text.h"

#include "common/one_line.h"
#include "report/report_format.h"

#include <cmath>
#include <cstdio>
#include <string>


namespace foresight {

namespace {

std::string TurnText(double rotation_rad) {
  const double deg = rotation_rad * kRadToDeg;
  if (std::abs(deg) < 0.05) return "without turning";
  return Format("after turning %.1f deg %s around the ball", std::abs(deg),
                deg > 0 ? "counter-clockwise" : "clockwise");
}

std::string Row(const std::string& name, const std::string& turn, const ActionEvaluation& e,
                const std::string& mark) {
  return Format("%-18s %9s %7.2f %7.2f %7.2f %9.2f %8.3f %8.3f  %s\n", name.c_str(), turn.c_str(),
                e.p_opp_goal, e.p_own_goal, e.p_out, e.p_infield, e.utility, e.trimmed_utility,
                mark.c_str());
}

}  // namespace

std::string DecisionText(const DecisionRun& run) {
  const Decision& d = run.decision;
  const Situation& s = run.planner->situation();
  std::string out;
  // Names from data files in their printable form: a newline in one cannot split a line.
  out += "situation: " + PrintableName(s.name) + " (" +
         PrintableName(run.situation_file.string()) + ")\n";
  out += Format("strategy: %s, %d samples per hypothesis, seed %llu\n",
                std::string(StrategyName(d.strategy)).c_str(), run.samples,
                static_cast<unsigned long long>(run.seed));
  out += "decision: " + PrintableName(KickName(run, d.kick_index)) + " " +
         TurnText(d.rotation_rad) + "\n";
  if (!d.note.empty()) out += "note: " + d.note + "\n";
  out += "\n";
  out += Format("%-18s %9s %7s %7s %7s %9s %8s %8s\n", "action", "turn_deg", "p_goal", "p_own",
                "p_out", "p_infield", "utility", "trimmed");
  for (const KickOption& k : d.kicks) {
    const std::string name = PrintableName(KickName(run, k.kick_index));
    if (!k.considered) {
      out += Format(
          "%-18s %9s  (%s)\n", name.c_str(), "-",
          k.no_acceptable_rotation ? "no turn makes it acceptable" : "not used by this strategy");
      continue;
    }
    const std::string mark = (k.kick_index == d.kick_index ? "<- chosen" : "") +
                             std::string(k.choice.evaluation.too_risky ? " (too risky)" : "");
    out += Row(name, Format("%+.1f", k.choice.rotation_rad * kRadToDeg), k.choice.evaluation, mark);
  }
  out += Row("none", "0.0", d.none, d.kick_index == kNoKick ? "<- chosen" : "");
  return out;
}

}  // namespace foresight
