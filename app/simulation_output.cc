#include "app/simulation_output.h"

#include <sstream>

#include "common/geometry.h"
#include "common/one_line.h"
#include "models/model_paths.h"
#include "report/field_svg.h"
#include "report/provenance.h"
#include "report/report_format.h"
#include "report/viewer_page.h"
#include "validation/trial_view.h"

namespace foresight {

namespace {

constexpr Category kCategories[] = {Category::kInfield, Category::kOppGoal, Category::kOwnGoal,
                                    Category::kOut};
constexpr Contact kContacts[] = {Contact::kNone, Contact::kPost, Contact::kNet, Contact::kObstacle,
                                 Contact::kRobot};

double Share(int count, int total) {
  return total > 0 ? static_cast<double>(count) / total : 0.0;
}

std::string CategoryColour(Category category) {
  switch (category) {
    case Category::kOppGoal:
      return "#2ca02c";
    case Category::kOwnGoal:
      return "#d62728";
    case Category::kOut:
      return "#7f7f7f";
    default:
      return "#1f77b4";
  }
}

}  // namespace

std::string SimulationText(const SimulationRun& run) {
  const TrialSummary& s = run.summary;
  std::ostringstream out;
  out << Format("physics: %s kicks '%s' in %s, %d trials, seed %llu, turn %+.1f deg\n",
                PrintableName(run.robot->spec.name).c_str(), PrintableName(run.kick).c_str(),
                PrintableName(run.situation->name).c_str(), s.trials,
                static_cast<unsigned long long>(run.seed), run.rotation_rad * kRadToDeg);
  out << Format("robot (%.3f, %.3f) m heading %.1f deg, ball (%.3f, %.3f) m\n\n",
                run.state.robot.p_F.x(), run.state.robot.p_F.y(),
                run.state.robot.theta_rad * kRadToDeg, run.state.p_F_ball.x(),
                run.state.p_F_ball.y());
  out << "category   share\n";
  for (Category c : kCategories) {
    out << Format("%-10s %.3f\n", std::string(CategoryName(c)).c_str(),
                  Share(s.categories[static_cast<int>(c)], s.trials));
  }
  out << "\nfirst contact:";
  for (Contact c : kContacts) {
    out << " " << ContactName(c) << " " << s.first_contacts[static_cast<int>(c)];
  }
  out << Format(
      "\nlaunch: touched %d/%d, rolling freely %d; speed %.3f +- %.3f m/s, "
      "direction %+.2f +- %.2f deg\n",
      s.touched, s.trials, s.launched, s.launch_speed_mean_mps, s.launch_speed_sd_mps,
      s.launch_direction_mean_rad * kRadToDeg, s.launch_direction_sd_rad * kRadToDeg);
  out << Format("rest: mean (%.3f, %.3f) m, sd (%.3f, %.3f) m; mean time %.2f s; settled %d/%d\n",
                s.rest_mean_F.x(), s.rest_mean_F.y(), s.rest_sd_F.x(), s.rest_sd_F.y(),
                s.time_mean_s, s.settled, s.trials);
  out << Format("robot: %s base; fell %d/%d; blocked %d/%d; largest torso tilt %.1f deg\n",
                std::string(RobotBaseName(run.base)).c_str(), s.fell, s.trials, s.blocked, s.trials,
                s.max_tilt_rad * kRadToDeg);
  out << Format("placement: %d/%d trials drew the ball inside the robot first and drew again "
                "(%d draws rejected)\n",
                s.placement_redrawn, s.trials, s.placement_redraws);
  return out.str();
}

nlohmann::ordered_json SimulationJson(const SimulationRun& run) {
  const TrialSummary& s = run.summary;
  nlohmann::ordered_json j;
  j["foresight_version"] = FORESIGHT_VERSION;
  j["command"] = "simulate";
  j["situation"] = {{"name", run.situation->name},
                    {"file", run.situation_file.string()},
                    {"field", DisplayPath(run.situation->field_file, run.models_dir)},
                    {"kicks", DisplayPath(run.situation->kicks_file, run.models_dir)},
                    {"kicks_hash", ContentHash(run.situation->kicks_file)},
                    {"physics", DisplayPath(run.physics_file, run.models_dir)},
                    {"trial_variation",
                     run.variation_file.empty()
                         ? DisplayPath(run.models_dir / "robots" / run.robot->spec.name /
                                           "robot.json",
                                       run.models_dir)
                         : run.variation_file.generic_string()}};
  j["robot"] = run.robot->spec.name;
  j["base"] = RobotBaseName(run.base);
  j["kick"] = run.kick;
  j["rotation_deg"] = run.rotation_rad * kRadToDeg;
  j["seed"] = run.seed;
  j["trials"] = s.trials;
  nlohmann::ordered_json shares;
  for (Category c : kCategories)
    shares[std::string(CategoryName(c))] = Share(s.categories[static_cast<int>(c)], s.trials);
  nlohmann::ordered_json contacts;
  for (Contact c : kContacts)
    contacts[std::string(ContactName(c))] = s.first_contacts[static_cast<int>(c)];
  j["summary"] = {{"category_shares", shares},
                  {"first_contacts", contacts},
                  {"touched", s.touched},
                  {"launched", s.launched},
                  {"settled", s.settled},
                  {"fell", s.fell},
                  {"blocked", s.blocked},
                  {"max_tilt_deg", s.max_tilt_rad * kRadToDeg},
                  {"placement_redrawn", s.placement_redrawn},
                  {"placement_redraws", s.placement_redraws},
                  {"launch_speed_mean_mps", s.launch_speed_mean_mps},
                  {"launch_speed_sd_mps", s.launch_speed_sd_mps},
                  {"launch_direction_mean_deg", s.launch_direction_mean_rad * kRadToDeg},
                  {"launch_direction_sd_deg", s.launch_direction_sd_rad * kRadToDeg},
                  {"rest_mean_m", {s.rest_mean_F.x(), s.rest_mean_F.y()}},
                  {"rest_sd_m", {s.rest_sd_F.x(), s.rest_sd_F.y()}},
                  {"time_mean_s", s.time_mean_s}};
  nlohmann::ordered_json trials = nlohmann::ordered_json::array();
  for (const TrialResult& r : run.results) {
    nlohmann::ordered_json t;
    t["rest_m"] = {r.outcome.p_F_rest.x(), r.outcome.p_F_rest.y()};
    t["category"] = CategoryName(r.outcome.category);
    t["first_contact"] = ContactName(r.outcome.first_contact);
    t["time_s"] = r.outcome.time_s;
    t["touched"] = r.touched;
    t["launched"] = r.launched;
    t["settled"] = r.settled;
    t["fell"] = r.fell;
    t["blocked"] = r.blocked;
    t["status"] = OutcomeStatusName(r.outcome.status);
    t["max_tilt_deg"] = r.max_tilt_rad * kRadToDeg;
    t["launch_speed_mps"] = r.launch_speed_mps;
    t["launch_direction_deg"] = r.launch_direction_rad * kRadToDeg;
    t["draw"] = {{"placement_dx_m", r.draw.placement_dx_m},
                 {"placement_dy_m", r.draw.placement_dy_m},
                 {"placement_dtheta_deg", r.draw.placement_dtheta_rad * kRadToDeg},
                 {"motion_speed_factor", r.draw.speed_factor},
                 {"carpet_factor", r.draw.carpet_factor},
                 {"placement_redraws", r.draw.placement_redraws}};
    trials.push_back(t);
  }
  j["trials_detail"] = trials;
  return j;
}

std::string SimulationSvg(const SimulationRun& run) {
  const FieldSpec& field = run.situation->field;
  FieldCanvas canvas(field, 900.0 / field.carpet_length_m, 300.0);
  canvas.DrawField();
  for (const Obstacle& o : run.situation->obstacles) {
    canvas.DrawDot(o.p_F, canvas.Px(o.radius_m), "fill:#444;fill-opacity:0.85;stroke:#000");
  }
  // The robot where the kick's motion stands it: the ball at the motion's nominal spot, after
  // the turn around the ball.
  const KickMotion& motion = run.robot->motions[*run.robot->FindMotion(run.kick)];
  const double heading = run.state.robot.theta_rad + run.rotation_rad;
  const Vec2 stand = run.state.p_F_ball - Eigen::Rotation2Dd(heading) * motion.p_R_ball;
  canvas.DrawRobot(Pose2{stand, heading}, 0.12, "#dddddd");
  for (const TrialResult& r : run.results) {
    canvas.DrawDot(r.outcome.p_F_rest, 3.5,
                   "fill:" + CategoryColour(r.outcome.category) +
                       ";fill-opacity:0.7;stroke:#000;stroke-width:0.4");
  }
  canvas.DrawDot(run.state.p_F_ball, canvas.Px(field.ball.radius_m), "fill:#ff7f00;stroke:#000");
  canvas.DrawDot(run.summary.rest_mean_F, 6.0, "fill:none;stroke:#000;stroke-width:2");
  SvgWriter& svg = canvas.svg();
  const double x = canvas.legend_x();
  double y = 34.0;
  svg.Text(x, y, run.situation->name, "font-size:17px;font-weight:bold");
  y += 22.0;
  svg.Text(x, y,
           Format("physics: %s '%s', %d trials", run.robot->spec.name.c_str(), run.kick.c_str(),
                  run.summary.trials),
           "font-size:13px");
  y += 18.0;
  svg.Text(x, y,
           Format("seed %llu, turn %+.1f deg", static_cast<unsigned long long>(run.seed),
                  run.rotation_rad * kRadToDeg),
           "font-size:13px");
  y += 28.0;
  for (Category c : kCategories) {
    svg.Circle(x + 7, y - 5, 6, "fill:" + CategoryColour(c) + ";stroke:#000");
    svg.Text(x + 20, y,
             Format("%s %.3f", std::string(CategoryName(c)).c_str(),
                    Share(run.summary.categories[static_cast<int>(c)], run.summary.trials)),
             "font-size:13px");
    y += 20.0;
  }
  y += 8.0;
  svg.Text(x, y,
           Format("launch %.2f +- %.2f m/s", run.summary.launch_speed_mean_mps,
                  run.summary.launch_speed_sd_mps),
           "font-size:12px");
  y += 16.0;
  svg.Text(x, y,
           Format("direction %+.1f +- %.1f deg", run.summary.launch_direction_mean_rad * kRadToDeg,
                  run.summary.launch_direction_sd_rad * kRadToDeg),
           "font-size:12px");
  y += 16.0;
  svg.Text(x, y, "ring: mean rest position", "font-size:11px;fill:#555");
  return svg.Finish();
}

std::string SimulationTraceCsv(const SimulationRun& run) {
  std::ostringstream out;
  out << "trial,t_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps\n";
  for (std::size_t i = 0; i < run.results.size(); ++i) {
    for (const TracePoint& p : run.results[i].trace) {
      out << Format("%zu,%.4f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f\n", i, p.t_s, p.p_F.x(), p.p_F.y(),
                    p.p_F.z(), p.v_F.x(), p.v_F.y(), p.v_F.z());
    }
  }
  return out.str();
}

std::string SimulationViewHtml(const SimulationRun& run) {
  ViewerScene scene;
  scene.title = Format("%s kicks '%s' in %s: %d trials", run.robot->spec.name.c_str(),
                       run.kick.c_str(), run.situation->name.c_str(), run.summary.trials);
  scene.about = {
      {"command", "foresight simulate"},
      {"situation", run.situation_file.string()},
      {"physics", DisplayPath(run.physics_file, run.models_dir)},
      {"base", std::string(RobotBaseName(run.base))},
      {"turn", Format("%+.1f deg", run.rotation_rad * kRadToDeg)},
      {"seed", std::to_string(run.seed)},
      {"version", FORESIGHT_VERSION},
      {"drawn with", ViewerLibraryVersion()},
  };
  scene.field = &run.situation->field;
  scene.robot = &run.robot->model;
  AddTrialViews(run.results, scene);
  return ViewerHtml(scene);
}

}  // namespace foresight
