#include "cbr/coverage.h"

#include <algorithm>
#include <cmath>

#include "cbr/ball_scope_index.h"
#include "cbr/retrieval.h"
#include "common/geometry.h"
#include "common/random.h"

namespace foresight {
namespace {

double Uniform(RandomStream& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.NextUniform();
}

// Uniform in the disc of radius r; with `behind`, only its half at x <= 0.
Vec2 InDisc(RandomStream& rng, double r, bool behind) {
  for (;;) {
    const double x = Uniform(rng, -r, behind ? 0.0 : r);  // x, then y: a sequenced draw
    const Vec2 p(x, Uniform(rng, -r, r));
    if (p.squaredNorm() <= r * r) return p;
  }
}

}  // namespace

std::vector<AttackRegion> AttackRegions() {
  return {
      {"back", -2.0, -0.7, 0.0, 1.2},     {"center", -0.7, 0.7, 0.0, 1.2},
      {"side", -2.0, 0.7, 1.2, 1.6},      {"front", 0.7, 2.3, 0.0, 0.8},
      {"front_side", 0.7, 2.3, 0.8, 1.6}, {"corner", 2.3, 2.6, 0.5, 1.6},
  };
}

AttackCoverage MeasureAttackCoverage(const LoadedCaseBase& base, DefendingGoal goal,
                                     const RetrievalParams& params, int samples_per_region,
                                     std::uint64_t seed, const AttackSpec& spec) {
  const std::span<const Case> cases = base.cases.Defending(goal);
  const BallScopeIndex index(cases, params.thr_ball);
  const double half_length = base.rules.field.HalfLength();
  const double half_width = base.rules.field.HalfWidth();
  const double sign = AttackSign(goal);  // mirror x for yellow
  const auto on_field = [&](const Vec2& p) {
    return Vec2(std::clamp(p.x(), -half_length, half_length),
                std::clamp(p.y(), -half_width, half_width));
  };
  const double limit = -std::log(params.thr_ball);

  AttackCoverage out;
  const std::vector<AttackRegion>& regions = spec.regions;
  double area = 0.0;
  RetrievalResult result;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const AttackRegion& region = regions[r];
    RandomStream rng(StreamKey(seed, r, 0x13c0));
    RegionCoverage cov;
    cov.name = region.name;
    cov.area_m2 = region.Area();
    for (int s = 0; s < samples_per_region; ++s) {
      // Drawn for cyan (attacking +x), then mirrored in x for yellow.
      const double wing = rng.NextUniform() < 0.5 ? -1.0 : 1.0;
      const double ball_x = Uniform(rng, region.x_min_m, region.x_max_m);
      const Vec2 ball(ball_x, wing * Uniform(rng, region.abs_y_min_m, region.abs_y_max_m));
      const Vec2 t1 = on_field(ball + InDisc(rng, spec.behind_radius_m, true));
      const Vec2 t2 = on_field(ball + InDisc(rng, spec.support_radius_m, false));
      const auto in = [&](const FieldBox& h) {
        const double x = Uniform(rng, h.x_min_m, h.x_max_m);
        return Vec2(x, Uniform(rng, h.y_min_m, h.y_max_m));
      };
      const Vec2 defender = in(spec.defender);
      const Vec2 goalie = in(spec.goalie);
      const auto m = [&](const Vec2& p) { return Vec2(sign * p.x(), p.y()); };
      Problem p;
      p.defending = goal;
      p.p_F_ball = m(ball);
      const double heading = sign > 0.0 ? 0.0 : kPi;
      p.teammates = {{1, Pose2{m(t1), heading}}, {2, Pose2{m(t2), heading}}};
      p.opponents = {m(defender), m(goalie)};

      ++cov.samples;
      cov.in_scope += std::any_of(cases.begin(), cases.end(), [&](const Case& c) {
        const double u = (p.p_F_ball.x() - c.p_F_ball.x()) / c.ball_scope.tau_x_m;
        const double v = (p.p_F_ball.y() - c.p_F_ball.y()) / c.ball_scope.tau_y_m;
        return u * u + v * v < limit;
      });
      Retrieve(cases, index, p, params, &result);
      if (result.retrieved) {
        ++cov.retrieved;
        cov.cooperative +=
            cases[static_cast<std::size_t>(*result.retrieved)].teammates.size() >= 2 ? 1 : 0;
      } else {
        const bool any_blocked =
            std::any_of(result.evaluations.begin(), result.evaluations.end(),
                        [](const CaseEvaluation& e) { return e.verdict == Verdict::kPathBlocked; });
        const bool any_far =
            std::any_of(result.evaluations.begin(), result.evaluations.end(),
                        [](const CaseEvaluation& e) { return e.verdict == Verdict::kTooFar; });
        cov.blocked += any_blocked ? 1 : 0;
        cov.too_far += !any_blocked && any_far ? 1 : 0;
      }
    }
    if (cov.samples > 0) {
      out.in_scope += cov.area_m2 * cov.in_scope / cov.samples;
      out.retrieved += cov.area_m2 * cov.retrieved / cov.samples;
      out.cooperative += cov.area_m2 * cov.cooperative / cov.samples;
      area += cov.area_m2;
    }
    out.regions.push_back(std::move(cov));
  }
  if (area > 0.0) {
    out.in_scope /= area;
    out.retrieved /= area;
    out.cooperative /= area;
  }
  return out;
}

}  // namespace foresight
