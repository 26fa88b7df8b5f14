// foresight_mesh_tool OUT_DIR: writes the convex collision meshes of models/robots/ as Wavefront
// OBJ files (v and f lines, triangles wound counter-clockwise seen from outside, metres, in the
// link's frame):
//   OUT_DIR/nao/meshes/{l_foot,r_foot}.obj   OUT_DIR/aibo_ers7/meshes/{paw_front,paw_hind,head}.obj
// Run it with OUT_DIR = models/robots to regenerate the shipped files.
//
// Every part is an asymmetric superellipsoid (Barr 1981): with the signed power
// spow(c, e) = sign(c) |c|^e, latitude eta in [-pi/2, pi/2] and longitude omega in [-pi, pi),
//   x = x0 + ax * spow(cos eta, e_vertical) * spow(cos omega, e_plan)
//   y = y0 + ay * spow(cos eta, e_vertical) * spow(sin omega, e_plan)
//   z = z0 + az * spow(sin eta, e_vertical)
// where each semi-axis (ax, ay, az) takes its positive or its negative value depending on the
// side. Exponents below 1 flatten the faces and round the edges (a rounded box as e -> 0; an
// ellipsoid at e = 1). The surface is convex for exponents <= 1, and stays convex when two
// halves with different semi-axes meet (the normal there has no component along that axis).
// The sizes come from published figures of the robots; see the notes of robot.json.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "report/output_set.h"

namespace {

struct SuperellipsoidParams {
  std::string file;            // relative to OUT_DIR
  std::string description;     // one line, written into the header of the OBJ
  Eigen::Vector3d centre_m;    // (x0, y0, z0) in the link frame
  Eigen::Vector3d semi_pos_m;  // semi-axes towards +x, +y, +z
  Eigen::Vector3d semi_neg_m;  // semi-axes towards -x, -y, -z
  double e_vertical = 1.0;     // roundness of the edges of top and bottom (latitude)
  double e_plan = 1.0;         // roundness of the corners seen from above (longitude)
  int rings = 14;              // latitude steps from pole to pole
  int segments = 28;           // longitude steps
};

struct Mesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;  // 0-based, counter-clockwise seen from outside
};

double SignedPow(double c, double e) {
  return std::copysign(std::pow(std::abs(c), e), c);
}

double Semi(double direction, double positive, double negative) {
  return direction >= 0.0 ? positive : negative;
}

Eigen::Vector3d SurfacePoint(const SuperellipsoidParams& p, double eta, double omega) {
  const double horizontal = SignedPow(std::cos(eta), p.e_vertical);
  const double ux = horizontal * SignedPow(std::cos(omega), p.e_plan);
  const double uy = horizontal * SignedPow(std::sin(omega), p.e_plan);
  const double uz = SignedPow(std::sin(eta), p.e_vertical);
  return p.centre_m + Eigen::Vector3d(ux * Semi(ux, p.semi_pos_m.x(), p.semi_neg_m.x()),
                                      uy * Semi(uy, p.semi_pos_m.y(), p.semi_neg_m.y()),
                                      uz * Semi(uz, p.semi_pos_m.z(), p.semi_neg_m.z()));
}

// Vertex 0 is the south pole, then rings - 1 rings of `segments` vertices from south to north,
// then the north pole.
Mesh Superellipsoid(const SuperellipsoidParams& p) {
  const double pi = std::numbers::pi;
  Mesh mesh;
  mesh.vertices.push_back(p.centre_m - Eigen::Vector3d(0.0, 0.0, p.semi_neg_m.z()));
  for (int ring = 1; ring < p.rings; ++ring) {
    const double eta = -pi / 2.0 + pi * ring / p.rings;
    for (int s = 0; s < p.segments; ++s) {
      mesh.vertices.push_back(SurfacePoint(p, eta, -pi + 2.0 * pi * s / p.segments));
    }
  }
  mesh.vertices.push_back(p.centre_m + Eigen::Vector3d(0.0, 0.0, p.semi_pos_m.z()));

  const int south = 0;
  const int north = static_cast<int>(mesh.vertices.size()) - 1;
  auto at = [&](int ring, int s) { return 1 + (ring - 1) * p.segments + s % p.segments; };
  // Longitude increases counter-clockwise seen from +z, latitude increases upwards, so
  // (lower s, lower s+1, upper s+1) is counter-clockwise seen from outside.
  for (int s = 0; s < p.segments; ++s) {
    mesh.faces.emplace_back(south, at(1, s + 1), at(1, s));
    for (int ring = 1; ring + 1 < p.rings; ++ring) {
      mesh.faces.emplace_back(at(ring, s), at(ring, s + 1), at(ring + 1, s + 1));
      mesh.faces.emplace_back(at(ring, s), at(ring + 1, s + 1), at(ring + 1, s));
    }
    mesh.faces.emplace_back(north, at(p.rings - 1, s), at(p.rings - 1, s + 1));
  }
  return mesh;
}

// Every face must look away from the centre and have a non-degenerate area.
bool FacesPointOutwards(const Mesh& mesh, const Eigen::Vector3d& centre) {
  for (const Eigen::Vector3i& f : mesh.faces) {
    const Eigen::Vector3d& a = mesh.vertices[f.x()];
    const Eigen::Vector3d& b = mesh.vertices[f.y()];
    const Eigen::Vector3d& c = mesh.vertices[f.z()];
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.norm() < 1e-12 || normal.dot((a + b + c) / 3.0 - centre) <= 0.0) return false;
  }
  return true;
}

std::string Triple(const Eigen::Vector3d& v) {
  char text[80];
  std::snprintf(text, sizeof text, "(%.5g, %.5g, %.5g)", v.x(), v.y(), v.z());
  return text;
}

std::string Header(const SuperellipsoidParams& p, const Mesh& mesh) {
  std::ostringstream out;
  out << "# " << p.description << "\n"
      << "# Generated by tools/mesh_tool.cc (foresight_mesh_tool models/robots); do not edit.\n"
      << "# Asymmetric superellipsoid in the link frame, metres: centre " << Triple(p.centre_m)
      << ", semi-axes +" << Triple(p.semi_pos_m) << " -" << Triple(p.semi_neg_m) << ", e_vertical "
      << p.e_vertical << ", e_plan " << p.e_plan << ", " << p.rings << " rings x " << p.segments
      << " segments: " << mesh.vertices.size() << " vertices, " << mesh.faces.size()
      << " triangles.\n";
  return out.str();
}

std::string ObjText(const std::string& header, const Mesh& mesh) {
  std::string text = header;
  char line[96];
  for (const Eigen::Vector3d& v : mesh.vertices) {
    std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", v.x(), v.y(), v.z());
    text += line;
  }
  for (const Eigen::Vector3i& f : mesh.faces) {
    text += "f " + std::to_string(f.x() + 1) + ' ' + std::to_string(f.y() + 1) + ' ' +
            std::to_string(f.z() + 1) + '\n';
  }
  return text;
}

// NAO left foot in the l_foot frame (the ankle roll axis): sole 0.04519 m below the ankle
// (Aldebaran's FootHeight), toe 0.100 m ahead of and heel 0.055 m behind the ankle, 0.090 m
// wide with the sole 4 mm towards the outside (the FSR positions lie about 4 mm outwards),
// top flush with the ankle axis. Rounded toe and heel seen from above, flat sole.
SuperellipsoidParams NaoFoot(bool left) {
  const double outer = 0.049;
  const double inner = 0.041;
  const double half_height = 0.04519 / 2.0;
  SuperellipsoidParams p;
  p.file = left ? "nao/meshes/l_foot.obj" : "nao/meshes/r_foot.obj";
  p.description = std::string("NAO H25 ") + (left ? "left" : "right") +
                  " foot collision hull (toe +0.100, heel -0.055, sole -0.04519 m from the ankle)";
  p.centre_m = {0.0, 0.0, -half_height};
  p.semi_pos_m = {0.100, left ? outer : inner, half_height};
  p.semi_neg_m = {0.055, left ? inner : outer, half_height};
  p.e_vertical = 0.3;
  p.e_plan = 0.5;
  return p;
}

// AIBO ERS-7 lower leg with its paw along the lower leg's line, in a frame at the knee axis
// turned by the foot's angle (the URDF's collision origin turns it back): Tekkotsu's ERS-7.kin
// puts the paw's centre 65.434 mm (front legs) or 67.647 mm (hind legs) from the knee and gives
// the ball of the foot 26 mm across; the shin narrows towards the knee. Symmetric in y, so one
// mesh serves the left and the right leg.
SuperellipsoidParams AiboPaw(bool front) {
  const double knee_to_paw_m = front ? 0.065434 : 0.067647;
  const double paw_radius_m = 0.013;
  SuperellipsoidParams p;
  p.file = front ? "aibo_ers7/meshes/paw_front.obj" : "aibo_ers7/meshes/paw_hind.obj";
  p.description = front ? "AIBO ERS-7 front lower leg and paw collision hull (paw centre 65.434 mm "
                          "from the knee, ball of the foot 26 mm across)"
                        : "AIBO ERS-7 hind lower leg and paw collision hull (paw centre 67.647 mm "
                          "from the knee, ball of the foot 26 mm across)";
  p.centre_m = {0.0, 0.0, -knee_to_paw_m};
  p.semi_pos_m = {paw_radius_m, paw_radius_m, knee_to_paw_m - 0.010};
  p.semi_neg_m = {paw_radius_m, paw_radius_m, paw_radius_m};
  p.e_vertical = 0.6;
  p.e_plan = 0.7;
  p.rings = 16;
  p.segments = 24;
  return p;
}

// AIBO ERS-7 head in the head frame (the head tilt axis): about 0.113 m from the back of the
// skull to the muzzle (the camera in the nose lies about 0.081 m ahead of the tilt axis), 0.09 m
// wide without the ears, 0.09 m high from the crown to the lower jaw.
SuperellipsoidParams AiboHead() {
  SuperellipsoidParams p;
  p.file = "aibo_ers7/meshes/head.obj";
  p.description = "AIBO ERS-7 head collision hull (skull, muzzle and jaw, 0.113 x 0.09 x 0.09 m)";
  p.centre_m = {0.040, 0.0, -0.005};
  p.semi_pos_m = {0.055, 0.045, 0.045};
  p.semi_neg_m = {0.058, 0.045, 0.045};
  p.e_vertical = 0.35;
  p.e_plan = 0.35;
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: foresight_mesh_tool OUT_DIR   (OUT_DIR = models/robots for the shipped "
                 "meshes)\n";
    return 2;
  }
  const std::filesystem::path out_dir = argv[1];
  const std::vector<SuperellipsoidParams> parts = {NaoFoot(true), NaoFoot(false), AiboPaw(true),
                                                   AiboPaw(false), AiboHead()};
  try {
    // Every mesh file is declared (and its folder made and checked) first, then every mesh is
    // made, then all are written as one set (report/output_set.h): each file replaced whole,
    // none if one cannot be written.
    foresight::OutputSet outputs;
    for (const SuperellipsoidParams& part : parts) {
      const std::filesystem::path file = out_dir / part.file;
      std::filesystem::create_directories(file.parent_path());
      outputs.AddFile(part.file, file);
    }
    std::vector<std::string> lines;
    for (const SuperellipsoidParams& part : parts) {
      const Mesh mesh = Superellipsoid(part);
      if (!FacesPointOutwards(mesh, part.centre_m)) {
        std::cerr << "foresight_mesh_tool: " << part.file << ": a face points inwards\n";
        return 1;
      }
      outputs.Put(part.file, ObjText(Header(part, mesh), mesh));
      lines.push_back((out_dir / part.file).string() + ": " + std::to_string(mesh.vertices.size()) +
                      " vertices, " + std::to_string(mesh.faces.size()) + " triangles\n");
    }
    outputs.Commit();
    for (const std::string& line : lines) std::cout << line;
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << "foresight_mesh_tool: " << e.what() << "\n";
    return 1;
  } catch (const foresight::InputError& e) {
    std::cerr << "foresight_mesh_tool: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
