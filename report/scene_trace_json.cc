#include "report/scene_trace_json.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "report/report_format.h"

namespace foresight {

namespace {

// Appends round(value * units) to `out`, after a comma unless `first`.
void Int(std::string& out, double value, double units, bool first = false) {
  if (!first) out += ',';
  out += std::to_string(std::llround(value * units));
}

void Vector(std::string& out, const Eigen::Vector3d& v, double units, bool first = false) {
  Int(out, v.x(), units, first);
  Int(out, v.y(), units);
  Int(out, v.z(), units);
}

// x, y, z, qx, qy, qz, qw; the quaternion with qw >= 0 (q and -q are the same turn).
void Pose(std::string& out, const ScenePose& pose, bool first = false) {
  Vector(out, pose.p_F, kTraceUnitsPerM, first);
  const double sign = pose.q_F.w() < 0.0 ? -1.0 : 1.0;
  Vector(out, sign * pose.q_F.vec(), kTraceUnitsPerQuat);
  Int(out, sign * pose.q_F.w(), kTraceUnitsPerQuat);
}

void Isometry(std::string& out, const Eigen::Isometry3d& pose) {
  ScenePose p;
  p.p_F = pose.translation();
  p.q_F = Eigen::Quaterniond(pose.linear()).normalized();
  Pose(out, p, true);
}

std::string Quoted(const std::string& text) { return nlohmann::json(text).dump(); }

std::string Strings(const std::vector<std::string>& names) {
  std::string out = "[";
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += ',';
    out += Quoted(names[i]);
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
    Int(t, f.t_s, kTraceUnitsPerS, true);
    phase += sep;
    phase += std::to_string(f.phase);
    ball += sep;
    ball += '[';
    Pose(ball, f.ball, true);
    Vector(ball, f.w_F_ball, kTraceUnitsPerRadps);
    ball += "]";
    links += sep;
    links += '[';
    for (std::size_t k = 0; k < f.links.size(); ++k) Pose(links, f.links[k], k == 0);
    links += "]";
    bodies += sep;
    bodies += '[';
    for (std::size_t k = 0; k < f.bodies.size(); ++k) {
      Int(bodies, f.bodies[k].p_F.x(), kTraceUnitsPerM, k == 0);
      Int(bodies, f.bodies[k].p_F.y(), kTraceUnitsPerM);
      Int(bodies, f.bodies[k].theta_rad, kTraceUnitsPerQuat);
    }
    bodies += "]";
  }
  return t + "],\n" + phase + "],\n" + ball + "],\n" + links + "],\n" + bodies + "]";
}

}  // namespace

std::string SceneTraceJson(const SceneTrace& trace) {
  std::string out = "{\"format\":" + Quoted(kSceneTraceFormat);
  out += Format(",\"rate_hz\":%.17g", trace.rate_hz);
  out += Format(
      ",\"units\":{\"m\":%g,\"quaternion\":%g,\"rad_per_s\":%g,\"N_s\":%g,\"s\":%g,"
      "\"heading_rad\":%g}",
      kTraceUnitsPerM, kTraceUnitsPerQuat, kTraceUnitsPerRadps, kTraceUnitsPerNs, kTraceUnitsPerS,
      kTraceUnitsPerQuat);
  out += ",\n\"links\":" + Strings(trace.links);
  out += ",\n\"phases\":" + Strings(trace.phases);
  out += ",\n\"bodies\":[";
  for (std::size_t i = 0; i < trace.bodies.size(); ++i) {
    const SceneBody& b = trace.bodies[i];
    out += Format("%s{\"name\":%s,\"team\":%d,\"radius_m\":%.6g,\"height_m\":%.6g}", i ? "," : "",
                  Quoted(b.name).c_str(), b.team, b.radius_m, b.height_m);
  }
  out += "],\n" + Frames(trace);
  out += ",\n\"contacts\":[";
  for (std::size_t i = 0; i < trace.contacts.size(); ++i) {
    const SceneContact& c = trace.contacts[i];
    out += (i ? ",\n[" : "\n[");
    Int(out, c.t_s, kTraceUnitsPerS, true);
    out += "," + Quoted(c.a) + "," + Quoted(c.b);
    Vector(out, c.p_F, kTraceUnitsPerM);
    Int(out, c.impulse_Ns, kTraceUnitsPerNs);
    out += "]";
  }
  out += "],\n\"obstacles\":[";
  for (std::size_t i = 0; i < trace.obstacles.size(); ++i) {
    out += i ? ",[" : "[";
    for (std::size_t k = 0; k < trace.obstacles[i].size(); ++k) {
      Pose(out, trace.obstacles[i][k], k == 0);
    }
    out += "]";
  }
  return out + "]}";
}

std::string RobotShapesJson(const RobotModel& model) {
  std::string out = "{\"name\":" + Quoted(model.name) + ",\"links\":[";
  for (std::size_t l = 0; l < model.links.size(); ++l) {
    const RobotLink& link = model.links[l];
    out += l ? ",\n{\"name\":" : "\n{\"name\":";
    out += Quoted(link.name);
    out += ",\"shapes\":[";
    for (std::size_t s = 0; s < link.collisions.size(); ++s) {
      const RobotShape& shape = link.collisions[s];
      out += s ? ",{\"pose\":[" : "{\"pose\":[";
      Isometry(out, shape.pose_L_S);
      out += "]";
      switch (shape.kind) {
        case RobotShape::Kind::kBox:
          out += ",\"box\":[";
          Vector(out, shape.box_size_m, kTraceUnitsPerM, true);
          out += "]";
          break;
        case RobotShape::Kind::kSphere:
          out += ",\"sphere\":";
          Int(out, shape.radius_m, kTraceUnitsPerM, true);
          break;
        case RobotShape::Kind::kCylinder:
          out += ",\"cylinder\":[";
          Int(out, shape.radius_m, kTraceUnitsPerM, true);
          Int(out, shape.length_m, kTraceUnitsPerM);
          out += "]";
          break;
        case RobotShape::Kind::kMesh:
          out += ",\"vertices\":[";
          for (std::size_t v = 0; v < shape.mesh_vertices_S_m.size(); ++v) {
            Vector(out, shape.mesh_vertices_S_m[v], kTraceUnitsPerM, v == 0);
          }
          out += "],\"triangles\":[";
          for (std::size_t t = 0; t < shape.mesh_triangles.size(); ++t) {
            const auto& tri = shape.mesh_triangles[t];
            out += Format("%s%d,%d,%d", t ? "," : "", tri[0], tri[1], tri[2]);
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
