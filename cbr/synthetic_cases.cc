#include "cbr/synthetic_cases.h"

#include <string>

#include "common/error.h"
#include "common/random.h"

namespace foresight {

std::vector<Case> SyntheticCases(std::span<const Case> cases, const KickMirrors& mirrors,
                                 const SyntheticCaseSpec& spec) {
  if (cases.empty() || spec.count < 0) {
    throw InputError("SyntheticCases: needs cases to copy and a count >= 0");
  }
  RandomStream rng(StreamKey(spec.seed, 0, 0x5e7));
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.NextUniform(); };
  std::vector<Case> out;
  out.reserve(static_cast<std::size_t>(spec.count));
  for (int i = 0; i < spec.count; ++i) {
    const Case& source = cases[static_cast<std::size_t>(i) % cases.size()];
    Case c =
        rng.NextUniform() < 0.5 ? MirrorCase(source, CaseTransform::kMirrorY, mirrors) : source;
    c.name = source.name + "#" + std::to_string(i);
    // x, then y: two sequenced draws (the order of a constructor's arguments is unspecified).
    const double ball_x =
        uniform(-spec.half_length_m + spec.margin_m, spec.half_length_m - spec.margin_m);
    const Vec2 ball(ball_x,
                    uniform(-spec.half_width_m + spec.margin_m, spec.half_width_m - spec.margin_m));
    const Vec2 shift = ball - c.p_F_ball;
    const auto jitter = [&] {
      const double x = uniform(-spec.jitter_m, spec.jitter_m);
      return Vec2(x, uniform(-spec.jitter_m, spec.jitter_m));
    };
    c.p_F_ball = ball;
    c.ball_scope.tau_x_m *= spec.scope_scale;
    c.ball_scope.tau_y_m *= spec.scope_scale;
    for (CaseTeammate& tm : c.teammates) {
      tm.p_F += shift + jitter();
      for (CaseAction& a : tm.actions) {
        if (a.target_F) a.target_F = *a.target_F + shift;
      }
    }
    for (CaseOpponent& o : c.opponents) {
      o.p_F += shift + jitter();
      o.scope.tau_x_m *= spec.scope_scale;
      o.scope.tau_y_m *= spec.scope_scale;
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace foresight
