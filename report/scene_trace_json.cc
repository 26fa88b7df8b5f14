#include "report/scene_trace_json.h"

#include "report/json_text.h"

namespace foresight {

namespace {

// Appends round(value * units) to `out`, after a comma unless `first`; `what` names the value
// when it is not finite (report/json_text.h).
void Int(std::string& out, double value, double units, const char* what, bool first = false) {
  if (!first) out += ',';
  out += std::to_string(JsonRounded(value * units, what));
}

void Vector(std::string& out, const Eigen::Vector3d& v, double units, const char* what,
            bool first = false) {
  Int(out, v.x(), units, what, first);
  Int(out, v.y(), units, what);
  Int(out, v.z(), units, what);
}

// x, y, z, qx, qy, qz, qw; the quaternion with qw >= 0 (q and -q are the same turn).
void Pose(std::string& out, const ScenePose& pose, const char* what, bool first = false) {
  Vector(out, pose.p_F, kTraceUnitsPerM, what, first);
  const double sign = pose.q_F.w() < 0.0 ? -1.0 : 1.0;
  Vector(out, sign * pose.q_F.vec(), kTraceUnitsPerQuat, what);
  Int(out, sign * pose.q_F.w(), kTraceUnitsPerQuat, what);
}

void Isometry(std::string& out, const Eigen::Isometry3d& pose) {
  ScenePose p;
  p.p_F = pose.translation();
  p.q_F = Eigen::Quaterniond(pose.linear()).normalized();
  Pose(out, p, "robot shape pose", true);
}

std::string Strings(const std::vector<std::string>& names) {
  std::string out = "[";
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += ',';
    out += JsonString(names[i]);
  }
  return out + "]";
}

std::string Frames(const SceneTrace& trace) {
  std::string t = "\"t\":[", phase = "\"phase\":[", ball = "\"ball\":[", links = "\"links_pose\":[",
              bodies = "\"bodies_pose\":[";
  for (std::size_t i = 0; i < trace.frames.size(); ++i) {
    const SceneFrame& f = trace.frames[i];
    const char* sep = i ? "," : "";
    t += sep;
    Int(t, f.t_s, kTraceUnitsPerS, "scene trace frame time", true);
    phase += sep;
    phase += std::to_string(f.phase);
    ball += sep;
    ball += '[';
    Pose(ball, f.ball, "scene trace ball pose", true);
    Vector(ball, f.w_F_ball, kTraceUnitsPerRadps, "scene trace ball spin");
    ball += "]";
    links += sep;
    links += '[';
    for (std::size_t k = 0; k < f.links.size(); ++k)
      Pose(links, f.links[k], "scene trace link pose", k == 0);
    links += "]";
    bodies += sep;
    bodies += '[';
    for (std::size_t k = 0; k < f.bodies.size(); ++k) {
      Int(bodies, f.bodies[k].p_F.x(), kTraceUnitsPerM, "scene trace body pose", k == 0);
      Int(bodies, f.bodies[k].p_F.y(), kTraceUnitsPerM, "scene trace body pose");
      Int(bodies, f.bodies[k].theta_rad, kTraceUnitsPerQuat, "scene trace body pose");
    }
    bodies += "]";
  }
  return t + "],\n" + phase + "],\n" + ball + "],\n" + links + "],\n" + bodies + "]";
}

}  // namespace

std::string SceneTraceJson(const SceneTrace& trace) {
  std::string out = "{\"format\":" + JsonString(kSceneTraceFormat);
  out += ",\"rate_hz\":" + JsonNumber(trace.rate_hz, "scene trace rate_hz");
  out += ",\"units\":{";
  const std::pair<const char*, double> units[] = {{"m", kTraceUnitsPerM},
                                                  {"quaternion", kTraceUnitsPerQuat},
                                                  {"rad_per_s", kTraceUnitsPerRadps},
                                                  {"N_s", kTraceUnitsPerNs},
                                                  {"s", kTraceUnitsPerS},
                                                  {"heading_rad", kTraceUnitsPerQuat}};
  for (const auto& [name, value] : units) {
    if (out.back() != '{') out += ',';
    out += JsonString(name);
    out += ':';
    out += JsonNumber(value, name);
  }
  out += "}";
  out += ",\n\"links\":" + Strings(trace.links);
  out += ",\n\"phases\":" + Strings(trace.phases);
  out += ",\n\"bodies\":[";
  for (std::size_t i = 0; i < trace.bodies.size(); ++i) {
    const SceneBody& b = trace.bodies[i];
    out += std::string(i ? "," : "") + "{\"name\":" + JsonString(b.name) +
           ",\"team\":" + std::to_string(b.team) +
           ",\"radius_m\":" + JsonNumber(b.radius_m, "scene trace body radius_m") +
           ",\"height_m\":" + JsonNumber(b.height_m, "scene trace body height_m") + "}";
  }
  out += "],\n" + Frames(trace);
  out += ",\n\"contacts\":[";
  for (std::size_t i = 0; i < trace.contacts.size(); ++i) {
    const SceneContact& c = trace.contacts[i];
    out += (i ? ",\n[" : "\n[");
    Int(out, c.t_s, kTraceUnitsPerS, "scene trace contact time", true);
    out += "," + JsonString(c.a) + "," + JsonString(c.b);
    Vector(out, c.p_F, kTraceUnitsPerM, "scene trace contact point");
    Int(out, c.impulse_Ns, kTraceUnitsPerNs, "scene trace contact impulse");
    out += "]";
  }
  out += "],\n\"obstacles\":[";
  for (std::size_t i = 0; i < trace.obstacles.size(); ++i) {
    out += i ? ",[" : "[";
    for (std::size_t k = 0; k < trace.obstacles[i].size(); ++k) {
      Pose(out, trace.obstacles[i][k], "scene trace obstacle link pose", k == 0);
    }
    out += "]";
  }
  return out + "]}";
}

std::string RobotShapesJson(const RobotModel& model) {
  std::string out = "{\"name\":" + JsonString(model.name) + ",\"links\":[";
  for (std::size_t l = 0; l < model.links.size(); ++l) {
    const RobotLink& link = model.links[l];
    out += l ? ",\n{\"name\":" : "\n{\"name\":";
    out += JsonString(link.name);
    out += ",\"shapes\":[";
    for (std::size_t s = 0; s < link.collisions.size(); ++s) {
      const RobotShape& shape = link.collisions[s];
      out += s ? ",{\"pose\":[" : "{\"pose\":[";
      Isometry(out, shape.pose_L_S);
      out += "]";
      switch (shape.kind) {
        case RobotShape::Kind::kBox:
          out += ",\"box\":[";
          Vector(out, shape.box_size_m, kTraceUnitsPerM, "robot box size", true);
          out += "]";
          break;
        case RobotShape::Kind::kSphere:
          out += ",\"sphere\":";
          Int(out, shape.radius_m, kTraceUnitsPerM, "robot sphere radius", true);
          break;
        case RobotShape::Kind::kCylinder:
          out += ",\"cylinder\":[";
          Int(out, shape.radius_m, kTraceUnitsPerM, "robot cylinder radius", true);
          Int(out, shape.length_m, kTraceUnitsPerM, "robot cylinder length");
          out += "]";
          break;
        case RobotShape::Kind::kMesh:
          out += ",\"vertices\":[";
          for (std::size_t v = 0; v < shape.mesh_vertices_S_m.size(); ++v) {
            Vector(out, shape.mesh_vertices_S_m[v], kTraceUnitsPerM, "robot mesh vertex", v == 0);
          }
          out += "],\"triangles\":[";
          for (std::size_t t = 0; t < shape.mesh_triangles.size(); ++t) {
            const auto& tri = shape.mesh_triangles[t];
            for (int k = 0; k < 3; ++k) {
              if (t > 0 || k > 0) out += ',';
              out += std::to_string(tri[k]);
            }
          }
          out += "]";
          break;
      }
      out += "}";
    }
    out += "]}";
  }
  return out + "]}";
}

}  // namespace foresight
