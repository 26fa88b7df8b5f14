#include "cbr/symmetry.h"

#include "common/geometry.h"

namespace foresight {
namespace {

int Bits(CaseTransform t) {
  switch (t) {
    case CaseTransform::kOriginal:
      return 0;
    case CaseTransform::kMirrorY:
      return 1;
    case CaseTransform::kMirrorX:
      return 2;
    case CaseTransform::kMirrorXY:
      return 3;
  }
  return 0;
}

constexpr CaseTransform kByBits[] = {CaseTransform::kOriginal, CaseTransform::kMirrorY,
                                     CaseTransform::kMirrorX, CaseTransform::kMirrorXY};

struct Mirror {
  bool flip_y = false;  // y -> -y
  bool flip_x = false;  // x -> -x
  Vec2 Point(const Vec2& p) const { return Vec2(flip_x ? -p.x() : p.x(), flip_y ? -p.y() : p.y()); }
  double Heading(double theta_rad) const {
    double t = flip_y ? -theta_rad : theta_rad;
    if (flip_x) t = kPi - t;
    return WrapAngle(t);
  }
  bool SwapsHands() const { return flip_x != flip_y; }
};

std::string MirrorKick(const std::string& kick, const KickMirrors& mirrors) {
  const auto it = mirrors.find(kick);
  return it == mirrors.end() ? kick : it->second;
}

}  // namespace

CaseTransform ComposeTransforms(CaseTransform a, CaseTransform b) {
  return kByBits[Bits(a) ^ Bits(b)];
}

Case MirrorCase(const Case& c, CaseTransform t, const KickMirrors& mirrors) {
  const Mirror m{(Bits(t) & 1) != 0, (Bits(t) & 2) != 0};
  Case out = c;
  out.transform = ComposeTransforms(c.transform, t);
  out.name = out.transform == CaseTransform::kOriginal
                 ? out.source
                 : out.source + "/" + std::string(CaseTransformName(out.transform));
  if (m.flip_x) {
    out.defending =
        c.defending == DefendingGoal::kCyan ? DefendingGoal::kYellow : DefendingGoal::kCyan;
  }
  out.p_F_ball = m.Point(c.p_F_ball);
  for (CaseTeammate& tm : out.teammates) {
    tm.p_F = m.Point(tm.p_F);
    for (CaseAction& a : tm.actions) {
      if (a.target_F) a.target_F = m.Point(*a.target_F);
      if (a.heading_rad) a.heading_rad = m.Heading(*a.heading_rad);
      if (!a.kick.empty() && m.SwapsHands()) a.kick = MirrorKick(a.kick, mirrors);
    }
  }
  for (CaseOpponent& o : out.opponents) o.p_F = m.Point(o.p_F);
  return out;
}

}  // namespace foresight
